#pragma once

#include <ostream>
#include <string>

#include "kernel/assembly/assembly.h"
#include "reasoning/gap_search.h"

namespace mechanist {

/// `mechanist gaps` summary: the voxel and decomposition size; a note for each set of parts
/// that encloses two or more thin gaps (1 to 2 voxels thick: often one narrow space cut where
/// it is thinner than a voxel), suggesting half the voxel; then one line per gap (largest
/// first) with its volume and error bound (mm^3), bounds, enclosing parts and where it comes
/// closest to the outside.
void WriteGapSummary(const Assembly& assembly, const GapSearch& search, std::ostream& out);

/// The gap JSON report: {"assembly", "voxel" (mm), "grid": [nx, ny, nz], "cells" (octree
/// leaves), "memory_bytes", "gaps": [{"id", "volume", "volume_error", "voxels",
/// "boundary_voxels", "box": {"min", "max"}, "parts", "closest_to_outside": {"gap_point",
/// "outside_point", "distance"}}]}; lengths in mm, volumes in mm^3, 9 significant digits.
std::string GapJson(const Assembly& assembly, const GapSearch& search);

}  // namespace mechanist
