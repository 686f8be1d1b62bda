#include "io/feature_report.h"

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <numbers>

#include "io/info_report.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

using Json = nlohmann::ordered_json;

double Num(double x) { return RoundToSignificant(x); }

Json Vec(const Eigen::Vector3d& v) { return Json::array({Num(v.x()), Num(v.y()), Num(v.z())}); }

}  // namespace

std::vector<FeatureReportEntry> RecogniseAssemblyFeatures(const Assembly& assembly) {
  std::vector<FeatureReportEntry> entries;
  for (const Part& part : assembly.parts()) {
    // Library parts come with their features; features-only parts have no faces to read.
    if (part.mesh_source.rfind("library:", 0) == 0 || !part.HasGeometry()) continue;
    if (part.mesh_source.find('#') != std::string::npos) {  // imported: from its exact faces
      FeatureReportEntry e{part.id, part.X_WP, MeshFeatures(), true};
      for (const Feature& f : part.features) {
        const bool teeth = f.kind == FeatureKind::kGear || f.kind == FeatureKind::kBevelGear ||
                           f.kind == FeatureKind::kWorm || f.kind == FeatureKind::kRack ||
                           f.kind == FeatureKind::kCycloidDisc;
        e.found.features.push_back({f, 0.0,
                                    teeth ? "from the solid's tessellation (see its note)"
                                          : "from the STEP file's exact faces"});
      }
      e.found.notes = part.notes;
      entries.push_back(std::move(e));
      continue;
    }
    FeatureReportEntry e{part.id, part.X_WP, RecognizeFeatures(*part.mesh), true};
    e.found.notes.insert(e.found.notes.end(), part.notes.begin(), part.notes.end());
    e.used = e.found.features.size() == part.features.size();
    for (std::size_t i = 0; e.used && i < part.features.size(); ++i) {
      e.used = part.features[i].id == e.found.features[i].feature.id &&
               part.features[i].kind == e.found.features[i].feature.kind;
    }
    entries.push_back(std::move(e));
  }
  return entries;
}

void WriteFeatureReport(const std::vector<FeatureReportEntry>& entries, std::ostream& out) {
  for (const FeatureReportEntry& e : entries) {
    out << e.part << ": ";
    if (e.found.axis) {
      const Eigen::Vector3d a = e.X_WP.RotateDirection(*e.found.axis);
      out << "prismatic along (" << FormatNumber(a.x()) << ", " << FormatNumber(a.y()) << ", "
          << FormatNumber(a.z()) << "), ";
    }
    out << e.found.features.size() << " feature" << (e.found.features.size() == 1 ? "" : "s")
        << " recognised" << (e.used ? "" : " (the file's own features are used)") << "\n";
    for (const RecognizedFeature& r : e.found.features) {
      out << "  " << DescribeFeature(r.feature, e.X_WP) << "; fit " << FormatNumber(r.fit_error, 3)
          << " mm: " << r.detail << "\n";
    }
    for (const std::string& note : e.found.notes) out << "  note: " << note << "\n";
  }
}

std::string FeatureJson(const std::vector<FeatureReportEntry>& entries) {
  Json report;
  report["parts"] = Json::array();
  for (const FeatureReportEntry& e : entries) {
    Json part = {
        {"part", e.part},
        {"axis", e.found.axis ? Vec(e.X_WP.RotateDirection(*e.found.axis)) : Json(nullptr)},
        {"used", e.used},
        {"features", Json::array()},
        {"notes", e.found.notes}};
    for (const RecognizedFeature& r : e.found.features) {
      const Feature& f = r.feature;
      Json j = {{"id", f.id},
                {"kind", std::string(ToString(f.kind))},
                {"origin", Vec(e.X_WP * f.origin)},
                {"axis", Vec(e.X_WP.RotateDirection(f.axis))},
                {"length", Num(f.length)}};
      if (f.kind == FeatureKind::kShaft || f.kind == FeatureKind::kHole)
        j["diameter"] = Num(f.diameter);
      if (f.kind == FeatureKind::kGear) {
        j["teeth"] = f.teeth;
        j["internal"] = f.internal;
        if (f.helix_angle != 0.0) j["helix_angle"] = Num(f.helix_angle * 180.0 / std::numbers::pi);
      }
      if (f.kind == FeatureKind::kBevelGear) {
        j["teeth"] = f.teeth;
        j["pitch_angle"] = Num(f.pitch_angle * 180.0 / std::numbers::pi);
        if (f.spiral_angle != 0.0) {
          j["spiral_angle"] = Num(f.spiral_angle * 180.0 / std::numbers::pi);
        }
      }
      if (f.kind == FeatureKind::kGear || f.kind == FeatureKind::kBevelGear ||
          f.kind == FeatureKind::kRack) {
        j["module"] = Num(f.module);
      }
      if (f.kind == FeatureKind::kRack) j["normal"] = Vec(e.X_WP.RotateDirection(f.normal));
      j["fit_error"] = Num(r.fit_error);
      j["detail"] = r.detail;
      part["features"].push_back(j);
    }
    report["parts"].push_back(part);
  }
  return report.dump(2) + "\n";
}

}  // namespace mechanist
