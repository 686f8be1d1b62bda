#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/geometry/aabb.h"
#include "kernel/mesh/triangle_mesh.h"
#include "kernel/voxels/occupancy_octree.h"

namespace mechanist {

/// Settings of a gap search.
struct GapSearchOptions {
  double voxel = 1.0;                  ///< voxel edge, mm
  OccupancyOctree::Progress progress;  ///< optional, for long decompositions
};

/// An enclosed empty space: a connected set of empty cells and free octants (half-voxel
/// cubes of partial voxels that no surface enters) that the outside does not reach through
/// empty cells and free octants (the seeds' gaps that sealant would fill). So a gap or a
/// passage at least a voxel thick between faces square to the axes holds a free octant
/// whatever its offset on the grid and is found (open, for a passage); one thinner than half a
/// voxel holds none and is not found (closed: a gap with such a leak stays a gap); between the
/// two, and between sloping faces (judged conservatively), it depends on the alignment. A gap
/// made of free octants only (`voxels` 0, between 1 and 2 voxels thick) is a thin gap.
struct Gap {
  /// The gap's component in the decomposition (OccupancyOctree::components()).
  std::int32_t component = -1;
  std::int64_t voxels = 0;  ///< its empty voxels
  /// Partial voxels within one voxel of its empty cells (26-neighbours) or touching one of a
  /// thin gap's octants.
  std::int64_t boundary_voxels = 0;
  /// Volume, mm^3: (voxels + the empty fractions of the boundary voxels) voxel^3
  /// (OccupancyOctree::Fill), within volume_error = (the sum of their fractions' errors)
  /// voxel^3 of the true volume as long as the boundary voxels' empty space is the gap's (no
  /// wall thinner than a voxel beside it) and a gap with empty cells has no part thinner than
  /// two voxels that reaches further than one voxel from them. Faces square to the axes add no
  /// error.
  double volume = 0.0;
  double volume_error = 0.0;
  Aabb box_W;                      ///< bounds of its empty cells or octants, world, mm
  std::vector<std::size_t> parts;  ///< parts whose surfaces bound it (indices, ascending)
  /// Where it comes closest to the outside: the nearest pair of a partial voxel next to the
  /// gap (or an octant of a thin gap) and a partial voxel next to the outside (their
  /// centres, world, mm; a pair within half a voxel of the nearest, the search's slack), and
  /// their distance `wall` (mm), the thinnest separation between the gap and the outside to
  /// within about a voxel (the centres lie up to half a voxel off the surfaces across the
  /// wall; on faces on voxel faces, half a voxel inside the wall).
  Eigen::Vector3d p_gap_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_outside_W = Eigen::Vector3d::Zero();
  double wall = 0.0;
};

/// The result of FindGaps.
struct GapSearch {
  double voxel = 0.0;  ///< mm
  std::shared_ptr<const OccupancyOctree> octree;
  /// Largest volume first (ties by the box's lowest corner, then component): numbered 1, 2,
  /// ...
  std::vector<Gap> gaps;
  /// For each component of the octree, its index into gaps, or -1.
  std::vector<std::int32_t> gap_of_component;
};

/// Decomposes the assembly's parts, in their poses in the file, into an OccupancyOctree at
/// options.voxel (mm), floods the empty cells and free octants from the root's boundary (the
/// outside) and reports those it does not reach, grouped into connected gaps, with their volumes,
/// bounds, enclosing parts and closest approach to the outside. Parts without a mesh take no
/// part. Throws std::invalid_argument for a voxel that is not positive or too small for the
/// assembly (more than 2^20 voxels along an axis).
GapSearch FindGaps(const Assembly& assembly, const GapSearchOptions& options);

/// The walls of the gaps as seen from inside: every cell face between a gap's cell and a cell
/// that is not in a gap, and every face of a thin gap's octant that no other of its octants
/// shares, as two triangles facing away from the gap (world, mm), the faces of
/// the gap numbered `gap_of_face` (index into search.gaps) by face. For display.
TriangleMesh GapSurface(const GapSearch& search, std::vector<std::int32_t>* gap_of_face = nullptr);

}  // namespace mechanist
