#include "io/analysis_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

std::string PairParameters(const Pair& p) {
  std::string s;
  auto out = std::back_inserter(s);
  if (p.dof) fmt::format_to(out, ", dof {}", *p.dof);
  if (p.ratio) fmt::format_to(out, ", ratio {}", p.ratio->ToString());
  if (p.travel_per_revolution) {
    fmt::format_to(out, ", {} mm per revolution", FormatNumber(*p.travel_per_revolution, 9));
  }
  if (p.type == PairType::kWormGear) s += p.self_locking ? ", self-locking" : ", back-drivable";
  if (p.fastening != PairFastening::kNone) fmt::format_to(out, ", {}", ToString(p.fastening));
  return s;
}

std::string Dq(const std::string& s) {
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

/// A world vector for reports: components below 1e-12 are 0, so that round-off never shows.
std::vector<double> Clean(const Eigen::Vector3d& v) {
  std::vector<double> c;
  for (int i = 0; i < 3; ++i) c.push_back(std::abs(v(i)) < 1e-12 ? 0.0 : v(i));
  return c;
}

std::string Vector(const Eigen::Vector3d& v) {
  const std::vector<double> c = Clean(v);
  return fmt::format("({}, {}, {})", FormatNumber(c[0]), FormatNumber(c[1]), FormatNumber(c[2]));
}

std::string DrivenTitle(const Assembly& assembly, const DrivenMotion& m) {
  if (!m.driver) return "all drivers at their rates";
  const Driver& d = assembly.drivers()[*m.driver];
  return fmt::format("driver {} ({} {}, per unit rate{}", d.id, assembly.FeatureName(d.feature),
                     d.motion == Driver::Motion::kRotation ? "rotation" : "translation",
                     d.rate == 0.0 ? "; held (rate 0): what it drives when released)" : ")");
}

std::string Describe(const Assembly& assembly, const PartMotion& m) {
  const std::string axis =
      m.axis_feature ? fmt::format("{} {}", assembly.FeatureName(*m.axis_feature), Vector(m.axis_W))
                     : Vector(m.axis_W);
  switch (m.kind) {
    case MotionKind::kRotation:
      return fmt::format("turns {} rev about {} through {}", m.rotation.ToString(), axis,
                         Vector(m.point_W));
    case MotionKind::kScrew:
      return fmt::format("turns {} rev about {} and advances {} along it", m.rotation.ToString(),
                         axis, m.translation.ToString());
    case MotionKind::kTranslation:
      return fmt::format("slides {} along {}", m.translation.ToString(), axis);
    case MotionKind::kNone:
      break;
  }
  return "still";
}

/// Part indices ordered by id, so that reordering the file's parts never reorders a report.
std::vector<std::size_t> ById(const Assembly& assembly) {
  std::vector<std::size_t> order(assembly.parts().size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return assembly.part(a).id < assembly.part(b).id;
  });
  return order;
}

}  // namespace

void WriteAnalysisSummary(const Assembly& assembly, const Analysis& analysis, std::ostream& out) {
  out << "assembly: " << (assembly.name().empty() ? "(unnamed)" : assembly.name()) << "\n";
  out << "subassemblies: " << analysis.subassemblies.size() << "\n";
  for (std::size_t i = 0; i < analysis.subassemblies.size(); ++i) {
    const Subassembly& s = analysis.subassemblies[i];
    out << "  S" << i + 1 << (s.ground ? " (ground):" : ":");
    for (std::size_t p : s.parts) out << " " << assembly.part(p).id;
    out << "\n";
  }
  out << "pairs: " << analysis.pairs.size() << "\n";
  for (std::size_t i = 0; i < analysis.pairs.size(); ++i) {
    const Pair& p = analysis.pairs[i];
    out << "  P" << i + 1 << " " << ToString(p.type) << ": " << assembly.FeatureName(p.a) << " + "
        << assembly.FeatureName(p.b) << PairParameters(p);
    if (p.source != PairSource::kRecognised) out << " (" << ToString(p.source);
    if (p.via) out << " by " << assembly.FeatureName(*p.via);
    if (p.source != PairSource::kRecognised) out << ")";
    out << "\n";
  }
  const Mobility& mobility = analysis.motion.mobility;
  out << "mobility: " << mobility.dof << " (" << mobility.redundant
      << (mobility.redundant == 1 ? " redundant constraint, " : " redundant constraints, ")
      << mobility.free_motions.size()
      << (mobility.free_motions.size() == 1 ? " free motion" : " free motions");
  if (mobility.on_faces > 0) {
    out << ", " << mobility.on_faces << " of them of parts held by face contacts alone";
  }
  if (mobility.idle > 0) {
    out << ", " << mobility.idle
        << (mobility.idle == 1 ? " of them an idle spin" : " of them idle spins")
        << " of round parts";
  }
  out << ")\n";
  for (const DrivenMotion& m : analysis.motion.driven) {
    out << DrivenTitle(assembly, m) << ":\n";
    if (!m.possible) {
      out << "  cannot run: " << m.reason << "\n";
      continue;
    }
    std::size_t still = 0;
    for (std::size_t p : ById(assembly)) {
      if (m.parts[p].kind == MotionKind::kNone) {
        ++still;
        continue;
      }
      out << "  " << assembly.part(p).id << " " << Describe(assembly, m.parts[p]) << "\n";
    }
    out << "  " << still << " parts still\n";
  }
  out << "diagnostics: " << analysis.diagnostics.size() << "\n";
  for (const Diagnostic& d : analysis.diagnostics) {
    out << "  " << ToString(d.severity) << " " << d.code << ": " << d.message << "\n";
  }
}

