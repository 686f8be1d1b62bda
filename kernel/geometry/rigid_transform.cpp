#include "kernel/geometry/rigid_transform.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mechanist {

RigidTransform::RigidTransform(const Eigen::Matrix3d& R, const Eigen::Vector3d& p, double tolerance)
    : R_(R), p_(p) {
  if (!R.allFinite() || !p.allFinite()) {
    throw std::invalid_argument("rigid transform has a non-finite value");
  }
  if (!IsProperRotation(R, tolerance)) {
    throw std::invalid_argument("rotation is not proper (orthonormal with determinant +1)");
  }
}

bool RigidTransform::IsProperRotation(const Eigen::Matrix3d& R, double tolerance) {
  if (!R.allFinite()) return false;
  const double orthonormality =
      (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return orthonormality <= tolerance && std::abs(R.determinant() - 1.0) <= tolerance;
}

RigidTransform RigidTransform::Translation(const Eigen::Vector3d& p) {
  if (!p.allFinite()) throw std::invalid_argument("translation has a non-finite value");
  return RigidTransform(Eigen::Matrix3d::Identity(), p, Unchecked{});
}

RigidTransform RigidTransform::AxisAngle(const Eigen::Vector3d& axis, double angle) {
  const double n = axis.norm();
  if (!(n > 0.0) || !std::isfinite(n) || !std::isfinite(angle)) {
    throw std::invalid_argument("rotation axis must be a finite non-zero vector");
  }
  return RigidTransform(Eigen::AngleAxisd(angle, axis / n).toRotationMatrix(),
                        Eigen::Vector3d::Zero(), Unchecked{});
}

RigidTransform RigidTransform::AxisAngleAbout(const Eigen::Vector3d& p_point,
                                              const Eigen::Vector3d& axis, double angle) {
  return Translation(p_point) * AxisAngle(axis, angle) * Translation(-p_point);
}

RigidTransform RigidTransform::FromQuaternion(const Eigen::Quaterniond& q,
                                              const Eigen::Vector3d& p) {
  const double n = q.norm();
  if (!(n > 0.0) || !std::isfinite(n)) {
    throw std::invalid_argument("quaternion must be finite and non-zero");
  }
  if (!p.allFinite()) throw std::invalid_argument("translation has a non-finite value");
  return RigidTransform(q.normalized().toRotationMatrix(), p, Unchecked{});
}

RigidTransform RigidTransform::FromZAxis(const Eigen::Vector3d& p_origin,
                                         const Eigen::Vector3d& z_axis) {
  const double n = z_axis.norm();
  if (!(n > 0.0) || !std::isfinite(n) || !p_origin.allFinite()) {
    throw std::invalid_argument("z axis must be a finite non-zero vector and the origin finite");
  }
  const Eigen::Vector3d z = z_axis / n;
  // ShortestRotation(a, b) loses precision as b nears -a (1 + a.b cancels: 4e-5 rad at 2e-6 rad
  // from -z), so axes in the lower half start from -z, reached by a half turn about x.
  if (z.z() >= 0.0) {
    return RigidTransform(ShortestRotation(Eigen::Vector3d::UnitZ(), z), p_origin, Unchecked{});
  }
  const Eigen::Matrix3d half_turn_x = Eigen::Vector3d(1, -1, -1).asDiagonal();
  return RigidTransform(ShortestRotation(-Eigen::Vector3d::UnitZ(), z) * half_turn_x, p_origin,
                        Unchecked{});
}

Eigen::Matrix4d RigidTransform::matrix() const {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = R_;
  m.topRightCorner<3, 1>() = p_;
  return m;
}

RigidTransform RigidTransform::operator*(const RigidTransform& X_BC) const {
  return RigidTransform(R_ * X_BC.R_, R_ * X_BC.p_ + p_, Unchecked{});
}

RigidTransform RigidTransform::inverse() const {
  const Eigen::Matrix3d R_BA = R_.transpose();
  return RigidTransform(R_BA, -(R_BA * p_), Unchecked{});
}

bool RigidTransform::IsNearlyEqualTo(const RigidTransform& other, double length_tolerance,
                                     double angle_tolerance) const {
  const Eigen::AngleAxisd difference(R_.transpose() * other.R_);
  return (p_ - other.p_).norm() <= length_tolerance &&
         std::abs(difference.angle()) <= angle_tolerance;
}

Eigen::Matrix3d ShortestRotation(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const double nu = u.norm(), nv = v.norm();
  if (!(nu > 0.0) || !(nv > 0.0) || !std::isfinite(nu) || !std::isfinite(nv)) {
    throw std::invalid_argument("the directions of a rotation must be finite and non-zero");
  }
  // Eigen's operations in Eigen's order, so that the result is the same to the last bit.
  const Eigen::Vector3d v0 = u.normalized();
  const Eigen::Vector3d v1 = v.normalized();
  const double c = v1.dot(v0);
  if (c < -1.0 + 1e-12) {
    return Eigen::AngleAxisd(std::numbers::pi, v0.unitOrthogonal()).toRotationMatrix();
  }
  const Eigen::Vector3d axis = v0.cross(v1);
  const double s = std::sqrt((1.0 + c) * 2.0);
  const double invs = 1.0 / s;
  Eigen::Quaterniond q;
  q.vec() = axis * invs;
  q.w() = s * 0.5;
  return q.toRotationMatrix();
}

}  // namespace mechanist
