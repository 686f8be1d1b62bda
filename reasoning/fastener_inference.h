#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "kernel/assembly/diagnostic.h"
#include "kernel/assembly/part.h"

namespace mechanist {

/// The nut-on-bolt heuristic of a CAD import whose threads are drawn as plain cylinders: a part
/// whose mesh is a prism with a convex polygonal outline of 3 to 8 sides (a hexagonal, square
/// or rectangular nut) and one hole along its axis, small for its bore (within two bore
/// diameters of the axis, at most two long), sitting coaxially (within `length_tolerance` mm
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

/// The screws of a CAD import whose threads are not modelled, screwed into a plain hole: a part
/// that is a head and a shank (two coaxial shafts, the head 1.3 to 2.5 times the shank's
/// diameter and no longer than its diameter; or, for a head that is no cylinder, one end of
/// the mesh that wide and no longer, the other end no wider than the shank; the shank at
/// least 1.5 diameters long, the whole part within the head's cylinder), whose shank's tip
/// ends inside a coaxial hole of another part (diameter 75% to 110% of the shank's: drawn at
/// the tap drill or the thread size; or one this made a tight tapped hole of the shank's size
/// for a screw from its other end; engaged, the tip not past the hole's end), or, when the
/// tip is out past every such hole, that comes through a hole narrower than the shank (a nut
/// or a tapped plate: the last such hole toward the tip), and which no nut holds (its shank
/// is still a shaft). That hole becomes a tight tapped hole of the
/// shank's diameter and the shank a tight thread (ISO coarse pitch), so that recognition fixes
/// the screw there and clamps the parts whose holes it passes (a cover and its spacers on a
/// housing); so does every other hole along the shank narrower than it (threaded through).
/// Returns one info `screw_in_plain_hole` per screw, naming the screw's thread and then every
/// hole it tapped, the tip's first (its parts likewise); screws that read alike but for their
/// names (of one size, through holes of the same parts and sizes) share one, which names the
/// screws, then the parts, and per screw its thread and holes. Only features for which
/// `inferred(part, feature)` holds are reinterpreted, and a screw's part must have no written
/// feature. Run after InferNutsOnBolts.
std::vector<Diagnostic> InferScrewsInPlainHoles(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred);

/// ISO 261 coarse pitch (mm) for a nominal diameter (mm): the table's nearest diameter.
double CoarsePitch(double diameter);

}  // namespace mechanist
