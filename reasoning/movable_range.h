#pragma once

#include <optional>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/collision/collision_model.h"
#include "kernel/geometry/screw_path.h"
#include "reasoning/analysis.h"
#include "reasoning/operation_check.h"

namespace mechanist {

/// How far a motion runs each way from the file poses before two parts meet (Abe et al.,
/// section 3.3): the first contact ahead (the paths as given) and behind (reversed), each at
/// its parameter `at` (positive, in the paths' units) with the parts and the point. Empty where
/// nothing stops the motion within the amount searched.
struct MovableRange {
  std::optional<OperationClash> ahead, behind;
};

/// The movable range of the motion `paths` (per part, the pose after s is paths[p].At(s) *
/// X_WP), searched over s in [0, amount] each way with the swept check (SweepPaths). A contact
/// with a part that a free motion moves is no stop: nothing holds that part, so the push
/// carries it (as CheckOperation settles it). With `periodic` (a turn of one revolution) a
/// motion that meets nothing ahead meets nothing behind either, and that search is skipped.
MovableRange FindMovableRange(const Assembly& assembly, const Analysis& analysis,
                              const CollisionModel& collision, const std::vector<ScrewPath>& paths,
                              double amount, bool periodic);

}  // namespace mechanist
