#include "kernel/voxels/triangle_box_overlap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mechanist {

TriangleBoxTester::TriangleBoxTester(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                     const Eigen::Vector3d& c, const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& half) {
  const Eigen::Vector3d v0 = a - origin, v1 = b - origin, v2 = c - origin;
  // Every projection is a short sum of products of coordinates of this magnitude (the
  // offsets reach up to `half`); a margin of 64 ulps of it covers their rounding.
  const double scale = std::max({v0.cwiseAbs().maxCoeff(), v1.cwiseAbs().maxCoeff(),
                                 v2.cwiseAbs().maxCoeff(), 2 * half.maxCoeff()});
  const double eps = 64 * std::numeric_limits<double>::epsilon() * scale;
  const Eigen::Vector3d h = half.array() + eps;

  const auto set = [&](Axis& axis, const Eigen::Vector3d& direction, double radius) {
    const double p0 = direction.dot(v0), p1 = direction.dot(v1), p2 = direction.dot(v2);
    axis = {direction, std::min({p0, p1, p2}), std::max({p0, p1, p2}), radius};
  };
  for (int i = 0; i < 3; ++i) set(axes_[i], Eigen::Vector3d::Unit(i), h[i]);
  const Eigen::Vector3d e[3] = {v1 - v0, v2 - v1, v0 - v2};
  // The nine axes e_j x u_i (u_i the box axes), then the triangle's normal.
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d direction = Eigen::Vector3d::Zero();
      direction[(i + 1) % 3] = -e[j][(i + 2) % 3];
      direction[(i + 2) % 3] = e[j][(i + 1) % 3];
      set(axes_[3 + 3 * j + i], direction,
          h.dot(direction.cwiseAbs()) + eps * direction.cwiseAbs().sum());
    }
  }
  const Eigen::Vector3d n = e[0].cross(e[1]);
  set(axes_[12], n, h.dot(n.cwiseAbs()) + eps * n.cwiseAbs().sum());
}

bool TriangleBoxTester::Overlaps(const Eigen::Vector3d& offset) const {
  for (const Axis& axis : axes_) {
    const double center = axis.direction.dot(offset);
    if (axis.min - center > axis.radius || axis.max - center < -axis.radius) return false;
  }
  return true;
}

bool TriangleOverlapsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& center,
                         const Eigen::Vector3d& half) {
  return TriangleBoxTester(a, b, c, center, half).Overlaps(Eigen::Vector3d::Zero());
}

}  // namespace mechanist
