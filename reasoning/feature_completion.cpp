#include "reasoning/feature_completion.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <utility>

#include "kernel/features/feature_recognition.h"
#include "kernel/features/spring_recognition.h"
#include "kernel/support/few_names.h"
#include "kernel/support/number_format.h"
#include "kernel/support/parallel_for.h"

namespace mechanist {
namespace {

/// The gears, bevel gears, worms, racks and cycloidal discs found on one solid's
/// tessellation, in the solid's frame.
struct TessellationGears {
  std::vector<Feature> features;
  std::vector<std::string> notes;
};

TessellationGears FindTessellationGears(const TriangleMesh& mesh) {
  TessellationGears gears;
  for (RecognizedFeature& r : RecognizeFeatures(mesh, MeshRecognition::kTeeth).features) {
    const FeatureKind k = r.feature.kind;
    if (k != FeatureKind::kGear && k != FeatureKind::kBevelGear && k != FeatureKind::kWorm &&
        k != FeatureKind::kRack && k != FeatureKind::kCycloidDisc) {
      continue;
    }
    gears.notes.push_back(
        fmt::format("{}: {} (found on the solid's tessellation)", r.feature.id, r.detail));
    gears.features.push_back(std::move(r.feature));
  }
  return gears;
}

std::string Mm(double x) { return fmt::format("{} mm", FormatNumber(x, 4)); }

}  // namespace

bool PartOrigin::Inferred(const Part& part, std::size_t feature) const {
  if (features_written) return false;
  return std::find(written.begin(), written.end(), part.features.at(feature).id) == written.end();
}

std::vector<Diagnostic> CompleteFeatures(std::vector<Part>* parts,
                                         const std::vector<PartOrigin>& origins) {
  // The recognisers look at each mesh once (instances share theirs), all meshes in parallel.
  std::map<const TriangleMesh*, TessellationGears> gears_of;
  std::map<const TriangleMesh*, std::optional<HelicalSpring>> springs_of;
  for (std::size_t p = 0; p < parts->size(); ++p) {
    if (origins.at(p).features_written) continue;
    for (const auto& solid : origins[p].step_solids)
      gears_of.emplace(solid.mesh.get(), TessellationGears());
    const Part& part = (*parts)[p];
    if (!part.compliant && part.HasGeometry()) springs_of.emplace(part.mesh.get(), std::nullopt);
  }
  std::vector<std::pair<const TriangleMesh*, TessellationGears*>> gear_work;
  for (auto& [mesh, gears] : gears_of) gear_work.emplace_back(mesh, &gears);
  std::vector<std::pair<const TriangleMesh*, std::optional<HelicalSpring>*>> spring_work;
  for (auto& [mesh, spring] : springs_of) spring_work.emplace_back(mesh, &spring);
  ParallelFor(gear_work.size() + spring_work.size(), [&](std::size_t k) {
    if (k < gear_work.size()) {
      *gear_work[k].second = FindTessellationGears(*gear_work[k].first);
    } else {
      const auto& [mesh, spring] = spring_work[k - gear_work.size()];
      *spring = RecognizeHelicalSpring(*mesh);
    }
  });
  std::vector<Diagnostic> springs;
  std::vector<std::string> recognised;
  std::vector<std::string> with_gears;
  for (std::size_t p = 0; p < parts->size(); ++p) {
    const PartOrigin& origin = origins.at(p);
    if (origin.features_written) continue;
    Part& part = (*parts)[p];
    // Backwards, so that each solid's insertion points stay where the reader put them.
    bool found_gears = false;
    for (auto solid = origin.step_solids.rbegin(); solid != origin.step_solids.rend(); ++solid) {
      const TessellationGears& found = gears_of.at(solid->mesh.get());
      std::vector<Feature> features = found.features;
      for (Feature& f : features) {
        f.id = solid->prefix + f.id;
        f.origin = solid->X_PS * f.origin;
        f.axis = solid->X_PS.RotateDirection(f.axis);
        f.normal = solid->X_PS.RotateDirection(f.normal);
      }
      std::vector<std::string> notes = found.notes;
      if (!solid->prefix.empty()) {
        const std::string label = solid->prefix.substr(0, solid->prefix.size() - 1);
        for (std::string& note : notes) note = fmt::format("{}: {}", label, note);
      }
      found_gears = found_gears || !features.empty();
      part.features.insert(part.features.begin() + solid->features_end,
                           std::make_move_iterator(features.begin()),
                           std::make_move_iterator(features.end()));
      part.notes.insert(part.notes.begin() + solid->notes_end, notes.begin(), notes.end());
    }
    if (found_gears) with_gears.push_back(part.id);
    // A helical spring is no rigid link (spec: `compliant`), whichever way its mesh came.
    if (!part.compliant && part.HasGeometry()) {
      if (const std::optional<HelicalSpring>& spring = springs_of.at(part.mesh.get())) {
        part.compliant = true;
        springs.push_back(
            {Severity::kInfo,
             "spring_recognised",
             fmt::format("part '{}' is a helical spring (coil {}, wire {}, {} turns of pitch {}, "
                         "{} hand): compliant, not a rigid link",
                         part.id, Mm(spring->mean_diameter), Mm(spring->wire_diameter),
                         FormatNumber(spring->turns, 3), Mm(spring->pitch),
                         spring->hand == Hand::kRight ? "right" : "left"),
             {part.id},
             {}});
      }
    }
    const bool only_tessellation_gears = origin.imported || !part.features.empty();
    if (!origin.step_solids.empty() && only_tessellation_gears) continue;
    if (!part.HasGeometry()) continue;
    for (RecognizedFeature& r : RecognizeFeatures(*part.mesh).features) {
      part.features.push_back(std::move(r.feature));
    }
    if (!part.features.empty()) recognised.push_back(part.id);
  }
  std::vector<Diagnostic> done;
  if (!recognised.empty()) {
    done.push_back({Severity::kInfo,
                    "features_recognised",
                    fmt::format("the file writes no features for {} {}, so they were recognised "
                                "from the mesh: {}",
                                recognised.size(), recognised.size() == 1 ? "part" : "parts",
                                FewNames(recognised)),
                    recognised,
                    {}});
  }
  if (!with_gears.empty()) {
    done.push_back(
        {Severity::kInfo,
         "tessellation_gears",
         fmt::format("gears, bevel gears, worms, racks or cycloidal discs of {} {} were found on "
                     "the tessellation of their faces (the part's notes say which): {}",
                     with_gears.size(), with_gears.size() == 1 ? "STEP solid" : "STEP solids",
                     FewNames(with_gears)),
         with_gears,
         {}});
  }
  done.insert(done.end(), springs.begin(), springs.end());
  return done;
}

}  // namespace mechanist
