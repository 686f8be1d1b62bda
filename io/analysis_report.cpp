#include "io/analysis_report.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "kernel/number_format.h"

namespace mechanist {
namespace {

std::string PairParameters(const Pair& p) {
  std::string s;
  if (p.dof) s += ", dof " + std::to_string(*p.dof);
  if (p.ratio) s += ", ratio " + p.ratio->ToString();
  if (p.travel_per_revolution) {
    s += ", " + FormatNumber(*p.travel_per_revolution, 9) + " mm per revolution";
  }
  if (p.type == PairType::kWormGear) s += p.self_locking ? ", self-locking" : ", back-drivable";
  if (p.fastening != PairFastening::kNone) s += ", " + std::string(ToString(p.fastening));
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
    j["id"] = "P" + std::to_string(i + 1);
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
    groups.push_back({{"id", "S" + std::to_string(i + 1)}, {"parts", parts}, {"ground", s.ground}});
  }
  report["subassemblies"] = std::move(groups);
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
        << " {\n    label=" << Dq("S" + std::to_string(i + 1) + (s.ground ? " (ground)" : ""))
        << ";\n";
    if (s.ground) dot << "    style=filled; color=lightgrey;\n";
    for (std::size_t p : s.parts) dot << "    " << Dq(assembly.part(p).id) << ";\n";
    dot << "  }\n";
  }
  for (const Pair& p : analysis.pairs) {
    dot << "  " << Dq(assembly.part(p.a.part).id) << " -- " << Dq(assembly.part(p.b.part).id)
        << " [label="
        << Dq(std::string(ToString(p.type)) + (p.ratio ? " " + p.ratio->ToString() : ""))
        << (p.type == PairType::kFixed ? ", style=dashed" : "") << "];\n";
  }
  dot << "}\n";
  return dot.str();
}

void WriteCheckResults(const std::vector<ExpectationResult>& results, std::ostream& out) {
  std::size_t passed = 0;
  for (const ExpectationResult& r : results) {
    passed += r.passed ? 1 : 0;
    out << (r.passed ? "PASS " : "FAIL ") << r.pointer << ": " << r.what << " (" << r.detail
        << ")\n";
  }
  out << passed << " passed, " << results.size() - passed << " failed\n";
}

}  // namespace mechanist
