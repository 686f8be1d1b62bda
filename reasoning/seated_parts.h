#pragma once

#include <cstddef>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "reasoning/motion.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// mm: the most a part may travel, both ways together, between the faces that stop it and
/// still count as seated: the clearance of a pocket or a knuckle between cheeks (a loose
/// clearance fit of ISO 286 up to 100 mm leaves well under 1 mm), not a guide's stroke.
inline constexpr double kMaxSeatPlay = 1.0;

/// What SeatParts changed.
struct Seating {
  bool changed = false;
  /// Infos `seated` (a part held in a pocket, taken as fixed) and `retained` (a part on a
  /// shaft held along it, taken as revolute), one per seat and kind, its parts grouped.
  std::vector<Diagnostic> diagnostics;
};

/// Settles free translations that the geometry stops within kMaxSeatPlay, for the rigid
/// bodies (`subassemblies`, and `subassembly_of` per part, as PairGraph gives them) that make
/// a free motion of `motion`. The pairs between
/// such a body B and one other body S are examined alone (their relative twists are the null
/// space of the pairs' velocity constraints, by SVD, at the assembly's angle tolerance):
/// - face contacts (planar pairs only) that leave B nothing but one translation d: B sits in
///   S's pocket. When B's parts, moved along +d and along -d (FirstBlockingContact, the exact
///   translational sweep of the tessellations), meet a part of S within kMaxSeatPlay in all,
///   the planar pairs are replaced by one fixed pair (source `seated`) on the first's faces:
///   what holds B there (screws, glue) is not in the file;
/// - cylindrical pairs on one axis (a part on a pin or screw), leaving a turn and a slide
///   along the axis: when S's parts stop the slide both ways within kMaxSeatPlay, the pairs
///   become revolute (source `seated`): the part is held along its pin, as in a fork.
/// Bodies whose parts have no mesh, or whose pairs' features lie outside their meshes' bounds
/// (a stand-in mesh), are left as they are. Does nothing when the file's
/// `infer` turns `seated_parts` off.
Seating SeatParts(const Assembly& assembly, const MotionAnalysis& motion,
                  const std::vector<Subassembly>& subassemblies,
                  const std::vector<std::size_t>& subassembly_of, std::vector<Pair>* pairs);

}  // namespace mechanist
