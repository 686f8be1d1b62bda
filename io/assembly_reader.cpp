#include "io/assembly_reader.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <numeric>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/input_error.h"
#include "io/internal/json_source.h"
#include "io/internal/memory_budget.h"
#include "io/mesh_reader.h"
#include "io/step_reader.h"
#include "kernel/features/part_library.h"
#include "kernel/support/few_names.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

// ReadStep, once the memory it takes is known to be there.
std::vector<StepSolid> ImportStep(const std::filesystem::path& file,
                                  std::vector<StepMessage>* messages,
                                  const StepFileProgress& progress,
                                  std::vector<std::string>* length_units) {
  if (const auto shortfall = internal::MemoryShortfall(
          internal::ReadingNeed(file, internal::kStepBytesPerFileByte), "a STEP file")) {
    throw std::runtime_error(*shortfall);
  }
  if (!progress) return ReadStep(file, messages, {}, length_units);
  return ReadStep(
      file, messages, [&](double fraction) { progress(file, fraction); }, length_units);
}

using Json = nlohmann::ordered_json;
using internal::JoinPointer;
using internal::JsonSource;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxMagnitude = 1e12;  // of every number a file gives

std::string Describe(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case Json::value_t::string:
      return fmt::format("the string \"{}\"", v.get<std::string>());
    case Json::value_t::object:
      return "an object";
    case Json::value_t::array:
      return fmt::format("an array of {}", v.size());
    default: {
      std::ostringstream s;
      s.precision(17);
      if (v.is_number_integer()) {
        s << v.get<long long>();
      } else {
        s << v.get<double>();
      }
      return fmt::format("the number {}", s.str());
    }
  }
}

std::string JoinWords(std::initializer_list<std::string_view> words) {
  std::string joined;
  for (const std::string_view w : words) {
    if (!joined.empty()) joined += ", ";
    joined += w;
  }
  return joined;
}

/// Reads one file. Keeps the pointer of the value under inspection in every call so that an
/// error names it.
class Reader {
 public:
  Reader(JsonSource source, std::filesystem::path dir)
      : src_(std::move(source)), dir_(std::move(dir)) {}

  WrittenParts ReadParts(const StepFileProgress& progress) {
    progress_ = progress;
    const Json& root = src_.root;
    ExpectObject(root, "");
    CheckKeys(root, "",
              {"mechanist", "name", "units", "tolerance", "friction", "infer", "import", "parts",
               "drivers", "adjustments", "goals", "steps", "overrides", "expect"});
    const Json* version = Find(root, "mechanist");
    if (!version) Fail("", "expected the format version \"mechanist\": 1, found no such key");
    if (!version->is_number_integer() || version->get<long long>() != 1) {
      Fail("/mechanist", fmt::format("expected format version 1, found {}", Describe(*version)));
    }
    spec_.source = src_.file;
    if (const Json* name = Find(root, "name")) spec_.name = String(*name, "/name");
    if (const Json* units = Find(root, "units")) ReadUnits(*units, "/units");
    if (const Json* tol = Find(root, "tolerance")) ReadTolerance(*tol, "/tolerance");
    if (const Json* infer = Find(root, "infer")) ReadInference(*infer, "/infer");
    if (const Json* friction = Find(root, "friction")) {
      spec_.friction = Number(*friction, "/friction");
      if (spec_.friction < 0) {
        Fail("/friction",
             fmt::format("expected a friction coefficient >= 0, found {}", Describe(*friction)));
      }
    }
    const Json* import = Find(root, "import");
    const Json* parts = Find(root, "parts");
    if (import) {
      ReadImport(*import, "/import");
      if (parts) AddToImported(*parts, "/parts");
    } else {
      if (!parts) Fail("", "expected \"parts\" (an array of parts), found no such key");
      ReadParts(*parts, "/parts");
      for (std::size_t i = 0; i < parts->size(); ++i) placed_.emplace_back(i, &(*parts)[i]);
    }
    return {std::move(spec_), std::move(origins_)};
  }

  AssemblySpec ReadRelations(AssemblySpec spec) {
    spec_ = std::move(spec);
    const Json& root = src_.root;
    ReadPlacements(placed_);
    ForEach(root, "drivers", [this](const Json& v, const std::string& p) { ReadDriver(v, p); });
    ForEach(root, "adjustments",
            [this](const Json& v, const std::string& p) { ReadAdjustment(v, p); });
    ForEach(root, "goals", [this](const Json& v, const std::string& p) { ReadGoal(v, p); });
    ForEach(root, "steps", [this](const Json& v, const std::string& p) { ReadStep(v, p); });
    ForEach(root, "overrides", [this](const Json& v, const std::string& p) { ReadOverride(v, p); });
    ForEach(root, "expect", [this](const Json& v, const std::string& p) { ReadExpectation(v, p); });
    return std::move(spec_);
  }

  [[noreturn]] void FailAtPlacement(std::size_t part, const std::string& message) const {
    Fail(EntryOf(part) + "/place", message);
  }

 private:
  // ---- errors and basic values ----

  [[noreturn]] void Fail(const std::string& pointer, const std::string& message) const {
    const internal::JsonPosition at = src_.PositionOf(pointer);
    throw InputError(src_.file, pointer.empty() ? "/" : pointer, at.line, at.column, message);
  }

  static const Json* Find(const Json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  const Json& Require(const Json& object, const std::string& pointer, const char* key,
                      const char* what) const {
    const Json* v = Find(object, key);
    if (!v) Fail(pointer, fmt::format("expected \"{}\" ({}), found no such key", key, what));
    return *v;
  }

  void ExpectObject(const Json& v, const std::string& pointer) const {
    if (!v.is_object()) Fail(pointer, fmt::format("expected an object, found {}", Describe(v)));
  }

  void CheckKeys(const Json& object, const std::string& pointer,
                 std::initializer_list<std::string_view> allowed) const {
    for (const auto& [key, value] : object.items()) {
      if (key == "extra") continue;
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        Fail(JoinPointer(pointer, key),
             fmt::format("unknown key \"{}\" (expected one of: {}, extra)", key,
                         JoinWords(allowed)));
      }
    }
  }

  double Number(const Json& v, const std::string& pointer) const {
    if (!v.is_number()) Fail(pointer, fmt::format("expected a number, found {}", Describe(v)));
    const double x = v.get<double>();
    if (!std::isfinite(x)) {
      Fail(pointer, fmt::format("expected a finite number, found {}", Describe(v)));
    }
    // Beyond any assembly (a million km in mm), and far from where squares and sums overflow.
    if (std::abs(x) > kMaxMagnitude) {
      Fail(pointer,
           fmt::format("expected a number of magnitude at most 1e12, found {}", Describe(v)));
    }
    return x;
  }

  std::string String(const Json& v, const std::string& pointer) const {
    if (!v.is_string()) Fail(pointer, fmt::format("expected a string, found {}", Describe(v)));
    return v.get<std::string>();
  }

  bool Bool(const Json& v, const std::string& pointer) const {
    if (!v.is_boolean()) {
      Fail(pointer, fmt::format("expected true or false, found {}", Describe(v)));
    }
    return v.get<bool>();
  }

