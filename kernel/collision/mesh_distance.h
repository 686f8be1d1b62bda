#pragma once

#include <limits>

#include "kernel/collision/collision_mesh.h"
#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// The distance (mm) between the surfaces of A at X_WA and B at X_WB: the smallest distance
/// between any two of their triangles (point-triangle and segment-segment cases), found by
/// traversing both hierarchies with box distances as lower bounds. Pairs of boxes farther apart
/// than `give_up` (mm) are not searched: the answer is then only known to be at least `give_up`.
/// Exactly 0 when two triangles share a point (exact predicates).
/// When `p_W` is given it receives the midpoint of the closest pair of points found (world);
/// untouched when nothing is nearer than `give_up`.
double SurfaceDistance(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                       const RigidTransform& X_WB,
                       double give_up = std::numeric_limits<double>::infinity(),
                       Eigen::Vector3d* p_W = nullptr);

}  // namespace mechanist
