#include "kernel/geometry/rigid_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace mechanist {
namespace {

constexpr double kTolerance = 1e-12;

/// Random rotations and translations from a fixed seed, so failures reproduce.
class RandomPoses {
 public:
  Eigen::Quaterniond Rotation() {
    // Normally distributed components give a uniformly distributed unit quaternion.
    Eigen::Quaterniond q(normal_(engine_), normal_(engine_), normal_(engine_), normal_(engine_));
    return q.normalized();
  }
  Eigen::Vector3d Vector(double scale = 100.0) {
    return scale * Eigen::Vector3d(normal_(engine_), normal_(engine_), normal_(engine_));
  }
  Eigen::Isometry3d Isometry() {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = Rotation().toRotationMatrix();
    X.translation() = Vector();
    return X;
  }

 private:
  std::mt19937 engine_{20240611};
  std::normal_distribution<double> normal_;
};

RigidTransform ToRigid(const Eigen::Isometry3d& X) {
  return RigidTransform(X.linear(), X.translation());
}

TEST(RigidTransform, DefaultIsIdentity) {
  const RigidTransform X;
  EXPECT_TRUE(X.matrix().isApprox(Eigen::Matrix4d::Identity()));
  EXPECT_EQ(X * Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3));
}

TEST(RigidTransform, MatrixIsHomogeneous) {
  RandomPoses random;
  const Eigen::Isometry3d iso = random.Isometry();
  const RigidTransform X = ToRigid(iso);
  EXPECT_TRUE(X.matrix().isApprox(iso.matrix(), kTolerance));
  EXPECT_EQ(X.matrix().row(3), Eigen::RowVector4d(0, 0, 0, 1));
}

TEST(RigidTransform, CompositionMatchesEigenIsometry) {
  RandomPoses random;
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Isometry3d iso_AB = random.Isometry(), iso_BC = random.Isometry();
    const RigidTransform X_AC = ToRigid(iso_AB) * ToRigid(iso_BC);
    const Eigen::Isometry3d iso_AC = iso_AB * iso_BC;
    EXPECT_TRUE(X_AC.matrix().isApprox(iso_AC.matrix(), kTolerance)) << "trial " << trial;
    const Eigen::Vector3d p_C = random.Vector();
    EXPECT_TRUE((X_AC * p_C).isApprox(iso_AC * p_C, kTolerance));
    EXPECT_TRUE(X_AC.RotateDirection(p_C).isApprox(iso_AC.linear() * p_C, kTolerance));
  }
}

TEST(RigidTransform, InverseMatchesEigenAndCancels) {
  RandomPoses random;
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Isometry3d iso = random.Isometry();
    const RigidTransform X = ToRigid(iso);
    EXPECT_TRUE(X.inverse().matrix().isApprox(iso.inverse().matrix(), kTolerance));
    EXPECT_TRUE((X * X.inverse()).IsNearlyEqualTo(RigidTransform(), 1e-10, 1e-10));
    EXPECT_TRUE((X.inverse() * X).IsNearlyEqualTo(RigidTransform(), 1e-10, 1e-10));
    const Eigen::Vector3d p = random.Vector();
    EXPECT_TRUE((X.inverse() * (X * p)).isApprox(p, 1e-10));
  }
}

TEST(RigidTransform, TranslationMovesPointsNotDirections) {
  const RigidTransform X = RigidTransform::Translation(Eigen::Vector3d(1, -2, 3));
  EXPECT_EQ(X * Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(2, -1, 4));
  EXPECT_EQ(X.RotateDirection(Eigen::Vector3d(1, 1, 1)), Eigen::Vector3d(1, 1, 1));
  EXPECT_THROW(RigidTransform::Translation(Eigen::Vector3d(0, std::nan(""), 0)),
               std::invalid_argument);
}

TEST(RigidTransform, AxisAngleFollowsTheRightHandRule) {
  // A quarter turn about a non-unit +z axis takes +x to +y.
  const RigidTransform X =
      RigidTransform::AxisAngle(Eigen::Vector3d(0, 0, 5), std::numbers::pi / 2);
  EXPECT_TRUE((X * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), kTolerance));
  EXPECT_TRUE(RigidTransform::IsProperRotation(X.rotation()));
  EXPECT_THROW(RigidTransform::AxisAngle(Eigen::Vector3d::Zero(), 1.0), std::invalid_argument);
  EXPECT_THROW(
      RigidTransform::AxisAngle(Eigen::Vector3d::UnitX(), std::numeric_limits<double>::infinity()),
      std::invalid_argument);
}

