#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "kernel/geometry/polygon_triangulation.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// A planar region: an outer ring with holes strictly inside it and apart from each other.
/// Rings may run either way; the builders orient them.
struct Region2d {
  Ring2d outer;
  std::vector<Ring2d> holes;
};

/// The regular `segments`-gon inscribed in the circle of `radius` about `center`,
/// counter-clockwise, its first vertex at angle 0 (on +x from the centre).
Ring2d CircleRing(const Eigen::Vector2d& center, double radius, int segments);

/// `ring` running counter-clockwise when `counter_clockwise`, else clockwise.
Ring2d Oriented(Ring2d ring, bool counter_clockwise);

/// Builds a closed triangle mesh from rings of vertices at constant z: walls between rings of
/// equal size and planar caps filling a ring with holes. Walls and caps refer to the same
/// vertex indices, so shared edges are welded by construction. The caller arranges the rings
/// so that every edge ends up used by exactly two faces.
class MeshBuilder {
 public:
  using Indices = std::vector<std::int32_t>;

  /// How a wall quad (lower i, lower i+1, upper i+1, upper i) is split into two triangles:
  /// forward along lower i - upper i+1 (a right-hand helix when the rings run counter-
  /// clockwise), backward along lower i+1 - upper i.
  enum class Diagonal { kForward, kBackward };

  /// Adds the vertices of `ring` at height `z` (mm) and returns their indices in ring order.
  Indices AddRing(const Ring2d& ring, double z);

  /// Adds a triangle, vertices counter-clockwise seen from outside.
  void AddTriangle(std::int32_t a, std::int32_t b, std::int32_t c);

  /// Adds the closed band of quads between `lower` and `upper`, rings of equal size whose
  /// vertex i lies below vertex i (in z). The faces point to the right of the rings' direction
  /// of travel seen from +z: outward for a counter-clockwise outer ring, into the hole for a
  /// clockwise hole. Throws std::invalid_argument when the sizes differ or are below 3.
  void AddWall(const Indices& lower, const Indices& upper, Diagonal diagonal = Diagonal::kForward);

  /// Fills the planar region bounded by the ring `outer` and the rings `holes` (indices of
  /// vertices added before, all at one z) with triangles facing +z when `facing_up`, else -z.
  /// Throws std::invalid_argument when the region cannot be triangulated (TriangulatePolygon).
  void AddCap(const Indices& outer, const std::vector<Indices>& holes, bool facing_up);

  /// The mesh built so far.
  const TriangleMesh& mesh() const { return mesh_; }
  /// Moves the mesh out of the builder.
  TriangleMesh Release() { return std::move(mesh_); }

 private:
  TriangleMesh mesh_;
};

/// The closed, outward-oriented prism of `region` between the planes z = z0 and z = z1 (mm):
/// one wall per ring, a cap at each end. Throws std::invalid_argument unless z0 < z1, or when
/// the region cannot be triangulated.
TriangleMesh ExtrudeRegion(const Region2d& region, double z0, double z1);

/// As ExtrudeRegion, with the region turned about the z axis by `twist` x (z - z0) radians
/// (twist in radians per mm; positive: counter-clockwise seen from +z as z grows, a right-hand
/// helix) and sampled at `layers` + 1 equally spaced heights: a helical gear's teeth. Throws
/// std::invalid_argument as ExtrudeRegion does, or for fewer than one layer.
TriangleMesh ExtrudeTwistedRegion(const Region2d& region, double z0, double z1, double twist,
                                  int layers);

/// A solid around the z axis whose outer surface is r = radius(theta, z), sampled on a grid
/// of `angular_segments` angles theta_i = 2 pi i / n and `axial_segments` + 1 levels
/// z_j = z0 + (z1 - z0) j / m, with flat caps at z0 and z1 and an optional coaxial cylindrical
/// bore. With a radius independent of theta this is a surface of revolution; with a radius of
/// z - lead theta / (2 pi) it is a helical surface (a worm's thread), and the grid's diagonals
/// should follow the helix (Diagonal::kForward for a right-hand helix).
struct RadialGrid {
  std::function<double(double theta, double z)> radius;  ///< mm, positive, above the bore
  int angular_segments = 0;
  int axial_segments = 0;
  double z0 = 0.0, z1 = 0.0;
  MeshBuilder::Diagonal diagonal = MeshBuilder::Diagonal::kForward;
  double bore_radius = 0.0;  ///< mm; 0: solid
  int bore_segments = 0;     ///< facets of the bore (regular polygon, first vertex on +x)
};

/// The closed, outward-oriented mesh of `grid`. Throws std::invalid_argument for fewer than 3
/// angular segments, no axial segment, z1 <= z0, a bore of fewer than 3 segments, or a cap
/// that cannot be triangulated (a bore reaching the outer surface).
TriangleMesh MakeRadialGridSolid(const RadialGrid& grid);

/// A closed, outward-oriented UV sphere of `radius` (mm) about the origin: two poles and
/// `rings` - 1 rings of `segments` vertices, 2 * segments * (rings - 1) triangles. Throws
/// std::invalid_argument for fewer than 2 rings or 3 segments.
TriangleMesh MakeUvSphere(double radius, int rings, int segments);

}  // namespace mechanist
