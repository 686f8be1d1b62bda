#include "kernel/mesh/mass_properties.h"

#include <array>

namespace mechanist {
namespace {

// Eberly's subexpressions of the face integrals for one coordinate w of a triangle's corners.
struct Subexpressions {
  double f1, f2, f3, g0, g1, g2;
  Subexpressions(double w0, double w1, double w2) {
    const double t0 = w0 + w1;
    const double t1 = w0 * w0;
    const double t2 = t1 + w1 * t0;
    f1 = t0 + w2;
    f2 = t2 + w2 * f1;
    f3 = w0 * t1 + w1 * t2 + w2 * f2;
    g0 = f2 + w0 * (f1 + w0);
    g1 = f2 + w1 * (f1 + w1);
    g2 = f2 + w2 * (f1 + w2);
  }
};

}  // namespace

MassProperties ComputeMassProperties(const TriangleMesh& mesh) {
  MassProperties result;
  if (mesh.faces.empty()) return result;
  // Integrals about a point of the mesh, not the frame's origin, so that a part far from its
  // origin loses no digits to cancellation.
  const Eigen::Vector3d origin = mesh.Bounds().center();
  // 1, x, y, z, x^2, y^2, z^2, xy, yz, zx over the solid.
  std::array<double, 10> integral{};
  for (const TriangleMesh::Face& face : mesh.faces) {
    const Eigen::Vector3d p0 = mesh.vertices[face[0]] - origin;
    const Eigen::Vector3d p1 = mesh.vertices[face[1]] - origin;
    const Eigen::Vector3d p2 = mesh.vertices[face[2]] - origin;
    const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);
    const Subexpressions x(p0.x(), p1.x(), p2.x());
    const Subexpressions y(p0.y(), p1.y(), p2.y());
    const Subexpressions z(p0.z(), p1.z(), p2.z());
    integral[0] += d.x() * x.f1;
    integral[1] += d.x() * x.f2;
    integral[2] += d.y() * y.f2;
    integral[3] += d.z() * z.f2;
    integral[4] += d.x() * x.f3;
    integral[5] += d.y() * y.f3;
    integral[6] += d.z() * z.f3;
    integral[7] += d.x() * (p0.y() * x.g0 + p1.y() * x.g1 + p2.y() * x.g2);
    integral[8] += d.y() * (p0.z() * y.g0 + p1.z() * y.g1 + p2.z() * y.g2);
    integral[9] += d.z() * (p0.x() * z.g0 + p1.x() * z.g1 + p2.x() * z.g2);
  }
  constexpr std::array<double, 10> kScale = {1.0 / 6,  1.0 / 24, 1.0 / 24,  1.0 / 24,  1.0 / 60,
                                             1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (std::size_t k = 0; k < integral.size(); ++k) integral[k] *= kScale[k];
  const double volume = integral[0];
  if (volume == 0.0) return result;
  const Eigen::Vector3d c(integral[1] / volume, integral[2] / volume, integral[3] / volume);
  Eigen::Matrix3d& I = result.inertia;
  I(0, 0) = integral[5] + integral[6] - volume * (c.y() * c.y() + c.z() * c.z());
  I(1, 1) = integral[4] + integral[6] - volume * (c.z() * c.z() + c.x() * c.x());
  I(2, 2) = integral[4] + integral[5] - volume * (c.x() * c.x() + c.y() * c.y());
  I(0, 1) = I(1, 0) = -(integral[7] - volume * c.x() * c.y());
  I(1, 2) = I(2, 1) = -(integral[8] - volume * c.y() * c.z());
  I(0, 2) = I(2, 0) = -(integral[9] - volume * c.z() * c.x());
  result.volume = volume;
  result.center = c + origin;
  return result;
}

}  // namespace mechanist