  int PositiveCount(const Json& v, const std::string& pointer) const {
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000) {
      Fail(pointer, fmt::format("expected a positive whole number, found {}", Describe(v)));
    }
    return static_cast<int>(v.get<long long>());
  }

  /// A positive length in file units, returned in mm.
  double PositiveLength(const Json& v, const std::string& pointer) const {
    const double x = Number(v, pointer);
    if (!(x > 0)) Fail(pointer, fmt::format("expected a positive length, found {}", Describe(v)));
    return x * spec_.units.mm_per_length;
  }

  double Length(const Json& v, const std::string& pointer) const {
    return Number(v, pointer) * spec_.units.mm_per_length;
  }

  double Angle(const Json& v, const std::string& pointer) const {
    return Number(v, pointer) * spec_.units.rad_per_angle;
  }

  Eigen::Vector3d Vec3(const Json& v, const std::string& pointer) const {
    if (!v.is_array() || v.size() != 3) {
      Fail(pointer, fmt::format("expected an array of 3 numbers, found {}", Describe(v)));
    }
    Eigen::Vector3d x;
    for (int i = 0; i < 3; ++i) x[i] = Number(v[i], JoinPointer(pointer, std::to_string(i)));
    return x;
  }

  Eigen::Vector3d Point(const Json& v, const std::string& pointer) const {
    return Vec3(v, pointer) * spec_.units.mm_per_length;
  }

  /// A direction, normalised. A zero vector is an error.
  Eigen::Vector3d Direction(const Json& v, const std::string& pointer) const {
    const Eigen::Vector3d d = Vec3(v, pointer);
    if (!(d.norm() > 1e-12)) Fail(pointer, "expected a non-zero direction, found [0, 0, 0]");
    return d.normalized();
  }

  std::string Choice(const Json& v, const std::string& pointer,
                     std::initializer_list<std::string_view> choices) const {
    if (v.is_string() &&
        std::find(choices.begin(), choices.end(), v.get<std::string>()) != choices.end()) {
      return v.get<std::string>();
    }
    Fail(pointer, fmt::format("expected one of {}, found {}", JoinWords(choices), Describe(v)));
  }

  Hand ReadHand(const Json& v, const std::string& pointer) const {
    return Choice(v, pointer, {"right", "left"}) == "right" ? Hand::kRight : Hand::kLeft;
  }

  Fastening ReadFastening(const Json& v, const std::string& pointer) const {
    return Choice(v, pointer, {"tight", "loose"}) == "tight" ? Fastening::kTight
                                                             : Fastening::kLoose;
  }

  std::size_t PartRef(const Json& v, const std::string& pointer) const {
    const std::string id = String(v, pointer);
    const auto it = part_index_.find(id);
    if (it == part_index_.end()) {
      Fail(pointer, fmt::format("expected a part id, found no part \"{}\"", id));
    }
    return it->second;
  }

  /// "part/feature", resolved against the parts read so far.
  FeatureRef Ref(const Json& v, const std::string& pointer) const {
    const std::string path = String(v, pointer);
    const std::size_t slash = path.find('/');
    if (slash == std::string::npos) {
      Fail(pointer, fmt::format("expected a feature as \"part/feature\", found \"{}\"", path));
    }
    const auto it = part_index_.find(path.substr(0, slash));
    if (it == part_index_.end()) {
      Fail(pointer,
           fmt::format("expected a feature as \"part/feature\", found \"{}\" (no part \"{}\")",
                       path, path.substr(0, slash)));
    }
    const auto feature = spec_.parts[it->second].FindFeature(path.substr(slash + 1));
    if (!feature) {
      Fail(pointer, fmt::format("expected a feature as \"part/feature\", found \"{}\" (part \"{}\" "
                                "has no feature \"{}\")",
                                path, it->first, path.substr(slash + 1)));
    }
    return {it->second, *feature};
  }

  std::array<FeatureRef, 2> RefPair(const Json& v, const std::string& pointer) const {
    if (!v.is_array() || v.size() != 2) {
      Fail(pointer, fmt::format("expected an array of two features, found {}", Describe(v)));
    }
    const FeatureRef a = Ref(v[0], pointer + "/0");
    const FeatureRef b = Ref(v[1], pointer + "/1");
    if (a.part == b.part) Fail(pointer, "expected features of two different parts");
    return {a, b};
  }

  void ForEach(const Json& root, const char* key,
               const std::function<void(const Json&, const std::string&)>& read) const {
    const Json* list = Find(root, key);
    if (!list) return;
    const std::string pointer = fmt::format("/{}", key);
    if (!list->is_array()) {
      Fail(pointer, fmt::format("expected an array, found {}", Describe(*list)));
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string p = JoinPointer(pointer, std::to_string(i));
      ExpectObject((*list)[i], p);
      read((*list)[i], p);
    }
  }

  // ---- top-level settings ----

  void ReadUnits(const Json& v, const std::string& pointer) {
    ExpectObject(v, pointer);
    CheckKeys(v, pointer, {"length", "angle"});
    if (const Json* length = Find(v, "length")) {
      static const std::map<std::string, double> kLengths = {
          {"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}};
      spec_.units.length = Choice(*length, pointer + "/length", {"mm", "cm", "m", "in"});
      spec_.units.mm_per_length = kLengths.at(spec_.units.length);
    }
    if (const Json* angle = Find(v, "angle")) {
      spec_.units.angle = Choice(*angle, pointer + "/angle", {"deg", "rad"});
      spec_.units.rad_per_angle = spec_.units.angle == "deg" ? kPi / 180.0 : 1.0;
    }
  }

  void ReadTolerance(const Json& v, const std::string& pointer) {
    ExpectObject(v, pointer);
    CheckKeys(v, pointer, {"length", "angle"});
    if (const Json* length = Find(v, "length")) {
      spec_.tolerance.length = PositiveLength(*length, pointer + "/length");
    }
    if (const Json* angle = Find(v, "angle")) {
      spec_.tolerance.angle = Angle(*angle, pointer + "/angle");
      if (!(spec_.tolerance.angle > 0)) {
        Fail(pointer + "/angle",
             fmt::format("expected a positive angle, found {}", Describe(*angle)));
      }
    }
  }

  void ReadInference(const Json& v, const std::string& pointer) {
    ExpectObject(v, pointer);
    CheckKeys(v, pointer,
              {"implied_pins", "implied_frame", "seated_parts", "embedded_parts", "centred_parts"});
    if (const Json* pins = Find(v, "implied_pins")) {
      spec_.inference.implied_pins = Bool(*pins, pointer + "/implied_pins");
    }
    if (const Json* frame = Find(v, "implied_frame")) {
      spec_.inference.implied_frame = Bool(*frame, pointer + "/implied_frame");
    }
    if (const Json* seated = Find(v, "seated_parts")) {
      spec_.inference.seated_parts = Bool(*seated, pointer + "/seated_parts");
    }
    if (const Json* embedded = Find(v, "embedded_parts")) {
      spec_.inference.embedded_parts = Bool(*embedded, pointer + "/embedded_parts");
    }
    if (const Json* centred = Find(v, "centred_parts")) {
      spec_.inference.centred_parts = Bool(*centred, pointer + "/centred_parts");
    }
  }

  // ---- parts ----

  void ReadParts(const Json& parts, const std::string& pointer) {
    if (!parts.is_array()) {
      Fail(pointer, fmt::format("expected an array of parts, found {}", Describe(parts)));
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      ReadPart(parts[i], JoinPointer(pointer, std::to_string(i)));
    }
  }

  // One part, appended to the spec.
  void ReadPart(const Json& v, const std::string& p) {
    static const std::regex kId("[A-Za-z0-9_.-]+");
    {
      ExpectObject(v, p);
      CheckKeys(
          v, p,
          {"id", "mesh", "library", "pose", "place", "ground", "group", "compliant", "features"});
      Part part;
      part.id = String(Require(v, p, "id", "the part's id"), p + "/id");
      if (!std::regex_match(part.id, kId)) {
        Fail(p + "/id",
             fmt::format("expected an id of letters, digits, '_', '.' and '-', found \"{}\"",
                         part.id));
      }
      if (part_index_.count(part.id)) {
        Fail(p + "/id", fmt::format("duplicate part id \"{}\" (first at /parts/{})", part.id,
                                    part_index_.at(part.id)));
      }
      const Json* mesh = Find(v, "mesh");
      const Json* library = Find(v, "library");
      if (mesh && library) Fail(p, "expected either \"mesh\" or \"library\", found both");
      std::vector<Feature> step_features;
      PartOrigin origin;
      if (mesh) {
        part.mesh_source = String(*mesh, p + "/mesh");
        if (IsStepFile(part.mesh_source)) {
          part.tessellated = true;
          part.mesh = LoadStepPart(part.mesh_source, p + "/mesh", &step_features, &part.notes,
                                   &origin.step_solids, &part.mesh_deviation, &part.mesh_angle);
        } else {
          part.mesh = LoadMesh(part.mesh_source, p + "/mesh");
        }
      } else if (library) {
        LibraryPart generated = MakeLibrary(*library, p + "/library");
        part.mesh_source = "library:" + String(library->at("kind"), p + "/library/kind");
        part.mesh = std::make_shared<const TriangleMesh>(std::move(generated.mesh));
        part.features = std::move(generated.features);
      }
      const Json* pose = Find(v, "pose");
      if (pose && Find(v, "place")) Fail(p, "expected either \"pose\" or \"place\", found both");
      if (pose) part.X_WP = ReadPose(*pose, p + "/pose");
      if (const Json* ground = Find(v, "ground")) part.ground = Bool(*ground, p + "/ground");
      if (const Json* group = Find(v, "group")) part.group = String(*group, p + "/group");
      if (const Json* compliant = Find(v, "compliant")) {
        part.compliant = Bool(*compliant, p + "/compliant");
      }
      if (const Json* features = Find(v, "features")) {
        ReadFeatures(*features, p + "/features", part);
        origin.step_solids.clear();
      } else if (mesh) {
        // The reasoning layer completes them from the geometry (CompleteFeatures).
        part.features = std::move(step_features);  // from the STEP file's exact faces
        origin.features_written = false;
      }
      origins_.push_back(std::move(origin));
      entry_of_.emplace(spec_.parts.size(), p);
      part_index_.emplace(part.id, spec_.parts.size());
      spec_.parts.push_back(std::move(part));
    }
  }

  // Every solid of the STEP file as a part, with the features of its exact faces.
  void ReadImport(const Json& v, const std::string& p) {
    const std::string relative = String(v, p);
    std::vector<StepSolid> solids;
    std::vector<StepMessage> messages;
    try {
      solids = ImportStep((dir_ / relative).lexically_normal(), &messages, progress_,
                          &AddStepUnits(relative));
    } catch (const std::exception& e) {
      Fail(p, fmt::format("cannot import \"{}\": {}", relative, e.what()));
    }
    AddStepMessages(relative, messages, solids);
    for (StepSolid& s : solids) {
      PartOrigin origin;
      origin.features_written = false;
      origin.imported = true;
      origin.step_solids.push_back(
          {s.mesh, RigidTransform(), "", s.features.size(), s.notes.size()});
      origins_.push_back(std::move(origin));
      Part part;
      part.id = s.path;
      part.mesh_source = fmt::format("{}#{}", relative, s.product);
      part.mesh = s.mesh;
      part.tessellated = true;
      part.mesh_deviation = s.mesh_deviation;
      part.mesh_angle = s.mesh_angle;
      part.X_WP = s.X_WP;
      part.group = s.path;
      part.body_of = s.body_of;
      part.features = std::move(s.features);
      part.notes = std::move(s.notes);
      part_index_.emplace(part.id, spec_.parts.size());
      spec_.parts.push_back(std::move(part));
    }
  }

  // Entries next to an import: an imported part's id adds `ground` and features to it (an
  // imported feature's id with `fastening` sets that); a new id adds a part, with a pose or a
  // placement by features (its own and the imported parts').
  void AddToImported(const Json& parts, const std::string& pointer) {
    if (!parts.is_array()) {
      Fail(pointer, fmt::format("expected an array of parts, found {}", Describe(parts)));
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const std::string p = JoinPointer(pointer, std::to_string(i));
      const Json& v = parts[i];
      ExpectObject(v, p);
      const std::string id = String(Require(v, p, "id", "a part's id"), p + "/id");
      const auto it = part_index_.find(id);
      if (it == part_index_.end()) {
        ReadPart(v, p);
        placed_.emplace_back(spec_.parts.size() - 1, &v);
        continue;
      }
      CheckKeys(v, p, {"id", "ground", "compliant", "features"});
      Part& part = spec_.parts[it->second];
      if (const Json* ground = Find(v, "ground")) part.ground = Bool(*ground, p + "/ground");
      if (const Json* compliant = Find(v, "compliant")) {
        part.compliant = Bool(*compliant, p + "/compliant");
      }
      const Json* features = Find(v, "features");
      if (!features) continue;
      if (!features->is_array()) {
        Fail(p + "/features",
             fmt::format("expected an array of features, found {}", Describe(*features)));
      }
      for (std::size_t k = 0; k < features->size(); ++k) {
        const std::string fp = JoinPointer(p + "/features", std::to_string(k));
        const Json& f = (*features)[k];
        ExpectObject(f, fp);
        const Json* fid = Find(f, "id");
        const auto existing =
            fid && fid->is_string() ? part.FindFeature(fid->get<std::string>()) : std::nullopt;
        if (!existing) {
          part.features.push_back(ReadFeature(f, fp));
          origins_[it->second].written.push_back(part.features.back().id);
          continue;
        }
        CheckKeys(f, fp, {"id", "fastening"});
        if (const Json* fastening = Find(f, "fastening")) {
          const std::string value = String(*fastening, fp + "/fastening");
          if (value != "tight" && value != "loose") {
            Fail(fp + "/fastening",
                 fmt::format("expected \"tight\" or \"loose\", found \"{}\"", value));
          }
          part.features[*existing].fastening =
              value == "tight" ? Fastening::kTight : Fastening::kLoose;
          origins_[it->second].written.push_back(part.features[*existing].id);
        }
      }
    }
  }

  // A warning `step_reader` about a STEP file read.
  void WarnAboutStep(std::string message) {
    spec_.findings.push_back({Severity::kWarning, "step_reader", std::move(message), {}, {}});
  }

  // The length units of the STEP file `relative` (as written), to be filled as it is read: a
  // file read twice is listed once.
  std::vector<std::string>& AddStepUnits(const std::string& relative) {
    for (StepFileUnits& u : spec_.step_units) {
      if (u.file == relative) {
        u.length.clear();
        return u.length;
      }
    }
    spec_.step_units.push_back({relative, {}});
    return spec_.step_units.back().length;
  }

  // Open CASCADE's messages on reading `relative` as findings `step_reader` (an error as a
  // warning, since the file was still read; a warning as info), repeats counted once. The
  // references to entities the file does not define are one warning, naming the first three;
  // in such a damaged file, the product instances that hold no solid are another; and the
  // `solids` read with no face (in any file) a third.
  void AddStepMessages(const std::string& relative, const std::vector<StepMessage>& messages,
                       const std::vector<StepSolid>& solids) {
    std::vector<std::pair<const StepMessage*, std::size_t>> unique;  // first of a text, count
    std::vector<std::string> no_solid;
    for (const StepMessage& m : messages) {
      if (m.no_solid) no_solid.push_back(m.text);
      if (m.undefined_reference || m.no_solid) continue;
      auto same = std::find_if(unique.begin(), unique.end(),
                               [&](const auto& u) { return u.first->text == m.text; });
      if (same == unique.end()) {
        unique.emplace_back(&m, 1);
      } else {
        ++same->second;
      }
    }
    const std::string undefined = UndefinedReferenceWords(messages);
    if (!undefined.empty()) {
      WarnAboutStep(fmt::format("{}: {}, and what uses them is missing from the parts read",
                                relative, undefined));
    }
    // In a damaged file, products without a solid are likely among what it lacks (a sound file
    // has them too: Fusion 360 writes a bearing's balls and inner ring into its outer ring).
    if (!undefined.empty() && !no_solid.empty()) {
      const bool one = no_solid.size() == 1;
      WarnAboutStep(fmt::format("{}: {} no solid ({} may be among what the file lacks): {}",
                                relative,
                                one ? "a product instance holds"
                                    : fmt::format("{} product instances hold", no_solid.size()),
                                one ? "its shape" : "their shapes", FewNames(no_solid)));
    }
    std::vector<std::string> faceless;
    for (const StepSolid& s : solids) {
      if (s.mesh->faces.empty()) faceless.push_back(s.path);
    }
    if (!faceless.empty()) {
      const bool one = faceless.size() == 1;
      WarnAboutStep(fmt::format(
          "{}: {} no face that could be read, so {} left without geometry: {}", relative,
          one ? "a solid has" : fmt::format("{} solids have", faceless.size()),
          one ? "it is" : "they are", FewNames(faceless)));
    }
    for (const auto& [m, count] : unique) {
      spec_.findings.push_back(
          {m->error ? Severity::kWarning : Severity::kInfo,
           "step_reader",
           fmt::format("{}: Open CASCADE's STEP reader: {}{}", relative, m->text,
                       count > 1 ? fmt::format(" ({} times)", count) : ""),
           {},
           {}});
    }
  }

  // A STEP file as one rigid part: its solids' meshes and features at their placements (ids
  // prefixed "solidN_" when it holds several solids), each solid in `in_part`, and the largest
  // of their meshes' deviations and angles in `deviation` and `angle`.
  std::shared_ptr<const TriangleMesh> LoadStepPart(const std::string& relative,
                                                   const std::string& pointer,
                                                   std::vector<Feature>* features,
                                                   std::vector<std::string>* notes,
                                                   std::vector<PartOrigin::StepSolid>* in_part,
                                                   double* deviation, double* angle) {
    std::vector<StepSolid> solids;
    std::vector<StepMessage> messages;
    try {
      solids = ImportStep((dir_ / relative).lexically_normal(), &messages, progress_,
                          &AddStepUnits(relative));
    } catch (const std::exception& e) {
      Fail(pointer, fmt::format("cannot use mesh \"{}\": {}", relative, e.what()));
    }
    AddStepMessages(relative, messages, solids);
    auto mesh = std::make_shared<TriangleMesh>();
    for (std::size_t k = 0; k < solids.size(); ++k) {
      const std::string prefix = solids.size() > 1 ? fmt::format("solid{}", k + 1) : "";
      TriangleMesh placed = *solids[k].mesh;
      for (Eigen::Vector3d& v : placed.vertices) v = solids[k].X_WP * v;
      mesh->Append(placed);
      *deviation = std::max(*deviation, solids[k].mesh_deviation);
      *angle = std::max(*angle, solids[k].mesh_angle);
      for (Feature f : solids[k].features) {
        if (!prefix.empty()) f.id = fmt::format("{}_{}", prefix, f.id);
        f.origin = solids[k].X_WP * f.origin;
        f.axis = solids[k].X_WP.RotateDirection(f.axis);
        f.normal = solids[k].X_WP.RotateDirection(f.normal);
        features->push_back(f);
      }
      for (const std::string& note : solids[k].notes) {
        notes->push_back(prefix.empty() ? note : fmt::format("{}: {}", prefix, note));
      }
      in_part->push_back({solids[k].mesh, solids[k].X_WP, prefix.empty() ? "" : prefix + "_",
                          features->size(), notes->size()});
    }
    return mesh;
  }

  std::shared_ptr<const TriangleMesh> LoadMesh(const std::string& relative,
                                               const std::string& pointer) {
    const std::filesystem::path path = (dir_ / relative).lexically_normal();
    if (auto it = mesh_cache_.find(path); it != mesh_cache_.end()) return it->second;
    TriangleMesh mesh;
    try {
      mesh = ReadMesh(path);
    } catch (const InputError& e) {
      Fail(pointer, fmt::format("cannot use mesh \"{}\": {}", relative, e.what()));
    }
    mesh.Scale(spec_.units.mm_per_length);
    auto shared = std::make_shared<const TriangleMesh>(std::move(mesh));
    mesh_cache_.emplace(path, shared);
    return shared;
  }

  RigidTransform ReadPose(const Json& v, const std::string& pointer) const {
    ExpectObject(v, pointer);
    CheckKeys(v, pointer, {"position", "rotation", "quaternion", "matrix"});
    if (const Json* m = Find(v, "matrix")) {
      if (v.size() - (Find(v, "extra") ? 1 : 0) != 1) {
        Fail(pointer, "expected \"matrix\" alone, found it with \"position\" or a rotation");
      }
      const std::string mp = pointer + "/matrix";
      if (!m->is_array() || m->size() != 4) {
        Fail(mp,
             fmt::format("expected a 4x4 matrix (4 rows of 4 numbers), found {}", Describe(*m)));
      }
      Eigen::Matrix4d matrix;
      for (int r = 0; r < 4; ++r) {
        const std::string rp = JoinPointer(mp, std::to_string(r));
        const Json& row = (*m)[r];
        if (!row.is_array() || row.size() != 4) {
          Fail(rp, fmt::format("expected a row of 4 numbers, found {}", Describe(row)));
        }
        for (int c = 0; c < 4; ++c)
          matrix(r, c) = Number(row[c], JoinPointer(rp, std::to_string(c)));
      }
      if ((matrix.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-12) {
        Fail(mp + "/3", "expected the last row [0, 0, 0, 1]");
      }
      const Eigen::Matrix3d R = matrix.topLeftCorner<3, 3>();
      CheckProper(R, mp);
      return RigidTransform(R, matrix.topRightCorner<3, 1>() * spec_.units.mm_per_length);
    }
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    if (const Json* position = Find(v, "position")) p = Point(*position, pointer + "/position");
    const Json* rotation = Find(v, "rotation");
    const Json* quaternion = Find(v, "quaternion");
    if (rotation && quaternion) {
      Fail(pointer, "expected either \"rotation\" or \"quaternion\", found both");
    }
    if (rotation) {
      const std::string rp = pointer + "/rotation";
      ExpectObject(*rotation, rp);
      CheckKeys(*rotation, rp, {"axis", "angle"});
      const Eigen::Vector3d axis =
          Direction(Require(*rotation, rp, "axis", "a direction"), rp + "/axis");
      const double angle = Angle(Require(*rotation, rp, "angle", "an angle"), rp + "/angle");
      return RigidTransform::Translation(p) * RigidTransform::AxisAngle(axis, angle);
    }
    if (quaternion) {
      const std::string qp = pointer + "/quaternion";
      if (!quaternion->is_array() || quaternion->size() != 4) {
        Fail(qp, fmt::format("expected [w, x, y, z], found {}", Describe(*quaternion)));
      }
      double q[4];
      for (int i = 0; i < 4; ++i)
        q[i] = Number((*quaternion)[i], JoinPointer(qp, std::to_string(i)));
      const Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
      if (!(quat.norm() > 1e-12)) Fail(qp, "expected a non-zero quaternion, found [0, 0, 0, 0]");
      return RigidTransform::FromQuaternion(quat, p);
    }
    return RigidTransform::Translation(p);
  }

  void CheckProper(const Eigen::Matrix3d& R, const std::string& pointer) const {
    if (RigidTransform::IsProperRotation(R)) return;
    std::ostringstream found;
    found.precision(6);
    found << "determinant " << R.determinant() << ", |R^T R - I| = "
          << (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    Fail(pointer, fmt::format("expected a proper rotation (orthonormal within 1e-6, determinant "
                              "+1), found {}",
                              found.str()));
  }

  // ---- features ----

  void ReadFeatures(const Json& features, const std::string& pointer, Part& part) const {
    if (!features.is_array()) {
      Fail(pointer, fmt::format("expected an array of features, found {}", Describe(features)));
    }
    for (std::size_t i = 0; i < features.size(); ++i) {
      const std::string p = JoinPointer(pointer, std::to_string(i));
      Feature f = ReadFeature(features[i], p);
      if (part.FindFeature(f.id)) {
        Fail(p + "/id", fmt::format("duplicate feature id \"{}\" in part \"{}\"{}", f.id, part.id,
                                    part.mesh_source.rfind("library:", 0) == 0
                                        ? " (the library part defines it)"
                                        : ""));
      }
      part.features.push_back(std::move(f));
    }
  }

  Feature ReadFeature(const Json& v, const std::string& p) const {
    ExpectObject(v, p);
    Feature f;
    f.id = String(Require(v, p, "id", "the feature's id"), p + "/id");
    if (f.id.empty() || f.id.find('/') != std::string::npos) {
      Fail(p + "/id", fmt::format("expected a non-empty id without '/', found \"{}\"", f.id));
    }
    const Json& kind = Require(v, p, "kind", "the feature's kind");
    const auto parsed = ParseFeatureKind(kind.is_string() ? kind.get<std::string>() : "");
    if (!parsed) {
      Fail(p + "/kind",
           fmt::format("expected one of {}, found {}", FeatureKindNames(), Describe(kind)));
    }
    f.kind = *parsed;
    const bool point_feature = f.kind == FeatureKind::kBall || f.kind == FeatureKind::kSocket;
    f.origin = Point(Require(v, p, "origin", "a point"), p + "/origin");
    if (const Json* axis = Find(v, "axis")) {
      f.axis = Direction(*axis, p + "/axis");
    } else if (!point_feature) {
      Fail(p, "expected \"axis\" (a direction), found no such key");
    }

    auto length = [&](const char* key) {
      return PositiveLength(Require(v, p, key, "a positive length"), p + "/" + key);
    };
    auto count = [&](const char* key) {
      return PositiveCount(Require(v, p, key, "a positive whole number"), p + "/" + key);
    };
    auto opt = [&](const char* key) { return Find(v, key); };
    auto normal = [&] {
      const Eigen::Vector3d n = Direction(Require(v, p, "normal", "a direction"), p + "/normal");
      if (std::abs(n.dot(f.axis)) > std::sin(spec_.tolerance.angle)) {
        Fail(p + "/normal",
             fmt::format(
                 "expected a normal perpendicular to the axis, found one at {} degrees to it",
                 std::to_string(std::acos(std::clamp(n.dot(f.axis), -1.0, 1.0)) * 180.0 / kPi)));
      }
      return Eigen::Vector3d((n - n.dot(f.axis) * f.axis).normalized());
    };
    switch (f.kind) {
      case FeatureKind::kShaft:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "diameter", "length", "retained"});
        f.diameter = length("diameter");
        f.length = length("length");
        if (const Json* r = opt("retained")) f.retained = Bool(*r, p + "/retained");
        break;
      case FeatureKind::kHole:
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "diameter", "length", "through", "retained"});
        f.diameter = length("diameter");
        f.length = length("length");
        if (const Json* t = opt("through")) f.through = Bool(*t, p + "/through");
        if (const Json* r = opt("retained")) f.retained = Bool(*r, p + "/retained");
        break;
      case FeatureKind::kThread:
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "diameter", "pitch", "length", "starts", "hand",
                   "fastening"});
        f.diameter = length("diameter");
        f.pitch = length("pitch");
        f.length = length("length");
        if (const Json* s = opt("starts")) f.starts = PositiveCount(*s, p + "/starts");
        if (const Json* h = opt("hand")) f.hand = ReadHand(*h, p + "/hand");
        if (const Json* x = opt("fastening")) f.fastening = ReadFastening(*x, p + "/fastening");
        break;
      case FeatureKind::kTappedHole:
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "diameter", "pitch", "length", "through",
                   "starts", "hand"});
        f.diameter = length("diameter");
        f.pitch = length("pitch");
        f.length = length("length");
        if (const Json* t = opt("through")) f.through = Bool(*t, p + "/through");
        if (const Json* s = opt("starts")) f.starts = PositiveCount(*s, p + "/starts");
        if (const Json* h = opt("hand")) f.hand = ReadHand(*h, p + "/hand");
        break;
      case FeatureKind::kSlot:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "width", "length", "depth", "normal"});
        f.width = length("width");
        f.length = length("length");
        if (const Json* d = opt("depth")) f.depth = PositiveLength(*d, p + "/depth");
        f.normal = normal();
        break;
      case FeatureKind::kKey:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "width", "length", "normal"});
        f.width = length("width");
        f.length = length("length");
        f.normal = normal();
        break;
      case FeatureKind::kGear:
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "teeth", "module", "length", "internal",
                   "helix_angle"});
        f.teeth = count("teeth");
        f.module = length("module");
        f.length = length("length");
        if (const Json* i = opt("internal")) f.internal = Bool(*i, p + "/internal");
        if (const Json* h = opt("helix_angle")) {
          f.helix_angle = Angle(*h, p + "/helix_angle");
          if (!(std::abs(f.helix_angle) < kPi / 2)) {
            Fail(p + "/helix_angle",
                 fmt::format("expected an angle between -90 and 90 degrees, found {}",
                             Describe(*h)));
          }
        }
        break;
      case FeatureKind::kBevelGear: {
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "teeth", "module", "pitch_angle", "length",
                   "spiral_angle"});
        f.teeth = count("teeth");
        f.module = length("module");
        const Json& pitch_angle = Require(v, p, "pitch_angle", "an angle");
        f.pitch_angle = Angle(pitch_angle, p + "/pitch_angle");
        if (!(f.pitch_angle > 0 && f.pitch_angle <= kPi / 2)) {
          Fail(p + "/pitch_angle",
               fmt::format("expected a pitch cone half-angle above 0 and at most 90 degrees, "
                           "found {}",
                           Describe(pitch_angle)));
        }
        f.length = length("length");
        if (!(f.length < f.OuterConeDistance())) {
          Fail(p + "/length",
               fmt::format("expected a face width shorter than the outer cone distance {} = "
                           "module x teeth / (2 sin(pitch_angle)), found {}",
                           FormatNumber(f.OuterConeDistance() / spec_.units.mm_per_length),
                           Describe(*Find(v, "length"))));
        }
        if (const Json* s = opt("spiral_angle")) {
          f.spiral_angle = Angle(*s, p + "/spiral_angle");
          if (!(std::abs(f.spiral_angle) < kPi / 2)) {
            Fail(p + "/spiral_angle",
                 fmt::format("expected an angle between -90 and 90 degrees, found {}",
                             Describe(*s)));
          }
        }
        break;
      }
      case FeatureKind::kWorm:
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "starts", "module", "pitch_diameter", "length",
                   "hand"});
        if (const Json* s = opt("starts")) f.starts = PositiveCount(*s, p + "/starts");
        f.module = length("module");
        f.pitch_diameter = length("pitch_diameter");
        f.length = length("length");
        if (const Json* h = opt("hand")) f.hand = ReadHand(*h, p + "/hand");
        break;
      case FeatureKind::kWormWheel:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "teeth", "module", "length"});
        f.teeth = count("teeth");
        f.module = length("module");
        f.length = length("length");
        break;
      case FeatureKind::kRack:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "module", "length", "normal"});
        f.module = length("module");
        f.length = length("length");
        f.normal = normal();
        break;
      case FeatureKind::kBall:
      case FeatureKind::kSocket:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "diameter"});
        f.diameter = length("diameter");
        break;
      case FeatureKind::kCycloidDisc:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "lobes", "eccentricity", "length"});
        f.teeth = count("lobes");
        f.eccentricity = length("eccentricity");
        f.length = length("length");
        break;
      case FeatureKind::kPinRing:
        CheckKeys(v, p,
                  {"id", "kind", "origin", "axis", "pins", "diameter", "pin_diameter", "length"});
        f.teeth = count("pins");
        f.diameter = length("diameter");
        f.pin_diameter = length("pin_diameter");
        f.length = length("length");
        break;
      case FeatureKind::kFace:
        CheckKeys(v, p, {"id", "kind", "origin", "axis", "width", "height"});
        if (const Json* w = opt("width")) f.width = PositiveLength(*w, p + "/width");
        if (const Json* h = opt("height")) f.height = PositiveLength(*h, p + "/height");
        break;
    }
    return f;
  }

  // ---- library parts ----

  LibraryPart MakeLibrary(const Json& v, const std::string& p) const {
    ExpectObject(v, p);
    const std::string kind = String(Require(v, p, "kind", "a library part kind"), p + "/kind");
    auto len = [&](const char* key, double& field) {
      if (const Json* x = Find(v, key)) field = PositiveLength(*x, p + "/" + key);
    };
    auto req = [&](const char* key, double& field) {
      field = PositiveLength(Require(v, p, key, "a positive length"), p + "/" + key);
    };
    auto cnt = [&](const char* key, int& field, bool required) {
      if (const Json* x =
              required ? &Require(v, p, key, "a positive whole number") : Find(v, key)) {
        field = PositiveCount(*x, p + "/" + key);
      }
    };
    auto hand = [&](Hand& field) {
      if (const Json* x = Find(v, "hand")) field = ReadHand(*x, p + "/hand");
    };
    auto fastening = [&](Fastening& field) {
      if (const Json* x = Find(v, "fastening")) field = ReadFastening(*x, p + "/fastening");
    };
    auto pressure = [&](double& field) {
      if (const Json* x = Find(v, "pressure_angle")) {
        field = Angle(*x, p + "/pressure_angle");
        if (!(field > 0 && field < kPi / 4)) {
          Fail(p + "/pressure_angle",
               fmt::format("expected an angle between 0 and 45 degrees, found {}", Describe(*x)));
        }
      }
    };
    auto holes = [&](const char* key) {
      std::vector<LibraryHole> result;
      const Json* list = Find(v, key);
      if (!list) return result;
      const std::string lp = p + "/" + key;
      if (!list->is_array()) {
        Fail(lp, fmt::format("expected an array of holes, found {}", Describe(*list)));
      }
      for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string hp = JoinPointer(lp, std::to_string(i));
        const Json& h = (*list)[i];
        ExpectObject(h, hp);
        CheckKeys(h, hp, {"id", "at", "diameter"});
        LibraryHole hole;
        if (const Json* id = Find(h, "id")) hole.id = String(*id, hp + "/id");
        const Json& at = Require(h, hp, "at", "[x, y]");
        if (!at.is_array() || at.size() != 2) {
          Fail(hp + "/at", fmt::format("expected [x, y], found {}", Describe(at)));
        }
        hole.center = Eigen::Vector2d(Length(at[0], hp + "/at/0"), Length(at[1], hp + "/at/1"));
        hole.diameter =
            PositiveLength(Require(h, hp, "diameter", "a positive length"), hp + "/diameter");
        result.push_back(hole);
      }
      return result;
    };
    LibrarySpec spec;
    if (kind == "plate") {
      CheckKeys(v, p, {"kind", "length", "width", "thickness", "holes", "segments"});
      PlateSpec s;
      req("length", s.length), req("width", s.width), req("thickness", s.thickness);
      s.holes = holes("holes");
      cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "l_bracket") {
      CheckKeys(v, p,
                {"kind", "length", "height", "width", "thickness", "base_holes", "upright_holes",
                 "segments"});
      LBracketSpec s;
      req("length", s.length), req("height", s.height), req("width", s.width);
      req("thickness", s.thickness);
      s.base_holes = holes("base_holes");
      s.upright_holes = holes("upright_holes");
      cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "hex_bolt") {
      CheckKeys(v, p,
                {"kind", "diameter", "pitch", "length", "thread_length", "across_flats",
                 "head_height", "hand", "fastening", "segments"});
      HexBoltSpec s;
      req("diameter", s.diameter), len("pitch", s.pitch), req("length", s.length);
      len("thread_length", s.thread_length), len("across_flats", s.across_flats);
      len("head_height", s.head_height);
      hand(s.hand), fastening(s.fastening), cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "hex_nut") {
      CheckKeys(v, p,
                {"kind", "diameter", "pitch", "across_flats", "thickness", "hand", "segments"});
      HexNutSpec s;
      req("diameter", s.diameter), len("pitch", s.pitch), len("across_flats", s.across_flats);
      len("thickness", s.thickness), hand(s.hand), cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "washer") {
      CheckKeys(v, p, {"kind", "inner_diameter", "outer_diameter", "thickness", "segments"});
      WasherSpec s;
      req("inner_diameter", s.inner_diameter), req("outer_diameter", s.outer_diameter);
      req("thickness", s.thickness), cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "setscrew") {
      CheckKeys(v, p, {"kind", "diameter", "pitch", "length", "hand", "fastening", "segments"});
      SetscrewSpec s;
      req("diameter", s.diameter), len("pitch", s.pitch), req("length", s.length);
      hand(s.hand), fastening(s.fastening), cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "shaft") {
      CheckKeys(v, p, {"kind", "diameter", "length", "retained", "segments"});
      ShaftSpec s;
      req("diameter", s.diameter), req("length", s.length);
      if (const Json* r = Find(v, "retained")) s.retained = Bool(*r, p + "/retained");
      cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "spur_gear") {
      CheckKeys(v, p,
                {"kind", "teeth", "module", "face_width", "bore_diameter", "pressure_angle",
                 "segments", "helix_angle"});
      SpurGearSpec s;
      cnt("teeth", s.teeth, true), req("module", s.module), req("face_width", s.face_width);
      len("bore_diameter", s.bore_diameter), pressure(s.pressure_angle);
      cnt("segments", s.segments, false);
      if (const Json* h = Find(v, "helix_angle")) {
        s.helix_angle = Angle(*h, p + "/helix_angle");
        if (!(std::abs(s.helix_angle) < kPi / 3)) {
          Fail(p + "/helix_angle",
               fmt::format("expected an angle between -60 and 60 degrees, found {}", Describe(*h)));
        }
      }
      spec = s;
    } else if (kind == "ring_gear") {
      CheckKeys(v, p,
                {"kind", "teeth", "module", "face_width", "outer_diameter", "pressure_angle",
                 "segments"});
      RingGearSpec s;
      cnt("teeth", s.teeth, true), req("module", s.module), req("face_width", s.face_width);
      req("outer_diameter", s.outer_diameter), pressure(s.pressure_angle);
      cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "worm") {
      CheckKeys(v, p,
                {"kind", "starts", "module", "pitch_diameter", "length", "bore_diameter", "hand",
                 "segments"});
      WormSpec s;
      cnt("starts", s.starts, false), req("module", s.module);
      req("pitch_diameter", s.pitch_diameter), req("length", s.length);
      len("bore_diameter", s.bore_diameter), hand(s.hand), cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "worm_wheel") {
      CheckKeys(v, p, {"kind", "teeth", "module", "face_width", "bore_diameter", "segments"});
      WormWheelSpec s;
      cnt("teeth", s.teeth, true), req("module", s.module), req("face_width", s.face_width);
      len("bore_diameter", s.bore_diameter), cnt("segments", s.segments, false);
      spec = s;
    } else if (kind == "rack") {
      CheckKeys(v, p, {"kind", "module", "length", "face_width", "height", "pressure_angle"});
      RackSpec s;
      req("module", s.module), req("length", s.length), req("face_width", s.face_width);
      len("height", s.height), pressure(s.pressure_angle);
      spec = s;
    } else {
      Fail(p + "/kind",
           fmt::format(
               "expected one of plate, l_bracket, hex_bolt, hex_nut, washer, setscrew, shaft, "
               "spur_gear, ring_gear, worm, worm_wheel, rack, found \"{}\"",
               kind));
    }
    try {
      return MakeLibraryPart(spec);
    } catch (const std::invalid_argument& e) {
      Fail(p, e.what());
    }
  }

  // ---- placements ----

  /// Where a part's entry is in the file: its JSON pointer, for messages about its `place`.
  std::string EntryOf(std::size_t part) const {
    const auto it = entry_of_.find(part);
    return it == entry_of_.end() ? "/parts" : it->second;
  }

  /// The `place` of the parts read from the entries in `entries` (part index -> its entry);
  /// the reasoning layer solves them (ResolvePlacements).
  void ReadPlacements(const std::vector<std::pair<std::size_t, const Json*>>& entries) {
    for (const auto& [i, entry] : entries) {
      const Json* place = Find(*entry, "place");
      if (!place) continue;
      const std::string p = EntryOf(i) + "/place";
      Part& part = spec_.parts[i];
      if (place->is_object()) {
        part.placement.push_back(ReadCondition(*place, p, i));
      } else if (place->is_array() && !place->empty()) {
        for (std::size_t k = 0; k < place->size(); ++k) {
          const std::string cp = JoinPointer(p, std::to_string(k));
          ExpectObject((*place)[k], cp);
          part.placement.push_back(ReadCondition((*place)[k], cp, i));
        }
      } else {
        Fail(p, fmt::format("expected a placement condition or a non-empty array of them, found {}",
                            Describe(*place)));
      }
    }
    CheckPlacementTree();
  }

  PlacementCondition ReadCondition(const Json& v, const std::string& p, std::size_t part) const {
    PlacementCondition c;
    const char* own_key = nullptr;
    const char* target_key = nullptr;
    if (Find(v, "insert")) {
      CheckKeys(v, p, {"insert", "into", "depth", "angle"});
      c.kind = PlacementCondition::Kind::kInsert;
      own_key = "insert", target_key = "into";
      if (const Json* d = Find(v, "depth")) c.depth = Length(*d, p + "/depth");
      if (const Json* a = Find(v, "angle")) c.angle = Angle(*a, p + "/angle");
    } else if (Find(v, "mesh")) {
      CheckKeys(v, p, {"mesh", "with", "angle"});
      c.kind = PlacementCondition::Kind::kMesh;
      own_key = "mesh", target_key = "with";
      if (const Json* a = Find(v, "angle")) c.angle = Angle(*a, p + "/angle");
    } else if (Find(v, "against")) {
      CheckKeys(v, p, {"against", "on"});
      c.kind = PlacementCondition::Kind::kAgainst;
      own_key = "against", target_key = "on";
    } else {
      Fail(p, "expected a condition with \"insert\", \"mesh\" or \"against\", found none");
    }
    const FeatureRef own = Ref(v[own_key], p + "/" + own_key);
    if (own.part != part) {
      Fail(p + "/" + own_key,
           fmt::format("expected a feature of the placed part \"{}\", found one of \"{}\"",
                       spec_.parts[part].id, spec_.parts[own.part].id));
    }
    c.feature = own.feature;
    c.target = Ref(Require(v, p, target_key, "a feature \"part/feature\""), p + "/" + target_key);
    if (c.target.part == part) Fail(p + "/" + target_key, "expected a feature of another part");
    return c;
  }

  /// Placements must form a tree rooted at parts with poses: no cycles.
  void CheckPlacementTree() const {
    enum class Mark { kNone, kVisiting, kDone };
    std::vector<Mark> marks(spec_.parts.size(), Mark::kNone);
    std::function<void(std::size_t)> visit = [&](std::size_t i) {
      if (marks[i] == Mark::kDone) return;
      if (marks[i] == Mark::kVisiting) {
        Fail(EntryOf(i) + "/place",
             fmt::format("placement of part \"{}\" depends on itself through a cycle of placements",
                         spec_.parts[i].id));
      }
      marks[i] = Mark::kVisiting;
      for (const PlacementCondition& c : spec_.parts[i].placement) visit(c.target.part);
      marks[i] = Mark::kDone;
    };
    for (std::size_t i = 0; i < spec_.parts.size(); ++i) visit(i);
  }

  // ---- drivers, adjustments, goals, steps, overrides ----

  void ReadDriver(const Json& v, const std::string& p) {
    CheckKeys(v, p, {"id", "part", "feature", "relative_to", "motion", "rate", "amount"});
    Driver d;
    const std::size_t part = PartRef(Require(v, p, "part", "a part id"), p + "/part");
    const std::string feature =
        String(Require(v, p, "feature", "a feature id of the part"), p + "/feature");
    const auto index = spec_.parts[part].FindFeature(feature);
    if (!index) {
      Fail(p + "/feature", fmt::format("expected a feature of part \"{}\", found \"{}\"",
                                       spec_.parts[part].id, feature));
    }
    d.feature = {part, *index};
    d.id = Find(v, "id") ? String(v["id"], p + "/id")
                         : fmt::format("{}/{}", spec_.parts[part].id, feature);
    for (const Driver& other : spec_.drivers) {
      if (other.id == d.id) Fail(p + "/id", fmt::format("duplicate driver id \"{}\"", d.id));
    }
    if (const Json* r = Find(v, "relative_to")) {
      d.relative_to = PartRef(*r, p + "/relative_to");
      if (*d.relative_to == part) {
        Fail(p + "/relative_to", "expected a part other than the driven part");
      }
    }
    if (const Json* m = Find(v, "motion")) {
      d.motion = Choice(*m, p + "/motion", {"rotation", "translation"}) == "rotation"
                     ? Driver::Motion::kRotation
                     : Driver::Motion::kTranslation;
    }
    const bool translation = d.motion == Driver::Motion::kTranslation;
    const double scale = translation ? spec_.units.mm_per_length : 1.0;
    if (const Json* r = Find(v, "rate")) {
      d.rate = Number(*r, p + "/rate") * scale;  // 0 holds the driver's freedom still
    } else {
      d.rate = scale;
    }
    if (const Json* a = Find(v, "amount")) {
      d.amount = Number(*a, p + "/amount") * scale;
      if (!(d.amount > 0)) {
        Fail(p + "/amount", fmt::format("expected a positive amount, found {}", Describe(*a)));
      }
    } else {
      d.amount = scale;
    }
    spec_.drivers.push_back(d);
  }

  void ReadAdjustment(const Json& v, const std::string& p) {
    CheckKeys(v, p, {"id", "moves", "rotate_about", "translate_along", "range"});
    Adjustment a;
    a.id = String(Require(v, p, "id", "the adjustment's id"), p + "/id");
    for (const Adjustment& other : spec_.adjustments) {
      if (other.id == a.id) Fail(p + "/id", fmt::format("duplicate adjustment id \"{}\"", a.id));
    }
    a.moves = PartRef(Require(v, p, "moves", "a part id"), p + "/moves");
    const Json* rotate = Find(v, "rotate_about");
    const Json* translate = Find(v, "translate_along");
    if (rotate && translate) {
      Fail(p, "expected either \"rotate_about\" or \"translate_along\", found both");
    }
    if (!rotate && !translate) {
      Fail(p, "expected \"rotate_about\" or \"translate_along\" (a feature), found neither");
    }
    a.kind = rotate ? Adjustment::Kind::kRotate : Adjustment::Kind::kTranslate;
    a.axis =
        Ref(rotate ? *rotate : *translate, p + (rotate ? "/rotate_about" : "/translate_along"));
    const Json& range = Require(v, p, "range", "[lower, upper]");
    if (!range.is_array() || range.size() != 2) {
      Fail(p + "/range", fmt::format("expected [lower, upper], found {}", Describe(range)));
    }
    auto bound = [&](int i) {
      const std::string bp = fmt::format("{}/range/{}", p, i);
      return rotate ? Angle(range[i], bp) : Length(range[i], bp);
    };
    a.lower = bound(0);
    a.upper = bound(1);
    if (a.lower > a.upper) {
      Fail(p + "/range", fmt::format("expected lower <= upper, found {} > {}", Describe(range[0]),
                                     Describe(range[1])));
    }
    spec_.adjustments.push_back(a);
  }

  void ReadGoal(const Json& v, const std::string& p) {
    CheckKeys(v, p, {"mesh", "coaxial"});
    Goal g;
    if (const Json* mesh = Find(v, "mesh")) {
      g.kind = Goal::Kind::kMesh;
      g.features = RefPair(*mesh, p + "/mesh");
    } else if (const Json* coaxial = Find(v, "coaxial")) {
      g.kind = Goal::Kind::kCoaxial;
      g.features = RefPair(*coaxial, p + "/coaxial");
    } else {
      Fail(p, "expected \"mesh\" or \"coaxial\" (two features), found neither");
    }
    if (Find(v, "mesh") && Find(v, "coaxial")) {
      Fail(p, "expected one of \"mesh\" or \"coaxial\", found both");
    }
    const std::string fp = p + (g.kind == Goal::Kind::kMesh ? "/mesh" : "/coaxial");
    if (g.features[0].part == g.features[1].part) {
      Fail(fp, "expected features of two different parts, found one part");
    }
    const FeatureKind k0 = spec_.parts[g.features[0].part].features[g.features[0].feature].kind;
    const FeatureKind k1 = spec_.parts[g.features[1].part].features[g.features[1].feature].kind;
    auto either = [&](FeatureKind x, FeatureKind y) {
      return (k0 == x && k1 == y) || (k0 == y && k1 == x);
    };
    if (g.kind == Goal::Kind::kMesh && !(either(FeatureKind::kGear, FeatureKind::kGear) ||
                                         either(FeatureKind::kBevelGear, FeatureKind::kBevelGear) ||
                                         either(FeatureKind::kWorm, FeatureKind::kWormWheel) ||
                                         either(FeatureKind::kGear, FeatureKind::kRack))) {
      Fail(fp, fmt::format("expected two features that mesh (gear and gear, bevel_gear and "
                           "bevel_gear, worm and worm_wheel, gear and rack), found {} and {}",
                           ToString(k0), ToString(k1)));
    }
    if (g.kind == Goal::Kind::kCoaxial && (k0 == FeatureKind::kFace || k1 == FeatureKind::kFace)) {
      Fail(fp, "expected two features with axes, found a face");
    }
    spec_.goals.push_back(g);
  }

  void ReadStep(const Json& v, const std::string& p) {
    CheckKeys(v, p, {"insert", "into"});
    AssemblyStep s;
    s.insert = Ref(Require(v, p, "insert", "a feature \"part/feature\""), p + "/insert");
    s.into = Ref(Require(v, p, "into", "a feature \"part/feature\""), p + "/into");
    if (s.insert.part == s.into.part) Fail(p + "/into", "expected a feature of another part");
    spec_.steps.push_back(s);
  }

  void ReadOverride(const Json& v, const std::string& p) {
    CheckKeys(v, p, {"pair", "type", "lead"});
    PairOverride o;
    o.features = RefPair(Require(v, p, "pair", "two features"), p + "/pair");
    const Json& type = Require(v, p, "type", "a pair type or \"none\"");
    o.type = PairTypeOrNone(type, p + "/type");
    const auto kind = [&](int i) {
      return spec_.parts[o.features[i].part].features[o.features[i].feature].kind;
    };
    if (const Json* lead = Find(v, "lead")) {
      if (o.type != PairType::kScrew) {
        Fail(p + "/lead",
             fmt::format("expected \"lead\" only with type \"screw\", found type \"{}\"",
                         o.type ? ToString(*o.type) : std::string_view("none")));
      }
      o.lead = Length(*lead, p + "/lead");
      if (*o.lead == 0.0) {
        Fail(p + "/lead", "expected a nonzero length (negative for a left-hand thread), found 0");
      }
    } else if (o.type == PairType::kScrew && kind(0) != FeatureKind::kThread &&
               kind(1) != FeatureKind::kThread) {
      // A screw pair between plain features (a lead screw whose thread the file leaves out)
      // has no lead to take from a thread.
      Fail(p, fmt::format("expected \"lead\" (the length one turn advances) for a screw pair "
                          "without a thread, found {} and {}",
                          ToString(kind(0)), ToString(kind(1))));
    }
    spec_.overrides.push_back(o);
  }

  std::optional<PairType> PairTypeOrNone(const Json& type, const std::string& p) const {
    const std::string name = type.is_string() ? type.get<std::string>() : "";
    if (name == "none") return std::nullopt;
    const auto parsed = ParsePairType(name);
    if (!parsed) {
      Fail(p, fmt::format("expected one of {}, none, found {}", PairTypeNames(), Describe(type)));
    }
    return parsed;
  }

  // ---- expectations ----

  void ReadExpectation(const Json& v, const std::string& p) {
    Expectation e;
    e.pointer = p;
    if (const Json* ratio = Find(v, "ratio")) {
      CheckKeys(v, p, {"part", "feature", "ratio"});
      e.kind = Expectation::Kind::kRatio;
      e.part = PartRef(Require(v, p, "part", "a part id"), p + "/part");
      if (const Json* feature = Find(v, "feature")) {
        const std::string id = String(*feature, p + "/feature");
        const auto index = spec_.parts[*e.part].FindFeature(id);
        if (!index) {
          Fail(p + "/feature", fmt::format("expected a feature of part \"{}\", found \"{}\"",
                                           spec_.parts[*e.part].id, id));
        }
        e.feature = FeatureRef{*e.part, *index};
      }
      e.ratio = ReadRatio(*ratio, p + "/ratio");
    } else if (const Json* moves = Find(v, "moves")) {
      CheckKeys(v, p, {"part", "moves"});
      e.kind = Expectation::Kind::kMoves;
      e.part = PartRef(Require(v, p, "part", "a part id"), p + "/part");
      e.flag = Bool(*moves, p + "/moves");
    } else if (const Json* mobility = Find(v, "mobility")) {
      CheckKeys(v, p, {"mobility"});
      e.kind = Expectation::Kind::kMobility;
      if (!mobility->is_number_integer() || mobility->get<long long>() < 0 ||
          mobility->get<long long>() > 1000000) {
        Fail(p + "/mobility",
             fmt::format("expected a whole number >= 0, found {}", Describe(*mobility)));
      }
      e.mobility = static_cast<int>(mobility->get<long long>());
    } else if (const Json* pair = Find(v, "pair")) {
      CheckKeys(v, p, {"pair", "type"});
      e.kind = Expectation::Kind::kPair;
      e.pair = RefPair(*pair, p + "/pair");
      if (const Json* type = Find(v, "type")) {
        e.pair_type = PairTypeOrNone(*type, p + "/type");
        if (!e.pair_type) Fail(p + "/type", "expected a pair type, found \"none\"");
      }
    } else if (const Json* same = Find(v, "same_subassembly")) {
      CheckKeys(v, p, {"same_subassembly"});
      e.kind = Expectation::Kind::kSameSubassembly;
      e.parts = PartList(*same, p + "/same_subassembly");
      if (e.parts.size() < 2) {
        Fail(p + "/same_subassembly",
             fmt::format("expected at least two parts, found {}", Describe(*same)));
      }
    } else if (const Json* assemblable = Find(v, "assemblable")) {
      CheckKeys(v, p, {"assemblable"});
      e.kind = Expectation::Kind::kAssemblable;
      e.flag = Bool(*assemblable, p + "/assemblable");
    } else if (const Json* diagnostic = Find(v, "diagnostic")) {
      CheckKeys(v, p, {"diagnostic", "parts"});
      e.kind = Expectation::Kind::kDiagnostic;
      e.diagnostic = String(*diagnostic, p + "/diagnostic");
      if (e.diagnostic.empty()) Fail(p + "/diagnostic", "expected a code or text, found \"\"");
      if (const Json* parts = Find(v, "parts")) e.parts = PartList(*parts, p + "/parts");
    } else {
      Fail(p,
           "expected an expectation with one of \"ratio\", \"moves\", \"mobility\", \"pair\", "
           "\"same_subassembly\", \"assemblable\", \"diagnostic\", found none");
    }
    spec_.expectations.push_back(std::move(e));
  }

  std::vector<std::size_t> PartList(const Json& v, const std::string& p) const {
    if (!v.is_array()) Fail(p, fmt::format("expected an array of part ids, found {}", Describe(v)));
    std::vector<std::size_t> parts;
    for (std::size_t i = 0; i < v.size(); ++i) {
      parts.push_back(PartRef(v[i], JoinPointer(p, std::to_string(i))));
    }
    return parts;
  }

  ExpectedRatio ReadRatio(const Json& v, const std::string& p) const {
    ExpectedRatio r;
    if (v.is_number_integer()) {
      r.exact = true;
      r.numerator = v.get<long long>();
      r.value = static_cast<double>(r.numerator);
      r.text = std::to_string(r.numerator);
      return r;
    }
    if (v.is_number()) {
      r.value = Number(v, p);
      std::ostringstream s;
      s.precision(17);
      s << r.value;
      r.text = s.str();
      return r;
    }
    if (!v.is_string()) {
      Fail(p, fmt::format("expected a ratio (an integer, \"p/q\" or a decimal), found {}",
                          Describe(v)));
    }
    r.text = v.get<std::string>();
    const std::optional<ExpectedRatio> parsed = ParseRatio(r.text);
    static const std::regex kZeroDenominator(R"(\s*[+-]?\d{1,18}\s*/\s*0+\s*)");
    if (!parsed && std::regex_match(r.text, kZeroDenominator)) {
      Fail(p, fmt::format("expected a non-zero denominator, found \"{}\"", r.text));
    }
    if (!parsed) {
      Fail(p, fmt::format("expected a ratio (an integer, \"p/q\" or a decimal), found \"{}\"",
                          r.text));
    }
    return *parsed;
  }

  JsonSource src_;
  std::filesystem::path dir_;
  StepFileProgress progress_;  // ReadParts's, for the STEP files it imports (only it does)
  AssemblySpec spec_;
  std::vector<PartOrigin> origins_;  // per part
  // The entries whose `place` ReadRelations reads: (part index, its entry).
  std::vector<std::pair<std::size_t, const Json*>> placed_;
  std::map<std::string, std::size_t> part_index_;
  std::map<std::size_t, std::string> entry_of_;  // part index -> its entry's JSON pointer
  std::map<std::filesystem::path, std::shared_ptr<const TriangleMesh>> mesh_cache_;
};

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "", 0, 0, "cannot open the file for reading");
  if (const auto shortfall = internal::MemoryShortfall(
          internal::ReadingNeed(file, internal::kJsonBytesPerFileByte), "an assembly file")) {
    throw InputError(file.string(), "", 0, 0, *shortfall);
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(file.string(), "", 0, 0, "error while reading the file");
  return text.str();
}

}  // namespace

