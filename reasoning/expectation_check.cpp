#include "reasoning/expectation_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

std::string PartList(const Assembly& assembly, const std::vector<std::size_t>& parts) {
  std::string s;
  for (std::size_t p : parts) s += (s.empty() ? "" : ", ") + assembly.part(p).id;
  return s;
}

ExpectationResult CheckPair(const Assembly& assembly, const Analysis& analysis,
                            const Expectation& e) {
  ExpectationResult r;
  const std::string a = assembly.FeatureName(e.pair[0]);
  const std::string b = assembly.FeatureName(e.pair[1]);
  r.what = e.pair_type ? fmt::format("pair {} + {} is {}", a, b, ToString(*e.pair_type))
                       : fmt::format("pair {} + {}", a, b);
  std::vector<std::string> found;
  for (const Pair& p : analysis.pairs) {
    if ((p.a == e.pair[0] && p.b == e.pair[1]) || (p.a == e.pair[1] && p.b == e.pair[0])) {
      found.emplace_back(ToString(p.type));
      if (!e.pair_type || *e.pair_type == p.type) r.passed = true;
    }
  }
  if (found.empty()) {
    r.detail = "no pair between these features";
    for (const Diagnostic& d : analysis.diagnostics) {
      if (std::find(d.features.begin(), d.features.end(), a) != d.features.end() &&
          std::find(d.features.begin(), d.features.end(), b) != d.features.end()) {
        fmt::format_to(std::back_inserter(r.detail), "; {}: {}", d.code, d.message);
      }
    }
  } else {
    r.detail = "found";
    for (const std::string& t : found) r.detail += " " + t;
  }
  return r;
}

ExpectationResult CheckSameSubassembly(const Assembly& assembly, const Analysis& analysis,
                                       const Expectation& e) {
  ExpectationResult r;
  r.what = fmt::format("same subassembly: {}", PartList(assembly, e.parts));
  const std::size_t first = analysis.subassembly_of[e.parts.front()];
  r.passed = std::all_of(e.parts.begin(), e.parts.end(),
                         [&](std::size_t p) { return analysis.subassembly_of[p] == first; });
  if (r.passed) {
    r.detail = fmt::format("all in subassembly S{}", first + 1);
  } else {
    for (std::size_t p : e.parts) {
      fmt::format_to(std::back_inserter(r.detail), "{}{} in S{}", r.detail.empty() ? "" : ", ",
                     assembly.part(p).id, analysis.subassembly_of[p] + 1);
    }
  }
  return r;
}

ExpectationResult CheckDiagnostic(const Assembly& assembly, const Analysis& analysis,
                                  const Expectation& e) {
  ExpectationResult r;
  r.what = e.parts.empty() ? fmt::format("diagnostic \"{}\"", e.diagnostic)
                           : fmt::format("diagnostic \"{}\" about {}", e.diagnostic,
                                         PartList(assembly, e.parts));
  for (const Diagnostic& d : analysis.diagnostics) {
    const bool text = d.code == e.diagnostic || d.message.find(e.diagnostic) != std::string::npos;
    const bool parts = std::all_of(e.parts.begin(), e.parts.end(), [&](std::size_t p) {
      return std::find(d.parts.begin(), d.parts.end(), assembly.part(p).id) != d.parts.end();
    });
    if (text && parts) {
      r.passed = true;
      r.detail = fmt::format("{}: {}", d.code, d.message);
      return r;
    }
  }
  r.detail = fmt::format("no such diagnostic among {}", analysis.diagnostics.size());
  return r;
}

ExpectationResult CheckRatio(const Assembly& assembly, const Analysis& analysis,
                             const Expectation& e) {
  ExpectationResult r;
  const std::size_t part = *e.part;
  r.what = e.feature ? fmt::format("ratio of {}/{} is {}", assembly.part(part).id,
                                   assembly.feature(*e.feature).id, e.ratio.text)
                     : fmt::format("ratio of {} is {}", assembly.part(part).id, e.ratio.text);
  const DrivenMotion* motion = analysis.motion.ForExpectations();
  if (!motion) {
    r.detail = "the file has no drivers";
    return r;
  }
  if (!motion->possible) {
    r.detail = motion->reason;
    return r;
  }
  const PartMotion& m = motion->parts[part];
  const bool turns = m.kind == MotionKind::kRotation || m.kind == MotionKind::kScrew;
  const ExactReal& found = e.feature ? motion->features[part][e.feature->feature].Ratio(turns)
                                     : (turns ? m.rotation : m.translation);
  if (e.ratio.exact) {
    const Rational expected(e.ratio.numerator, e.ratio.denominator);
    r.passed = found.is_exact() && *found.exact() == expected;
    r.detail = fmt::format("found {}{}", found.ToString(), found.is_exact() ? "" : " (not exact)");
  } else {
    r.passed =
        std::abs(found.value() - e.ratio.value) <= std::max(1e-9 * std::abs(e.ratio.value), 1e-12);
    r.detail = fmt::format("found {}", FormatNumber(found.value(), 12));
  }
  return r;
}

