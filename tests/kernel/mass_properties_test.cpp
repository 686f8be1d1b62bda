#include "kernel/mesh/mass_properties.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "kernel/mesh/mesh_builder.h"

namespace mechanist {
namespace {

Ring2d Rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Inertia of a solid box a x b x c about its centre per unit density (the textbook formula).
Eigen::Matrix3d BoxInertia(double a, double b, double c) {
  const double m = a * b * c;
  return Eigen::Vector3d(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                         m * (a * a + b * b) / 12)
      .asDiagonal();
}

TEST(MassProperties, BoxMatchesTheTextbook) {
  const TriangleMesh box = ExtrudeRegion({Rectangle(1, 2, 4, 7), {}}, -1, 1);  // 3 x 5 x 2
  const MassProperties m = ComputeMassProperties(box);
  EXPECT_NEAR(m.volume, 30.0, 1e-12);
  EXPECT_TRUE(m.center.isApprox(Eigen::Vector3d(2.5, 4.5, 0.0), 1e-12)) << m.center.transpose();
  EXPECT_TRUE(m.inertia.isApprox(BoxInertia(3, 5, 2), 1e-12)) << m.inertia;
}

TEST(MassProperties, HollowBoxIsTheDifferenceOfTwoBoxes) {
  // A square tube 10 x 10 with a 6 x 6 hole, 4 long: the hole's inertia subtracts.
  const TriangleMesh tube =
      ExtrudeRegion({Rectangle(-5, -5, 5, 5), {Rectangle(-3, -3, 3, 3)}}, 0, 4);
  const MassProperties m = ComputeMassProperties(tube);
  EXPECT_NEAR(m.volume, 400.0 - 144.0, 1e-9);
  EXPECT_TRUE(m.center.isApprox(Eigen::Vector3d(0, 0, 2), 1e-12));
  const Eigen::Matrix3d expected = BoxInertia(10, 10, 4) - BoxInertia(6, 6, 4);
  EXPECT_TRUE(m.inertia.isApprox(expected, 1e-12)) << m.inertia << "\n" << expected;
}

TEST(MassProperties, MovedBoxRotatesItsTensorAndKeepsItsDigits) {
  // Far from the origin and turned: the tensor is R I R^T about the moved centre.
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(1e5, -2e5, 3e4);
  TriangleMesh box = ExtrudeRegion({Rectangle(0, 0, 3, 5), {}}, 0, 2);
  for (Eigen::Vector3d& v : box.vertices) v = R * v + t;
  const MassProperties m = ComputeMassProperties(box);
  EXPECT_NEAR(m.volume, 30.0, 1e-6);
  EXPECT_TRUE(m.center.isApprox(R * Eigen::Vector3d(1.5, 2.5, 1) + t, 1e-12));
  const Eigen::Matrix3d expected = R * BoxInertia(3, 5, 2) * R.transpose();
  EXPECT_LT((m.inertia - expected).norm(), 1e-6 * expected.norm()) << m.inertia;
}

TEST(MassProperties, EmptyAndInsideOutMeshes) {
  EXPECT_EQ(ComputeMassProperties(TriangleMesh()).volume, 0.0);
  TriangleMesh box = ExtrudeRegion({Rectangle(0, 0, 1, 1), {}}, 0, 1);
  for (auto& f : box.faces) std::swap(f[1], f[2]);
  const MassProperties m = ComputeMassProperties(box);
  EXPECT_NEAR(m.volume, -1.0, 1e-12);
  EXPECT_TRUE(m.center.isApprox(Eigen::Vector3d(0.5, 0.5, 0.5), 1e-12));
  EXPECT_LT(m.inertia(0, 0), 0.0);
}

}  // namespace
}  // namespace mechanist