std::optional<ExpectedRatio> ParseRatio(const std::string& text) {
  static const std::regex kFraction(R"(\s*([+-]?\d{1,18})\s*(?:/\s*(\d{1,18})\s*)?)");
  static const std::regex kDecimal(R"(\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*)");
  ExpectedRatio r;
  r.text = text;
  std::smatch m;
  if (std::regex_match(text, m, kFraction)) {
    r.exact = true;
    r.numerator = std::stoll(m[1].str());
    r.denominator = m[2].matched ? std::stoll(m[2].str()) : 1;
    if (r.denominator == 0) return std::nullopt;
    const std::int64_t g = std::gcd(r.numerator, r.denominator);
    r.numerator /= g;
    r.denominator /= g;
    r.value = static_cast<double>(r.numerator) / static_cast<double>(r.denominator);
  } else if (std::regex_match(text, kDecimal)) {
    r.value = std::stod(text);
  } else {
    return std::nullopt;
  }
  return r;
}

struct AssemblyFileReader::Impl {
  Reader reader;
  bool step_alone = false;  // a STEP file read as a file that imports it and adds nothing

  // Runs `read`; for a STEP file alone, its errors name the STEP file itself, not a line of
  // the file made up around it.
  template <typename Read>
  auto Run(Read&& read) {
    try {
      return read();
    } catch (const InputError& e) {
      if (!step_alone) throw;
      throw InputError(e.file(), "", 0, 0, e.detail());
    }
  }
};

