#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "kernel/assembly/assembly.h"

namespace mechanist {

/// A placement that cannot be solved: names the part (index into the spec's parts).
class PlacementError : public std::invalid_argument {
 public:
  PlacementError(std::size_t part, const std::string& message)
      : std::invalid_argument(message), part_(part) {}
  std::size_t part() const { return part_; }

 private:
  std::size_t part_;
};

/// Gives every part placed by features (Part::placement, spec "place") its pose X_WP, parts
/// before the parts placed relative to them. A single condition is solved in closed form:
/// - insert: the feature's axis made collinear with the target's, same sense (the shortest
///   rotation, a half turn about the part's x for opposite axes, then `angle` about the axis),
///   its origin `depth` past the target's origin (default: the shorter of the two lengths);
/// - mesh: the gear's centre at the centre distance from the target's axis, in the direction
///   at polar `angle` about the target's axis from the target part's local x (its y when x is
///   along the axis), mid-faces coplanar; gears parallel and of the same sense, a worm wheel or
///   worm square to its partner with the worm's axis in the wheel's mid-plane, a rack's pitch
///   line tangent to the pinion's pitch circle with its teeth facing it (a pinion on a rack:
///   at the rack's middle, the angle unused);
/// - against: the face's normal opposite the target face's, its origin on the target's.
/// Several conditions are solved together by least squares over the part's pose
/// (SolveLeastSquares), from the first condition's closed form: insert keeps the axes
/// collinear (and its depth when written; the turn about the axis stays the start's unless
/// another condition turns the part), mesh the centre and axis, against the normals opposite
/// and the face in the plane. Teeth are not phased: a gear placed by mesh keeps the shortest
/// rotation, so its teeth may stand in its partner's (turn it with an insert's angle). Throws
/// PlacementError for a condition whose features cannot do what it asks (a mesh of a shaft) and for
/// conditions that cannot all hold (a residual above the file's length tolerance after solving).
/// The reader has rejected cycles.
void ResolvePlacements(AssemblySpec* spec);

}  // namespace mechanist
