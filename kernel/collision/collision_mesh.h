#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "kernel/geometry/aabb.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// A triangle mesh prepared for collision queries, in its own frame M (mm): a bounding-volume
/// hierarchy of axis-aligned boxes over its triangles (binned surface-area heuristic along the
/// longest axis of the centroids, leaves of at most four triangles), face normals, and the edge
/// adjacency that the sweep's
/// contact classification needs. Built once per distinct mesh and shared by the parts that
/// use it; immutable.
class CollisionMesh {
 public:
  /// One BVH node: a box and either two children or a range of `order()`.
  struct Node {
    Aabb box_M;
    Eigen::Vector3d center_M = Eigen::Vector3d::Zero();  ///< of box_M
    Eigen::Vector3d half_M = Eigen::Vector3d::Zero();    ///< half extents of box_M
    std::int32_t left = -1;                              ///< child index, -1 for a leaf
    std::int32_t right = -1;                             ///< child index
    std::int32_t first = 0;                              ///< leaf: first index into order()
    std::int32_t count = 0;                              ///< leaf: number of triangles
    bool leaf() const { return left < 0; }
  };
  /// An edge of the mesh and the faces on either side (-1 when the edge is a boundary).
  struct Edge {
    std::array<std::int32_t, 2> vertices;
    std::array<std::int32_t, 2> faces;  ///< the first two faces on it; -1 when it has one
    bool more_faces = false;            ///< more than two faces share it
  };

  /// Builds the hierarchy. The mesh must not be null; degenerate triangles are kept (they
  /// still take part in intersection tests as segments or points).
  explicit CollisionMesh(std::shared_ptr<const TriangleMesh> mesh);