std::string AnalysisJson(const Assembly& assembly, const Analysis& analysis) {
  using Json = nlohmann::ordered_json;
  Json report;
  report["mechanist_report"] = 1;
  report["assembly"] = assembly.name();
  report["file"] = assembly.source();
  Json pairs = Json::array();
  for (std::size_t i = 0; i < analysis.pairs.size(); ++i) {
    const Pair& p = analysis.pairs[i];
    Json j;
    j["id"] = fmt::format("P{}", i + 1);
    j["type"] = ToString(p.type);
    j["a"] = assembly.FeatureName(p.a);
    j["b"] = assembly.FeatureName(p.b);
    j["source"] = ToString(p.source);
    j["fastening"] =
        p.fastening == PairFastening::kNone ? Json(nullptr) : Json(ToString(p.fastening));
    j["dof"] = p.dof ? Json(*p.dof) : Json(nullptr);
    if (p.ratio) {
      j["ratio"] = p.ratio->ToString();
      j["ratio_value"] = p.ratio->ToDouble();
    }
    if (p.travel_per_revolution) j["travel_per_revolution"] = *p.travel_per_revolution;
    if (p.type == PairType::kWormGear) j["self_locking"] = p.self_locking;
    if (p.via) j["via"] = assembly.FeatureName(*p.via);
    pairs.push_back(std::move(j));
  }
  report["pairs"] = std::move(pairs);
  Json groups = Json::array();
  for (std::size_t i = 0; i < analysis.subassemblies.size(); ++i) {
    const Subassembly& s = analysis.subassemblies[i];
    Json parts = Json::array();
    for (std::size_t p : s.parts) parts.push_back(assembly.part(p).id);
    groups.push_back({{"id", fmt::format("S{}", i + 1)}, {"parts", parts}, {"ground", s.ground}});
  }
  report["subassemblies"] = std::move(groups);

  const Mobility& mobility = analysis.motion.mobility;
  Json redundant = Json::array();
  for (const RedundantConstraint& r : mobility.redundant_pairs) {
    redundant.push_back({{"pair", fmt::format("P{}", r.pair + 1)}, {"count", r.count}});
  }
  Json free = Json::array();
  for (const FreeMotion& f : mobility.free_motions) {
    Json parts = Json::array();
    for (std::size_t p : f.parts) parts.push_back(assembly.part(p).id);
    free.push_back({{"part", assembly.part(f.part).id},
                    {"pair", f.pair ? Json(fmt::format("P{}", *f.pair + 1)) : Json(nullptr)},
                    {"freedom", f.freedom},
                    {"parts", parts},
                    {"idle", f.idle}});
  }
  Json freedoms = Json::array();
  for (std::size_t p : ById(assembly)) {
    if (mobility.part_freedoms[p] > 0) {
      freedoms.push_back({{"part", assembly.part(p).id}, {"freedoms", mobility.part_freedoms[p]}});
    }
  }
  report["mobility"] = {{"dof", mobility.dof},
                        {"redundant", mobility.redundant},
                        {"redundant_constraints", redundant},
                        {"free_motions", free},
                        {"on_faces", mobility.on_faces},
                        {"idle", mobility.idle},
                        {"part_freedoms", freedoms}};
  Json motion = Json::array();
  for (const DrivenMotion& m : analysis.motion.driven) {
    Json parts = Json::array();
    for (std::size_t p : ById(assembly)) {
      if (!m.possible) break;
      const PartMotion& pm = m.parts[p];
      Json j = {{"part", assembly.part(p).id}, {"kind", ToString(pm.kind)}};
      if (pm.kind != MotionKind::kNone) {
        const bool turns = pm.kind != MotionKind::kTranslation;
        const ExactReal& ratio = turns ? pm.rotation : pm.translation;
        j["axis"] = Clean(pm.axis_W);
        if (turns) j["point"] = Clean(pm.point_W);
        j["axis_feature"] =
            pm.axis_feature ? Json(assembly.FeatureName(*pm.axis_feature)) : Json(nullptr);
        j["ratio"] = ratio.ToString();
        j["ratio_value"] = ratio.value();
        j["exact"] = ratio.is_exact();
        if (pm.kind == MotionKind::kScrew) {
          j["translation"] = pm.translation.ToString();
          j["translation_value"] = pm.translation.value();
        }
      }
      parts.push_back(std::move(j));
    }
    Json entry = {{"driver", m.driver ? Json(assembly.drivers()[*m.driver].id) : Json(nullptr)},
                  {"possible", m.possible},
                  {"reason", m.reason},
                  {"parts", parts}};
    if (m.driver && assembly.drivers()[*m.driver].rate == 0.0) entry["held"] = true;
    motion.push_back(std::move(entry));
  }
  report["motion"] = std::move(motion);
  Json diagnostics = Json::array();
  for (const Diagnostic& d : analysis.diagnostics) {
    diagnostics.push_back({{"severity", ToString(d.severity)},
                           {"code", d.code},
                           {"message", d.message},
                           {"parts", d.parts},
                           {"features", d.features}});
  }
  report["diagnostics"] = std::move(diagnostics);
  return report.dump(2) + "\n";
}

