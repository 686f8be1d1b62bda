#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/collision/collision_mesh.h"

namespace mechanist {

/// The collision meshes of an assembly's parts: one CollisionMesh per distinct mesh (parts
/// made from the same file or library entry share it), built once. Immutable.
class CollisionModel {
 public:
  explicit CollisionModel(const Assembly& assembly);
  /// The collision mesh of part `part` (index into Assembly::parts()), in the part's frame.
  const CollisionMesh& part_mesh(std::size_t part) const { return *meshes_.at(part); }
  std::size_t size() const { return meshes_.size(); }

 private:
  std::vector<std::shared_ptr<const CollisionMesh>> meshes_;
};

}  // namespace mechanist
