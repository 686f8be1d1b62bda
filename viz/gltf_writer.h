#pragma once

#include <string>

#include "kernel/assembly/assembly.h"
#include "kernel/mesh/triangle_mesh.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"

namespace mechanist {

/// The animation as a binary glTF 2.0 file (.glb, Khronos glTF 2.0 specification), returned as
/// its bytes. One root node named after the assembly turns the CAD's z-up world into glTF's
/// y-up one and scales millimetres to metres; under it one node per part (named by its id)
/// whose translation (mm) and rotation are the part's pose X_WP, sharing a mesh with the parts
/// that share its mesh and colour. A single animation holds, for every part that moves, a
/// translation and a rotation channel with one linearly interpolated key per frame at time
/// frame / fps seconds: exactly the frames' poses (between keys a viewer turns along the
/// shorter arc, so a part that turns half a revolution or more between frames is ambiguous).
/// Colours as ColorParts, red for a part in a clash at any frame (core glTF has no animated
/// colours). With `gap_surface_W`, the gaps' walls are a translucent node "gaps". Throws
/// std::invalid_argument when fps is not positive.
std::string GlbAnimation(const Assembly& assembly, const Analysis& analysis,
                         const Animation& animation, double fps,
                         const TriangleMesh* gap_surface_W = nullptr);

}  // namespace mechanist
