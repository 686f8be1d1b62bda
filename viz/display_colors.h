#pragma once

#include <Eigen/Core>
#include <vector>

#include "reasoning/analysis.h"

namespace mechanist {

/// Display colours (linear RGB, components in [0, 1]) shared by every animation output.
struct DisplayColors {
  /// Per part: its subassembly's colour (a palette of eight distinct hues in subassembly
  /// order, repeating), muted grey for the parts of ground subassemblies.
  std::vector<Eigen::Vector3d> part;
};

/// The colours of the parts of `analysis`'s subassemblies.
DisplayColors ColorParts(const Analysis& analysis);

/// A part in a clash.
inline Eigen::Vector3d ClashColor() { return {0.85, 0.05, 0.05}; }
/// The walls of enclosed gaps.
inline Eigen::Vector3d GapColor() { return {0.10, 0.35, 0.95}; }
/// Feature axes (the seeds' auxiliary lines).
inline Eigen::Vector3d AxisColor() { return {0.15, 0.15, 0.15}; }

}  // namespace mechanist
