#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "kernel/assembly/diagnostic.h"
#include "kernel/assembly/part.h"

namespace mechanist {

/// The pin ring of a cycloidal reducer built from separate pins (dowels or rollers, one part
/// each) held in holes of a housing: three or more parts that are each a single shaft (no
/// other feature than faces), of one diameter (within `length_tolerance` mm), parallel
/// (within `angle_tolerance` rad), each in a collinear hole of one other part (the host: the
/// hole's diameter within 5% of the pin's, or the tolerance, and overlapping it along the
/// axis), their axes evenly spaced on one circle (every axis and every gap between
/// neighbours within the tolerance; each set of pins of one diameter and direction is tried
/// on its own), give the host a `pin_ring` feature `pins_N` (the circle,
/// the pins' count and diameter, their extent along the axis), in the host's coordinates, so
/// that a cycloidal disc rolling on the pins couples with it. A pin held by several hosts
/// (a housing and its cover) counts for the one holding the most of the pins (the first in
/// the file among equals). Returns one info `pin_ring_of_parts` per ring, naming the host,
/// the pins and the feature. Only features for which `inferred(part, feature)` holds
/// (recognised or imported, not written by the file) count.
std::vector<Diagnostic> InferPinRingsOfParts(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred);

}  // namespace mechanist
