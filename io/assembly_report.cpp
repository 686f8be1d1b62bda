#include "io/assembly_report.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "kernel/assembly/assembly_check.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

using Json = nlohmann::ordered_json;

// Report numbers carry 9 significant digits, so that rounding noise never shows and the same
// input gives byte-identical reports.
double Num(double x) { return RoundToSignificant(x); }

Json Point(const Eigen::Vector3d& p) { return Json::array({Num(p.x()), Num(p.y()), Num(p.z())}); }

std::string Text(const Eigen::Vector3d& p) {
  return fmt::format("({}, {}, {})", FormatNumber(p.x()), FormatNumber(p.y()), FormatNumber(p.z()));
}

std::string PairText(const Assembly& assembly, const Analysis& analysis, std::size_t k) {
  const Pair& p = analysis.pairs.at(k);
  return fmt::format("{} {} - {}", ToString(p.type), assembly.FeatureName(p.a),
                     assembly.FeatureName(p.b));
}

Json ContactJson(const Assembly& assembly, const Analysis& analysis, const PartContact& c) {
  Json j;
  j["parts"] = Json::array({assembly.part(c.part_a).id, assembly.part(c.part_b).id});
  j["verdict"] = std::string(ToString(c.verdict));
  j["depth"] = std::isfinite(c.measure.depth) ? Json(Num(c.measure.depth)) : Json(nullptr);
  j["depth_bound"] = Num(c.measure.depth_bound);
  Json open = Json::array();  // the parts whose open sheets left the depth unknown
  if (c.measure.open[0]) open.push_back(assembly.part(c.part_a).id);
  if (c.measure.open[1]) open.push_back(assembly.part(c.part_b).id);
  j["open_sheets"] = open;
  j["location"] = Point(c.measure.p_W);
  j["contained"] = c.measure.contained == 0
                       ? Json(nullptr)
                       : Json(assembly.part(c.measure.contained == 1 ? c.part_a : c.part_b).id);
  j["pair"] = c.pair ? Json(PairText(assembly, analysis, *c.pair)) : Json(nullptr);
  return j;
}

// "the mesh of P is an open sheet: it has no inside" for the parts whose meshes made the
// depth unknown.
std::string OpenSheets(const Assembly& assembly, const PartContact& c) {
  std::string ids;
  for (int k = 0; k < 2; ++k) {
    if (c.measure.open[k])
      ids += (ids.empty() ? "" : " and ") + assembly.part(k ? c.part_b : c.part_a).id;
  }
  const bool both = c.measure.open[0] && c.measure.open[1];
  return fmt::format("the mesh{}{}{} an open sheet with no inside", both ? "es of " : " of ", ids,
                     both ? " are" : " is");
}

std::string ContactText(const Assembly& assembly, const Analysis& analysis, const PartContact& c) {
  std::string s;
  auto out = std::back_inserter(s);
  fmt::format_to(out, "{} and {}: {}", assembly.part(c.part_a).id, assembly.part(c.part_b).id,
                 ToString(c.verdict));
  if (std::isfinite(c.measure.depth)) {
    fmt::format_to(out, ", depth {} mm", FormatNumber(c.measure.depth));
  } else {
    fmt::format_to(out, ", depth unknown ({})", OpenSheets(assembly, c));
  }
  fmt::format_to(out, " at {}", Text(c.measure.p_W));
  if (c.measure.contained != 0) {
    fmt::format_to(out, ", {} lies entirely inside the other",
                   assembly.part(c.measure.contained == 1 ? c.part_a : c.part_b).id);
  }
  if (c.pair) fmt::format_to(out, " ({})", PairText(assembly, analysis, *c.pair));
  return s;
}

// The holes a pin goes through, "A/hole_1, B/hole_1".
std::string HolesText(const Assembly& assembly, const std::vector<FeatureRef>& holes) {
  std::string t;
  for (const FeatureRef& h : holes) t += (t.empty() ? "" : ", ") + assembly.FeatureName(h);
  return t;
}

