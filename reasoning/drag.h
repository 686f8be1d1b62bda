#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/motion.h"

namespace mechanist {

/// The seeds' forward and backward propagation: take hold of one part and turn it about, or
/// push it along, one of its feature axes.
struct DragRequest {
  std::size_t part = 0;
  /// The feature whose axis is used; empty: of the part's sides of its pairs with other
  /// subassemblies, then of the other parts of its subassembly, in pair order, the first
  /// about (along) which it can move, else the first of them (for a part of the ground
  /// subassembly, which cannot move, that one alone); with none, the part's first feature.
  std::optional<std::size_t> feature;
  bool rotate = true;
};

/// What a drag moves.
struct DragResult {
  std::size_t part = 0;  ///< the part dragged
  FeatureRef axis;       ///< the feature whose axis the part was dragged about or along
  DrivenMotion motion;   ///< per part; `possible` false when the pairs forbid the motion
  /// Pairs across which the motion stops: one side moves, the other stays (the pair that
  /// absorbs the motion), ascending.
  std::vector<std::size_t> absorbing_pairs;
  /// When the motion is impossible, the pairs that hold the part, ascending: for a part of the
  /// ground subassembly its fixed pairs (the tight bolts that fix a motor to the housing; none
  /// for a ground part itself), otherwise its subassembly's pairs with the others.
  std::vector<std::size_t> holding_pairs;
  int part_freedoms = 0;  ///< dimension of the dragged part's allowable motion
};

/// Drags a part (at unit rate) about (along) the axis' line where the pairs allow it
/// (ImposedMotion::about_line), with every other freedom held still. Throws
/// std::invalid_argument when the part has no feature to take the axis from.
DragResult Drag(const Assembly& assembly, const Analysis& analysis, const DragRequest& request);

}  // namespace mechanist
