#include "reasoning/adjustment.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>

#include "kernel/geometry/line_geometry.h"
#include "reasoning/analysis.h"
#include "reasoning/pair_graph.h"
#include "reasoning/pair_recognition.h"

namespace mechanist {
namespace {

// The goal's features as the pair type wants them: the worm or the pinion first.
struct GoalFeatures {
  FeatureRef first, second;
};

GoalFeatures Ordered(const Assembly& assembly, const Goal& goal) {
  const FeatureKind k0 = assembly.feature(goal.features[0]).kind;
  const bool swap = k0 == FeatureKind::kWormWheel || k0 == FeatureKind::kRack;
  return swap ? GoalFeatures{goal.features[1], goal.features[0]}
              : GoalFeatures{goal.features[0], goal.features[1]};
}

// Appends the goal's residuals (mm) at `state` to `r`.
void GoalResiduals(const Assembly& assembly, const AssemblyState& state, const Goal& goal,
                   std::vector<double>* r) {
  const GoalFeatures g = Ordered(assembly, goal);
  const Feature& fa = assembly.feature(g.first);
  const Feature& fb = assembly.feature(g.second);
  const AxisSegment a = fa.WorldAxis(state.X_WP[g.first.part]);
  const AxisSegment b = fb.WorldAxis(state.X_WP[g.second.part]);
  if (goal.kind == Goal::Kind::kCoaxial) {
    const double scale = std::max({a.length, b.length, 1.0});
    const Eigen::Vector3d cross = scale * a.direction.cross(b.direction);
    const Eigen::Vector3d d = b.origin - a.origin;
    const Eigen::Vector3d off = d - d.dot(a.direction) * a.direction;
    r->insert(r->end(), {cross.x(), cross.y(), cross.z(), off.x(), off.y(), off.z()});
    return;
  }
  if (fa.kind == FeatureKind::kBevelGear) {
    // Common apex, and the angle between the axes the sum of the pitch angles (as an arc at
    // the outer cone distance).
    const Eigen::Vector3d apart = b.origin - a.origin;
    const double angle = std::acos(std::clamp(a.direction.dot(b.direction), -1.0, 1.0));
    r->insert(r->end(), {apart.x(), apart.y(), apart.z()});
    r->push_back(fa.OuterConeDistance() * (angle - fa.pitch_angle - fb.pitch_angle));
    return;
  }
  const double required = MeshCentreDistance(fa, fb);
  if (fa.kind == FeatureKind::kWorm || fb.kind == FeatureKind::kRack) {
    const LineLineClosest c = ClosestPointsOfLines(a.origin, a.direction, b.origin, b.direction);
    r->push_back(c.distance - required);
    r->push_back(required * a.direction.dot(b.direction));
    if (fb.kind == FeatureKind::kRack) {
      const Eigen::Vector3d n_W = state.X_WP[g.second.part].RotateDirection(fb.normal);
      r->push_back(required * a.direction.dot(n_W));
    } else {
      r->push_back(c.t - b.length / 2);  // the wheel's mid-plane through the worm's axis
    }
    return;
  }
  const Eigen::Vector3d mid_a = a.origin + 0.5 * a.length * a.direction;
  const Eigen::Vector3d mid_b = b.origin + 0.5 * b.length * b.direction;
  const Eigen::Vector3d cross = required * a.direction.cross(b.direction);
  r->push_back(DistanceToLine(mid_b, a.origin, a.direction) - required);
  r->insert(r->end(), {cross.x(), cross.y(), cross.z()});
  r->push_back((mid_b - mid_a).dot(a.direction));  // coplanar mid-faces
}

std::size_t ResidualCount(const Assembly& assembly, const Goal& goal) {
  std::vector<double> r;
  GoalResiduals(assembly, InitialState(assembly), goal, &r);
  return r.size();
}

// The poses after the adjustments take `values` (unused ones none), in file order.
AssemblyState AdjustedState(const Assembly& assembly,
                            const std::vector<AdjustmentOutcome>& adjustments,
                            const std::vector<double>& values) {
  AssemblyState state = InitialState(assembly);
  for (std::size_t k = 0; k < adjustments.size(); ++k) {
    if (!adjustments[k].used || values[k] == 0.0) continue;
    const Adjustment& adj = assembly.adjustments()[k];
    const AxisSegment axis = assembly.feature(adj.axis).WorldAxis(state.X_WP[adj.axis.part]);
    const RigidTransform D =
        adj.kind == Adjustment::Kind::kRotate
            ? RigidTransform::AxisAngleAbout(axis.origin, axis.direction, values[k])
            : RigidTransform::Translation(values[k] * axis.direction);
    for (const std::size_t p : adjustments[k].carried) state.X_WP[p] = D * state.X_WP[p];
  }
  return state;
}

bool IsLooseThread(const Assembly& assembly, FeatureRef ref) {
  const Feature& f = assembly.feature(ref);
  return f.kind == FeatureKind::kThread && f.fastening == Fastening::kLoose;
}

// The loose threads of the pairs between a part in `carried` and one that is not, without
// repeats, in feature-name order.
std::vector<FeatureRef> LooseThreadsAcross(const Assembly& assembly, const std::vector<Pair>& pairs,
                                           const std::set<std::size_t>& carried) {
  std::vector<FeatureRef> loose;
  for (const Pair& pair : pairs) {
    if (carried.count(pair.a.part) == carried.count(pair.b.part)) continue;
    for (const FeatureRef f : {pair.a, pair.b}) {
      if (IsLooseThread(assembly, f)) loose.push_back(f);
    }
  }
  const auto by_name = [&](FeatureRef x, FeatureRef y) {
    return assembly.FeatureNameRank(x) < assembly.FeatureNameRank(y);
  };
  std::sort(loose.begin(), loose.end(), by_name);
  loose.erase(std::unique(loose.begin(), loose.end()), loose.end());
  return loose;
}

}  // namespace

std::vector<std::size_t> CarriedParts(const Assembly& assembly, const PairGraph& graph,
                                      const std::vector<Pair>& pairs, std::size_t adjustment) {
  const std::size_t start = assembly.adjustments().at(adjustment).moves;
  // Across every pair but meshing teeth, and into no ground part.
  return graph.Reachable({&start, 1}, [&](std::size_t pair, std::size_t, std::size_t to) {
    return !IsCoupling(pairs[pair].type) && !assembly.part(to).ground;
  });
}

GoalError MeasureGoal(const Assembly& assembly, const AssemblyState& state, std::size_t goal) {
  const Goal& gl = assembly.goals().at(goal);
  const GoalFeatures g = Ordered(assembly, gl);
  const Feature& fa = assembly.feature(g.first);
  const Feature& fb = assembly.feature(g.second);
  const AxisSegment a = fa.WorldAxis(state.X_WP[g.first.part]);
  const AxisSegment b = fb.WorldAxis(state.X_WP[g.second.part]);
  const double L = assembly.tolerance().length;
  GoalError e;
  const double angle = AngleBetweenLines(a.direction, b.direction);
  if (gl.kind == Goal::Kind::kCoaxial) {
    e.angle = angle;
    e.distance = DistanceToLine(b.origin, a.origin, a.direction);
  } else if (fa.kind == FeatureKind::kBevelGear) {
    // The apexes' distance, and the axes' angle from the sum of the pitch angles.
    e.apexes = true;
    e.distance = (b.origin - a.origin).norm();
    e.angle = std::abs(std::acos(std::clamp(a.direction.dot(b.direction), -1.0, 1.0)) -
                       fa.pitch_angle - fb.pitch_angle);
    const double La = fa.OuterConeDistance(), Lb = fb.OuterConeDistance();
    e.engaged = std::min(La, Lb) - std::max(La - fa.length, Lb - fb.length) > L;
  } else if (fa.kind == FeatureKind::kWorm || fb.kind == FeatureKind::kRack) {
    const LineLineClosest c = ClosestPointsOfLines(a.origin, a.direction, b.origin, b.direction);
    e.distance = c.distance - MeshCentreDistance(fa, fb);
    e.angle = std::abs(M_PI / 2 - angle);
    if (fb.kind == FeatureKind::kRack) {
      const Eigen::Vector3d n_W = state.X_WP[g.second.part].RotateDirection(fb.normal);
      e.angle = std::max(e.angle, std::abs(M_PI / 2 - AngleBetweenLines(a.direction, n_W)));
    } else {
      e.axial = c.t - b.length / 2;
    }
    e.engaged = c.s >= -L && c.s <= a.length + L && c.t >= -L && c.t <= b.length + L;
  } else {
    const Eigen::Vector3d mid_b = b.origin + 0.5 * b.length * b.direction;
    e.distance = DistanceToLine(mid_b, a.origin, a.direction) - MeshCentreDistance(fa, fb);
    e.angle = angle;
    e.axial = (mid_b - (a.origin + 0.5 * a.length * a.direction)).dot(a.direction);
    e.engaged = AxialOverlap(a, b) > L;
  }
  e.met = std::abs(e.distance) <= L && e.angle <= assembly.tolerance().angle && e.engaged;
  return e;
}

AdjustmentSummary SolveAdjustments(const Assembly& assembly, const std::vector<Pair>& pairs) {
  AdjustmentSummary summary;
  const std::size_t n = assembly.adjustments().size();
  summary.adjustments.resize(n);
  const PairGraph graph(assembly, pairs);
  for (std::size_t k = 0; k < n; ++k) {
    AdjustmentOutcome& out = summary.adjustments[k];
    out.carried = CarriedParts(assembly, graph, pairs, k);
    const std::set<std::size_t> carried(out.carried.begin(), out.carried.end());
    out.loosened = LooseThreadsAcross(assembly, pairs, carried);
    for (const Goal& goal : assembly.goals()) {
      out.used =
          out.used || carried.count(goal.features[0].part) != carried.count(goal.features[1].part);
    }
  }
  const AssemblyState start = InitialState(assembly);
  for (std::size_t g = 0; g < assembly.goals().size(); ++g) {
    summary.before.push_back(MeasureGoal(assembly, start, g));
  }

  std::vector<std::size_t> variable_of;  // the used adjustments, in file order
  LeastSquaresProblem problem;
  for (std::size_t k = 0; k < n; ++k) {
    if (!summary.adjustments[k].used) continue;
    variable_of.push_back(k);
    problem.lower.push_back(assembly.adjustments()[k].lower);
    problem.upper.push_back(assembly.adjustments()[k].upper);
  }
  for (const Goal& goal : assembly.goals()) problem.residuals += ResidualCount(assembly, goal);
  problem.evaluate = [&](const double* x, double* r) {
    std::vector<double> values(n, 0.0);
    for (std::size_t i = 0; i < variable_of.size(); ++i) values[variable_of[i]] = x[i];
    const AssemblyState state = AdjustedState(assembly, summary.adjustments, values);
    std::vector<double> residuals;
    for (const Goal& goal : assembly.goals()) GoalResiduals(assembly, state, goal, &residuals);
    std::copy(residuals.begin(), residuals.end(), r);
    return true;
  };
  std::vector<double> x(variable_of.size(), 0.0);
  summary.solver = SolveLeastSquares(problem, &x);

  std::vector<double> values(n, 0.0);
  for (std::size_t i = 0; i < variable_of.size(); ++i) {
    const std::size_t k = variable_of[i];
    const Adjustment& adj = assembly.adjustments()[k];
    AdjustmentOutcome& out = summary.adjustments[k];
    out.value = values[k] = x[i];
    const double eps = 1e-9 * std::max(1.0, adj.upper - adj.lower);
    if (adj.lower < adj.upper && x[i] <= adj.lower + eps)
      out.active = AdjustmentOutcome::Bound::kLower;
    if (adj.lower < adj.upper && x[i] >= adj.upper - eps)
      out.active = AdjustmentOutcome::Bound::kUpper;
  }
  summary.state = AdjustedState(assembly, summary.adjustments, values);
  for (std::size_t g = 0; g < assembly.goals().size(); ++g) {
    summary.after.push_back(MeasureGoal(assembly, summary.state, g));
    summary.all_met = summary.all_met && summary.after.back().met;
  }
  return summary;
}

Assembly ApplyAdjustments(const Assembly& assembly, const AdjustmentSummary& summary) {
  AssemblySpec spec = assembly.spec();
  for (std::size_t p = 0; p < spec.parts.size(); ++p) spec.parts[p].X_WP = summary.state.X_WP[p];
  for (std::size_t k = 0; k < spec.adjustments.size(); ++k) {
    const AdjustmentOutcome& out = summary.adjustments[k];
    spec.adjustments[k].lower -= out.value;
    spec.adjustments[k].upper -= out.value;
    if (out.loosened.empty()) continue;
    std::string names;
    std::vector<std::string> parts, features;
    for (const FeatureRef f : out.loosened) {
      spec.parts[f.part].features[f.feature].fastening = Fastening::kTight;
      names += (names.empty() ? "" : ", ") + assembly.FeatureName(f);
      parts.emplace_back(assembly.PartId(f.part));
      features.push_back(assembly.FeatureName(f));
    }
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    spec.findings.push_back({Severity::kInfo, "adjustment_locked",
                             fmt::format("adjustment {} is locked at its solved value: its loose "
                                         "fastening{} {} {} taken as tightened",
                                         spec.adjustments[k].id, out.loosened.size() > 1 ? "s" : "",
                                         names, out.loosened.size() > 1 ? "are" : "is"),
                             parts, features});
  }
  return Assembly(std::move(spec));
}

Assembly Adjusted(const Assembly& assembly, AdjustmentSummary* summary) {
  if (assembly.adjustments().empty() || assembly.goals().empty()) return assembly;
  // The pairs alone, as recognised at the file's poses: the motion of the unadjusted
  // assembly is not needed.
  AdjustmentSummary solved = SolveAdjustments(assembly, RecognizePairs(assembly).pairs);
  Assembly adjusted = ApplyAdjustments(assembly, solved);
  if (summary) *summary = std::move(solved);
  return adjusted;
}

void SuggestAdjustments(const Assembly& assembly, const PairGraph& graph,
                        const std::vector<Pair>& pairs, std::vector<Diagnostic>* diagnostics) {
  if (assembly.adjustments().empty()) return;  // nothing to suggest: no finding is read
  static const std::set<std::string> kNearMisses = {"gear_center_distance",
                                                    "gear_axes_not_parallel",
                                                    "worm_center_distance",
                                                    "worm_axes_not_perpendicular",
                                                    "rack_pitch_line_distance",
                                                    "axes_not_collinear",
                                                    "bevel_apex",
                                                    "bevel_pitch_angles"};
  std::vector<std::set<std::string>> carried;
  for (std::size_t k = 0; k < assembly.adjustments().size(); ++k) {
    std::set<std::string> ids;
    for (const std::size_t p : CarriedParts(assembly, graph, pairs, k)) {
      ids.insert(assembly.part(p).id);
    }
    carried.push_back(std::move(ids));
  }
  for (Diagnostic& d : *diagnostics) {
    if (!kNearMisses.count(d.code) || d.parts.size() != 2) continue;
    for (std::size_t k = 0; k < carried.size(); ++k) {
      if (carried[k].count(d.parts[0]) != carried[k].count(d.parts[1])) {
        fmt::format_to(std::back_inserter(d.message),
                       " (adjustment {} can fix this: mechanist adjust)",
                       assembly.adjustments()[k].id);
        break;
      }
    }
  }
}

}  // namespace mechanist