TEST(RigidTransform, AxisAngleAboutLeavesTheAxisFixed) {
  RandomPoses random;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d p_point = random.Vector(), axis = random.Vector(1.0);
    const double angle = 0.3 + trial * 0.1;
    const RigidTransform X = RigidTransform::AxisAngleAbout(p_point, axis, angle);
    for (double t : {-7.0, 0.0, 2.5}) {
      const Eigen::Vector3d on_axis = p_point + t * axis;
      EXPECT_TRUE((X * on_axis).isApprox(on_axis, 1e-10)) << "trial " << trial << " t " << t;
    }
    // Off the axis, points turn like the rotation about the origin.
    const Eigen::Vector3d q = random.Vector();
    const RigidTransform R = RigidTransform::AxisAngle(axis, angle);
    EXPECT_TRUE((X * q - p_point).isApprox(R * (q - p_point), 1e-10));
    EXPECT_TRUE(X.rotation().isApprox(R.rotation(), kTolerance));
  }
}

TEST(RigidTransform, RejectsReflections) {
  const Eigen::Matrix3d mirror = Eigen::Vector3d(1, 1, -1).asDiagonal();
  EXPECT_FALSE(RigidTransform::IsProperRotation(mirror));
  EXPECT_THROW(RigidTransform(mirror, Eigen::Vector3d::Zero()), std::invalid_argument);
  const Eigen::Matrix3d inversion = -Eigen::Matrix3d::Identity();
  EXPECT_THROW(RigidTransform(inversion, Eigen::Vector3d::Zero()), std::invalid_argument);
}