// The holes a pin goes through, by name.
Json HolesJson(const Assembly& assembly, const std::vector<FeatureRef>& holes) {
  Json names = Json::array();
  for (const FeatureRef& h : holes) names.push_back(assembly.FeatureName(h));
  return names;
}

Json BlockedJson(const Assembly& assembly, const std::vector<InsertionObstacle>& blocked_by) {
  Json blocked = Json::array();
  for (const InsertionObstacle& o : blocked_by) {
    const bool part = o.pin.empty();
    blocked.push_back(
        {{"part", part ? Json(assembly.part(o.part).id) : Json(nullptr)},
         {"pin", part ? Json(nullptr) : HolesJson(assembly, o.pin)},
         {"travel", Num(o.travel)},
         {"short_by", Num(o.short_by)},
         {"location", Point(o.p_W)},
         {"held_by", o.held_by ? Json(assembly.FeatureName(*o.held_by)) : Json(nullptr)},
         {"clash_at_rest", o.clash_at_rest}});
  }
  return blocked;
}

std::string BlockedText(const Assembly& assembly, bool clear,
                        const std::vector<InsertionObstacle>& blocked_by) {
  if (clear) return "clear";
  std::string t = "blocked by ";
  auto out = std::back_inserter(t);
  for (std::size_t k = 0; k < blocked_by.size(); ++k) {
    const InsertionObstacle& o = blocked_by[k];
    const std::string what =
        o.pin.empty() ? assembly.part(o.part).id
                      : "the pin the file leaves out through " + HolesText(assembly, o.pin);
    if (o.held_by) {
      // Its fit, not a contact: the part cannot travel across the fit's axis.
      fmt::format_to(out, "{}{}, whose {} holds it across its travel (an axial fit)", k ? "; " : "",
                     what, assembly.FeatureName(*o.held_by));
    } else if (o.clash_at_rest) {
      fmt::format_to(out, "{}{} where it is (they clash there: below) at {}", k ? "; " : "", what,
                     Text(o.p_W));
    } else {
      fmt::format_to(out, "{}{} after {} mm ({} mm short of its place) at {}", k ? "; " : "", what,
                     FormatNumber(o.travel), FormatNumber(o.short_by), Text(o.p_W));
    }
  }
  return t;
}

Json PinsJson(const Assembly& assembly, const std::vector<PinInsertion>& pins) {
  Json list = Json::array();
  for (const PinInsertion& p : pins) {
    list.push_back({{"holes", HolesJson(assembly, p.holes)},
                    {"diameter", Num(p.diameter)},
                    {"ends", Json::array({Point(p.ends_W[0]), Point(p.ends_W[1])})},
                    {"direction", Point(p.direction_W)},
                    {"travel", Num(p.travel)},
                    {"clear", p.clear},
                    {"blocked_by", BlockedJson(assembly, p.blocked_by)}});
  }
  return list;
}

// "then the pin the file leaves out, 3.2 mm, through A/hole_1, B/hole_1 along (0, 0, 1),
// 12 mm: clear", one line per pin, each indented by `indent`; `then` false for an unplaced
// part's attempt, whose pins go in at no point ("its pin the file leaves out, ...").
std::string PinsText(const Assembly& assembly, const std::vector<PinInsertion>& pins,
                     std::string_view indent, bool then) {
  std::string t;
  auto out = std::back_inserter(t);
  for (const PinInsertion& p : pins) {
    fmt::format_to(out, "{}{} pin the file leaves out, {} mm, through {} along {}, {} mm: {}\n",
                   indent, then ? "then the" : "its", FormatNumber(p.diameter),
                   HolesText(assembly, p.holes), Text(p.direction_W), FormatNumber(p.travel),
                   BlockedText(assembly, p.clear, p.blocked_by));
  }
  return t;
}

