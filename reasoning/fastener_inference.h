#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "kernel/assembly/diagnostic.h"
#include "kernel/assembly/part.h"

namespace mechanist {

/// The nut-on-bolt heuristic of a CAD import whose threads are drawn as plain cylinders: a part
/// whose mesh is a prism with a convex polygonal outline of 3 to 8 sides (a hexagonal, square
/// or rectangular nut) and one hole along its axis, sitting coaxially (within `length_tolerance` mm
/// and `angle_tolerance` rad) on a shaft of another part of the same diameter (within 2%) that
/// overlaps it along the axis, is a nut on a bolt: the hole becomes a tight tapped hole and the
/// shaft a tight thread (ISO coarse pitch for the diameter), so that recognition makes the
/// pair fixed and clamps every part whose clearance hole the bolt passes through. Returns one
/// info diagnostic `nut_on_bolt` per nut, naming both parts and features. Only features for
/// which `inferred(part, feature)` holds (recognised or imported, not written by the file)
/// are reinterpreted, and a nut's part must have no written feature.
std::vector<Diagnostic> InferNutsOnBolts(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred);

/// ISO 261 coarse pitch (mm) for a nominal diameter (mm): the table's nearest diameter.
double CoarsePitch(double diameter);

}  // namespace mechanist
