#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/features/feature_recognition.h"

namespace mechanist {

/// What `mechanist features` reports for one mesh: its name, the part's pose (the mesh's own
/// frame for a lone mesh file), whether the assembly uses the recognised features, and what was
/// recognised.
struct FeatureReportEntry {
  std::string part;  ///< part id, or the mesh file's name
  RigidTransform X_WP;
  MeshFeatures found;
  /// True when the part's features are the recognised ones (the file writes none for it).
  bool used = true;
};

/// The recognition of every part with a mesh file in `assembly` (library parts have their
/// features by construction and are left out); a part imported from STEP lists the features
/// taken from its exact faces.
std::vector<FeatureReportEntry> RecogniseAssemblyFeatures(const Assembly& assembly);

/// One block per entry: the extrusion axis, each feature as `info` writes it with its fit error
/// and how it was found, and the notes.
void WriteFeatureReport(const std::vector<FeatureReportEntry>& entries, std::ostream& out);

/// {"parts": [{"part", "axis", "used", "features": [{"id", "kind", "origin", "axis", "length",
/// "diameter", "teeth", "module", "internal", "helix_angle", "pitch_angle", "spiral_angle",
/// "normal", "fit_error", "detail"}], "notes"}]}; world coordinates, mm, angles in degrees
/// (a helix or spiral angle only when not 0).
std::string FeatureJson(const std::vector<FeatureReportEntry>& entries);

}  // namespace mechanist
