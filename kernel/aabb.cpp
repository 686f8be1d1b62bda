#include "kernel/aabb.h"

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

}  // namespace mechanist
