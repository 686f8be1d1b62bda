#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "kernel/assembly/diagnostic.h"
#include "kernel/assembly/part.h"
#include "kernel/geometry/rigid_transform.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// Where a part's features come from, as the reader found them (one per part of the spec).
struct PartOrigin {
  /// One STEP solid the part's mesh was made of, and where its tessellation gears go.
  struct StepSolid {
    std::shared_ptr<const TriangleMesh> mesh;  ///< in the solid's frame (mm)
    RigidTransform X_PS;                       ///< the solid's pose in the part
    std::string prefix;  ///< prepended to its feature ids ("solid2_") and notes ("solid2: ")
    std::size_t features_end = 0;  ///< the end of its exact-face features in Part::features
    std::size_t notes_end = 0;     ///< the end of its notes in Part::notes
  };

  /// The file wrote the part's features (or a library part made them): nothing is added, and
  /// no heuristic reinterprets them.
  bool features_written = true;
  /// The part is a solid of an imported STEP assembly: its exact faces are all the features
  /// besides tessellation gears, even when they give none.
  bool imported = false;
  /// The STEP solids the part's mesh was made of, in order (empty for other meshes).
  std::vector<StepSolid> step_solids;
  /// Ids of features that the file wrote on an imported part, or whose fastening it set.
  std::vector<std::string> written;

  /// Whether `feature` of `part` (described by this origin) came from the geometry rather than
  /// from the file's own words, so that a heuristic may reinterpret it.
  bool Inferred(const Part& part, std::size_t feature) const;
};

/// Completes the features the file did not write, the first step of the reasoning after
/// reading (io/load_assembly.h):
/// - a STEP solid (imported, or a part's mesh file) gets the gears and racks that
///   RecognizeFeatures finds on its tessellation (CAD systems write involute flanks as free-form
///   faces or as many small cylinder patches, which give no exact feature), after its exact-face
///   features, with a note each; once per shared mesh;
/// - a part whose mesh is not a STEP solid, or a STEP mesh file with no exact feature, gets
///   every feature RecognizeFeatures finds on its mesh;
/// - a part whose mesh is a helical spring (RecognizeHelicalSpring) becomes compliant.
/// Returns one info diagnostic per kind of step that did something (`features_recognised`,
/// `tessellation_gears`), naming the parts, and one `spring_recognised` per spring. Deterministic.
std::vector<Diagnostic> CompleteFeatures(std::vector<Part>* parts,
                                         const std::vector<PartOrigin>& origins);

}  // namespace mechanist
