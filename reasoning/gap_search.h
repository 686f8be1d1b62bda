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

/// An enclosed empty space: a connected set of empty cells that the outside does not reach
/// through empty cells (the seeds' gaps that sealant would fill). A passage narrower than
/// about a voxel is closed by the partial cells on its walls, so a gap with a leak of that
/// size stays a gap until the voxel is smaller than the leak.
struct Gap {
  /// The gap's component in the decomposition (OccupancyOctree::components()).
  std::int32_t component = -1;
  std::int64_t voxels = 0;           ///< its empty voxels
  std::int64_t boundary_voxels = 0;  ///< partial voxels within one voxel of it (26-neighbours)
  /// Volume, mm^3: (voxels + the empty fractions of the boundary voxels) voxel^3
  /// (OccupancyOctree::Fill), within volume_error = (the sum of their fractions' errors)
  /// voxel^3 of the true volume as long as the boundary voxels' empty space is the gap's (no
  /// wall thinner than a voxel beside it) and the gap has no part thinner than a voxel that
  /// reaches further than one voxel from its empty cells. Faces square to the axes add no error.
  double volume = 0.0;
  double volume_error = 0.0;
  Aabb box_W;                      ///< bounds of its empty cells, world, mm
  std::vector<std::size_t> parts;  ///< parts whose surfaces bound it (indices, ascending)
  /// Where it comes closest to the outside: the nearest pair of a face between the gap and
  /// a partial voxel and a face between the outside and a partial voxel (face centres,
  /// world, mm), and their distance `wall` (mm), the thinnest separation between the gap and
  /// the outside to within about two voxels (the faces lie up to a voxel off the surfaces).
  Eigen::Vector3d p_gap_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_outside_W = Eigen::Vector3d::Zero();
  double wall = 0.0;
};

/// The result of FindGaps.
struct GapSearch {
  double voxel = 0.0;  ///< mm
  std::shared_ptr<const OccupancyOctree> octree;
  /// Largest first (ties by the box's lowest corner, then component): numbered 1, 2, ...
  std::vector<Gap> gaps;
  /// For each component of the octree, its index into gaps, or -1.
  std::vector<std::int32_t> gap_of_component;
};

/// Decomposes the assembly's parts, in their poses in the file, into an OccupancyOctree at
/// options.voxel (mm), floods the empty cells from the root's boundary (the outside) and
/// reports the empty cells it does not reach, grouped into connected gaps, with their volumes,
/// bounds, enclosing parts and closest approach to the outside. Parts without a mesh take no
/// part. Throws std::invalid_argument for a voxel that is not positive or too small for the
/// assembly (more than 2^20 voxels along an axis).
GapSearch FindGaps(const Assembly& assembly, const GapSearchOptions& options);

/// The walls of the gaps as seen from inside: every cell face between a gap's cell and a cell
/// that is not in a gap, as two triangles facing away from the gap (world, mm), the faces of
/// the gap numbered `gap_of_face` (index into search.gaps) by face. For display.
TriangleMesh GapSurface(const GapSearch& search, std::vector<std::int32_t>* gap_of_face = nullptr);

}  // namespace mechanist
