#pragma once

#include <vector>

#include "kernel/assembly/diagnostic.h"
#include "kernel/assembly/part.h"

namespace mechanist {

/// The frame the motion is counted from when the file fixes no part (the spec's `ground` is
/// optional, and CAD exports mark none): as a CAD system fixes its first component, the part
/// with the largest mesh volume (a housing, a frame, a base plate) becomes ground; among equal
/// volumes, and when no part has a mesh, the first in the file. Compliant parts are never
/// chosen. Returns the info finding `ground_chosen` naming it, or nothing when a part is ground
/// already (or there is no part). Without this, every CAD export's mobility would count the
/// six freedoms of the whole assembly in space.
std::vector<Diagnostic> ChooseGround(std::vector<Part>* parts);

}  // namespace mechanist
