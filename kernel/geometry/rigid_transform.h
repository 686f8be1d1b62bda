#pragma once

#include <Eigen/Geometry>

namespace mechanist {

/// A proper rigid transform X_AB: maps coordinates in frame B to coordinates in frame A,
/// p_A = R_AB * p_B + p_AoBo_A (Drake's monogram notation). Lengths are in millimetres.
/// The rotation is kept orthonormal with determinant +1; constructors check that.
class RigidTransform {
 public:
  /// The identity transform.
  RigidTransform() : R_(Eigen::Matrix3d::Identity()), p_(Eigen::Vector3d::Zero()) {}

  /// From a rotation matrix and a translation. Throws std::invalid_argument when R is not a
  /// proper rotation within `tolerance` (|R^T R - I| and |det R - 1|), or a value is not finite.
  RigidTransform(const Eigen::Matrix3d& R, const Eigen::Vector3d& p, double tolerance = 1e-6);

  /// A pure translation.
  static RigidTransform Translation(const Eigen::Vector3d& p);
  /// A rotation of `angle` radians about the unit-or-not `axis` (right-hand rule) through the
  /// origin. Throws std::invalid_argument for a zero axis.
  static RigidTransform AxisAngle(const Eigen::Vector3d& axis, double angle);
  /// A rotation about the line through `p_point` with direction `axis`.
  static RigidTransform AxisAngleAbout(const Eigen::Vector3d& p_point, const Eigen::Vector3d& axis,
                                       double angle);
  /// From a quaternion (normalised here) and a translation. Throws for a zero quaternion.
  static RigidTransform FromQuaternion(const Eigen::Quaterniond& q, const Eigen::Vector3d& p);
  /// The rotation that takes the unit z axis to `z_axis` (any rotation about it) at `p_origin`;
  /// the frame of an axial feature. Throws std::invalid_argument for a zero or non-finite axis
  /// or a non-finite origin.
  static RigidTransform FromZAxis(const Eigen::Vector3d& p_origin, const Eigen::Vector3d& z_axis);

  /// True when R is orthonormal with determinant +1 within `tolerance`.
  static bool IsProperRotation(const Eigen::Matrix3d& R, double tolerance = 1e-6);

  const Eigen::Matrix3d& rotation() const { return R_; }
  const Eigen::Vector3d& translation() const { return p_; }
  /// The 4x4 homogeneous matrix.
  Eigen::Matrix4d matrix() const;

  /// X_AC = X_AB * X_BC.
  RigidTransform operator*(const RigidTransform& X_BC) const;
  /// p_A = X_AB * p_B for a point.
  Eigen::Vector3d operator*(const Eigen::Vector3d& p_B) const { return R_ * p_B + p_; }
  /// v_A = R_AB v_B for a direction (translation not applied).
  Eigen::Vector3d RotateDirection(const Eigen::Vector3d& v_B) const { return R_ * v_B; }
  /// X_BA.
  RigidTransform inverse() const;

  /// True when both rotation and translation agree within the given tolerances
  /// (rotation: angle of R_this^T R_other in radians; translation: distance in mm).
  bool IsNearlyEqualTo(const RigidTransform& other, double length_tolerance,
                       double angle_tolerance) const;

 private:
  struct Unchecked {};
  RigidTransform(const Eigen::Matrix3d& R, const Eigen::Vector3d& p, Unchecked) : R_(R), p_(p) {}

  Eigen::Matrix3d R_;
  Eigen::Vector3d p_;
};

/// The shortest rotation taking the direction of `u` to that of `v`: the quaternion
/// (sqrt(2 + 2c) / 2, (u x v) / sqrt(2 + 2c)) of the unit vectors, c their cosine, as Eigen's
/// Quaternion::FromTwoVectors computes it. Within 1e-12 of opposite directions (c < -1 + 1e-12),
/// where u x v gives no axis, a half turn about a unit vector square to u (Eigen's
/// unitOrthogonal) instead of Eigen's singular value decomposition, whose code takes seconds to
/// compile in each source. Throws std::invalid_argument when u or v is zero or not finite.
Eigen::Matrix3d ShortestRotation(const Eigen::Vector3d& u, const Eigen::Vector3d& v);

}  // namespace mechanist