Json StepJson(const Assembly& assembly, const Analysis& analysis, const InsertionStep& s) {
  Json j;
  j["part"] = assembly.part(s.part).id;
  Json carried = Json::array();
  for (const std::size_t c : s.carried) carried.push_back(assembly.part(c).id);
  j["carried"] = carried;
  j["feature"] = s.feature ? Json(assembly.FeatureName(*s.feature)) : Json(nullptr);
  j["into"] = s.into ? Json(assembly.FeatureName(*s.into)) : Json(nullptr);
  j["direction"] = Point(s.direction_W);
  j["travel"] = Num(s.travel);
  j["clear"] = s.clear;
  j["blocked_by"] = BlockedJson(assembly, s.blocked_by);
  j["pair"] = s.pair ? Json(PairText(assembly, analysis, *s.pair)) : Json(nullptr);
  j["pins"] = PinsJson(assembly, s.pins);
  j["subassembly"] = s.subassembly;
  j["apart_for"] = s.apart_for ? Json(*s.apart_for) : Json(nullptr);
  return j;
}

// "A + B (A/hole_1) into C/shaft_1 along (0, 0, 1), 12 mm: clear; makes ...", after "apart,
// into the sub-assembly of step 5: " for a step that puts the sub-assembly of step 5 together,
// or "sub-assembly " for a sub-assembly's insertion.
std::string StepText(const Assembly& assembly, const Analysis& analysis, const InsertionStep& s) {
  std::string t = s.apart_for
                      ? fmt::format("apart, into the sub-assembly of step {}: ", *s.apart_for + 1)
                  : s.subassembly ? "sub-assembly "
                                  : "";
  t += assembly.part(s.part).id;
  auto out = std::back_inserter(t);
  for (const std::size_t c : s.carried) fmt::format_to(out, " + {}", assembly.part(c).id);
  if (s.feature) fmt::format_to(out, " ({})", assembly.FeatureName(*s.feature));
  if (s.into) fmt::format_to(out, " into {}", assembly.FeatureName(*s.into));
  fmt::format_to(out, " along {}, {} mm: {}", Text(s.direction_W), FormatNumber(s.travel),
                 BlockedText(assembly, s.clear, s.blocked_by));
  if (s.pair) fmt::format_to(out, "; makes {}", PairText(assembly, analysis, *s.pair));
  return t;
}

std::string DriverUnit(const Assembly& assembly, const OperationCheck& check) {
  if (!check.driver) return "time units (all drivers at their rates)";
  const Driver& d = assembly.drivers()[*check.driver];
  return d.motion == Driver::Motion::kRotation
             ? fmt::format("rev of {}", d.id)
             : fmt::format("{} of {}", assembly.units().length, d.id);
}

Json ClashJson(const Assembly& assembly, const OperationClash& c) {
  return {{"parts", Json::array({assembly.part(c.part_a).id, assembly.part(c.part_b).id})},
          {"at", Num(c.at)},
          {"distance", Num(c.distance)},
          {"location", Point(c.p_W)}};
}

}  // namespace

void WriteSkippedParts(const Assembly& assembly, std::ostream& out) {
  const std::vector<std::size_t> skipped = PartsWithoutGeometry(assembly);
  if (skipped.empty()) return;
  out << "  skipped, no geometry (features only):";
  for (std::size_t k = 0; k < skipped.size(); ++k) {
    out << (k ? ", " : " ") << assembly.PartId(skipped[k]);
  }
  out << "\n";
}

namespace {

Json SkippedJson(const Assembly& assembly) {
  Json ids = Json::array();
  for (const std::size_t p : PartsWithoutGeometry(assembly)) ids.push_back(assembly.PartId(p));
  return ids;
}

}  // namespace

