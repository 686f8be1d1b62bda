#include "kernel/collision/rotational_symmetry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstddef>

namespace mechanist {

bool IsRoundAbout(const CollisionMesh& mesh, const Eigen::Vector3d& p_M,
                  const Eigen::Vector3d& axis_M, double tolerance) {
  if (axis_M.norm() == 0.0) return false;
  const Eigen::Vector3d u = axis_M.normalized();
  // For every symmetry order n up to 300, one of these angles is at least a quarter of half
  // the pattern's pitch (pi / n) away from every multiple of 2 pi / n, so no pattern of teeth,
  // lobes or flats turned by all three lands on itself.
  constexpr std::array<double, 3> kAngles{0.25, 1.1474, 1.503};
  const std::vector<Eigen::Vector3d>& vertices = mesh.mesh().vertices;
  constexpr std::size_t kMaxSamples = 4000;
  const std::size_t stride = std::max<std::size_t>(1, vertices.size() / kMaxSamples);
  for (double angle : kAngles) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, u).toRotationMatrix();
    for (std::size_t i = 0; i < vertices.size(); i += stride) {
      const Eigen::Vector3d turned = p_M + R * (vertices[i] - p_M);
      if (mesh.ClosestPoint(turned).distance > tolerance) return false;
    }
  }
  return !vertices.empty();
}

}  // namespace mechanist
