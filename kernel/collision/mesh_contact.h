#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "kernel/collision/collision_mesh.h"
#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// Static collision queries between two meshes in their poses X_WA and X_WB.
///
/// Exactness contract: B's vertices are expressed in A's frame once, in double precision, by
/// X_AB = X_WA^-1 X_WB (ExpressVertices); every intersection answer is then exact for those
/// coordinates (exact predicates; the hierarchy only prunes with a margin that covers its own
/// rounding). A brute-force test over all triangle pairs on the same coordinates gives the same
/// answer.

/// `mesh`'s vertices mapped by X_AM: p_A = X_AM p_M, in double precision.
std::vector<Eigen::Vector3d> ExpressVertices(const TriangleMesh& mesh, const RigidTransform& X_AM);

/// Pairs (face of A, face of B) whose closed triangles share a point, in traversal order,
/// at most `max_pairs` of them.
std::vector<std::pair<std::int32_t, std::int32_t>> IntersectingTriangles(
    const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
    const RigidTransform& X_WB, std::size_t max_pairs = std::numeric_limits<std::size_t>::max());

/// True when the two surfaces share a point (touching counts): FCL's notion of collision.
bool SurfacesIntersect(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                       const RigidTransform& X_WB);

/// How two solids meet. Touching is not penetrating: CAD mates touch everywhere, and faceted
/// cylinders of a fit cross each other by a few micrometres.
struct ContactMeasure {
  enum class Kind { kSeparate, kTouching, kPenetrating };
  Kind kind = Kind::kSeparate;
  /// Penetration depth, mm: the largest distance from a point of one surface inside the other
  /// solid to that solid's surface, over a sample grid (corners included; spacing at most the
  /// tolerance, at most 8 intervals per edge) of every face whose box meets the other solid's
  /// box. The distance is 1-Lipschitz along the surface, so it underestimates the true maximum
  /// by at most `depth_bound`, the largest sample spacing used. Infinity when a mesh that crosses
  /// the other is an open sheet (not CollisionMesh::solid(): no inside to measure).
  double depth = 0.0;
  double depth_bound = 0.0;
  /// Where: the deepest point found, or a point of the first crossing, in world coordinates.
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  /// One solid lies entirely inside the other (no surfaces cross): 1 when A is inside B,
  /// 2 when B is inside A, 0 otherwise. FCL's surface test misses this case.
  int contained = 0;
  std::size_t crossing_pairs = 0;  ///< triangle pairs that share a point
  /// Whether A's and B's meshes are open sheets, when the depth is unknown because of them.
  std::array<bool, 2> open = {false, false};
};

/// Classifies the contact of A and B: separate, touching (depth <= `tolerance`, mm) or
/// penetrating. Containment is tested only for solid() meshes.
ContactMeasure MeasureContact(const CollisionMesh& a, const RigidTransform& X_WA,
                              const CollisionMesh& b, const RigidTransform& X_WB, double tolerance);

}  // namespace mechanist
