#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>

#include "kernel/collision/collision_mesh.h"
#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// Options of a translational sweep.
struct SweepOptions {
  double max_travel = 0.0;  ///< mm; the sweep covers travels in [0, max_travel]
  /// A contact blocks only when the moving part approaches the obstacle's surface faster than
  /// this per unit travel (the sine of the angular tolerance): a part sliding along a face
  /// parallel to its motion is not stopped by it.
  double min_approach = 0.0;
  /// Contacts at points (world coordinates) for which this returns true are designed
  /// engagements (a thread entering its nut) and do not block. May be empty.
  std::function<bool(const Eigen::Vector3d& p_W)> ignore;
};

/// The first contact that blocks a sweep.
struct SweepContact {
  enum class Kind {
    kVertexFace,  ///< a vertex (or face centroid) of the moving mesh reaches a face of the obstacle
    kFaceVertex,  ///< a face of the moving mesh reaches a vertex (or face centroid) of the obstacle
    kEdgeEdge     ///< an edge of the moving mesh crosses an edge of the obstacle
  };
  Kind kind = Kind::kVertexFace;
  double travel = 0.0;                            ///< mm along the direction
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  ///< contact point at that travel
  double approach = 0.0;  ///< rate at which the surfaces approach per unit travel (0..1]
};

/// Moves `moving` (at X_WM) by s d_W for s in [0, options.max_travel] against the fixed
/// `obstacle` (at X_WO) and returns the first contact that blocks, or nothing when the path is
/// free. d_W must be a unit vector.
///
/// Contact conditions are linear in the travel (vertex-face: the vertex's line meets the face,
/// tested for every vertex and every face centroid, so that faces meeting face to face with
/// their corners on each other's corners are seen;
/// edge-edge: the two edge lines meet) and are decided with exact predicates on the moving
/// mesh's vertices expressed in the obstacle's frame (double precision), so no contact is
/// missed between samples: there are none. The travel itself is then computed in double
/// precision. A contact blocks when the moving solid would enter the obstacle there: a vertex
/// entering a face from outside, a face reaching a vertex, or two convex edges crossing with
/// their solids on opposite sides; contacts that separate or slide (approach at or below
/// `min_approach`) do not block, so a part resting on a face can leave it. Edges between
/// coplanar faces are not edges of the solid and take no part. Entering is told by the faces'
/// outward normals for every mesh that bounds a solid by its edges (CollisionMesh::oriented:
/// closed, or closed but meeting itself along some edges, as CAD tessellations may); the faces
/// of any other mesh (a surface, a triangle soup, a cracked tessellation) are two-sided: every
/// contact with them that approaches blocks; when either mesh is such, every edge pair is
/// tested and an edge crossing that approaches blocks. An edge that more than two faces share
/// has no single angle (CollisionMesh::EdgeConvexity 0): a point that reaches a face across it
/// enters, and it takes no part in the crossings of convex edges. Throws std::invalid_argument for
/// a negative or non-finite max_travel, a negative min_approach, or a direction that is not a unit
/// vector. The meshes' hierarchies are searched with the parallelograms that the edges sweep (and
/// the segments the points travel), not their boxes, so a long oblique travel costs about what it
/// passes near.
std::optional<SweepContact> FirstBlockingContact(
    const CollisionMesh& moving, const RigidTransform& X_WM, const CollisionMesh& obstacle,
    const RigidTransform& X_WO, const Eigen::Vector3d& d_W, const SweepOptions& options);

}  // namespace mechanist
