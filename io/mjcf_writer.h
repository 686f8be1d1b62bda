#pragma once

#include <string>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/simulation_model.h"

namespace mechanist {

/// Options of MjcfText.
struct MjcfOptions {
  std::string mesh_dir = "meshes";  ///< mesh files, relative to the MJCF file
  /// Write a keyframe "drive" at the file pose with every actuator's control at its driver's
  /// rate, so that resetting to it runs the mechanism.
  bool drive = false;
};

/// The MJCF (MuJoCo 2.2) text of `model`: nested bodies with their inertials, joints (hinge,
/// slide, ball, free) with ranges from the swept check, couplings as fixed tendons (sum of
/// coefficient * joint) held at length 0 by `<equality><tendon>`, loops
/// closed by `<connect>` constraints, a velocity actuator per running driver whose gain gives a
/// time constant of 0.02 s on the inertia its joint moves, and an equality holding the joint of
/// each held driver (a brake). Gravity is 0: the file does not say which way is up. Mesh geoms
/// are visual only (contype 0): MuJoCo collides convex hulls, and a housing's hull would
/// swallow its gears.
std::string MjcfText(const Assembly& assembly, const Analysis& analysis,
                     const SimulationModel& model, const MjcfOptions& options = {});

}  // namespace mechanist