AssemblyFileReader::AssemblyFileReader(std::string_view text, const std::filesystem::path& file)
    : impl_(std::make_unique<Impl>(
          Impl{Reader(internal::ParseJson(text, file.string()), file.parent_path())})) {}

AssemblyFileReader AssemblyFileReader::Open(const std::filesystem::path& file) {
  if (std::filesystem::is_directory(file)) {
    throw InputError(file.string(), "", 0, 0, "expected an assembly file, found a directory");
  }
  if (!IsStepFile(file)) return AssemblyFileReader(ReadText(file), file);
  const nlohmann::json text = {
      {"mechanist", 1}, {"name", file.stem().string()}, {"import", file.filename().string()}};
  AssemblyFileReader reader(text.dump(), file);
  reader.impl_->step_alone = true;
  return reader;
}

AssemblyFileReader::AssemblyFileReader(AssemblyFileReader&&) noexcept = default;
AssemblyFileReader& AssemblyFileReader::operator=(AssemblyFileReader&&) noexcept = default;
AssemblyFileReader::~AssemblyFileReader() = default;

WrittenParts AssemblyFileReader::ReadParts(const StepFileProgress& progress) {
  return impl_->Run([&] { return impl_->reader.ReadParts(progress); });
}

AssemblySpec AssemblyFileReader::ReadRelations(AssemblySpec spec) {
  return impl_->Run([&] { return impl_->reader.ReadRelations(std::move(spec)); });
}

void AssemblyFileReader::FailAtPlacement(std::size_t part, const std::string& message) const {
  impl_->reader.FailAtPlacement(part, message);
}

}  // namespace mechanist
