#include "io/adjustment_report.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <nlohmann/json.hpp>

#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

using Json = nlohmann::ordered_json;

// Solved values carry the solver's noise (1e-11): reports keep 9 decimals, so that they are
// byte-identical wherever the noise differs.
double Num(double x) { return RoundToSignificant(std::round(x * 1e9) / 1e9); }

// Four decimals for the summary, without "-0".
std::string Fixed(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", std::abs(x) < 5e-5 ? 0.0 : x);
  return text;
}

// An adjustment's value in the file's units, and the unit's name.
double InFileUnits(const Assembly& assembly, const Adjustment& a, double value) {
  return a.kind == Adjustment::Kind::kRotate ? value / assembly.units().rad_per_angle
                                             : value / assembly.units().mm_per_length;
}

const std::string& UnitOf(const Assembly& assembly, const Adjustment& a) {
  return a.kind == Adjustment::Kind::kRotate ? assembly.units().angle : assembly.units().length;
}

std::string Degrees(double radians) { return fmt::format("{} deg", Fixed(radians * 180.0 / M_PI)); }

std::string Mm(double mm) { return fmt::format("{} mm", Fixed(mm)); }

std::string Describe(const GoalError& e) {
  std::string s =
      fmt::format("{} {}, axes off by {}", e.apexes ? "apexes apart by" : "centre distance off by",
                  Mm(e.distance), Degrees(e.angle));
  if (std::abs(e.axial) >= 5e-5) {
    fmt::format_to(std::back_inserter(s), ", axial offset {}", Mm(e.axial));
  }
  if (!e.engaged) s += ", not engaged along the axes";
  return s;
}

Json ErrorJson(const GoalError& e) {
  return Json{{"distance", Num(e.distance)},
              {"angle", Num(e.angle * 180.0 / M_PI)},
              {"axial", Num(e.axial)},
              {"engaged", e.engaged},
              {"met", e.met}};
}

const char* BoundName(AdjustmentOutcome::Bound b) {
  return b == AdjustmentOutcome::Bound::kLower ? "lower" : "upper";
}

}  // namespace

void WriteAdjustmentSummary(const Assembly& assembly, const AdjustmentSummary& summary,
                            std::ostream& out) {
  out << "adjust: " << assembly.adjustments().size() << " adjustment"
      << (assembly.adjustments().size() == 1 ? "" : "s") << ", " << assembly.goals().size()
      << " goal" << (assembly.goals().size() == 1 ? "" : "s") << "; solver "
      << ToString(summary.solver.status) << " after " << summary.solver.iterations
      << " iterations (cost " << FormatNumber(summary.solver.initial_cost, 3) << " -> "
      << FormatNumber(summary.solver.final_cost, 3) << ")\n";
  for (std::size_t k = 0; k < assembly.adjustments().size(); ++k) {
    const Adjustment& a = assembly.adjustments()[k];
    const AdjustmentOutcome& o = summary.adjustments[k];
    const bool rotate = a.kind == Adjustment::Kind::kRotate;
    out << "  " << a.id << ": " << (rotate ? "rotate " : "translate ") << assembly.part(a.moves).id
        << (rotate ? " about " : " along ") << assembly.FeatureName(a.axis);
    if (!o.used) {
      out << ": no goal depends on it, left at 0";
    } else {
      out << " by " << Fixed(InFileUnits(assembly, a, o.value)) << " " << UnitOf(assembly, a)
          << " (range " << FormatNumber(InFileUnits(assembly, a, a.lower)) << " .. "
          << FormatNumber(InFileUnits(assembly, a, a.upper)) << ")";
      if (o.active != AdjustmentOutcome::Bound::kNone)
        out << ", at its " << BoundName(o.active) << " bound";
      out << "; carries";
      for (const std::size_t p : o.carried) out << " " << assembly.part(p).id;
    }
    // Locked, the loose fastenings that allowed it are tightened (ApplyAdjustments).
    for (std::size_t f = 0; f < o.loosened.size(); ++f) {
      out << (f ? ", " : "; locked, tightens ") << assembly.FeatureName(o.loosened[f]);
    }
    out << "\n";
  }
  for (std::size_t g = 0; g < assembly.goals().size(); ++g) {
    const Goal& goal = assembly.goals()[g];
    const GoalError& after = summary.after[g];
    out << "  goal " << (goal.kind == Goal::Kind::kMesh ? "mesh " : "coaxial ")
        << assembly.FeatureName(goal.features[0]) << " with "
        << assembly.FeatureName(goal.features[1]) << ": " << (after.met ? "met" : "NOT met") << " ("
        << Describe(after) << "; before: " << Describe(summary.before[g]) << ")";
    if (!after.met) {
      for (std::size_t k = 0; k < summary.adjustments.size(); ++k) {
        const AdjustmentOutcome& o = summary.adjustments[k];
        if (o.used && o.active != AdjustmentOutcome::Bound::kNone) {
          out << "; " << assembly.adjustments()[k].id << " is held at its " << BoundName(o.active)
              << " bound";
        }
      }
    }
    out << "\n";
  }
  out << (summary.all_met ? "all goals met\n" : "some goals are not met\n");
}

std::string AdjustmentJson(const Assembly& assembly, const AdjustmentSummary& summary) {
  Json report;
  report["assembly"] = assembly.name();
  report["all_met"] = summary.all_met;
  report["solver"] = Json{{"status", std::string(ToString(summary.solver.status))},
                          {"message", summary.solver.message},
                          {"iterations", summary.solver.iterations},
                          {"initial_cost", Num(summary.solver.initial_cost)},
                          {"final_cost", Num(summary.solver.final_cost)}};
  report["adjustments"] = Json::array();
  for (std::size_t k = 0; k < assembly.adjustments().size(); ++k) {
    const Adjustment& a = assembly.adjustments()[k];
    const AdjustmentOutcome& o = summary.adjustments[k];
    Json carried = Json::array(), tightened = Json::array();
    for (const std::size_t p : o.carried) carried.push_back(assembly.part(p).id);
    for (const FeatureRef f : o.loosened) tightened.push_back(assembly.FeatureName(f));
    report["adjustments"].push_back(Json{
        {"id", a.id},
        {"moves", assembly.part(a.moves).id},
        {"kind", a.kind == Adjustment::Kind::kRotate ? "rotate" : "translate"},
        {"axis", assembly.FeatureName(a.axis)},
        {"value", Num(InFileUnits(assembly, a, o.value))},
        {"unit", UnitOf(assembly, a)},
        {"used", o.used},
        {"active_bound",
         o.active == AdjustmentOutcome::Bound::kNone ? Json(nullptr) : Json(BoundName(o.active))},
        {"carried", carried},
        {"tightened", tightened}});
  }
  report["goals"] = Json::array();
  for (std::size_t g = 0; g < assembly.goals().size(); ++g) {
    const Goal& goal = assembly.goals()[g];
    report["goals"].push_back(
        Json{{"kind", goal.kind == Goal::Kind::kMesh ? "mesh" : "coaxial"},
             {"features", Json::array({assembly.FeatureName(goal.features[0]),
                                       assembly.FeatureName(goal.features[1])})},
             {"met", summary.after[g].met},
             {"before", ErrorJson(summary.before[g])},
             {"after", ErrorJson(summary.after[g])}});
  }
  return report.dump(2) + "\n";
}

}  // namespace mechanist