std::string AnalysisDot(const Assembly& assembly, const Analysis& analysis) {
  std::ostringstream dot;
  dot << "graph mechanism {\n  label=" << Dq(assembly.name()) << ";\n  node [shape=box];\n";
  for (std::size_t i = 0; i < analysis.subassemblies.size(); ++i) {
    const Subassembly& s = analysis.subassemblies[i];
    dot << "  subgraph cluster_S" << i + 1
        << " {\n    label=" << Dq(fmt::format("S{}{}", i + 1, s.ground ? " (ground)" : ""))
        << ";\n";
    if (s.ground) dot << "    style=filled; color=lightgrey;\n";
    for (std::size_t p : s.parts) dot << "    " << Dq(assembly.part(p).id) << ";\n";
    dot << "  }\n";
  }
  for (const Pair& p : analysis.pairs) {
    dot << "  " << Dq(assembly.part(p.a.part).id) << " -- " << Dq(assembly.part(p.b.part).id)
        << " [label="
        << Dq(p.ratio ? fmt::format("{} {}", ToString(p.type), p.ratio->ToString())
                      : std::string(ToString(p.type)))
        << (p.type == PairType::kFixed ? ", style=dashed" : "") << "];\n";
  }
  dot << "}\n";
  return dot.str();
}

void WriteDragReport(const Assembly& assembly, const Analysis& analysis, const DragResult& drag,
                     bool rotate, std::ostream& out) {
  auto pair_line = [&](std::size_t i) {
    const Pair& p = analysis.pairs[i];
    return fmt::format("P{} {}: {} + {}", i + 1, ToString(p.type), assembly.FeatureName(p.a),
                       assembly.FeatureName(p.b));
  };
  out << "drag " << assembly.part(drag.part).id << (rotate ? " about " : " along ")
      << assembly.FeatureName(drag.axis) << ": allowable motion " << drag.part_freedoms
      << (drag.part_freedoms == 1 ? " freedom" : " freedoms") << "\n";
  if (!drag.motion.possible) {
    out << "blocked: " << drag.motion.reason << "\n";
    if (assembly.part(drag.part).ground) out << "held by: the ground (a ground part)\n";
    if (!drag.holding_pairs.empty()) out << "held by:\n";
    for (std::size_t i : drag.holding_pairs) out << "  " << pair_line(i) << "\n";
    return;
  }
  out << "moves:\n";
  for (std::size_t p : ById(assembly)) {
    if (drag.motion.parts[p].kind == MotionKind::kNone) continue;
    out << "  " << assembly.part(p).id << " " << Describe(assembly, drag.motion.parts[p]) << "\n";
  }
  out << "absorbed by:\n";
  for (std::size_t i : drag.absorbing_pairs) out << "  " << pair_line(i) << "\n";
}

void WriteCheckResults(const std::vector<ExpectationResult>& results, std::ostream& out) {
  std::size_t passed = 0;
  for (const ExpectationResult& r : results) {
    passed += r.passed ? 1 : 0;
    out << (r.passed ? "PASS " : "FAIL ") << r.pointer << ": " << r.what << " (" << r.detail
        << ")\n";
  }
  if (results.empty()) {
    out << "no expectations: the file has no `expect` entries (for a STEP file, write them in an "
           "assembly file that imports it)\n";
  }
  out << passed << " passed, " << results.size() - passed << " failed\n";
}

}  // namespace mechanist
