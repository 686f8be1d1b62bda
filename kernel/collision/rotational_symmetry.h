#pragma once

#include <Eigen/Core>

#include "kernel/collision/collision_mesh.h"

namespace mechanist {

/// True when the mesh is a solid of revolution about the line through p_M along axis_M (frame
/// M, mm): every vertex (at most a few thousand, evenly strided), turned about the line by
/// three angles that no symmetry order up to 300 comes near, lies on the mesh's surface within
/// `tolerance` mm. The vertices of a tessellated surface of revolution lie on it, so a turned
/// vertex lies within the tessellation's chordal deviation of the facets; a hexagon, a cam, a
/// gear or a hex socket moves its corners off them. A zero axis is never round.
bool IsRoundAbout(const CollisionMesh& mesh, const Eigen::Vector3d& p_M,
                  const Eigen::Vector3d& axis_M, double tolerance);

}  // namespace mechanist
