#include "reasoning/operation_check.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "kernel/assembly_state.h"
#include "kernel/broad_phase.h"
#include "kernel/mesh_distance.h"
#include "kernel/motion_sweep.h"

namespace mechanist {

OperationCheck CheckOperation(const Assembly& assembly, const Analysis& analysis,
                              const CollisionModel& model, std::optional<std::size_t> driver,
                              std::optional<double> amount) {
  OperationCheck check;
  const auto& drivers = assembly.drivers();
  if (!driver && drivers.size() == 1) driver = 0;  // one driver: its own units
  check.driver = driver;
  if (driver && *driver >= drivers.size()) {
    throw std::invalid_argument("CheckOperation: no driver " + std::to_string(*driver));
  }
  if (amount && !(*amount >= 0.0)) {
    throw std::invalid_argument("CheckOperation: the amount must be >= 0");
  }
  const auto& driven = analysis.motion.driven;
  if (drivers.empty() || driven.empty()) {
    check.possible = false;
    check.reason = "no driver: nothing runs";
    return check;
  }
  // driven: one entry per driver, then all together.
  const DrivenMotion& motion = driver ? driven[*driver] : driven.back();
  if (amount) {
    check.amount = *amount;
  } else if (driver) {
    check.amount = drivers[*driver].amount;
  } else {
    check.amount = std::numeric_limits<double>::infinity();
    for (const Driver& d : drivers) {
      if (d.rate != 0.0) check.amount = std::min(check.amount, d.amount / std::abs(d.rate));
    }
    if (!std::isfinite(check.amount)) check.amount = 0.0;
  }
  if (!motion.possible) {
    check.possible = false;
    check.reason = motion.reason;
    return check;
  }

  const AssemblyState state = InitialState(assembly);
  const std::size_t n = assembly.parts().size();
  const double tolerance = assembly.tolerance().length;
  std::vector<const ScrewPath*> path(n);
  std::vector<Aabb> reach(n);
  for (std::size_t p = 0; p < n; ++p) {
    path[p] = &motion.parts[p].path;
    // Everywhere the part can be over the run: its box grown by the farthest any point goes.
    Aabb box = TransformBox(state.X_WP[p], model.part_mesh(p).bounds());
    const double travel =
        path[p]->SpeedBound(box.center(), 0.5 * box.size().norm(), check.amount) * check.amount;
    box.min.array() -= travel;
    box.max.array() += travel;
    reach[p] = box;
  }
  std::set<std::pair<std::size_t, std::size_t>> paired;
  for (const Pair& pair : analysis.pairs) {
    paired.insert(std::minmax(pair.a.part, pair.b.part));
  }
  for (const auto& [i, j] : OverlappingBoxes(reach, tolerance)) {
    if (path[i]->still() && path[j]->still()) continue;
    if (analysis.subassembly_of[i] == analysis.subassembly_of[j]) continue;
    if (paired.count({i, j})) continue;
    const CollisionMesh& a = model.part_mesh(i);
    const CollisionMesh& b = model.part_mesh(j);
    if (SurfaceDistance(a, state.X_WP[i], b, state.X_WP[j], 2 * tolerance) <= tolerance) continue;
    ++check.pairs_swept;
    const MotionSweepResult r = SweepMotion(a, state.X_WP[i], *path[i], b, state.X_WP[j], *path[j],
                                            check.amount, tolerance);
    if (r.status == MotionSweepResult::Status::kClear) continue;
    const bool ordered = assembly.part(i).id < assembly.part(j).id;
    const OperationClash clash{ordered ? i : j, ordered ? j : i, r.s, r.distance, r.p_W};
    (r.status == MotionSweepResult::Status::kContact ? check.clashes : check.undecided)
        .push_back(clash);
  }
  auto by_time = [&](const OperationClash& x, const OperationClash& y) {
    return std::tie(x.at, assembly.part(x.part_a).id, assembly.part(x.part_b).id) <
           std::tie(y.at, assembly.part(y.part_a).id, assembly.part(y.part_b).id);
  };
  std::sort(check.clashes.begin(), check.clashes.end(), by_time);
  std::sort(check.undecided.begin(), check.undecided.end(), by_time);
  return check;
}

}  // namespace mechanist