void WriteOperationSummary(const Assembly& assembly, const OperationCheck& check,
                           std::ostream& out) {
  out << "sweep over " << FormatNumber(check.amount) << " " << DriverUnit(assembly, check) << ": ";
  if (!check.possible) {
    out << "cannot run: " << check.reason << "\n";
    return;
  }
  out << check.clashes.size() << " clashes, " << check.undecided.size() << " undecided ("
      << check.pairs_swept << " pairs of parts swept)\n";
  WriteSkippedParts(assembly, out);
  for (const OperationClash& c : check.clashes) {
    out << "  clash: " << assembly.part(c.part_a).id << " and " << assembly.part(c.part_b).id
        << " meet at " << FormatNumber(c.at) << ", at " << Text(c.p_W) << "\n";
  }
  if (!check.touching_at_rest.empty()) {
    out << "  not swept, touching at rest:";
    for (const auto& [a, b] : check.touching_at_rest) {
      out << " " << assembly.part(a).id << "+" << assembly.part(b).id;
    }
    out << "\n";
  }
  for (const InferredCoupling& i : check.inferred) {
    out << "  " << (i.carried ? "carried: " : "jam: ") << assembly.part(i.pusher).id << " meets "
        << assembly.part(i.pushed).id << ", which nothing drives or holds, at "
        << FormatNumber(i.at) << ", at " << Text(i.p_W)
        << (i.carried ? ": it is pushed along from there (inferred coupling)"
                      : ": it cannot give way, the drive jams there")
        << "\n";
  }
  if (check.after) {
    const DrivenMotion* after = check.driver ? &check.after->motion.driven[*check.driver]
                                             : check.after->motion.ForExpectations();
    if (after) {
      out << "  then moving:";
      for (std::size_t p = 0; p < after->parts.size(); ++p) {
        const PartMotion& m = after->parts[p];
        if (m.kind == MotionKind::kNone) continue;
        out << " " << assembly.part(p).id << " ("
            << (m.kind == MotionKind::kTranslation
                    ? fmt::format("{} along ", m.translation.ToString())
                    : fmt::format("{} rev about ", m.rotation.ToString()))
            << Text(m.axis_W) << ")";
      }
      out << "\n";
    }
  }
  for (const OperationClash& c : check.undecided) {
    out << "  undecided: " << assembly.part(c.part_a).id << " and " << assembly.part(c.part_b).id
        << " stay within " << FormatNumber(c.distance) << " mm from " << FormatNumber(c.at) << "\n";
  }
}

std::string OperationJson(const Assembly& assembly, const OperationCheck& check) {
  Json report;
  report["assembly"] = assembly.name();
  report["skipped"] = SkippedJson(assembly);
  report["driver"] = check.driver ? Json(assembly.drivers()[*check.driver].id) : Json(nullptr);
  report["amount"] = Num(check.amount);
  report["possible"] = check.possible;
  report["reason"] = check.reason;
  report["pairs_swept"] = check.pairs_swept;
  Json clashes = Json::array(), undecided = Json::array(), inferred = Json::array();
  for (const InferredCoupling& i : check.inferred) {
    inferred.push_back({{"pusher", assembly.part(i.pusher).id},
                        {"pushed", assembly.part(i.pushed).id},
                        {"at", Num(i.at)},
                        {"location", Point(i.p_W)},
                        {"carried", i.carried}});
  }
  for (const OperationClash& c : check.clashes) clashes.push_back(ClashJson(assembly, c));
  for (const OperationClash& c : check.undecided) undecided.push_back(ClashJson(assembly, c));
  report["clashes"] = clashes;
  report["undecided"] = undecided;
  report["inferred"] = inferred;
  Json touching = Json::array();
  for (const auto& [a, b] : check.touching_at_rest) {
    touching.push_back(Json::array({assembly.part(a).id, assembly.part(b).id}));
  }
  report["touching_at_rest"] = touching;
  return report.dump(2) + "\n";
}

