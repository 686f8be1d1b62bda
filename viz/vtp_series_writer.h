#pragma once

#include <filesystem>

#include "kernel/assembly/assembly.h"
#include "kernel/mesh/triangle_mesh.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"

namespace mechanist {

/// Writes the animation as a ParaView time series: the collection `pvd` (VTK's .pvd format)
/// and, in the folder named after it without the extension (motion.pvd: motion/), one
/// PolyData file frame_NNNN.vtp per frame holding every part's triangles in the world (mm) at
/// that frame's pose (Float32 points; VTK's own writer, raw appended arrays), with the cell data
/// `part` (the part's index in the file), `subassembly` (its index as in the analysis report) and
/// `clash` (1 while the part is in a clash). The time steps are the run's parameter s. With
/// `gap_surface_W`, every time step also holds the static dataset part gaps.vtp (the gaps' walls,
/// cell data `gap` numbered from 1 as in the gap report). Each file is written atomically; none
/// over `protect`. Throws InputError naming a file that cannot be written.
void WriteVtpSeries(const std::filesystem::path& pvd, const Assembly& assembly,
                    const Analysis& analysis, const Animation& animation,
                    const TriangleMesh* gap_surface_W = nullptr,
                    const std::vector<std::int32_t>* gap_of_face = nullptr,
                    const std::filesystem::path& protect = {});

}  // namespace mechanist
