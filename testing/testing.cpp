#include "mechanist/testing.h"

#include <stdexcept>

#include "io/assembly_reader.h"
#include "io/load_assembly.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/expectation_check.h"

namespace mechanist::testing {
namespace {

::testing::AssertionResult Verdict(const Mechanism& m, const Expectation& e) {
  const ExpectationResult r = CheckExpectation(m.assembly(), m.analysis(), e);
  return (r.passed ? ::testing::AssertionSuccess() : ::testing::AssertionFailure())
         << r.what << " (" << r.detail << ")";
}

/// The index of a part, or a failure naming what is missing.
std::optional<std::size_t> PartIndex(const Mechanism& m, const std::string& id,
                                     ::testing::AssertionResult& failure) {
  const auto part = m.assembly().FindPart(id);
  if (!part) failure = ::testing::AssertionFailure() << "no part \"" << id << "\"";
  return part;
}

std::optional<FeatureRef> FeatureIndex(const Mechanism& m, const std::string& path,
                                       ::testing::AssertionResult& failure) {
  const auto f = m.assembly().FindFeature(path);
  if (!f) failure = ::testing::AssertionFailure() << "no feature \"" << path << "\"";
  return f;
}

}  // namespace

Mechanism::Mechanism(Assembly assembly)
    : assembly_(std::move(assembly)), analysis_(Analyze(assembly_)) {}

Mechanism Mechanism::Load(const std::filesystem::path& file) {
  return Mechanism(LoadAssembly(file, {.adjust = true}));
}

::testing::AssertionResult HasRatio(const Mechanism& m, const std::string& feature,
                                    const std::string& ratio) {
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  const auto f = FeatureIndex(m, feature, failure);
  if (!f) return failure;
  const auto parsed = ParseRatio(ratio);
  if (!parsed) return ::testing::AssertionFailure() << "\"" << ratio << "\" is not a ratio";
  Expectation e;
  e.kind = Expectation::Kind::kRatio;
  e.part = f->part;
  e.feature = *f;
  e.ratio = *parsed;
  return Verdict(m, e);
}

::testing::AssertionResult HasPair(const Mechanism& m, const std::string& a, const std::string& b,
                                   std::optional<PairType> type) {
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  const auto fa = FeatureIndex(m, a, failure);
  const auto fb = FeatureIndex(m, b, failure);
  if (!fa || !fb) return failure;
  Expectation e;
  e.kind = Expectation::Kind::kPair;
  e.pair = {*fa, *fb};
  e.pair_type = type;
  return Verdict(m, e);
}

::testing::AssertionResult IsAssemblable(const Mechanism& m, bool assemblable) {
  Expectation e;
  e.kind = Expectation::Kind::kAssemblable;
  e.flag = assemblable;
  const AssemblyPlan plan = PlanAssembly(m.assembly(), m.analysis(), CollisionModel(m.assembly()));
  const ExpectationResult r = CheckExpectation(m.assembly(), m.analysis(), e, &plan);
  return (r.passed ? ::testing::AssertionSuccess() : ::testing::AssertionFailure())
         << r.what << " (" << r.detail << ")";
}

::testing::AssertionResult HasMobility(const Mechanism& m, int dof) {
  Expectation e;
  e.kind = Expectation::Kind::kMobility;
  e.mobility = dof;
  return Verdict(m, e);
}

::testing::AssertionResult InSameSubassembly(const Mechanism& m,
                                             const std::vector<std::string>& parts) {
  if (parts.empty()) return ::testing::AssertionFailure() << "no parts given";
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  Expectation e;
  e.kind = Expectation::Kind::kSameSubassembly;
  for (const std::string& id : parts) {
    const auto p = PartIndex(m, id, failure);
    if (!p) return failure;
    e.parts.push_back(*p);
  }
  return Verdict(m, e);
}

::testing::AssertionResult Moves(const Mechanism& m, const std::string& part, bool moves) {
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  const auto p = PartIndex(m, part, failure);
  if (!p) return failure;
  Expectation e;
  e.kind = Expectation::Kind::kMoves;
  e.part = *p;
  e.flag = moves;
  return Verdict(m, e);
}

::testing::AssertionResult HasDiagnostic(const Mechanism& m, const std::string& text,
                                         const std::vector<std::string>& parts) {
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  Expectation e;
  e.kind = Expectation::Kind::kDiagnostic;
  e.diagnostic = text;
  for (const std::string& id : parts) {
    const auto p = PartIndex(m, id, failure);
    if (!p) return failure;
    e.parts.push_back(*p);
  }
  return Verdict(m, e);
}

}  // namespace mechanist::testing