void WriteInterferenceSummary(const Assembly& assembly, const Analysis& analysis,
                              const std::vector<PartContact>& contacts, std::ostream& out) {
  std::size_t clashes = 0, fits = 0, touching = 0;
  for (const PartContact& c : contacts) {
    clashes += c.verdict == ContactVerdict::kClash;
    fits += c.verdict == ContactVerdict::kDesignedFit;
    touching += c.verdict == ContactVerdict::kTouching;
  }
  out << "interference: " << clashes << " clashes, " << fits << " designed fits, " << touching
      << " touching contacts (tolerance " << FormatNumber(assembly.tolerance().length) << " mm)\n";
  WriteSkippedParts(assembly, out);
  for (const ContactVerdict v : {ContactVerdict::kClash, ContactVerdict::kDesignedFit}) {
    for (const PartContact& c : contacts) {
      if (c.verdict == v) out << "  " << ContactText(assembly, analysis, c) << "\n";
    }
  }
}

std::string InterferenceJson(const Assembly& assembly, const Analysis& analysis,
                             const std::vector<PartContact>& contacts) {
  Json report;
  report["assembly"] = assembly.name();
  report["skipped"] = SkippedJson(assembly);
  std::size_t clashes = 0;
  Json list = Json::array();
  for (const PartContact& c : contacts) {
    clashes += c.verdict == ContactVerdict::kClash;
    list.push_back(ContactJson(assembly, analysis, c));
  }
  report["clashes"] = clashes;
  report["contacts"] = list;
  return report.dump(2) + "\n";
}

void WriteAssemblySummary(const Assembly& assembly, const Analysis& analysis,
                          const AssemblyPlan& plan, std::ostream& out) {
  out << "assemblable: " << (plan.assemblable ? "yes" : "no") << " ("
      << (plan.from_steps ? "the file's steps" : "sequence found by disassembly") << ")\n";
  WriteSkippedParts(assembly, out);
  out << "in place first:";
  for (const std::size_t p : plan.base) out << " " << assembly.part(p).id;
  // The search leaves them where they are: every step finds them in place.
  if (!plan.from_steps && std::any_of(plan.unplaced.begin(), plan.unplaced.end(),
                                      [](const InsertionStep& s) { return !s.apart_for; })) {
    std::size_t parts = 0;  // each unplaced part with what travels with it
    for (const InsertionStep& s : plan.unplaced) parts += s.apart_for ? 0 : 1 + s.carried.size();
    out << fmt::format(", and the {} that cannot be placed (below), which the steps find in place",
                       parts == 1 ? "part" : fmt::format("{} parts", parts));
  }
  out << "\n" << PinsText(assembly, plan.base_pins, "  ", true);
  for (std::size_t k = 0; k < plan.steps.size(); ++k) {
    out << "  " << k + 1 << ". " << StepText(assembly, analysis, plan.steps[k]) << "\n"
        << PinsText(assembly, plan.steps[k].pins, "     ", true);
  }
  for (const InsertionStep& s : plan.unplaced) {
    out << "  cannot be placed: " << StepText(assembly, analysis, s) << "\n"
        << PinsText(assembly, s.pins, "     ", false);
  }
  for (const PartContact& c : plan.clashes) {
    out << "  clash: " << ContactText(assembly, analysis, c) << "\n";
  }
}

std::string AssemblyPlanJson(const Assembly& assembly, const Analysis& analysis,
                             const AssemblyPlan& plan) {
  Json report;
  report["assembly"] = assembly.name();
  report["skipped"] = SkippedJson(assembly);
  report["assemblable"] = plan.assemblable;
  report["source"] = plan.from_steps ? "steps" : "search";
  Json base = Json::array();
  for (const std::size_t p : plan.base) base.push_back(assembly.part(p).id);
  report["base"] = base;
  report["base_pins"] = PinsJson(assembly, plan.base_pins);
  Json steps = Json::array(), unplaced = Json::array(), clashes = Json::array();
  for (const InsertionStep& s : plan.steps) steps.push_back(StepJson(assembly, analysis, s));
  for (const InsertionStep& s : plan.unplaced) unplaced.push_back(StepJson(assembly, analysis, s));
  for (const PartContact& c : plan.clashes) clashes.push_back(ContactJson(assembly, analysis, c));
  report["steps"] = steps;
  report["unplaced"] = unplaced;
  report["clashes"] = clashes;
  return report.dump(2) + "\n";
}

}  // namespace mechanist
