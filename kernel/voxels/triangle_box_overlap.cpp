#include "kernel/voxels/triangle_box_overlap.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mechanist {

bool TriangleOverlapsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& center,
                         const Eigen::Vector3d& half) {
  const Eigen::Vector3d v0 = a - center, v1 = b - center, v2 = c - center;
  // Every projection below is a short sum of products of coordinates of this magnitude; a
  // margin of 64 ulps of it covers their rounding.
  const double scale = std::max({v0.cwiseAbs().maxCoeff(), v1.cwiseAbs().maxCoeff(),
                                 v2.cwiseAbs().maxCoeff(), half.maxCoeff()});
  const double eps = 64 * std::numeric_limits<double>::epsilon() * scale;
  const Eigen::Vector3d h = half.array() + eps;

  for (int i = 0; i < 3; ++i) {
    if (std::min({v0[i], v1[i], v2[i]}) > h[i] || std::max({v0[i], v1[i], v2[i]}) < -h[i]) {
      return false;
    }
  }
  const Eigen::Vector3d e[3] = {v1 - v0, v2 - v1, v0 - v2};
  // The nine axes e_j x u_i (u_i the box axes), then the triangle's normal.
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      axis[(i + 1) % 3] = -e[j][(i + 2) % 3];
      axis[(i + 2) % 3] = e[j][(i + 1) % 3];
      const double p0 = axis.dot(v0), p1 = axis.dot(v1), p2 = axis.dot(v2);
      const double r = h.dot(axis.cwiseAbs()) + eps * axis.cwiseAbs().sum();
      if (std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r) return false;
    }
  }
  const Eigen::Vector3d n = e[0].cross(e[1]);
  const double d = n.dot(v0);
  const double r = h.dot(n.cwiseAbs()) + eps * n.cwiseAbs().sum();
  return std::abs(d) <= r;
}

}  // namespace mechanist
