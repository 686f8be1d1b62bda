#include "reasoning/operation_check.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <tuple>

#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/broad_phase.h"
#include "kernel/collision/mesh_distance.h"
#include "kernel/collision/motion_sweep.h"
#include "reasoning/motion_run.h"

namespace mechanist {
namespace {

// Orders contacts by driver parameter, ties by the parts' ids.
void SortByTime(const Assembly& assembly, std::vector<OperationClash>& clashes) {
  std::sort(clashes.begin(), clashes.end(), [&](const OperationClash& x, const OperationClash& y) {
    return std::tie(x.at, assembly.part(x.part_a).id, assembly.part(x.part_b).id) <
           std::tie(y.at, assembly.part(y.part_a).id, assembly.part(y.part_b).id);
  });
}

// Turns the earliest contact of each free subassembly (one that nothing drives or holds) into
// an inferred coupling, carried or jammed, and re-analyses with the carried ones.
void SettleFreeMotions(const Assembly& assembly, const Analysis& analysis,
                       const AssemblyState& state, const std::vector<ScrewPath>& paths,
                       OperationCheck* check) {
  const double tolerance = assembly.tolerance().length;
  // The free motion of each part of a free subassembly.
  std::vector<const FreeMotion*> free_of(assembly.parts().size(), nullptr);
  for (const FreeMotion& f : analysis.motion.mobility.free_motions) {
    for (const std::size_t q : f.parts) free_of[q] = &f;
    free_of[f.part] = &f;
  }
  std::vector<bool> settled(analysis.subassemblies.size(), false);
  std::vector<OperationClash> clashes;  // the clashes come in time order, ties by part ids
  std::vector<Pair> couplings;
  for (const OperationClash& c : check->clashes) {
    const bool a_moves = !paths[c.part_a].still();
    const std::size_t pusher = a_moves ? c.part_a : c.part_b;
    const std::size_t pushed = a_moves ? c.part_b : c.part_a;
    const FreeMotion* free = free_of[pushed];
    if (paths[pusher].still() || !paths[pushed].still() || !free) {
      clashes.push_back(c);
      continue;
    }
    const std::size_t group = analysis.subassembly_of[pushed];
    if (settled[group]) continue;  // already carried or jammed at an earlier contact
    settled[group] = true;
    // The pusher's velocity at the contact point, by a finite step along its path.
    const ScrewPath& path = paths[pusher];
    const double h = 1e-6;
    const Eigen::Vector3d v = ((path.At(c.at + h) * path.At(c.at).inverse()) * c.p_W - c.p_W) / h;
    InferredCoupling coupling{pusher, pushed, c.at, c.p_W, true};
    if (free->pair && v.norm() > 0.0) {
      const Pair& pair = analysis.pairs[*free->pair];
      const AxisSegment axis = assembly.feature(pair.a).WorldAxis(state.X_WP[pair.a.part]);
      const Eigen::Vector3d r = c.p_W - axis.origin;
      const Eigen::Vector3d radial = r - r.dot(axis.direction) * axis.direction;
      double along = 0.0;  // the push's component along the free motion
      if (pair.type == PairType::kPrismatic) {
        along = std::abs(v.normalized().dot(axis.direction));
      } else if (radial.norm() > tolerance) {
        along = std::abs(v.normalized().dot(axis.direction.cross(radial).normalized()));
        if (pair.type == PairType::kCylindrical) {
          along = std::max(along, std::abs(v.normalized().dot(axis.direction)));
        }
      } else if (pair.type == PairType::kCylindrical) {
        along = std::abs(v.normalized().dot(axis.direction));
      }
      coupling.carried = along > 1e-6;
    }
    check->inferred.push_back(coupling);
    // A part in a pair has features; the coupling names the first of each.
    if (!coupling.carried || assembly.part(pusher).features.empty() ||
        assembly.part(pushed).features.empty()) {
      continue;
    }
    Pair p;
    p.type = PairType::kFixed;
    p.a = {pusher, 0};
    p.b = {pushed, 0};
    p.source = PairSource::kInferred;
    p.dof = 0;
    couplings.push_back(p);
  }
  check->clashes = std::move(clashes);
  if (!couplings.empty()) check->after = Analyze(assembly, couplings);
}

}  // namespace

OperationCheck SweepPaths(const Assembly& assembly, const Analysis& analysis,
                          const CollisionModel& model, const std::vector<ScrewPath>& path,
                          double amount, const PartPairFilter& swept) {
  OperationCheck check;
  check.amount = amount;
  const AssemblyState state = InitialState(assembly);
  const std::size_t n = assembly.parts().size();
  const double tolerance = assembly.tolerance().length;
  std::vector<Aabb> reach(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (model.part_mesh(p).mesh().faces.empty()) continue;  // nothing to meet: an empty box
    // Everywhere the part can be over the run: its box grown by the farthest any point goes.
    Aabb box = TransformBox(state.X_WP[p], model.part_mesh(p).bounds());
    const double travel =
        path[p].SpeedBound(box.center(), 0.5 * box.size().norm(), amount) * amount;
    box.min.array() -= travel;
    box.max.array() += travel;
    reach[p] = box;
  }
  std::set<std::pair<std::size_t, std::size_t>> paired;
  for (const Pair& pair : analysis.pairs) {
    paired.insert(std::minmax(pair.a.part, pair.b.part));
  }
  for (const auto& [i, j] : OverlappingBoxes(reach, tolerance)) {
    if (path[i].still() && path[j].still()) continue;
    if (analysis.subassembly_of[i] == analysis.subassembly_of[j]) continue;
    if (paired.count({i, j})) continue;
    if (swept && !swept(i, j)) continue;
    const CollisionMesh& a = model.part_mesh(i);
    const CollisionMesh& b = model.part_mesh(j);
    if (SurfaceDistance(a, state.X_WP[i], b, state.X_WP[j], 2 * tolerance) <= tolerance) {
      // Touching at rest: the sweep cannot tell parting from pressing on, so say so.
      const bool ordered = assembly.part(i).id < assembly.part(j).id;
      check.touching_at_rest.emplace_back(ordered ? i : j, ordered ? j : i);
      continue;
    }
    ++check.pairs_swept;
    const MotionSweepResult r =
        SweepMotion(a, state.X_WP[i], path[i], b, state.X_WP[j], path[j], amount, tolerance);
    if (r.status == MotionSweepResult::Status::kClear) continue;
    const bool ordered = assembly.part(i).id < assembly.part(j).id;
    const OperationClash clash{ordered ? i : j, ordered ? j : i, r.s, r.distance, r.p_W};
    (r.status == MotionSweepResult::Status::kContact ? check.clashes : check.undecided)
        .push_back(clash);
  }
  SortByTime(assembly, check.clashes);
  SortByTime(assembly, check.undecided);
  std::sort(check.touching_at_rest.begin(), check.touching_at_rest.end(),
            [&](const auto& x, const auto& y) {
              return std::tie(assembly.part(x.first).id, assembly.part(x.second).id) <
                     std::tie(assembly.part(y.first).id, assembly.part(y.second).id);
            });
  return check;
}

OperationCheck CheckOperation(const Assembly& assembly, const Analysis& analysis,
                              const CollisionModel& model, std::optional<std::size_t> driver,
                              std::optional<double> amount) {
  const MotionRun run = PlanRun(assembly, analysis, driver, amount);
  if (!run.possible) {
    OperationCheck check;
    check.driver = run.driver;
    check.amount = run.amount;
    check.possible = false;
    check.reason = run.reason;
    return check;
  }
  OperationCheck check = SweepPaths(assembly, analysis, model, run.paths, run.amount);
  check.driver = run.driver;
  SettleFreeMotions(assembly, analysis, InitialState(assembly), run.paths, &check);
  SortByTime(assembly, check.clashes);
  return check;
}

}  // namespace mechanist
