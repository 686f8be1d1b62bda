#include "kernel/assembly/assembly_state.h"

namespace mechanist {

AssemblyState InitialState(const Assembly& assembly) { return {assembly.FilePoses()}; }

Aabb WorldBox(const Assembly& assembly, const AssemblyState& state, std::size_t part) {
  return TransformBox(state.X_WP.at(part), assembly.MeshBox(part));
}

}  // namespace mechanist
