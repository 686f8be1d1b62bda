#include "viz/feature_lines.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace mechanist {

std::vector<std::vector<Eigen::Vector3d>> FeatureLines(const Part& part, bool pitch_circles) {
  std::vector<std::vector<Eigen::Vector3d>> lines;
  for (const Feature& f : part.features) {
    if (f.kind == FeatureKind::kFace) continue;
    const bool bevel = f.kind == FeatureKind::kBevelGear;
    // A bevel gear's axis runs from its apex to its outer pitch circle.
    const double extent =
        bevel ? f.OuterConeDistance() * std::cos(f.pitch_angle) : std::max(f.length, 0.0);
    const double size =
        std::max({extent, f.diameter, f.pitch_diameter, f.module * std::max(f.teeth, 1), 2.0});
    const double margin = 0.25 * size;
    lines.push_back({f.origin - margin * f.axis, f.origin + (extent + margin) * f.axis});
    const bool toothed = f.kind == FeatureKind::kGear || f.kind == FeatureKind::kWormWheel || bevel;
    if (!pitch_circles || (!toothed && f.kind != FeatureKind::kPinRing)) continue;
    const Eigen::Vector3d u = f.axis.unitOrthogonal(), v = f.axis.cross(u);
    const Eigen::Vector3d center = f.origin + (bevel ? extent : 0.5 * f.length) * f.axis;
    const double radius = toothed ? f.PitchRadius() : 0.5 * f.diameter;
    constexpr int kSegments = 72;
    std::vector<Eigen::Vector3d> circle;
    for (int k = 0; k <= kSegments; ++k) {
      const double t = 2.0 * M_PI * k / kSegments;
      circle.push_back(center + radius * (std::cos(t) * u + std::sin(t) * v));
    }
    lines.push_back(std::move(circle));
  }
  return lines;
}

}  // namespace mechanist
