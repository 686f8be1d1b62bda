#pragma once

#include <Eigen/Core>

#include "kernel/collision/collision_mesh.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// A quick necessary condition for IsRoundAbout, without a hierarchy: the mesh's vertices
/// reach as far from the line through p_M along axis_M (frame M, mm) in four directions across
/// it (two perpendicular ones, both ways) as anywhere, within `tolerance` mm. A solid of
/// revolution reaches its largest radius all round; a lever with a hole at one end does not.
bool ReachesEquallyAround(const TriangleMesh& mesh, const Eigen::Vector3d& p_M,
                          const Eigen::Vector3d& axis_M, double tolerance);

/// True when the mesh is a solid of revolution about the line through p_M along axis_M (frame
/// M, mm): it reaches equally far all round (ReachesEquallyAround), and every vertex (at most a
/// few thousand, evenly strided), turned about the line by three angles that no symmetry order
/// up to 300 comes near, lies on the mesh's surface within `tolerance` mm. The vertices of a
/// tessellated surface of revolution lie on it, so a turned vertex lies within the
/// tessellation's chordal deviation of the facets; a hexagon, a cam, a gear or a hex socket
/// moves its corners off them. A zero axis is never round.
bool IsRoundAbout(const CollisionMesh& mesh, const Eigen::Vector3d& p_M,
                  const Eigen::Vector3d& axis_M, double tolerance);

}  // namespace mechanist
