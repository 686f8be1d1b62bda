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
namespace {

ScrewMotion ToScrew(const PartMotion& m, double mm_per_length) {
  ScrewMotion s;
  if (m.kind == MotionKind::kNone) return s;
  s.axis_W = m.axis_W;
  s.point_W = m.point_W;
  if (m.kind == MotionKind::kRotation || m.kind == MotionKind::kScrew) {
    s.turns_per_unit = m.rotation.value();
  }
  if (m.kind == MotionKind::kTranslation || m.kind == MotionKind::kScrew) {
    s.travel_per_unit = m.translation.value() * mm_per_length;
  }
  return s;
}

}  // namespace

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
  std::vector<ScrewMotion> screw(n);
  std::vector<Aabb> reach(n);
  for (std::size_t p = 0; p < n; ++p) {
    screw[p] = ToScrew(motion.parts[p], assembly.units().mm_per_length);
    // Everywhere the part can be over the run: its box grown by the farthest any point goes.
    Aabb box = TransformBox(state.X_WP[p], model.part_mesh(p).bounds());
    double radius = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d c((corner & 1) ? box.max.x() : box.min.x(),
                              (corner & 2) ? box.max.y() : box.min.y(),
                              (corner & 4) ? box.max.z() : box.min.z());
      const Eigen::Vector3d d = c - screw[p].point_W;
      radius = std::max(radius, (d - d.dot(screw[p].axis_W) * screw[p].axis_W).norm());
    }
    const double travel = screw[p].SpeedBound(radius) * check.amount;
    box.min.array() -= travel;
    box.max.array() += travel;
    reach[p] = box;
  }
  // Fixed-axis motion: a lower pair between the part's subassembly and a still part, along the
  // motion's axis.
  std::vector<bool> fixed_axis(n, false);
  for (const Pair& pair : analysis.pairs) {
    if (pair.type != PairType::kRevolute && pair.type != PairType::kCylindrical &&
        pair.type != PairType::kScrew && pair.type != PairType::kPrismatic) {
      continue;
    }
    for (const auto& [mine, theirs] : {std::pair{pair.a, pair.b}, std::pair{pair.b, pair.a}}) {
      if (!screw[theirs.part].still() || screw[mine.part].still()) continue;
      const AxisSegment axis = assembly.feature(theirs).WorldAxis(state.X_WP[theirs.part]);
      const ScrewMotion& m = screw[mine.part];
      const bool parallel =
          std::abs(axis.direction.dot(m.axis_W)) >= std::cos(assembly.tolerance().angle);
      const Eigen::Vector3d offset = m.point_W - axis.origin;
      const bool on_axis =
          m.turns_per_unit == 0.0 ||
          (offset - offset.dot(axis.direction) * axis.direction).norm() <= tolerance;
      if (!parallel || !on_axis) continue;
      for (std::size_t q = 0; q < n; ++q) {
        if (analysis.subassembly_of[q] == analysis.subassembly_of[mine.part]) fixed_axis[q] = true;
      }
    }
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (!screw[p].still() && !fixed_axis[p]) check.not_swept.push_back(p);
  }
  std::sort(check.not_swept.begin(), check.not_swept.end(), [&](std::size_t x, std::size_t y) {
    return assembly.part(x).id < assembly.part(y).id;
  });
  std::set<std::pair<std::size_t, std::size_t>> paired;
  for (const Pair& pair : analysis.pairs) {
    paired.insert(std::minmax(pair.a.part, pair.b.part));
  }
  for (const auto& [i, j] : OverlappingBoxes(reach, tolerance)) {
    if (screw[i].still() && screw[j].still()) continue;
    if ((!screw[i].still() && !fixed_axis[i]) || (!screw[j].still() && !fixed_axis[j])) continue;
    if (analysis.subassembly_of[i] == analysis.subassembly_of[j]) continue;
    if (paired.count({i, j})) continue;
    const CollisionMesh& a = model.part_mesh(i);
    const CollisionMesh& b = model.part_mesh(j);
    if (SurfaceDistance(a, state.X_WP[i], b, state.X_WP[j], 2 * tolerance) <= tolerance) continue;
    ++check.pairs_swept;
    const MotionSweepResult r = SweepMotion(a, state.X_WP[i], screw[i], b, state.X_WP[j], screw[j],
                                            check.amount, tolerance);
    if (r.status == MotionSweepResult::Status::kClear) continue;
    const bool ordered = assembly.part(i).id < assembly.part(j).id;
    const OperationClash clash{ordered ? i : j, ordered ? j : i, r.s, r.distance};
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
