#include "kernel/collision/collision_mesh_cache.h"

namespace mechanist {

const CollisionMesh& CollisionMeshCache::Get(const std::shared_ptr<const TriangleMesh>& mesh) {
  auto [it, added] = meshes_.try_emplace(mesh.get());
  if (added) it->second = std::make_unique<CollisionMesh>(mesh);
  return *it->second;
}

}  // namespace mechanist
