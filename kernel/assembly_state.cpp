#include "kernel/assembly_state.h"

namespace mechanist {

AssemblyState InitialState(const Assembly& assembly) {
  AssemblyState state;
  state.X_WP.reserve(assembly.parts().size());
  for (const Part& part : assembly.parts()) state.X_WP.push_back(part.X_WP);
  return state;
}

Aabb WorldBox(const Assembly& assembly, const AssemblyState& state, std::size_t part) {
  return TransformBox(state.X_WP.at(part), assembly.part(part).mesh->Bounds());
}

}  // namespace mechanist
