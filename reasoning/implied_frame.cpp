#include "reasoning/implied_frame.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <optional>
#include <string>

#include "kernel/geometry/line_geometry.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

bool IsExternalGear(const Feature& f) {
  switch (f.kind) {
    case FeatureKind::kGear:
      return !f.internal;
    case FeatureKind::kBevelGear:
    case FeatureKind::kWorm:
    case FeatureKind::kWormWheel:
      return true;
    default:
      return false;
  }
}

// Whether the lines through p_a along unit u_a and through p_b along u_b are one line, within
// `tolerance` (mm, radians). All in one frame.
bool Collinear(const Eigen::Vector3d& p_a, const Eigen::Vector3d& u_a, const Eigen::Vector3d& p_b,
               const Eigen::Vector3d& u_b, const Tolerance& tolerance) {
  return AngleBetweenLines(u_a, u_b) <= tolerance.angle &&
         DistanceToLine(p_b, p_a, u_a) <= tolerance.length;
}

// The index of `part`'s first hole collinear with its first external gear, or nothing.
std::optional<std::size_t> BoreOfGear(const Part& part, const Tolerance& tolerance) {
  const auto gear = std::find_if(part.features.begin(), part.features.end(), IsExternalGear);
  if (gear == part.features.end()) return std::nullopt;
  for (std::size_t k = 0; k < part.features.size(); ++k) {
    const Feature& f = part.features[k];
    if (f.kind == FeatureKind::kHole &&
        Collinear(gear->origin, gear->axis, f.origin, f.axis, tolerance)) {
      return k;
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<Diagnostic> ImplyGearFrame(AssemblySpec* spec) {
  if (!spec->inference.implied_frame) return {};
  std::vector<Part>& parts = spec->parts;
  if (std::any_of(parts.begin(), parts.end(), [](const Part& p) { return p.ground; })) return {};
  struct Bore {
    std::size_t part;
    std::size_t hole;
  };
  std::vector<Bore> bores;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].compliant) continue;
    const std::optional<std::size_t> hole = BoreOfGear(parts[p], spec->tolerance);
    if (!hole) return {};
    bores.push_back({p, *hole});
  }
  if (bores.size() < 2) return {};
  // The bores are empty: no other part's shaft or thread runs along one.
  for (const Bore& bore : bores) {
    const Part& owner = parts[bore.part];
    const Feature& hole = owner.features[bore.hole];
    const Eigen::Vector3d p_W = owner.X_WP * hole.origin;
    const Eigen::Vector3d u_W = owner.X_WP.RotateDirection(hole.axis);
    for (std::size_t q = 0; q < parts.size(); ++q) {
      if (q == bore.part) continue;
      for (const Feature& f : parts[q].features) {
        if (f.kind != FeatureKind::kShaft && f.kind != FeatureKind::kThread) continue;
        if (Collinear(p_W, u_W, parts[q].X_WP * f.origin, parts[q].X_WP.RotateDirection(f.axis),
                      spec->tolerance)) {
          return {};
        }
      }
    }
  }
  Part frame;
  frame.id = "implied_frame";
  for (int n = 2;
       std::any_of(parts.begin(), parts.end(), [&](const Part& p) { return p.id == frame.id; });
       ++n) {
    frame.id = fmt::format("implied_frame_{}", n);
  }
  frame.ground = true;
  const std::size_t frame_index = parts.size();
  std::vector<std::string> gears;
  for (const Bore& bore : bores) {
    const Part& owner = parts[bore.part];
    const Feature& hole = owner.features[bore.hole];
    Feature axle;
    axle.kind = FeatureKind::kShaft;
    axle.id = fmt::format("axle_{}", frame.features.size() + 1);
    axle.origin = owner.X_WP * hole.origin;
    axle.axis = owner.X_WP.RotateDirection(hole.axis);
    axle.diameter = hole.diameter;
    axle.length = hole.length;
    spec->overrides.push_back({.features = {FeatureRef(frame_index, frame.features.size()),
                                            FeatureRef(bore.part, bore.hole)},
                               .type = PairType::kRevolute,
                               .implied_frame = true});
    frame.features.push_back(axle);
    gears.push_back(fmt::format("'{}' ({} mm bore)", owner.id, FormatNumber(hole.diameter, 4)));
  }
  std::vector<std::string> ids;
  for (const Bore& bore : bores) ids.push_back(parts[bore.part].id);
  ids.push_back(frame.id);
  parts.push_back(std::move(frame));
  return {{Severity::kInfo,
           "implied_frame",
           fmt::format("no part is ground and the file models the gears alone, without a frame "
                       "or shafts: each is taken to turn on an axle fixed to the world through "
                       "its bore, {}, held by the features-only part '{}' (set \"ground\": true "
                       "on a part to count from it instead, or \"infer\": {{\"implied_frame\": "
                       "false}})",
                       fmt::join(gears, ", "), parts.back().id),
           ids,
           {}}};
}

}  // namespace mechanist
