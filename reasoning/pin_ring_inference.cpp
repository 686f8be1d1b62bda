#include "reasoning/pin_ring_inference.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "kernel/geometry/circle_fit.h"
#include "kernel/geometry/line_geometry.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A pin's axis in world coordinates, oriented like the first pin of its ring when grouped.
struct Pin {
  std::size_t part;
  Eigen::Vector3d p_W;  // one end of the shaft
  Eigen::Vector3d u_W;  // unit, from that end along the shaft
  double length;
  double diameter;
};

// The part's only shaft when the part is a pin: all its features inferred, one shaft and
// otherwise faces.
std::optional<Pin> AsPin(const std::vector<Part>& parts, std::size_t p,
                         const std::function<bool(std::size_t, std::size_t)>& inferred) {
  const Part& part = parts[p];
  const Feature* shaft = nullptr;
  for (std::size_t k = 0; k < part.features.size(); ++k) {
    if (!inferred(p, k)) return std::nullopt;
    const Feature& f = part.features[k];
    if (f.kind == FeatureKind::kFace) continue;
    if (f.kind != FeatureKind::kShaft || shaft) return std::nullopt;
    shaft = &f;
  }
  if (!shaft || part.compliant) return std::nullopt;
  return Pin{p, part.X_WP * shaft->origin, part.X_WP.RotateDirection(shaft->axis).normalized(),
             shaft->length, shaft->diameter};
}

// Whether `pin` sits in one of part `host`'s holes: collinear, of its diameter, overlapping.
bool HoldsPin(const Part& host, const Pin& pin, double L, double A) {
  for (const Feature& f : host.features) {
    if (f.kind != FeatureKind::kHole) continue;
    if (std::abs(f.diameter - pin.diameter) > std::max(L, 0.05 * pin.diameter)) continue;
    const AxisSegment hole{host.X_WP * f.origin, host.X_WP.RotateDirection(f.axis).normalized(),
                           f.length};
    if (AngleBetweenLines(hole.direction, pin.u_W) > A) continue;
    if (DistanceToLine(hole.origin, pin.p_W, pin.u_W) > L) continue;
    if (AxialOverlap({pin.p_W, pin.u_W, pin.length}, hole) > L) return true;
  }
  return false;
}

// When the axes of `ring` (pins of one diameter, pointing alike) stand evenly on one circle
// across their axis, within L: adds the pin ring to part `host` and returns its finding.
std::optional<Diagnostic> RingOf(const std::vector<Pin>& ring, std::size_t host,
                                 std::vector<Part>* parts, double L) {
  if (ring.size() < 3) return std::nullopt;
  const Pin& first = ring.front();
  const Eigen::Vector3d u = first.u_W;
  const Eigen::Vector3d x = u.unitOrthogonal(), y = u.cross(x);
  std::vector<Eigen::Vector2d> centres;
  for (const Pin& pin : ring) centres.emplace_back(pin.p_W.dot(x), pin.p_W.dot(y));
  const FittedCircle circle = FitCircle(centres);
  if (!(circle.radius > first.diameter)) return std::nullopt;
  std::vector<double> angles;
  for (const Eigen::Vector2d& c : centres) {
    if (std::abs((c - circle.center).norm() - circle.radius) > L) return std::nullopt;
    angles.push_back(std::atan2(c.y() - circle.center.y(), c.x() - circle.center.x()));
  }
  std::sort(angles.begin(), angles.end());
  const double step = 2 * kPi / static_cast<double>(angles.size());
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double gap = k + 1 < angles.size() ? angles[k + 1] - angles[k]
                                             : angles.front() + 2 * kPi - angles.back();
    if (std::abs(gap - step) * circle.radius > L) return std::nullopt;
  }
  double t_min = 1e300, t_max = -1e300;
  for (const Pin& pin : ring) {
    t_min = std::min(t_min, pin.p_W.dot(u));
    t_max = std::max(t_max, pin.p_W.dot(u) + pin.length);
  }
  Part& owner = (*parts)[host];
  const RigidTransform X_PW = owner.X_WP.inverse();
  Feature f;
  f.kind = FeatureKind::kPinRing;
  for (int n = 1; f.id.empty() || owner.FindFeature(f.id); ++n) f.id = fmt::format("pins_{}", n);
  f.origin = X_PW * (circle.center.x() * x + circle.center.y() * y + t_min * u);
  f.axis = X_PW.RotateDirection(u);
  f.length = t_max - t_min;
  f.teeth = static_cast<int>(ring.size());
  f.diameter = 2 * circle.radius;
  f.pin_diameter = first.diameter;
  owner.features.push_back(f);
  std::vector<std::string> names = {owner.id}, quoted;
  for (const Pin& pin : ring) {
    names.push_back((*parts)[pin.part].id);
    quoted.push_back(fmt::format("'{}'", names.back()));
  }
  return Diagnostic{
      Severity::kInfo,
      "pin_ring_of_parts",
      fmt::format("the {} pins {} ({} mm on a {} mm circle) held in '{}' are its "
                  "pin ring {}/{}: a cycloidal disc rolls on them",
                  ring.size(), fmt::join(quoted, ", "), FormatNumber(f.pin_diameter, 4),
                  FormatNumber(f.diameter, 4), owner.id, owner.id, f.id),
      names,
      {owner.id + "/" + f.id}};
}

}  // namespace

