#pragma once

#include <map>
#include <memory>

#include "kernel/collision/collision_mesh.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// Collision meshes built on first use, one per distinct mesh: for queries that touch a few
/// parts of an assembly (a CollisionModel builds every part's).
class CollisionMeshCache {
 public:
  /// The collision mesh of `mesh`, which must not be null; the cache keeps `mesh` alive.
  const CollisionMesh& Get(const std::shared_ptr<const TriangleMesh>& mesh);

 private:
  std::map<const TriangleMesh*, std::unique_ptr<CollisionMesh>> meshes_;
};

}  // namespace mechanist
