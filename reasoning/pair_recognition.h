#pragma once

#include <optional>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/assembly/diagnostic.h"
#include "reasoning/pair.h"

namespace mechanist {

/// The pairs recognised between the parts of an assembly and the near misses.
struct Recognition {
  std::vector<Pair> pairs;              ///< sorted by ("a" name, "b" name)
  std::vector<Diagnostic> diagnostics;  ///< sorted by (code, features, message)
  /// Every feature's axis in world coordinates at the recognised poses (mm), per
  /// Assembly::FeatureIndex: for the motion analysis, which would otherwise compute them again.
  std::vector<AxisSegment> axes_W;
  /// The parts of each rolling bearing recognised (info `bearing`): its rings, rolling
  /// elements and cages, ascending part indices. A bearing is bought as one: the assembly
  /// plan moves them together.
  std::vector<std::vector<std::size_t>> bearings;
};

/// Recognises the pairs of spec/assembly-format.md ("Recognition") between features of
/// different parts at the poses of `state`, with the assembly's tolerances:
/// - candidate feature pairs come from a uniform-grid broad phase over each feature's reach
///   box (its axis segment inflated by its radius, a gear's addendum circle, plus a
///   near-miss margin), not from all pairs;
/// - each candidate is tested for position, orientation, kind and parameters;
/// - overrides replace or forbid the recognised pairs of their two features;
/// - side effects of tight threads: a tight thread fixed in a nut or tapped hole clamps every
///   part whose clearance hole it passes through (those pairs become `fixed`, source clamp);
///   a tight thread whose tip bears on a shaft of a third part (the tip within the length
///   tolerance of the shaft's surface, the thread at right angles to the shaft, pointing at
///   its axis) fixes that shaft to the part the thread is screwed into (source setscrew);
/// - near misses become warnings naming both features, the quantity, the required and found
///   values: axes_not_collinear, feature_sense_reversed, shaft_larger_than_hole (a retained
///   hole is meant to turn on its shaft), hole_smaller_than_thread, thread_mismatch,
///   pin_wider_than_slot, key_wider_than_slot, gear_center_distance, gear_module_mismatch,
///   gear_axes_not_parallel, worm_center_distance, worm_module_mismatch,
///   worm_axes_not_perpendicular, rack_pitch_line_distance, rack_module_mismatch,
///   ball_socket_mismatch; and part_unconnected for a non-ground part in no pair;
/// - a part in no pair sunk into another part's solid is fixed to it (source embedded).
/// Near-miss windows: angles up to max(4 x tolerance, 2 degrees), offsets up to
/// max(4 x tolerance, 0.5 mm), centre distances off by less than one module.
/// Throws std::invalid_argument unless `state` has one pose per part.
Recognition RecognizePairs(const Assembly& assembly, const AssemblyState& state);

/// RecognizePairs at the file's poses, read from the assembly without making a state.
Recognition RecognizePairs(const Assembly& assembly);

/// The warning `part_unconnected` naming every non-ground, rigid part in none of `pairs` (one
/// finding for all, names sorted), or nothing when every part is in one.
std::optional<Diagnostic> UnconnectedParts(const Assembly& assembly,
                                           const std::vector<Pair>& pairs);

}  // namespace mechanist
