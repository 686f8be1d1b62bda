#include "io/adjusted_file_writer.h"

#include <Eigen/Geometry>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/input_error.h"
#include "io/internal/json_source.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

using Json = nlohmann::ordered_json;

double Num(double x) { return RoundToSignificant(x, 12); }

// A path written relative to `from` rewritten relative to `to` (absolute paths stay).
std::string Rebase(const std::string& path, const std::filesystem::path& from,
                   const std::filesystem::path& to) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || path.rfind("library:", 0) == 0) return path;
  const std::filesystem::path target = std::filesystem::absolute(from / p).lexically_normal();
  return target.lexically_relative(std::filesystem::absolute(to).lexically_normal())
      .generic_string();
}

// Writes `fastening: tight` for feature `id` into the part's entry: in the library
// parameters when the library part defines the feature (a bolt's or setscrew's thread), else
// in the feature's own entry, added (as for an imported part) when there is none.
void Tighten(Json* entry, const std::string& id) {
  const Json* library = entry->contains("library") ? &(*entry)["library"] : nullptr;
  if (library && library->is_object() && id == "thread" &&
      (library->value("kind", "") == "hex_bolt" || library->value("kind", "") == "setscrew")) {
    (*entry)["library"]["fastening"] = "tight";
    return;
  }
  if (!entry->contains("features")) (*entry)["features"] = Json::array();
  for (Json& f : (*entry)["features"]) {
    if (f.contains("id") && f["id"] == id) {
      f["fastening"] = "tight";
      return;
    }
  }
  (*entry)["features"].push_back(Json{{"id", id}, {"fastening", "tight"}});
}

}  // namespace

std::string AdjustedAssemblyText(const Assembly& original, const Assembly& adjusted,
                                 const std::filesystem::path& output) {
  const std::filesystem::path source(original.source());
  std::ifstream in(source, std::ios::binary);
  if (!in) throw InputError(source.string(), "", 0, 0, "cannot read the file");
  std::stringstream text;
  text << in.rdbuf();
  Json root = internal::ParseJson(text.str(), source.string()).root;
  const std::filesystem::path from = source.parent_path();
  const std::filesystem::path to = std::filesystem::absolute(output).parent_path();
  const double mm = original.units().mm_per_length;
  if (root.contains("import") && root["import"].is_string()) {
    root["import"] = Rebase(root["import"].get<std::string>(), from, to);
  }
  if (!root.contains("parts")) root["parts"] = Json::array();
  for (std::size_t p = 0; p < adjusted.parts().size(); ++p) {
    const Part& part = adjusted.part(p);
    Json* entry = nullptr;
    for (Json& e : root["parts"]) {
      if (e.contains("id") && e["id"] == part.id) entry = &e;
    }
    if (entry && entry->contains("mesh") && (*entry)["mesh"].is_string()) {
      (*entry)["mesh"] = Rebase((*entry)["mesh"].get<std::string>(), from, to);
    }
    for (std::size_t f = 0; f < part.features.size(); ++f) {
      if (part.features[f].fastening != original.part(p).features[f].fastening) {
        if (!entry) {
          root["parts"].push_back(Json{{"id", part.id}});
          entry = &root["parts"].back();
        }
        Tighten(entry, part.features[f].id);
      }
    }
    if (part.X_WP.IsNearlyEqualTo(original.part(p).X_WP, 0.0, 0.0)) continue;
    if (!entry) {  // an imported part: an entry with its id overrides it
      root["parts"].push_back(Json{{"id", part.id}});
      entry = &root["parts"].back();
    }
    const Eigen::Quaterniond q(part.X_WP.rotation());
    const Eigen::Vector3d t = part.X_WP.translation() / mm;
    entry->erase("place");
    (*entry)["pose"] = Json{{"position", {Num(t.x()), Num(t.y()), Num(t.z())}},
                            {"quaternion", {Num(q.w()), Num(q.x()), Num(q.y()), Num(q.z())}}};
  }
  if (root.contains("adjustments")) {
    for (std::size_t k = 0; k < adjusted.adjustments().size() && k < root["adjustments"].size();
         ++k) {
      const Adjustment& a = adjusted.adjustments()[k];
      const double unit = a.kind == Adjustment::Kind::kRotate ? original.units().rad_per_angle : mm;
      root["adjustments"][k]["range"] = {Num(a.lower / unit), Num(a.upper / unit)};
    }
  }
  return root.dump(2) + "\n";
}

}  // namespace mechanist
