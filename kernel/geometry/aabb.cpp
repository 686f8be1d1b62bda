#include "kernel/geometry/aabb.h"

#include <cmath>

namespace mechanist {

Aabb TransformBox(const RigidTransform& X_WP, const Aabb& box_P) {
  Aabb box_W;
  if (box_P.empty()) return box_W;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p_P((corner & 1) ? box_P.max.x() : box_P.min.x(),
                              (corner & 2) ? box_P.max.y() : box_P.min.y(),
                              (corner & 4) ? box_P.max.z() : box_P.min.z());
    box_W.Extend(X_WP * p_P);
  }
  return box_W;
}

bool OrientedBoxesOverlap(const Eigen::Vector3d& t, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Matrix3d& R,
                          const Eigen::Matrix3d& absR) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(t[i]) > a[i] + absR.row(i).dot(b)) return false;
  }
  for (int j = 0; j < 3; ++j) {
    if (std::abs(R.col(j).dot(t)) > absR.col(j).dot(a) + b[j]) return false;
  }
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = a[i1] * absR(i2, j) + a[i2] * absR(i1, j);
      const double rb = b[j1] * absR(i, j2) + b[j2] * absR(i, j1);
      if (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) > ra + rb) return false;
    }
  }
  return true;
}

bool BoxesOverlap(const Aabb& box_A, const Aabb& box_B, const RigidTransform& X_AB, double margin) {
  if (box_A.empty() || box_B.empty()) return false;
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(margin);
  const Eigen::Matrix3d absR = X_AB.rotation().cwiseAbs().array() + 1e-12;
  const Eigen::Vector3d t = X_AB * box_B.center() - box_A.center();
  return OrientedBoxesOverlap(t, 0.5 * box_A.size() + grow, 0.5 * box_B.size() + grow,
                              X_AB.rotation(), absR);
}

}  // namespace mechanist
