#pragma once

#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"

namespace mechanist {

/// The frame of a gear train exported without it (a CAD file of the gears alone, with no frame,
/// shafts or pins: common when gears are modelled to check their mesh). When no part is ground and
/// every part that is not compliant carries an external gear (`gear`, `bevel_gear`, `worm` or
/// `worm_wheel`) and a hole collinear with it (its bore, within the spec's tolerances) that no
/// other part's shaft or thread runs along, adds the features-only part `implied_frame` (ground,
/// identity pose) with a shaft `axle_N` along each bore, of its diameter and length, and a forced
/// `revolute` pair (an override marked `implied_frame`, the pair's source) between each axle and
/// its bore: each gear turns about its bore's axis, as the frame the file leaves out would hold it.
/// Returns the info finding `implied_frame` naming the gears and their bores' diameters, or nothing
/// when the rule does not apply (then ChooseGround picks a ground part). Needs at least two gear
/// parts, and the spec's `inference.implied_frame`. Part ids stay unique (`implied_frame_2` if the
/// name is taken).
std::vector<Diagnostic> ImplyGearFrame(AssemblySpec* spec);

}  // namespace mechanist
