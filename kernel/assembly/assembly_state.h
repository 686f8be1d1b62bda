#pragma once

#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/geometry/aabb.h"
#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// The changing state of an assembly (Pinocchio's Data): the pose X_WP of every part, indexed
/// like Assembly::parts(). Motion and assembly operations change a state, never the Assembly.
struct AssemblyState {
  std::vector<RigidTransform> X_WP;
};

/// The state with every part at its pose in the file.
AssemblyState InitialState(const Assembly& assembly);

/// World box of part `part` in `state`: its tight box in part coordinates, transformed.
Aabb WorldBox(const Assembly& assembly, const AssemblyState& state, std::size_t part);

}  // namespace mechanist
