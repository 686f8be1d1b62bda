#include "viz/viewer_page.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "kernel/geometry/aabb.h"
#include "kernel/support/parallel_for.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/drag.h"
#include "reasoning/expectation_check.h"
#include "reasoning/gap_search.h"
#include "reasoning/interference.h"
#include "reasoning/motion_run.h"
#include "reasoning/movable_range.h"
#include "reasoning/operation_check.h"
#include "viz/display_colors.h"
#include "viz/feature_lines.h"
#include "viz/viewer_template.h"

namespace mechanist {
namespace {

using nlohmann::json;

std::string Base64(const void* data, std::size_t size) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t b0 = bytes[i];
    const std::uint32_t b1 = i + 1 < size ? bytes[i + 1] : 0;
    const std::uint32_t b2 = i + 2 < size ? bytes[i + 2] : 0;
    const std::uint32_t v = b0 << 16 | b1 << 8 | b2;
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += i + 1 < size ? kAlphabet[v >> 6 & 63] : '=';
    out += i + 2 < size ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::runtime_error(
        fmt::format("three.js not found at {} (Debian package libjs-three)", path.string()));
  }
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

json Vector(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

// A 4x4 pose, column-major as three.js' Matrix4.fromArray reads it.
json Matrix(const RigidTransform& X) {
  const Eigen::Matrix4d m = X.matrix();
  return json(std::vector<double>(m.data(), m.data() + 16));
}

// The parts' paths that move: {part index: [screws]}, the others still.
json Paths(const std::vector<ScrewPath>& paths) {
  json out = json::object();
  for (std::size_t p = 0; p < paths.size(); ++p) {
    if (paths[p].still()) continue;
    json screws = json::array();
    for (const ScrewMotion& m : paths[p].screws) {
      screws.push_back({{"point", Vector(m.point_W)},
                        {"axis", Vector(m.axis_W)},
                        {"turns", m.turns_per_unit},
                        {"travel", m.travel_per_unit}});
    }
    out[std::to_string(p)] = screws;
  }
  return out;
}

json PairJson(const Assembly& assembly, const Pair& p) {
  json j = {{"type", ToString(p.type)},       {"a", assembly.FeatureName(p.a)},
            {"b", assembly.FeatureName(p.b)}, {"parts", json::array({p.a.part, p.b.part})},
            {"source", ToString(p.source)},   {"fastening", ToString(p.fastening)}};
  if (p.ratio) j["ratio"] = p.ratio->ToString();
  if (p.travel_per_revolution) j["travel"] = *p.travel_per_revolution;
  if (p.dof) j["dof"] = *p.dof;
  return j;
}

// A mesh quantised for the page: each coordinate a 16-bit step across the mesh's box (a step
// is the box's size / 65535, so a vertex moves by at most half a step: 0.8 um on a 100 mm
// part), and indices 16-bit when the mesh has at most 65,536 vertices. A quarter of the
// vertex bytes and half the index bytes of float32 and uint32.
json QuantisedMesh(const TriangleMesh& mesh) {
  const Aabb box = mesh.Bounds();
  const Eigen::Vector3d step = (box.max - box.min) / 65535.0;
  std::vector<std::uint16_t> xyz;
  xyz.reserve(3 * mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) {
    for (int k = 0; k < 3; ++k) {
      const double q = step[k] > 0 ? std::round((v[k] - box.min[k]) / step[k]) : 0.0;
      xyz.push_back(static_cast<std::uint16_t>(std::clamp(q, 0.0, 65535.0)));
    }
  }
  json j = {{"triangles", mesh.faces.size()},
            {"min", Vector(box.min)},
            {"step", Vector(step)},
            {"positions", Base64(xyz.data(), sizeof(std::uint16_t) * xyz.size())}};
  const bool narrow = mesh.vertices.size() <= 65536;
  std::vector<std::uint16_t> narrow_indices;
  std::vector<std::uint32_t> wide_indices;
  for (const TriangleMesh::Face& f : mesh.faces) {
    for (const std::int32_t i : f) {
      if (narrow) {
        narrow_indices.push_back(static_cast<std::uint16_t>(i));
      } else {
        wide_indices.push_back(static_cast<std::uint32_t>(i));
      }
    }
  }
  j["index_bytes"] = narrow ? 2 : 4;
  j["indices"] = narrow ? Base64(narrow_indices.data(), 2 * narrow_indices.size())
                        : Base64(wide_indices.data(), 4 * wide_indices.size());
  return j;
}

// The assembly sequence for the stepper: the insertions in order, then the parts no insertion
// places (with the attempt that got furthest), each with the pins the file leaves out that go
// in after it.

// The holes a pin goes through, by name.
json HoleNames(const Assembly& assembly, const std::vector<FeatureRef>& holes) {
  json names = json::array();
  for (const FeatureRef& h : holes) names.push_back(assembly.FeatureName(h));
  return names;
}

json Blocked(const Assembly& assembly, const std::vector<InsertionObstacle>& blocked_by) {
  json blocked = json::array();
  for (const InsertionObstacle& o : blocked_by) {
    const bool part = o.pin.empty();
    blocked.push_back(
        {{"part", part ? json(o.part) : json(nullptr)},
         {"pin", part ? json(nullptr) : HoleNames(assembly, o.pin)},
         {"travel", o.travel},
         {"short_by", o.short_by},
         {"point", Vector(o.p_W)},
         {"held_by", o.held_by ? json(assembly.FeatureName(*o.held_by)) : json(nullptr)},
         {"clash_at_rest", o.clash_at_rest}});
  }
  return blocked;
}

json Pins(const Assembly& assembly, const std::vector<PinInsertion>& pins) {
  json list = json::array();
  for (const PinInsertion& pin : pins) {
    list.push_back({{"holes", HoleNames(assembly, pin.holes)},
                    {"diameter", pin.diameter},
                    {"ends", json::array({Vector(pin.ends_W[0]), Vector(pin.ends_W[1])})},
                    {"direction", Vector(pin.direction_W)},
                    {"travel", pin.travel},
                    {"clear", pin.clear},
                    {"blocked_by", Blocked(assembly, pin.blocked_by)}});
  }
  return list;
}

json Insertion(const Assembly& assembly, const InsertionStep& step, bool placed) {
  return {{"part", step.part},
          {"carried", step.carried},
          {"direction", Vector(step.direction_W)},
          {"travel", step.travel},
          {"clear", step.clear},
          {"placed", placed},
          {"blocked_by", Blocked(assembly, step.blocked_by)},
          {"pins", Pins(assembly, step.pins)},
          {"subassembly", step.subassembly},
          {"apart_for", step.apart_for ? json(*step.apart_for) : json(nullptr)}};
}

json Sequence(const Assembly& assembly, const AssemblyPlan& plan) {
  json steps = json::array();
  for (const InsertionStep& step : plan.steps) steps.push_back(Insertion(assembly, step, true));
  for (const InsertionStep& step : plan.unplaced) steps.push_back(Insertion(assembly, step, false));
  return {{"assemblable", plan.assemblable},
          {"from_steps", plan.from_steps},
          {"base", plan.base},
          {"base_pins", Pins(assembly, plan.base_pins)},
          {"steps", steps}};
}

json Contact(const OperationClash& c) {
  return {{"at", c.at}, {"parts", json::array({c.part_a, c.part_b})}, {"point", Vector(c.p_W)}};
}

json Contact(const std::optional<OperationClash>& c) { return c ? Contact(*c) : json(nullptr); }

json Data(const Assembly& assembly, const Analysis& analysis, const ViewerOptions& options) {
  json data;
  data["name"] = assembly.name();
  data["length_unit"] = assembly.units().length;
  data["mm_per_length"] = assembly.units().mm_per_length;
  const DisplayColors colors = ColorParts(analysis);
  std::map<const TriangleMesh*, std::size_t> mesh_index;
  json meshes = json::array(), parts = json::array();
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    const Part& part = assembly.part(p);
    json j = {{"id", part.id},
              {"group", part.group},
              {"ground", part.ground},
              {"subassembly", analysis.subassembly_of[p]},
              {"color", Vector(colors.part[p])},
              {"X_WP", Matrix(part.X_WP)},
              {"mesh", -1}};
    if (part.HasGeometry()) {
      auto [it, added] = mesh_index.emplace(part.mesh.get(), meshes.size());
      if (added) meshes.push_back(QuantisedMesh(*part.mesh));
      j["mesh"] = it->second;
    }
    json lines = json::array();
    for (const auto& line : FeatureLines(part, !part.HasGeometry())) {
      json points = json::array();
      for (const Eigen::Vector3d& q : line) points.push_back(Vector(q));
      lines.push_back(points);
    }
    j["lines"] = lines;
    parts.push_back(j);
  }
  data["meshes"] = meshes;
  data["parts"] = parts;
  json pairs = json::array();
  for (const Pair& p : analysis.pairs) pairs.push_back(PairJson(assembly, p));
  data["pairs"] = pairs;
  json subassemblies = json::array();
  for (const Subassembly& s : analysis.subassemblies) {
    subassemblies.push_back({{"parts", s.parts}, {"ground", s.ground}});
  }
  data["subassemblies"] = subassemblies;
  const Mobility& mobility = analysis.motion.mobility;
  json free = json::array();
  for (const FreeMotion& f : mobility.free_motions) {
    free.push_back({{"part", f.part}, {"freedom", f.freedom}, {"parts", f.parts}});
  }
  data["mobility"] = {{"dof", mobility.dof}, {"redundant", mobility.redundant}, {"free", free}};
  json diagnostics = json::array();
  for (const Diagnostic& d : analysis.diagnostics) {
    diagnostics.push_back({{"severity", ToString(d.severity)},
                           {"code", d.code},
                           {"message", d.message},
                           {"parts", d.parts}});
  }
  data["diagnostics"] = diagnostics;

  // The collision model of the clashes, the assembly plan and the drags' ranges; none for a
  // kinematic sketch.
  std::optional<CollisionModel> collision;
  if (std::any_of(assembly.parts().begin(), assembly.parts().end(),
                  [](const Part& p) { return p.HasGeometry(); })) {
    collision.emplace(assembly);
  }

  // The assembly sequence (PlanAssembly sweeps every part) for the stepper, and for the
  // file's expectations as `mechanist check` evaluates them.
  std::optional<AssemblyPlan> plan;
  const bool asked =
      std::any_of(assembly.expectations().begin(), assembly.expectations().end(),
                  [](const Expectation& e) { return e.kind == Expectation::Kind::kAssemblable; });
  if (asked || (options.plan && collision)) {
    plan = collision
               ? PlanAssembly(assembly, analysis, *collision, options.plan_progress)
               : PlanAssembly(assembly, analysis, CollisionModel(assembly), options.plan_progress);
  }
  data["assembly"] = plan && options.plan ? Sequence(assembly, *plan) : json(nullptr);
  json expectations = json::array();
  for (const ExpectationResult& r :
       CheckExpectations(assembly, analysis, plan ? &*plan : nullptr)) {
    expectations.push_back({{"passed", r.passed}, {"what", r.what}, {"detail", r.detail}});
  }
  data["expectations"] = expectations;

  // Each driver's run, on the same paths as animate and sweep, then, with several, all of
  // them together at their rates (the run's parameter counts time units).
  json drivers = json::array();
  const std::size_t runs = assembly.drivers().size() + (assembly.drivers().size() > 1 ? 1 : 0);
  for (std::size_t d = 0; d < runs; ++d) {
    const bool together = d == assembly.drivers().size();
    const std::optional<std::size_t> driver = together ? std::nullopt : std::optional(d);
    const MotionRun run = PlanRun(assembly, analysis, driver, std::nullopt);
    json entry = {
        {"id", together ? "all together" : assembly.drivers()[d].id},
        {"together", together},
        {"rotation", !together && assembly.drivers()[d].motion == Driver::Motion::kRotation},
        {"amount", run.amount},
        {"possible", run.possible},
        {"reason", run.reason},
        {"paths", Paths(run.paths)}};
    // The swept check of the run, as `mechanist sweep` makes it: the first contact of each
    // pair of parts that meet on the way, and the jams where a part that nothing holds cannot
    // yield (one that yields is pushed along: no clash).
    if (options.ranges && collision && run.possible) {
      const OperationCheck check =
          CheckOperation(assembly, analysis, *collision, driver, std::nullopt);
      std::vector<OperationClash> stops = check.clashes;
      for (const InferredCoupling& c : check.inferred) {
        if (c.carried) continue;
        const bool in_order = assembly.PartRank(c.pusher) < assembly.PartRank(c.pushed);
        stops.push_back(
            {in_order ? c.pusher : c.pushed, in_order ? c.pushed : c.pusher, c.at, 0.0, c.p_W});
      }
      std::stable_sort(
          stops.begin(), stops.end(),
          [](const OperationClash& x, const OperationClash& y) { return x.at < y.at; });
      json clashes = json::array();
      for (const OperationClash& c : stops) clashes.push_back(Contact(c));
      entry["clashes"] = clashes;
    }
    drivers.push_back(entry);
  }
  data["drivers"] = drivers;

  // Clashes at rest (as `mechanist interference` finds them): the parts and where.
  json clashes = json::array();
  if (collision) {
    std::vector<PartContact> measured;  // unless the assembly plan, when made, found them
    if (!plan)
      measured = FindContacts(assembly, InitialState(assembly), *collision, analysis.pairs);
    for (const PartContact& c : plan ? plan->clashes : measured) {
      if (c.verdict != ContactVerdict::kClash) continue;
      clashes.push_back(
          {{"parts", json::array({c.part_a, c.part_b})},
           {"point", Vector(c.measure.p_W)},
           {"depth", std::isfinite(c.measure.depth) ? json(c.measure.depth) : json("unknown")}});
    }
  }
  data["clashes"] = clashes;

  // The enclosed gaps: their walls (world, mm) and volumes, when asked for.
  json gaps = json::array();
  if (options.gap_voxel > 0) {
    GapSearchOptions gap_options;
    gap_options.voxel = options.gap_voxel;
    const GapSearch search = FindGaps(assembly, gap_options);
    std::vector<std::int32_t> gap_of_face;
    const TriangleMesh surface = GapSurface(search, &gap_of_face);
    for (std::size_t g = 0; g < search.gaps.size(); ++g) {
      std::vector<float> xyz;
      for (std::size_t f = 0; f < surface.faces.size(); ++f) {
        if (gap_of_face[f] != static_cast<std::int32_t>(g)) continue;
        for (const std::int32_t i : surface.faces[f]) {
          const Eigen::Vector3d& v = surface.vertices[i];
          xyz.insert(xyz.end(), {static_cast<float>(v.x()), static_cast<float>(v.y()),
                                 static_cast<float>(v.z())});
        }
      }
      gaps.push_back({{"volume", search.gaps[g].volume},
                      {"error", search.gaps[g].volume_error},
                      {"triangles", Base64(xyz.data(), 4 * xyz.size())}});
    }
  }
  data["gaps"] = gaps;

  // Every part's drag: its allowable motion with what follows and how far it goes each way,
  // or the pairs that hold it. A slide is searched over the assembly's diagonal.
  Aabb bounds;
  for (const Part& part : assembly.parts()) {
    if (part.HasGeometry()) bounds.Extend(TransformBox(part.X_WP, part.mesh->Bounds()));
  }
  const double reach = bounds.empty() ? 0.0 : bounds.size().norm();
  data["reach_mm"] = reach;
  if (!options.ranges) collision.reset();
  // A range search per distinct motion (the drags of a rigid body's parts move it alike),
  // searched on every core once the drags are known.
  struct RangeSearch {
    std::vector<ScrewPath> paths;
    bool turn = false;
    MovableRange range;
  };
  std::vector<RangeSearch> searches;
  std::map<std::string, std::size_t> search_of;  // by the kind of drag and its paths
  struct Shown {
    std::size_t part;
    const char* drag;  // "turn" or "slide"
    std::size_t search;
  };
  std::vector<Shown> shown;
  json drags = json::array();
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    json entry = json::object();
    for (const bool rotate : {true, false}) {
      if (assembly.part(p).features.empty()) break;
      const DragResult r = Drag(assembly, analysis, {p, std::nullopt, rotate});
      json j = {{"axis", assembly.FeatureName(r.axis)}, {"possible", r.motion.possible}};
      if (r.motion.possible) {
        std::vector<ScrewPath> paths;
        for (const PartMotion& m : r.motion.parts) paths.push_back(m.path);
        j["paths"] = Paths(paths);
        if (collision && (rotate || reach > 0)) {
          const auto [found, added] =
              search_of.emplace(fmt::format("{} {}", rotate, j["paths"].dump()), searches.size());
          if (added) searches.push_back({std::move(paths), rotate, {}});
          shown.push_back({p, rotate ? "turn" : "slide", found->second});
        }
      } else {
        j["reason"] = r.motion.reason;
        j["holding"] = r.holding_pairs;
      }
      entry[rotate ? "turn" : "slide"] = j;
    }
    drags.push_back(entry);
  }
  std::mutex reporting;
  std::size_t searched = 0;
  if (options.range_progress && !searches.empty()) options.range_progress(0);
  ParallelFor(searches.size(), [&](std::size_t k) {
    RangeSearch& search = searches[k];
    search.range = FindMovableRange(assembly, analysis, *collision, search.paths,
                                    search.turn ? 1.0 : reach, search.turn);
    if (options.range_progress) {
      const std::lock_guard<std::mutex> lock(reporting);
      options.range_progress(static_cast<double>(++searched) / searches.size());
    }
  });
  for (const Shown& s : shown) {
    drags[s.part][s.drag]["ahead"] = Contact(searches[s.search].range.ahead);
    drags[s.part][s.drag]["behind"] = Contact(searches[s.search].range.behind);
  }
  data["drags"] = drags;
  return data;
}

std::string HtmlEscape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

// Closes no script element early: "</" inside the JSON becomes "<\/".
std::string ScriptSafe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) {
    text.replace(at, 2, "<\\/");
  }
  return text;
}

}  // namespace

std::string ViewerHtml(const Assembly& assembly, const Analysis& analysis,
                       const ViewerOptions& options) {
  const std::string three = ReadFile(options.three_dir / "three.min.js");
  const std::string orbit = ReadFile(options.three_dir / "examples/js/controls/OrbitControls.js");
  const std::string title = assembly.name().empty() ? "mechanist" : assembly.name();
  std::string html = kViewerTemplate;
  auto put = [&](const std::string& marker, const std::string& text) {
    const std::size_t at = html.find(marker);
    if (at == std::string::npos) {
      throw std::logic_error(fmt::format("viewer template lacks {}", marker));
    }
    html.replace(at, marker.size(), text);
  };
  put("@TITLE@", HtmlEscape(title));
  put("@THREE@", ScriptSafe(three));
  put("@ORBIT@", ScriptSafe(orbit));
  put("@DATA@", ScriptSafe(Data(assembly, analysis, options).dump()));
  return html;
}

}  // namespace mechanist