std::vector<Diagnostic> InferPinRingsOfParts(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred) {
  const double L = length_tolerance, A = angle_tolerance;
  std::vector<Pin> pins;
  for (std::size_t p = 0; p < parts->size(); ++p) {
    if (const std::optional<Pin> pin = AsPin(*parts, p, inferred)) pins.push_back(*pin);
  }
  if (pins.size() < 3) return {};
  // The pins each host holds, hosts with the most first.
  std::map<std::size_t, std::vector<std::size_t>> held;  // host part -> indices into pins
  for (std::size_t k = 0; k < pins.size(); ++k) {
    for (std::size_t h = 0; h < parts->size(); ++h) {
      if (h != pins[k].part && HoldsPin((*parts)[h], pins[k], L, A)) held[h].push_back(k);
    }
  }
  std::vector<std::pair<std::size_t, std::vector<std::size_t>>> hosts(held.begin(), held.end());
  std::stable_sort(hosts.begin(), hosts.end(),
                   [](const auto& a, const auto& b) { return a.second.size() > b.second.size(); });
  std::vector<bool> used(pins.size(), false);
  std::vector<Diagnostic> found;
  for (auto& [host, candidates] : hosts) {
    std::erase_if(candidates, [&](std::size_t k) { return used[k]; });
    // The pins of one diameter and direction, each such set tried as a ring.
    std::vector<std::vector<Pin>> sets;
    for (const std::size_t k : candidates) {
      Pin pin = pins[k];
      auto same = std::find_if(sets.begin(), sets.end(), [&](const std::vector<Pin>& set) {
        return std::abs(pin.diameter - set.front().diameter) <= L &&
               AngleBetweenLines(pin.u_W, set.front().u_W) <= A;
      });
      if (same == sets.end()) {
        sets.push_back({pin});
        continue;
      }
      if (pin.u_W.dot(same->front().u_W) < 0) {  // pointing like the set's first
        pin.p_W += pin.length * pin.u_W;
        pin.u_W = -pin.u_W;
      }
      same->push_back(pin);
    }
    for (const std::vector<Pin>& ring : sets) {
      std::optional<Diagnostic> d = RingOf(ring, host, parts, L);
      if (!d) continue;
      for (const Pin& pin : ring) {
        for (const std::size_t k : candidates) used[k] = used[k] || pins[k].part == pin.part;
      }
      found.push_back(std::move(*d));
    }
  }
  return found;
}

}  // namespace mechanist
