#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "kernel/collision/collision_model.h"
#include "kernel/features/feature_ref.h"
#include "reasoning/analysis.h"
#include "reasoning/hinge_pins.h"
#include "reasoning/interference.h"

namespace mechanist {

/// A part already in place that stops an insertion, or a pin the file leaves out that is in
/// place by then (PinInsertion).
struct InsertionObstacle {
  std::size_t part = 0;  ///< the part; for a pin, the part of its first hole
  /// For a pin, the holes it goes through (PinInsertion::holes); empty for a part.
  std::vector<FeatureRef> pin;
  /// mm travelled from the start of the insertion (outside every part in place) to the
  /// first blocking contact.
  double travel = 0.0;
  double short_by = 0.0;                          ///< mm still to go to the final pose
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();  ///< contact point at that travel
  /// The obstacle's feature of an axial fit with the moving part whose axis runs across the
  /// travel: the fit, not a contact, holds the part (at its place: short_by 0).
  std::optional<FeatureRef> held_by;
  /// The moving part (or one it carries) and the obstacle clash at rest
  /// (AssemblyPlan::clashes), and the stop is at its place (within the length tolerance): it
  /// cannot move from there.
  bool clash_at_rest = false;
};

/// A hinge pin that the file leaves out (HingePin, FindHingePins), pushed along its axis
/// through its holes once the parts it joins are in place. Contacts inside its holes do not
/// block it (the fit is by design; the meshes need not model the bores).
struct PinInsertion {
  std::vector<FeatureRef> holes;  ///< the holes it goes through, in the order of their names
  double diameter = 0.0;          ///< mm, its smallest hole's
  /// The ends of its axis in place (world, mm), in the sense of its first hole's axis.
  std::array<Eigen::Vector3d, 2> ends_W = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Eigen::Vector3d direction_W = Eigen::Vector3d::UnitZ();  ///< unit direction of travel
  double travel = 0.0;  ///< mm from the start outside everything in place to its place
  bool clear = false;
  std::vector<InsertionObstacle> blocked_by;  ///< first contact per obstacle, by travel
};

/// One insertion: a part (and what travels with it) moving in a straight line into its pose.
struct InsertionStep {
  std::size_t part = 0;
  /// Parts moving along: press-fitted or forced fixed to it, or of the rolling bearing it is
  /// a part of (Analysis::bearings: rings, elements and cages, bought as one).
  std::vector<std::size_t> carried;
  std::optional<FeatureRef> feature;  ///< the inserted feature, when the direction comes from one
  std::optional<FeatureRef> into;     ///< the feature it goes into
  Eigen::Vector3d direction_W = Eigen::Vector3d::UnitZ();  ///< unit direction of travel
  double travel = 0.0;  ///< mm from the start outside everything in place to the final pose
  /// Nothing stops the part; for an unplaced part's attempt, true when only a pin through it
  /// that cannot come out keeps it from leaving.
  bool clear = false;
  std::vector<InsertionObstacle> blocked_by;  ///< first contact per obstacle, by travel
  std::optional<std::size_t> pair;  ///< index into Analysis::pairs of the relation created
  /// The pins the file leaves out that go in right after this step: those through this
  /// step's parts whose other parts are in place.
  std::vector<PinInsertion> pins;
  /// A sub-assembly's insertion: `part` and `carried` were put together apart from the rest of
  /// the assembly (`part` first, with the parts that cannot leave it: AssemblyPlan::unplaced),
  /// by the steps just before this one that are `apart_for` it, and move in as one.
  bool subassembly = false;
  /// A step that puts a sub-assembly together apart, or (in AssemblyPlan::unplaced) an attempt
  /// to: the index into AssemblyPlan::steps of the sub-assembly's insertion. Only parts of the
  /// sub-assembly are in place: for a step, all but those of the later steps apart for it; for
  /// an attempt, all but those of the steps apart for it (its base, with what cannot leave it).
  std::optional<std::size_t> apart_for;
};

/// Whether and how the assembly can be put together.
struct AssemblyPlan {
  bool assemblable = false;
  bool from_steps = false;        ///< the file's `steps` were checked (else a search ran)
  std::vector<std::size_t> base;  ///< parts in place before the first step
  /// The pins the file leaves out that join parts in place before the first step only.
  std::vector<PinInsertion> base_pins;
  std::vector<InsertionStep> steps;
  /// Search only: parts that no straight insertion brings into place, with the attempt that
  /// got furthest (its blockers).
  std::vector<InsertionStep> unplaced;
  /// Penetrations in the assembled state that the pairs do not explain.
  std::vector<PartContact> clashes;
  std::vector<Diagnostic> diagnostics;
};

/// Checks the file's steps in order, or searches a sequence by disassembly when there are
/// none.
///
/// Steps: parts that no step inserts are in place first (the base). Each step moves its part,
/// with the parts press-fitted or forced fixed to it and the other parts of its rolling
/// bearing (Analysis::bearings) that no step inserts, along the inserted
/// feature's axis (a convex feature or a face leads along its axis, which for a convex
/// feature going into a concave one is the concave feature's axis; a concave feature going
/// onto its partner travels against its own axis) from where it is clear of every part in place to
/// its pose in the file; the exact translational sweep (FirstBlockingContact) finds what
/// stops it. Contacts in the engagement region of a pair between the moving part and the
/// obstacle (a thread entering its nut; the region grown by the two meshes' deviations,
/// MeshDeviation) and contacts within the length tolerance of the final
/// pose (the seat) do not block; nor do contacts that approach slower than the sine of the
/// angular tolerance (sliding). An axial fit holds the part against travel across its axis,
/// unless it is an implied pin or a fixed pair of implied pins (PairSource::kImpliedPin): the
/// pins the file leaves out go in after both parts: each hinge pin (FindHingePins) right after
/// the step that places the last of its parts (`pins`; the base's before the first step,
/// `base_pins`), from whichever end of its axis is clear (its first hole's, by name, axis'
/// sense first; else the attempt whose first stop is nearest its place is reported, with what
/// stops it). Dowels are not listed (see FindHingePins). A pin in place is an obstacle like a
/// part, to the parts and the pins that go in after it (every contact with it counts: it has
/// no pairs); a pin that cannot go in counts as in place, as a blocked part does. A part in
/// place that the moving parts clash with at rest (`clashes`) and that stops them nowhere on
/// the way stops them at their place (InsertionObstacle::clash_at_rest): a removal's sweep
/// does not see contacts that start inside each other.
///
/// Search: ground parts (or, without any, the part with the largest box) form the base; the
/// other parts are removed one at a time, in passes over the parts in the order of the file
/// until a pass removes none, each along the first clear direction among its feature axes (the
/// sense that withdraws a convex feature first), the world's principal directions, and, for
/// each axis it pivots on (a revolute or cylindrical pair with a part outside it), the way from
/// the axis to the middle of its box and the principal directions, each turned square to the
/// axis; a part leaves only when the pins the file leaves out through it can come out first
/// (with the parts present then), and the pins whose parts are all present, none of them
/// leaving, stand in its way; a part that clashes at rest with a part present leaves all the
/// same (the clash is the model's, in `clashes`), and its step is not clear. When a pass
/// removes none, a sub-assembly leaves as one: for each unit left and each of its removal
/// directions, the unit and, in turn, every unit that stops one of them along that direction
/// (the closure of the blocking relation, Wilson and Latombe's non-directional blocking graph),
/// (a pin the file leaves out that stops one brings in the parts it goes through), unless the
/// base, or a pin through the base alone, stops one; the smallest such set that can leave as
/// one (along that direction first, then its own; the pins through its parts come out first,
/// and go in right after it) goes, its largest unit first (`part`, the others `carried`,
/// `subassembly`), and is taken apart by the same one-at-a-time search with its parts alone
/// and no pins, down to that unit (no sub-assembly inside it): those steps are `apart_for` it,
/// and the units that cannot leave it are `unplaced` apart for it (of the smallest sets that
/// leave, one that comes apart down to its base is preferred). Then the passes go on. The sequence
/// is the reverse. Parts that cannot leave are `unplaced`, each with its best attempt: the
/// direction in which it gets furthest (the first of those that get equally far), with every part
/// on its way, and its pins. The search runs on all cores and gives the one-at-a-time search's
/// answer whatever the threads' timing.
///
/// The assembly is assemblable when there are no clashes, every part is placed, and every step
/// and every pin is clear.
///
/// `progress` (optional) receives the fraction done, never decreasing, 1 last: 0 at the start
/// (the clashes at rest are found first), then as the steps are checked, or as each part (with
/// what it carries) is removed or found unable to leave. The calls are made one at a time, not
/// always on the calling thread.
AssemblyPlan PlanAssembly(const Assembly& assembly, const Analysis& analysis,
                          const CollisionModel& model,
                          const std::function<void(double)>& progress = {});

}  // namespace mechanist
