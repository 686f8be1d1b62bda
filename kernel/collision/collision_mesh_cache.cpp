#include "kernel/collision/collision_mesh_cache.h"

#include <set>

#include "kernel/support/parallel_for.h"

namespace mechanist {

const CollisionMesh& CollisionMeshCache::Get(const std::shared_ptr<const TriangleMesh>& mesh) {
  auto [it, added] = meshes_.try_emplace(mesh.get());
  if (added) it->second = std::make_unique<CollisionMesh>(mesh);
  return *it->second;
}

const CollisionMesh* CollisionMeshCache::Find(const TriangleMesh* mesh) const {
  const auto found = meshes_.find(mesh);
  return found == meshes_.end() ? nullptr : found->second.get();
}

void CollisionMeshCache::Build(const std::vector<std::shared_ptr<const TriangleMesh>>& meshes) {
  std::set<const TriangleMesh*> seen;
  std::vector<std::shared_ptr<const TriangleMesh>> work;  // in the order given
  for (const auto& mesh : meshes) {
    if (!meshes_.count(mesh.get()) && seen.insert(mesh.get()).second) work.push_back(mesh);
  }
  std::vector<std::unique_ptr<CollisionMesh>> built(work.size());
  ParallelFor(work.size(),
              [&](std::size_t k) { built[k] = std::make_unique<CollisionMesh>(work[k]); });
  for (std::size_t k = 0; k < work.size(); ++k) meshes_.emplace(work[k].get(), std::move(built[k]));
}

}  // namespace mechanist
