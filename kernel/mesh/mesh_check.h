#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// What a mesh check found. Counts are of faces, edges (unordered vertex pairs) or vertices.
struct MeshCheck {
  std::size_t vertex_count = 0;
  std::size_t face_count = 0;
  std::size_t non_finite_vertices = 0;  ///< vertices with NaN or infinite coordinates
  std::size_t out_of_range_faces = 0;   ///< faces referring to a vertex that does not exist
  std::size_t degenerate_faces = 0;     ///< repeated index or zero area (relative 1e-12)
  std::size_t boundary_edges = 0;       ///< edges used by one face only: the mesh has a hole
  std::size_t non_manifold_edges = 0;   ///< edges used by more than two faces
  std::size_t misoriented_edges = 0;    ///< edges whose two faces traverse them the same way
  double signed_volume = 0.0;           ///< mm^3; positive when outward oriented

  /// Every edge shared by exactly two faces.
  bool closed() const { return boundary_edges == 0 && non_manifold_edges == 0; }
  /// Neighbouring faces traverse their shared edge in opposite directions.
  bool consistently_oriented() const { return misoriented_edges == 0; }
  /// Closed, consistently oriented, positive volume, no degenerate or invalid element.
  bool ok() const {
    return closed() && consistently_oriented() && signed_volume > 0.0 && degenerate_faces == 0 &&
           non_finite_vertices == 0 && out_of_range_faces == 0;
  }
  /// One readable sentence per problem found, empty when ok().
  std::vector<std::string> Problems() const;
};

/// Checks topology and geometry of `mesh`; never throws.
MeshCheck CheckMesh(const TriangleMesh& mesh);

}  // namespace mechanist
