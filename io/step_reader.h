#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kernel/features/feature.h"
#include "kernel/geometry/rigid_transform.h"
#include "kernel/mesh/triangle_mesh.h"
#include "kernel/support/ascii_lower.h"

namespace mechanist {

/// Whether `file` is named as a STEP file: its extension .step or .stp, in any case.
inline bool IsStepFile(const std::filesystem::path& file) {
  const std::string extension = AsciiLower(file.extension().string());
  return extension == ".step" || extension == ".stp";
}

/// One solid instance of a STEP assembly.
struct StepSolid {
  /// Its product-structure path: the instance names from the root, `.` between levels, unnamed
  /// levels left out, other characters than [A-Za-z0-9_.-] replaced by `_`, a repeated name
  /// under one parent suffixed `_2`, `_3`, ... and a product's second and later solids
  /// `_solid2`, ...
  std::string path;
  std::string product;  ///< the name of the product it is a solid of
  /// The instance's path (without `_solidN`) when its product has several solids; else empty.
  std::string body_of;
  RigidTransform X_WP;  ///< its placement (mm)
  /// Triangulated in its product's frame (mm); shared by the instances of one product.
  std::shared_ptr<const TriangleMesh> mesh;
  /// How far the mesh may lie from the solid's faces, mm: the mesher's linear deflection,
  /// 1/1000 of the solid's box diagonal and at least 0.01 mm.
  double mesh_deviation = 0.0;
  /// The mesher's angular deflection, rad (Part::mesh_angle).
  double mesh_angle = 0.0;
  /// From the exact faces: cylinders covering 270 degrees or more (faces of one cylinder
  /// merged) are shafts when convex and through holes when concave, with the extent of their
  /// faces along the axis; planes are faces with their outward normal and extent.
  std::vector<Feature> features;
  /// The faces that give no feature, in words: a cone covering 270 degrees or more as the
  /// countersink of a coaxial hole whose radius its narrow end meets ("countersink of hole_1: 90
  /// deg, diameter 6 to 12 mm"), the conical end of a coaxial shaft that it narrows from, the
  /// conical flare of one it widens from, or a cone of its own;
  /// counts of partial cones, spheres, tori and free-form faces.
  std::vector<std::string> notes;
};

/// A message about the file: one of Open CASCADE's reader, of warning gravity or above, or one
/// of its error reports, e.g. "ERR StepFile : Incorrect Syntax : Fails Count : 1"; or a
/// reference to an entity the file does not define (in place of the reader's reports of them);
/// or a product instance that holds no solid.
struct StepMessage {
  bool error = false;  ///< an error report or fail gravity; otherwise a warning
  std::string text;    ///< one line: blank runs and "***" as single spaces
  /// The text is a reference to an entity the file does not define (an error), the entity
  /// that holds it with its type, and the missing one: "#2878 PRODUCT_CATEGORY_RELATIONSHIP
  /// refers to #999998".
  bool undefined_reference = false;
  /// The text is the path of a product instance (as StepSolid::path) that holds no solid, so
  /// that no solid read stands for it: a product of surfaces, curves or sketches only, or one
  /// whose solid a damaged file lacks (not an error).
  bool no_solid = false;
};

/// Receives the fraction of a STEP file's reading done, in [0, 1], never decreasing, 1 last
/// when the reading succeeds: first when the file is parsed, then when its shapes are
/// transferred, then after each distinct solid (a product's, once for all its instances) is
/// healed, triangulated and its features taken. Called from the reading threads, one call at a
/// time.
using StepProgress = std::function<void(double fraction)>;

/// As StepProgress, for the STEP file `step_file` among others (an assembly file's imports).
using StepFileProgress =
    std::function<void(const std::filesystem::path& step_file, double fraction)>;

/// The references to entities the file does not define among `messages` (ReadStep's), in
/// words for a report: "2 references to entities the file does not define (#10 LINE refers to
/// #13; #12 FACE_BOUND refers to #14): it is damaged or cut short", the first three named;
/// empty when there is none.
std::string UndefinedReferenceWords(const std::vector<StepMessage>& messages);

/// Reads a STEP file (AP203, AP214 or AP242) with its product structure through Open
/// CASCADE's XCAF reader, triangulates each solid (0.01 mm or 0.1% of its size, whichever is
/// coarser, and 0.3 rad) and takes features from its analytic faces. Open CASCADE's messages go to
/// `messages` (when given), never to stdout, followed by one for each product instance that
/// holds no solid, none of its path's solids either (StepMessage::no_solid), in the order of
/// the product structure; `progress` (when given) follows the reading, the
/// solids weighed by their faces; `length_units` (when given) receives the length units the
/// file declares, lower case ("metre", "inch"; values are read in mm whatever they are).
/// Throws std::runtime_error when it cannot be read or holds no solid.
std::vector<StepSolid> ReadStep(const std::filesystem::path& file,
                                std::vector<StepMessage>* messages = nullptr,
                                const StepProgress& progress = {},
                                std::vector<std::string>* length_units = nullptr);

}  // namespace mechanist
