#include "kernel/collision/collision_model.h"

#include <map>

namespace mechanist {

CollisionModel::CollisionModel(const Assembly& assembly) {
  std::map<const TriangleMesh*, std::shared_ptr<const CollisionMesh>> built;
  for (const Part& part : assembly.parts()) {
    auto& mesh = built[part.mesh.get()];
    if (!mesh) mesh = std::make_shared<const CollisionMesh>(part.mesh);
    meshes_.push_back(mesh);
  }
}

}  // namespace mechanist
