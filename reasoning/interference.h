#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "kernel/collision/mesh_contact.h"
#include "reasoning/pair.h"

namespace mechanist {

/// How two parts meet in the assembled state.
enum class ContactVerdict {
  kTouching,     ///< surfaces meet, penetration within the length tolerance (a mate), or within
                 ///< the meshes' deviations in a fit with room (FindContacts)
  kDesignedFit,  ///< penetration inside the features of a recognised pair (press fit, thread
                 ///< in its nut, meshing teeth): intended, not a clash
  kClash         ///< penetration the pairs do not explain: an interference to fix
};

/// "touching", "designed_fit", "clash".
std::string_view ToString(ContactVerdict verdict);

/// Two parts in contact.
struct PartContact {
  std::size_t part_a = 0, part_b = 0;  ///< part indices, part_a < part_b
  ContactVerdict verdict = ContactVerdict::kTouching;
  ContactMeasure measure;           ///< depth (mm), location (world), containment
  std::optional<std::size_t> pair;  ///< kDesignedFit: index of the pair that explains it
};

/// True when p_W lies in the space that `feature` of a part at X_WP engages (its cylinder,
/// tip circle, sphere or pitch band, grown by `tolerance` mm): where a pair's designed
/// overlap can happen. Faces have no such space.
bool InEngagementRegion(const Feature& feature, const RigidTransform& X_WP,
                        const Eigen::Vector3d& p_W, double tolerance);

/// True for the pairs whose features overlap by design: press fits, threads in their nuts or
/// tapped holes (modelled at the major diameter in a hole at the minor one), setscrew tips,
/// and meshing teeth (gear, worm gear, rack and pinion). A shaft in a clearance hole is not
/// one: material there is a clash (often a mesh that does not model the hole).
bool OverlapIsDesigned(const Pair& pair);

/// True for the features of axial fits: shafts, holes, threads and tapped holes.
bool IsAxialFit(FeatureKind kind);

/// How far the mesh of `part` may lie off a circle of `radius` mm on its surface, mm: its
/// Part::mesh_deviation, and at most radius (1 - cos(mesh_angle / 2)) when the mesher's angle
/// is known (Part::mesh_angle). An infinite radius (a surface that is no circle) gives the
/// deviation. Two meshes that only touch there may overlap by the sum of theirs.
double MeshDeviation(const Assembly& assembly, std::size_t part, double radius);

/// True when p_W is in the engagement regions of both features of `pair` (parts at `state`);
/// for a shaft, hole or thread fit both cylinders are taken at the larger diameter, since the
/// designed overlap lies between the two.
bool InPairRegion(const Assembly& assembly, const AssemblyState& state, const Pair& pair,
                  const Eigen::Vector3d& p_W, double tolerance);

/// Every pair of parts whose meshes meet at `state`: a part-level sort-and-sweep broad phase
/// on world boxes, then MeasureContact (on every core). Penetrations deeper than the file's length
/// tolerance are designed fits when the deepest point lies in the engagement region of a pair
/// between the two parts that overlaps by design (OverlapIsDesigned) (`pairs`, as recognised at
/// this state); touching when it lies in that of a shaft in a hole at least as wide (within
/// the tolerance) and the depth is within the tolerance plus the two meshes' deviations at the
/// fit's radius (MeshDeviation: a line-on-line fit's tessellations); clashes otherwise. Sorted by
/// part ids. Deterministic.
std::vector<PartContact> FindContacts(const Assembly& assembly, const AssemblyState& state,
                                      const CollisionModel& model, const std::vector<Pair>& pairs);

}  // namespace mechanist
