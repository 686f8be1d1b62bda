#pragma once

#include <cstdint>
#include <filesystem>

#include "reasoning/gap_search.h"

namespace mechanist {

/// Most voxels WriteGapVolume writes (about 1.3 GB of file).
inline constexpr std::int64_t kMaxVolumeVoxels = std::int64_t{1} << 28;

/// Writes the decomposition as a VTK image (.vti, XML, raw appended data, VTK's own writer) for
/// ParaView: one
/// cell per voxel over the meshes' bounds plus the padding, world coordinates in mm, with two
/// cell arrays: "state" (UInt8: 0 outside, 1 gap, 2 material, 3 surface, i.e. a partial
/// voxel) and "gap" (Int32: the gap's number from 1, 0 elsewhere); holds them in memory (5
/// bytes a voxel) while VTK writes a temporary file that is renamed into place; refuses to write
/// over `protect`. Throws InputError naming the path when the grid has more than kMaxVolumeVoxels
/// voxels or the file cannot be written.
void WriteGapVolume(const std::filesystem::path& path, const GapSearch& search,
                    const std::filesystem::path& protect = {});

}  // namespace mechanist