ExpectationResult CheckMoves(const Assembly& assembly, const Analysis& analysis,
                             const Expectation& e) {
  ExpectationResult r;
  const std::size_t part = *e.part;
  r.what = fmt::format("{} {}", assembly.part(part).id, e.flag ? "moves" : "does not move");
  std::string moved_by;
  for (const DrivenMotion& m : analysis.motion.driven) {
    // A held driver (rate 0) moves nothing; its entry is what it would drive if released.
    if (!m.driver || assembly.drivers()[*m.driver].rate == 0.0 || !m.possible ||
        m.parts[part].kind == MotionKind::kNone) {
      continue;
    }
    moved_by += (moved_by.empty() ? "" : ", ") + assembly.drivers()[*m.driver].id;
  }
  r.passed = moved_by.empty() != e.flag;
  r.detail = moved_by.empty() ? "no driver moves it" : fmt::format("moved by driver {}", moved_by);
  return r;
}

ExpectationResult CheckMobility(const Analysis& analysis, const Expectation& e) {
  ExpectationResult r;
  r.what = fmt::format("mobility {}", e.mobility);
  const Mobility& m = analysis.motion.mobility;
  r.passed = m.dof == e.mobility;
  r.detail = fmt::format("found {} ({} redundant constraints)", m.dof, m.redundant);
  return r;
}

ExpectationResult CheckAssemblable(const Assembly& assembly, const AssemblyPlan* plan,
                                   const Expectation& e) {
  ExpectationResult r;
  r.what = fmt::format("assemblable {}", e.flag ? "true" : "false");
  if (plan == nullptr) {
    r.detail = "not evaluated: no assembly plan was given";
    return r;
  }
  r.passed = plan->assemblable == e.flag;
  std::size_t blocked = plan->unplaced.size(), blocked_pins = 0;
  const auto count_pins = [&](const std::vector<PinInsertion>& pins) {
    for (const PinInsertion& p : pins) blocked_pins += p.clear ? 0 : 1;
  };
  count_pins(plan->base_pins);
  for (const InsertionStep& s : plan->steps) {
    blocked += s.clear ? 0 : 1;
    count_pins(s.pins);
  }
  if (plan->assemblable) {
    r.detail = fmt::format("found assemblable ({} insertions {})", plan->steps.size(),
                           plan->from_steps ? "from the file's steps" : "found by disassembly");
  } else {
    r.detail = fmt::format("found not assemblable: {} clash{}, {} blocked insertion{}",
                           plan->clashes.size(), plan->clashes.size() == 1 ? "" : "es", blocked,
                           blocked == 1 ? "" : "s");
    if (blocked_pins > 0) {
      fmt::format_to(std::back_inserter(r.detail), ", {} pin{} the file leaves out blocked",
                     blocked_pins, blocked_pins == 1 ? "" : "s");
    }
    if (!plan->clashes.empty()) {
      fmt::format_to(std::back_inserter(r.detail), " (first clash: {} and {})",
                     assembly.part(plan->clashes.front().part_a).id,
                     assembly.part(plan->clashes.front().part_b).id);
    }
  }
  return r;
}

}  // namespace

ExpectationResult CheckExpectation(const Assembly& assembly, const Analysis& analysis,
                                   const Expectation& e, const AssemblyPlan* plan) {
  ExpectationResult r;
  switch (e.kind) {
    case Expectation::Kind::kPair:
      r = CheckPair(assembly, analysis, e);
      break;
    case Expectation::Kind::kSameSubassembly:
      r = CheckSameSubassembly(assembly, analysis, e);
      break;
    case Expectation::Kind::kDiagnostic:
      r = CheckDiagnostic(assembly, analysis, e);
      break;
    case Expectation::Kind::kRatio:
      r = CheckRatio(assembly, analysis, e);
      break;
    case Expectation::Kind::kMoves:
      r = CheckMoves(assembly, analysis, e);
      break;
    case Expectation::Kind::kMobility:
      r = CheckMobility(analysis, e);
      break;
    case Expectation::Kind::kAssemblable:
      r = CheckAssemblable(assembly, plan, e);
      break;
  }
  r.pointer = e.pointer;
  return r;
}

std::vector<ExpectationResult> CheckExpectations(const Assembly& assembly, const Analysis& analysis,
                                                 const AssemblyPlan* plan) {
  std::vector<ExpectationResult> results;
  for (const Expectation& e : assembly.expectations()) {
    results.push_back(CheckExpectation(assembly, analysis, e, plan));
  }
  return results;
}

}  // namespace mechanist
