#pragma once

#include <map>
#include <memory>
#include <vector>

#include "kernel/collision/collision_mesh.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// Collision meshes built on first use, or ahead on all cores (Build), one per distinct mesh:
/// for queries that touch a few parts of an assembly (a CollisionModel builds every part's).
class CollisionMeshCache {
 public:
  /// The collision mesh of `mesh`, which must not be null; the cache keeps `mesh` alive.
  const CollisionMesh& Get(const std::shared_ptr<const TriangleMesh>& mesh);
  /// Builds the collision meshes of `meshes` (none null; repeats allowed) that are not cached
  /// yet, on all cores (ParallelFor), for later Get or Find calls.
  void Build(const std::vector<std::shared_ptr<const TriangleMesh>>& meshes);
  /// The cached collision mesh of `mesh`, or null when it has none yet. Safe to call from
  /// several threads at once while nothing calls Get or Build.
  const CollisionMesh* Find(const TriangleMesh* mesh) const;
  /// How many collision meshes the cache holds.
  std::size_t size() const { return meshes_.size(); }

 private:
  std::map<const TriangleMesh*, std::unique_ptr<CollisionMesh>> meshes_;
};

}  // namespace mechanist