  const TriangleMesh& mesh() const { return *mesh_; }
  const std::shared_ptr<const TriangleMesh>& shared_mesh() const { return mesh_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  /// Triangle indices in leaf order.
  const std::vector<std::int32_t>& order() const { return order_; }
  /// Bounding box of each face in frame M.
  const std::vector<Aabb>& face_boxes() const { return face_boxes_; }
  /// Unit outward normal of each face (zero for a face whose corners are exactly collinear).
  /// For a closed mesh wound inside out (negative volume) the normals are flipped, so that
  /// they point out of the solid whatever the winding.
  const std::vector<Eigen::Vector3d>& face_normals() const { return normals_; }
  const std::vector<Edge>& edges() const { return edges_; }
  /// For each face, the indices into edges() of its edges (v0v1, v1v2, v2v0); -1 for an edge
  /// of zero length.
  const std::vector<std::array<std::int32_t, 3>>& face_edges() const { return face_edges_; }
  /// +1 when the edge is convex (the solid's interior angle below 180 degrees), -1 when
  /// concave, 0 when its faces are coplanar within 1e-9 or it is a boundary edge or one that
  /// more than two faces share (no single angle).
  int EdgeConvexity(std::int32_t edge) const;
  /// True when every edge has exactly two faces with opposite orientation (a closed, oriented
  /// surface): inside tests are then meaningful.
  bool closed() const { return closed_; }
  /// True when the mesh bounds a solid: closed(), or a mesh whose generalized winding number
  /// (WindingNumber) is within 0.2 of an integer at most points just off its faces, as for
  /// several closed shells in one mesh, boxes that share faces, T-junctions or small cracks
  /// (multi-body parts exported as one STL). False for open sheets, whose winding number is
  /// near a half beside them: they have no inside, and contact depths against them are unknown.
  bool solid() const { return solid_; }
  /// True when face_normals() point out of the solid the mesh bounds: closed(), or every edge
  /// run as often one way as the other by its faces (a closed surface that also meets itself
  /// along some edges, four faces on one, as some CAD tessellations do; or closed shells
  /// welded where they touch) with none of the faces sampled by solid()'s test wound inward
  /// (the winding number larger in front of it than behind, or negative in front: a shell
  /// wound inside out among them is found when a sampled face is on it). Sweeps tell entering
  /// from leaving by such normals (FirstBlockingContact).
  bool oriented() const { return oriented_; }
  /// Bounds of the mesh in its own frame.
  const Aabb& bounds() const { return nodes_.front().box_M; }

  /// Triangle `face`'s corners in frame M.
  std::array<Eigen::Vector3d, 3> Triangle(std::int32_t face) const;

  /// True when the point p_M lies strictly inside the closed mesh: when the exact ray crossings,
  /// counted with the sign of the side of each face that p_M is on, do not sum to zero (the
  /// winding number along the ray, so that closed shells which overlap or share faces in one
  /// mesh are one solid; a ray that grazes an edge or vertex is replaced by the next of a fixed
  /// list of directions); points on the surface (exactly, on a face) are not inside. For a
  /// solid() mesh that is not closed, when the generalized winding number at p_M is 0.5 or more
  /// in magnitude (WindingNumberAt; the exact sum when the estimate's bound does not decide).
  /// Meaningful only for solid() meshes.
  bool Contains(const Eigen::Vector3d& p_M) const;

  /// The generalized winding number at p_M (WindingNumber), summed over the hierarchy as
  /// Barill, Dickson, Schmidt, Levin and Jacobson do ("Fast winding numbers for soups and
  /// clouds", 2018): a node of area A whose triangles lie within r of their area-weighted
  /// centroid, at a distance d > 2 r from p_M, adds its expansion to first order (its area
  /// vector and first moment) when the remainder's bound, 3 A r^2 / (d - r)^4 steradians (the
  /// third derivative of 1 / |x| is at most 6 / |x|^4), is at most 1e-4 of a turn; nearer nodes
  /// add their triangles' exact solid angles. O(log faces) a query far from the surface, more
  /// near it. The bounds taken are summed into `error_bound`. Exact (WindingNumber, bound 0)
  /// for a closed() mesh or one that is not solid(), where Contains does not use it.
  struct WindingEstimate {
    double value = 0.0;
    double error_bound = 0.0;  ///< |value - WindingNumber(mesh(), p_M)| is at most this
  };
  WindingEstimate WindingNumberAt(const Eigen::Vector3d& p_M) const;

  /// The point of the surface closest to p_M, its distance (mm) and face.
  struct Closest {
    Eigen::Vector3d p_M = Eigen::Vector3d::Zero();
    double distance = 0.0;
    std::int32_t face = -1;
  };
  Closest ClosestPoint(const Eigen::Vector3d& p_M) const;

 private:
  // True when the winding number is near an integer just off most of the sampled faces;
  // `faces_out` tells whether none of them is wound inward (the winding number larger in
  // front of it than behind, or negative in front: a shell wound inside out).
  bool WindingNumberIsIntegral(bool* faces_out) const;
  // Fills edges_, face_edges_, closed_ and oriented_ with vertices identified by `canonical`.
  void BuildEdges(const std::vector<std::int32_t>& canonical);
  // Fills clusters_, one per node (WindingNumberAt).
  void BuildClusters();

  // A node's triangles as one far-field source (WindingNumberAt), in frame M: with a_i the
  // area, x_i the centroid and n_i the unit normal of triangle i (as wound),
  // area_vector = sum a_i n_i, centre = sum a_i x_i / sum a_i, moment = sum a_i (x_i - centre)
  // n_i^T, and every corner within `radius` of the centre.
  struct Cluster {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d area_vector = Eigen::Vector3d::Zero();
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    double area = 0.0;
    double radius = 0.0;
  };

  std::shared_ptr<const TriangleMesh> mesh_;
  std::vector<Node> nodes_;
  std::vector<std::int32_t> order_;
  std::vector<Eigen::Vector3d> normals_;
  std::vector<Aabb> face_boxes_;
  std::vector<Edge> edges_;
  std::vector<std::array<std::int32_t, 3>> face_edges_;
  std::vector<Cluster> clusters_;  // per node; empty unless solid() and not closed()
  bool closed_ = false;
  bool oriented_ = false;
  bool solid_ = false;
};

}  // namespace mechanist
