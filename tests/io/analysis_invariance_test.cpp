// Properties of the analysis of every example: reordering the file or renaming parts changes
// nothing but names, and the same input gives byte-identical reports.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "io/analysis_report.h"
#include "io/load_assembly.h"
#include "reasoning/adjustment.h"
#include "reasoning/analysis.h"

namespace mechanist {
namespace {

std::vector<std::filesystem::path> Examples() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(MECHANIST_SOURCE_DIR) / "examples")) {
    if (entry.is_directory()) files.push_back(entry.path() / "assembly.json");
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string Slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The report without the "file" member, which names the input path.
nlohmann::json ReportWithoutFile(const Assembly& assembly) {
  nlohmann::json report = nlohmann::json::parse(AnalysisJson(assembly, Analyze(assembly)));
  report.erase("file");
  return report;
}

TEST(AnalysisInvariance, SameInputGivesByteIdenticalReports) {
  for (const auto& file : Examples()) {
    const Assembly a = LoadAssembly(file);
    const Assembly b = LoadAssembly(file);
    EXPECT_EQ(AnalysisJson(a, Analyze(a)), AnalysisJson(b, Analyze(b))) << file;
    EXPECT_EQ(AnalysisDot(a, Analyze(a)), AnalysisDot(b, Analyze(b))) << file;
  }
}

TEST(AnalysisInvariance, ReorderingPartsAndFeaturesChangesNothing) {
  for (const auto& file : Examples()) {
    SCOPED_TRACE(file.string());
    nlohmann::json document = nlohmann::json::parse(Slurp(file), nullptr, true, true);
    std::reverse(document["parts"].begin(), document["parts"].end());
    for (auto& part : document["parts"]) {
      if (part.contains("features")) {
        std::reverse(part["features"].begin(), part["features"].end());
      }
    }
    const Assembly original = LoadAssembly(file);
    const Assembly reordered = LoadAssemblyText(document.dump(), file);
    EXPECT_EQ(ReportWithoutFile(original), ReportWithoutFile(reordered));
  }
}

TEST(AnalysisInvariance, RenamingPartsChangesOnlyNames) {
  for (const auto& file : Examples()) {
    SCOPED_TRACE(file.string());
    const Assembly original = LoadAssembly(file);
    AssemblySpec spec;
    spec.name = original.name();
    spec.tolerance = original.tolerance();
    spec.friction = original.friction();
    spec.parts = original.parts();
    spec.drivers = original.drivers();
    for (Part& part : spec.parts) {
      part.id = "renamed_" + part.id;
      for (Feature& f : part.features) f.id = "f_" + f.id;
    }
    spec.overrides = original.overrides();
    const Assembly renamed(std::move(spec));
    const Analysis a = Analyze(original);
    const Analysis b = Analyze(renamed);
    // Indices are the same in both: compare the pairs as sets of (type, a, b, source).
    auto key_set = [](const Analysis& x) {
      std::set<std::tuple<int, FeatureRef, FeatureRef, int>> keys;
      for (const Pair& p : x.pairs) {
        keys.emplace(static_cast<int>(p.type), std::min(p.a, p.b), std::max(p.a, p.b),
                     static_cast<int>(p.source));
      }
      return keys;
    };
    EXPECT_EQ(key_set(a), key_set(b));
    auto groups = [](const Analysis& x) {
      std::set<std::set<std::size_t>> g;
      for (const Subassembly& s : x.subassemblies) g.emplace(s.parts.begin(), s.parts.end());
      return g;
    };
    EXPECT_EQ(groups(a), groups(b));
    EXPECT_EQ(a.diagnostics.size(), b.diagnostics.size());
  }
}

TEST(AnalysisInvariance, ExamplesMeetTheirExpectations) {
  for (const auto& file : Examples()) {
    SCOPED_TRACE(file.string());
    const Assembly assembly = Adjusted(LoadAssembly(file));  // as the commands see it
    const Analysis analysis = Analyze(assembly);
    const std::vector<ExpectationResult> results = CheckExpectations(assembly, analysis);
    ASSERT_EQ(results.size(), assembly.expectations().size());
    for (std::size_t i = 0; i < results.size(); ++i) {
      const ExpectationResult& r = results[i];
      const Expectation::Kind kind = assembly.expectations()[i].kind;
      if (kind != Expectation::Kind::kAssemblable) {
        EXPECT_TRUE(r.passed) << r.pointer << " " << r.what << ": " << r.detail;
      } else {
        EXPECT_FALSE(r.passed) << "not built yet, must fail: " << r.what;
      }
    }
    for (const Diagnostic& d : analysis.diagnostics) {
      EXPECT_NE(d.severity, Severity::kError) << d.message;
    }
  }
}

}  // namespace
}  // namespace mechanist
