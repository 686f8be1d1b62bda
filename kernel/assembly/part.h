#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel/features/feature.h"
#include "kernel/features/feature_ref.h"
#include "kernel/geometry/rigid_transform.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// One condition of a placement by features (spec, "place"). Features are resolved: `feature`
/// is this part's, `target` a part placed before it.
struct PlacementCondition {
  enum class Kind { kInsert, kMesh, kAgainst };
  Kind kind = Kind::kInsert;
  std::size_t feature = 0;      ///< index into this part's features
  FeatureRef target;            ///< "into", "with" or "on"
  std::optional<double> depth;  ///< insert: mm past the target's origin; default: shorter length
  double angle = 0.0;           ///< insert: turn about the axis; mesh: polar angle. Radians.
};

/// A part of the assembly description: its mesh and features in its own frame, and its pose
/// as the file gives it. Immutable once the Assembly holds it.
struct Part {
  std::string id;
  /// The mesh in part coordinates (mm); shared between parts with the same source. Empty (no
  /// faces) for a features-only part, a kinematic sketch without geometry.
  std::shared_ptr<const TriangleMesh> mesh;
  /// Where the mesh came from: a file path as written in the file, or "library:<kind>"; empty
  /// for a features-only part.
  std::string mesh_source;
  /// The mesh is Open CASCADE's tessellation of a STEP solid: a gap in it is the mesher's, not
  /// the designer's (the mesh checks say so as info).
  bool tessellated = false;
  /// How far the mesh may lie from the part's true surface, mm: for a tessellated STEP solid
  /// the mesher's deflection (StepSolid::mesh_deviation), 0 for a mesh file or a library part
  /// (the mesh is the part's geometry). Where the features leave room, the meshes may still overlap
  /// by the two parts' deviations (a pin line-on-line in its bore, its vertices on the circle, the
  /// bore's facets inside it).
  double mesh_deviation = 0.0;
  /// The mesher's angular deflection, rad (0 when none is known): a circle of radius r on the
  /// part's surface lies within r (1 - cos(mesh_angle / 2)) of its facets, however large
  /// mesh_deviation is (a 4 mm bore in a 1 m frame is meshed finer than the frame).
  double mesh_angle = 0.0;
  /// X_WP, the pose in the file (identity when the file gives none or places the part).
  RigidTransform X_WP;
  /// Placement by features instead of a pose (resolved by the placement solver); empty when
  /// the part has a pose.
  std::vector<PlacementCondition> placement;
  bool ground = false;
  /// A spring, belt or hose (spec: `compliant`): not a rigid link. It joins no pair, moves with
  /// nothing and counts in no mobility; the parts it touches are reported.
  bool compliant = false;
  std::string group;  ///< CAD product-structure path, informational
  /// The CAD part instance this solid is one body of, when that part has several solids (a
  /// STEP product's solids share its instance path); empty otherwise. Bodies of one part that
  /// touch face to face are one piece (pair recognition).
  std::string body_of;
  std::vector<Feature> features;
  /// What reading the part's source saw but made no feature of, in words (a STEP solid's
  /// cones, spheres, tori and free-form faces); informational.
  std::vector<std::string> notes;

  /// False for a features-only part (no mesh, or one without faces): the commands that need
  /// geometry (interference, assembly paths, swept checks, gaps) skip it.
  bool HasGeometry() const { return mesh && !mesh->faces.empty(); }

  /// Index of the feature `feature_id`, or nothing.
  std::optional<std::size_t> FindFeature(const std::string& feature_id) const;
};

}  // namespace mechanist
