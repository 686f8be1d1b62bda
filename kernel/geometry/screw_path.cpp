#include "kernel/geometry/screw_path.h"

#include <algorithm>
#include <cmath>

namespace mechanist {
namespace {

constexpr double kTwoPi = 6.283185307179586;

double DistanceToAxis(const Eigen::Vector3d& p, const ScrewMotion& m) {
  const Eigen::Vector3d d = p - m.point_W;
  return (d - d.dot(m.axis_W) * m.axis_W).norm();
}

}  // namespace

RigidTransform ScrewPath::At(double s) const {
  RigidTransform D;
  for (const ScrewMotion& m : screws) D = D * m.At(s);
  return D;
}

double ScrewPath::SpeedBound(const Eigen::Vector3d& center_W, double radius, double s_max) const {
  // Inner screws first: moved[j] bounds how far screws j .. k-1 can carry the sphere's centre.
  // The body is rigid, so every point stays within `radius` of the carried centre: distances
  // to an axis are at most the centre's plus `radius`.
  const std::size_t k = screws.size();
  std::vector<double> moved(k + 1, 0.0);
  for (std::size_t j = k; j-- > 0;) {
    const ScrewMotion& m = screws[j];
    const double r = DistanceToAxis(center_W, m) + moved[j + 1];
    // A turn by angle a moves a point at distance r along a chord of at most min(2, a) r.
    const double angle = kTwoPi * std::abs(m.turns_per_unit) * s_max;
    moved[j] = moved[j + 1] + std::min(2.0, angle) * r + std::abs(m.travel_per_unit) * s_max;
  }
  double speed = 0.0;
  for (std::size_t j = 0; j < k; ++j) {
    const ScrewMotion& m = screws[j];
    speed += kTwoPi * std::abs(m.turns_per_unit) *
                 (DistanceToAxis(center_W, m) + moved[j + 1] + radius) +
             std::abs(m.travel_per_unit);
  }
  return speed;
}

}  // namespace mechanist
