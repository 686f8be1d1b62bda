#include "kernel/mesh/winding_number.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace mechanist {

double TriangleSolidAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  // tan(omega / 2) = numerator / denominator; atan2 keeps the quadrant.
  return 2.0 * std::atan2(numerator, denominator);
}

double WindingNumber(const TriangleMesh& mesh, const Eigen::Vector3d& p_M) {
  double sum = 0.0;
  for (const auto& f : mesh.faces) {
    sum += TriangleSolidAngle(mesh.vertices[f[0]] - p_M, mesh.vertices[f[1]] - p_M,
                              mesh.vertices[f[2]] - p_M);
  }
  return sum / (4.0 * std::numbers::pi);
}

}  // namespace mechanist
