#include "kernel/collision/rotational_symmetry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace mechanist {

bool ReachesEquallyAround(const TriangleMesh& mesh, const Eigen::Vector3d& p_M,
                          const Eigen::Vector3d& axis_M, double tolerance) {
  if (axis_M.norm() == 0.0 || mesh.vertices.empty()) return false;
  const Eigen::Vector3d u = axis_M.normalized();
  const Eigen::Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
  std::array<double, 4> reach;  // along e1, -e1, e2, -e2
  reach.fill(-std::numeric_limits<double>::infinity());
  double radius = 0.0;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const Eigen::Vector3d d = v - p_M;
    const double x = d.dot(e1), y = d.dot(e2);
    reach = {std::max(reach[0], x), std::max(reach[1], -x), std::max(reach[2], y),
             std::max(reach[3], -y)};
    radius = std::max(radius, std::hypot(x, y));
  }
  return std::all_of(reach.begin(), reach.end(), [&](double r) { return radius - r <= tolerance; });
}

bool IsRoundAbout(const CollisionMesh& mesh, const Eigen::Vector3d& p_M,
                  const Eigen::Vector3d& axis_M, double tolerance) {
  if (!ReachesEquallyAround(mesh.mesh(), p_M, axis_M, tolerance)) return false;
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
  return true;
}

}  // namespace mechanist
