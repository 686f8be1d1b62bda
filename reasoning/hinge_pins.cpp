#include "reasoning/hinge_pins.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "kernel/mesh/mesh_builder.h"

namespace mechanist {
namespace {

class PinFinder {
 public:
  PinFinder(const Assembly& assembly, const AssemblyState& state, const CollisionModel& model)
      : assembly_(assembly), state_(state), model_(model) {}

  Eigen::Vector3d Axis(FeatureRef h) const {
    return state_.X_WP[h.part].RotateDirection(assembly_.feature(h).axis);
  }
  Eigen::Vector3d Origin(FeatureRef h) const {
    return state_.X_WP[h.part] * assembly_.feature(h).origin;
  }

  // Where hole h begins and ends along the unit u, from the point o (mm).
  std::pair<double, double> Span(FeatureRef h, const Eigen::Vector3d& o,
                                 const Eigen::Vector3d& u) const {
    const double start = (Origin(h) - o).dot(u);
    const double end = start + assembly_.feature(h).length * Axis(h).dot(u);
    return std::minmax(start, end);
  }

  // Whether holes x and y of one part carry one rod: on one line, and the axis between them
  // outside the part (see FindHingePins).
  bool OneRod(FeatureRef x, FeatureRef y) const {
    if (x.part != y.part) return false;
    const Eigen::Vector3d u = Axis(x), o = Origin(x), d = Origin(y) - o;
    if (std::abs(u.dot(Axis(y))) < std::cos(assembly_.tolerance().angle) ||
        (d - d.dot(u) * u).norm() > assembly_.tolerance().length) {
      return false;
    }
    const auto [x_lo, x_hi] = Span(x, o, u);
    const auto [y_lo, y_hi] = Span(y, o, u);
    const double gap_start = std::min(x_hi, y_hi), gap_end = std::max(x_lo, y_lo);
    if (gap_end <= gap_start) return true;  // the holes meet
    const CollisionMesh& mesh = model_.part_mesh(x.part);
    if (!mesh.solid()) return false;
    const RigidTransform X_PW = state_.X_WP[x.part].inverse();
    constexpr int kSamples = 7;
    for (int k = 1; k <= kSamples; ++k) {
      const double s = gap_start + (gap_end - gap_start) * k / (kSamples + 1);
      if (mesh.Contains(X_PW * (o + s * u))) return false;
    }
    return true;
  }

  HingePin Pin(const std::vector<FeatureRef>& holes) const {
    HingePin pin;
    pin.holes = holes;
    const Eigen::Vector3d z = Axis(holes.front()), o = Origin(holes.front());
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    pin.diameter = lo;
    for (const FeatureRef h : holes) {
      const auto [start, end] = Span(h, o, z);
      lo = std::min(lo, start);
      hi = std::max(hi, end);
      pin.diameter = std::min(pin.diameter, assembly_.feature(h).diameter);
      pin.parts.push_back(h.part);
    }
    std::sort(pin.parts.begin(), pin.parts.end());
    pin.parts.erase(std::unique(pin.parts.begin(), pin.parts.end()), pin.parts.end());
    pin.ends_W = {o + lo * z, o + hi * z};
    pin.X_WPin = RigidTransform::FromZAxis(o, z);
    if (lo < hi && pin.diameter > 0) {
      constexpr int kSides = 24;
      pin.mesh =
          std::make_shared<const CollisionMesh>(std::make_shared<const TriangleMesh>(ExtrudeRegion(
              {CircleRing(Eigen::Vector2d::Zero(), pin.diameter / 2, kSides), {}}, lo, hi)));
      pin.box = TransformBox(pin.X_WPin, pin.mesh->bounds());
    }
    return pin;
  }

 private:
  const Assembly& assembly_;
  const AssemblyState& state_;
  const CollisionModel& model_;
};

}  // namespace

std::vector<HingePin> FindHingePins(const Assembly& assembly, const Analysis& analysis,
                                    const AssemblyState& state, const CollisionModel& model) {
  const PinFinder finder(assembly, state, model);
  std::vector<std::vector<FeatureRef>> groups;
  for (const Pair& p : analysis.pairs) {
    if (p.source == PairSource::kImpliedPin && p.type == PairType::kRevolute) {
      groups.push_back({p.a, p.b});
    }
  }
  const auto joined = [&](const std::vector<FeatureRef>& g, const std::vector<FeatureRef>& h) {
    return std::any_of(g.begin(), g.end(), [&](FeatureRef x) {
      return std::any_of(h.begin(), h.end(),
                         [&](FeatureRef y) { return x == y || finder.OneRod(x, y); });
    });
  };
  // Each group takes in every later group it joins, again from the first after it once it
  // grew (what it took in may join groups it passed over).
  for (std::size_t i = 0; i < groups.size(); ++i) {
    for (std::size_t j = i + 1; j < groups.size();) {
      if (!joined(groups[i], groups[j])) {
        ++j;
        continue;
      }
      groups[i].insert(groups[i].end(), groups[j].begin(), groups[j].end());
      groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(j));
      j = i + 1;
    }
    std::sort(groups[i].begin(), groups[i].end());
    groups[i].erase(std::unique(groups[i].begin(), groups[i].end()), groups[i].end());
  }
  const auto by_name = [&](FeatureRef x, FeatureRef y) {
    return assembly.FeatureName(x) < assembly.FeatureName(y);
  };
  for (auto& g : groups) std::sort(g.begin(), g.end(), by_name);
  std::sort(groups.begin(), groups.end(),
            [&](const auto& x, const auto& y) { return by_name(x.front(), y.front()); });
  std::vector<HingePin> pins;
  for (const auto& holes : groups) {
    HingePin pin = finder.Pin(holes);
    if (pin.mesh) pins.push_back(std::move(pin));  // one with no length or width goes nowhere
  }
  return pins;
}

}  // namespace mechanist
