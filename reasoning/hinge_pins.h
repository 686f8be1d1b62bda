#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_mesh.h"
#include "kernel/collision/collision_model.h"
#include "kernel/features/feature_ref.h"
#include "kernel/geometry/aabb.h"
#include "kernel/geometry/rigid_transform.h"
#include "reasoning/analysis.h"

namespace mechanist {

/// A hinge pin that the file leaves out, at its place: a cylinder of its smallest hole's
/// diameter over the length of all its holes.
struct HingePin {
  std::vector<FeatureRef> holes;   ///< the holes it goes through, in the order of their names
  std::vector<std::size_t> parts;  ///< its holes' parts, sorted, each once
  double diameter = 0.0;           ///< mm
  /// The ends of its axis (world, mm), in the sense of its first hole's axis.
  std::array<Eigen::Vector3d, 2> ends_W = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  RigidTransform X_WPin;                      ///< its frame: z along its first hole's axis
  std::shared_ptr<const CollisionMesh> mesh;  ///< the cylinder, in its frame (24 sides)
  Aabb box;                                   ///< world, at its place
};

/// The hinge pins that the file leaves out, for parts at `state` (meshes from `model`): the
/// holes of the revolute implied-pin pairs of `analysis` (PairSource::kImpliedPin), joined into
/// one pin where two pairs share a hole, or where two holes of one part lie on one line (within
/// the assembly's angle and length tolerances) with no material of that part on the axis
/// between them (sampled at 7 points with CollisionMesh::Contains): the ears of a clevis carry
/// one rod, two stub axles' holes at the ends of a solid part do not. Holes of a part whose mesh
/// bounds no solid (CollisionMesh::solid) are not joined that way. In the order of their first
/// holes' names. Dowels (a fixed pair of implied pins) are not hinge pins: the analysis keeps
/// one fixed pair for a part pair's dowels, which holds nothing.
std::vector<HingePin> FindHingePins(const Assembly& assembly, const Analysis& analysis,
                                    const AssemblyState& state, const CollisionModel& model);

}  // namespace mechanist
