#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/assembly/diagnostic.h"
#include "kernel/solvers/least_squares.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// The parts that move with adjustment `adjustment`: its `moves` part and every part held to
/// it through `pairs` (whose graph is `graph`), found by walking the pairs from it without
/// entering a ground part and without crossing a gear, worm-gear or rack-and-pinion mesh (a
/// mesh transmits motion, it does not carry). Ascending indices.
std::vector<std::size_t> CarriedParts(const Assembly& assembly, const PairGraph& graph,
                                      const std::vector<Pair>& pairs, std::size_t adjustment);

/// How far a goal is from being met, at some poses.
struct GoalError {
  /// mm: found minus required centre distance (mesh), the distance between the pitch cones'
  /// apexes (bevel gears), or the distance of the second axis' origin from the first axis
  /// (coaxial).
  double distance = 0.0;
  /// Radians from the required axis angle (parallel, perpendicular, or for bevel gears the
  /// sum of their pitch angles).
  double angle = 0.0;
  /// mm: mesh of gears, the offset between the mid-faces along the axis; worm gear, the
  /// wheel's mid-plane from the worm's axis. Reported, not required (as in recognition).
  double axial = 0.0;
  /// True when the features engage along their axes as recognition requires (overlapping face
  /// widths, the closest points of the axes within both features).
  bool engaged = true;
  /// True for a bevel pair: `distance` is between the apexes.
  bool apexes = false;
  /// True when the pair would be recognised: |distance| and the angle within the file's
  /// tolerances, and engaged.
  bool met = false;
};

/// The error of goal `goal` at `state`.
GoalError MeasureGoal(const Assembly& assembly, const AssemblyState& state, std::size_t goal);

/// The outcome of one adjustment.
struct AdjustmentOutcome {
  /// False when no goal depends on it (it carries both or neither part of every goal): it is
  /// left at zero.
  bool used = false;
  double value = 0.0;  ///< the solved rotation (radians) or translation (mm)
  enum class Bound { kNone, kLower, kUpper };
  Bound active = Bound::kNone;       ///< a bound of `range` the solution sits on
  std::vector<std::size_t> carried;  ///< CarriedParts
  /// The loose threads that let the carried parts move against the rest (a thread with
  /// `fastening: loose` in a pair between a carried part and one that is not): locking the
  /// adjustment tightens them. In feature-name order.
  std::vector<FeatureRef> loosened;
};

/// The result of SolveAdjustments, as data (like Ceres' summary).
struct AdjustmentSummary {
  LeastSquaresSummary solver;
  std::vector<AdjustmentOutcome> adjustments;  ///< per adjustment of the file
  std::vector<GoalError> before;               ///< per goal, at the file's poses
  std::vector<GoalError> after;                ///< per goal, at the solved poses
  AssemblyState state;                         ///< the solved poses
  bool all_met = true;
};

/// Solves the file's adjustments for its goals by bounded least squares (SolveLeastSquares):
/// the variables are the used adjustments' rotations or translations within their ranges;
/// every goal contributes its centre-distance error, its axis-angle error (as the cross or dot
/// product of the axes times the required centre distance, so in mm at the mesh) and, for
/// gears and worm gears, its axial offset; a coaxial goal the cross product of the axes and
/// the second origin's offset from the first axis. Each adjustment moves its carried parts
/// (CarriedParts over `pairs`, recognised at the file's poses) about or along its feature's
/// axis; adjustments apply in file order, each about its axis as the earlier ones left it.
AdjustmentSummary SolveAdjustments(const Assembly& assembly, const std::vector<Pair>& pairs);

/// The assembly with the adjustments locked at their solved values (spec, "Adjustments and
/// goals"): the carried parts at their solved poses, each range shifted by its value so that
/// it bounds the same positions as before, and the loose threads that allowed an adjustment
/// (AdjustmentOutcome::loosened) taken as tightened, each said in an info finding
/// `adjustment_locked` of the assembly.
Assembly ApplyAdjustments(const Assembly& assembly, const AdjustmentSummary& summary);

/// The assembly as the designer tightens it: when it declares adjustments and goals, solved
/// (SolveAdjustments over the pairs Analyze recognises at the file's poses) and locked
/// (ApplyAdjustments), the solve in `summary` when given; otherwise the assembly itself.
Assembly Adjusted(const Assembly& assembly, AdjustmentSummary* summary = nullptr);

/// For every near miss between two parts (a gear off by a little) that an adjustment of the
/// file can fix (it carries one of the two parts), the diagnostic with " (adjustment ID can
/// fix this: mechanist adjust)" appended.
void SuggestAdjustments(const Assembly& assembly, const PairGraph& graph,
                        const std::vector<Pair>& pairs, std::vector<Diagnostic>* diagnostics);

}  // namespace mechanist