TEST(RigidTransform, RejectsNonOrthonormalMatrices) {
  const Eigen::Matrix3d scaled = 2.0 * Eigen::Matrix3d::Identity();
  EXPECT_THROW(RigidTransform(scaled, Eigen::Vector3d::Zero()), std::invalid_argument);
  Eigen::Matrix3d shear = Eigen::Matrix3d::Identity();
  shear(0, 1) = 0.1;
  EXPECT_THROW(RigidTransform(shear, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(RigidTransform(Eigen::Matrix3d::Zero(), Eigen::Vector3d::Zero()),
               std::invalid_argument);
}

TEST(RigidTransform, ToleranceDecidesNearlyOrthonormalMatrices) {
  Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  R(0, 0) += 1e-4;
  EXPECT_THROW(RigidTransform(R, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_NO_THROW(RigidTransform(R, Eigen::Vector3d::Zero(), 1e-3));
}

TEST(RigidTransform, RejectsNonFiniteValues) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  R(2, 1) = std::nan("");
  EXPECT_FALSE(RigidTransform::IsProperRotation(R));
  EXPECT_THROW(RigidTransform(R, Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(RigidTransform(Eigen::Matrix3d::Identity(),
                              Eigen::Vector3d(std::numeric_limits<double>::infinity(), 0, 0)),
               std::invalid_argument);
}

TEST(RigidTransform, FromQuaternionNormalises) {
  RandomPoses random;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Quaterniond q = random.Rotation();
    const Eigen::Quaterniond scaled(3.5 * q.w(), 3.5 * q.x(), 3.5 * q.y(), 3.5 * q.z());
    const Eigen::Vector3d p = random.Vector();
    const RigidTransform X = RigidTransform::FromQuaternion(scaled, p);
    EXPECT_TRUE(RigidTransform::IsProperRotation(X.rotation(), 1e-12));
    EXPECT_TRUE(X.rotation().isApprox(q.toRotationMatrix(), kTolerance));
    EXPECT_EQ(X.translation(), p);
  }
  EXPECT_THROW(
      RigidTransform::FromQuaternion(Eigen::Quaterniond(0, 0, 0, 0), Eigen::Vector3d::Zero()),
      std::invalid_argument);
  EXPECT_THROW(RigidTransform::FromQuaternion(Eigen::Quaterniond(1, 0, 0, 0),
                                              Eigen::Vector3d(0, 0, std::nan(""))),
               std::invalid_argument);
}

TEST(RigidTransform, FromZAxisMapsZToTheAxis) {
  RandomPoses random;
  std::vector<Eigen::Vector3d> axes = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ(),
                                       Eigen::Vector3d(0, 0, -3), Eigen::Vector3d::UnitX()};
  // Axes just off -z, where the angle between z and the axis is ill-conditioned.
  for (double tilt : {1e-9, 1e-7, 2e-6, 1e-5, 1e-3}) {
    axes.emplace_back(tilt, 0, -1);
    axes.emplace_back(0, -tilt, -1);
  }
  for (int i = 0; i < 20; ++i) axes.push_back(random.Vector(10.0));
  for (const Eigen::Vector3d& axis : axes) {
    const Eigen::Vector3d origin = random.Vector();
    const RigidTransform X = RigidTransform::FromZAxis(origin, axis);
    EXPECT_TRUE(RigidTransform::IsProperRotation(X.rotation(), 1e-12)) << axis.transpose();
    EXPECT_TRUE(X.RotateDirection(Eigen::Vector3d::UnitZ()).isApprox(axis.normalized(), 1e-12))
        << axis.transpose();
    EXPECT_TRUE((X * Eigen::Vector3d::Zero()).isApprox(origin, kTolerance));
  }
}

TEST(RigidTransform, FromZAxisRejectsAZeroOrNonFiniteAxis) {
  EXPECT_THROW(RigidTransform::FromZAxis(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()),
               std::invalid_argument);
  EXPECT_THROW(
      RigidTransform::FromZAxis(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, std::nan(""), 1)),
      std::invalid_argument);
  EXPECT_THROW(
      RigidTransform::FromZAxis(Eigen::Vector3d(std::nan(""), 0, 0), Eigen::Vector3d::UnitZ()),
      std::invalid_argument);
}

TEST(ShortestRotation, IsEigensFromTwoVectorsToTheLastBit) {
  RandomPoses random;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d u = random.Vector(), v = random.Vector(0.01);
    const Eigen::Matrix3d eigen = Eigen::Quaterniond::FromTwoVectors(u, v).toRotationMatrix();
    EXPECT_EQ(ShortestRotation(u, v), eigen) << u.transpose() << " to " << v.transpose();
  }
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(ShortestRotation(z, z), Eigen::Matrix3d::Identity());
}

TEST(ShortestRotation, TurnsOppositeDirectionsHalfAroundASquareAxis) {
  RandomPoses random;
  for (int i = 0; i < 20; ++i) {
    const Eigen::Vector3d u = random.Vector();
    // Exactly opposite, and as near to it as the quaternion's formula is left for.
    for (const Eigen::Vector3d& v :
         {Eigen::Vector3d(-u), Eigen::Vector3d(-u + 1e-7 * u.norm() * u.unitOrthogonal())}) {
      const Eigen::Matrix3d R = ShortestRotation(u, v);
      EXPECT_TRUE(RigidTransform::IsProperRotation(R, 1e-12));
      EXPECT_LT((R * u.normalized() - v.normalized()).norm(), 1e-6) << u.transpose();
    }
  }
}

TEST(ShortestRotation, RejectsAZeroOrNonFiniteDirection) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_THROW(ShortestRotation(Eigen::Vector3d::Zero(), z), std::invalid_argument);
  EXPECT_THROW(ShortestRotation(z, Eigen::Vector3d(0, std::nan(""), 1)), std::invalid_argument);
  EXPECT_THROW(ShortestRotation(z, Eigen::Vector3d(0, 0, INFINITY)), std::invalid_argument);
}

TEST(RigidTransform, IsNearlyEqualToUsesBothTolerances) {
  const RigidTransform X =
      RigidTransform::AxisAngleAbout(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 1, 1), 0.4);
  const RigidTransform moved = RigidTransform::Translation(Eigen::Vector3d(0, 0, 0.01)) * X;
  EXPECT_TRUE(X.IsNearlyEqualTo(moved, 0.011, 1e-9));
  EXPECT_FALSE(X.IsNearlyEqualTo(moved, 0.009, 1e-9));
  const RigidTransform turned = X * RigidTransform::AxisAngle(Eigen::Vector3d::UnitX(), 0.002);
  EXPECT_TRUE(X.IsNearlyEqualTo(turned, 1e-9, 0.0021));
  EXPECT_FALSE(X.IsNearlyEqualTo(turned, 1e-9, 0.0019));
}

}  // namespace
}  // namespace mechanist
