#include "reasoning/assembly_plan.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <string_view>
#include <tuple>

#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/translational_sweep.h"
#include "kernel/support/parallel_for.h"

namespace mechanist {
namespace {

bool HasDirection(FeatureKind kind) {
  return kind != FeatureKind::kFace && kind != FeatureKind::kBall && kind != FeatureKind::kSocket;
}

// Pairs that hold parts together so that they travel as one: press fits and forced fixes.
// (The parts of a rolling bearing travel together too: Planner::Carried.)
bool Carries(const Pair& pair) {
  return pair.type == PairType::kFixed &&
         (pair.fastening == PairFastening::kPressFit || pair.source == PairSource::kOverride);
}

// The least travel s in [0, max_travel] at which `moving`, moved by s along d, meets `fixed`
// (the slabs of the three axes); none when it does not within max_travel.
std::optional<double> TravelToMeet(const Aabb& moving, const Aabb& fixed, const Eigen::Vector3d& d,
                                   double max_travel) {
  double lo = 0.0, hi = max_travel;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (moving.max[a] < fixed.min[a] || fixed.max[a] < moving.min[a]) return std::nullopt;
      continue;
    }
    const double enter =
        (d[a] > 0 ? fixed.min[a] - moving.max[a] : fixed.max[a] - moving.min[a]) / d[a];
    const double leave =
        (d[a] > 0 ? fixed.max[a] - moving.min[a] : fixed.min[a] - moving.max[a]) / d[a];
    lo = std::max(lo, enter);
    hi = std::min(hi, leave);
    if (lo > hi) return std::nullopt;
  }
  return lo;
}

// The parts that stop a unit leaving in a direction (Planner::Blockers; none when the base
// does), by unit and direction, kept from one search for a sub-assembly to the next: parts only
// leave in between, so a list only loses parts, and the base stays.
struct BlockerMemo {
  std::mutex mutex;
  std::map<std::tuple<std::size_t, double, double, double>, std::optional<std::vector<std::size_t>>>
      blockers;
};

// A removal direction (world, unit) with the feature that suggests it, if one does.
using Direction = std::pair<Eigen::Vector3d, std::optional<FeatureRef>>;

// Units that leave as one (Planner::RemovableSubassembly): the units, the removal of them all,
// the removals that take them apart, down to the first of them (the base), and the best
// attempts of those that cannot leave the base.
struct Subassembly {
  std::vector<std::size_t> members;
  InsertionStep step;
  std::vector<InsertionStep> apart;
  std::vector<InsertionStep> stuck;
};

// Something in place that can stop a motion: a part, or a pin the file leaves out.
struct Obstacle {
  std::size_t part = 0;
  const HingePin* pin = nullptr;  // the pin, when the obstacle is one (else a part)
};

class Planner {
 public:
  Planner(const Assembly& assembly, const Analysis& analysis, const CollisionModel& model,
          const std::function<void(double)>& progress)
      : assembly_(assembly),
        analysis_(analysis),
        model_(model),
        progress_(progress),
        state_(InitialState(assembly)),
        tolerance_(assembly.tolerance().length),
        min_approach_(std::sin(assembly.tolerance().angle)) {
    for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
      boxes_.push_back(TransformBox(state_.X_WP[p], model.part_mesh(p).bounds()));
    }
    pins_ = FindHingePins(assembly, analysis, state_, model);
  }

  AssemblyPlan Plan() {
    AssemblyPlan plan;
    Report(0);
    for (PartContact& c : FindContacts(assembly_, state_, model_, analysis_.pairs)) {
      if (c.verdict == ContactVerdict::kClash) plan.clashes.push_back(c);
    }
    clashes_ = plan.clashes;
    if (assembly_.steps().empty()) {
      Search(&plan);
    } else {
      plan.from_steps = true;
      CheckSteps(&plan);
    }
    Report(1);
    MarkClashesAtRest(&plan);
    const auto pins_clear = [](const std::vector<PinInsertion>& pins) {
      return std::all_of(pins.begin(), pins.end(), [](const PinInsertion& p) { return p.clear; });
    };
    bool all_clear = plan.unplaced.empty() && pins_clear(plan.base_pins);
    for (const InsertionStep& s : plan.steps) {
      all_clear = all_clear && s.clear && pins_clear(s.pins);
    }
    plan.assemblable = all_clear && plan.clashes.empty();
    return plan;
  }

 private:
  // Marks the stops of the plan's insertions at their places (within the length tolerance) by
  // an obstacle that the moving part, or one it carries, clashes with at rest
  // (InsertionObstacle::clash_at_rest).
  void MarkClashesAtRest(AssemblyPlan* plan) const {
    for (std::vector<InsertionStep>* steps : {&plan->steps, &plan->unplaced}) {
      for (InsertionStep& s : *steps) {
        const auto moves = [&s](std::size_t part) {
          return part == s.part || std::count(s.carried.begin(), s.carried.end(), part) > 0;
        };
        for (InsertionObstacle& o : s.blocked_by) {
          if (!o.pin.empty() || o.short_by > tolerance_) continue;
          o.clash_at_rest =
              std::any_of(plan->clashes.begin(), plan->clashes.end(), [&](const PartContact& c) {
                return (moves(c.part_a) && c.part_b == o.part) ||
                       (moves(c.part_b) && c.part_a == o.part);
              });
        }
      }
    }
  }

  // Adds to `blocked` (the stops of `unit`'s insertion of `travel`) a stop at the place for
  // each part `present` outside the unit that a part of it clashes with at rest (FindContacts)
  // and that stops it nowhere else (MarkClashesAtRest then says they clash there). The unit
  // cannot reach its place, whatever its way, which a sweep may find free: a sweep only sees
  // the contacts that it enters, not those it starts inside.
  void AddClashesAtRest(const std::vector<std::size_t>& unit, const std::vector<bool>& present,
                        double travel, std::vector<InsertionObstacle>* blocked) const {
    const auto moves = [&unit](std::size_t p) {
      return std::find(unit.begin(), unit.end(), p) != unit.end();
    };
    bool added = false;
    for (const PartContact& c : clashes_) {
      if (moves(c.part_a) == moves(c.part_b)) continue;
      const std::size_t other = moves(c.part_a) ? c.part_b : c.part_a;
      const bool stopped = std::any_of(
          blocked->begin(), blocked->end(),
          [other](const InsertionObstacle& o) { return o.part == other && o.pin.empty(); });
      if (present[other] && !stopped) {
        blocked->push_back(Stop({other, nullptr}, travel, 0.0, c.measure.p_W));
        added = true;
      }
    }
    if (added) SortByTravel(blocked);
  }

  // The pins through a part of `unit` whose parts are all `present`.
  std::vector<const HingePin*> PinsThrough(const std::vector<std::size_t>& unit,
                                           const std::vector<bool>& present) const {
    std::vector<const HingePin*> through;
    for (const HingePin& pin : pins_) {
      const bool in_unit = std::any_of(pin.parts.begin(), pin.parts.end(), [&](std::size_t p) {
        return std::find(unit.begin(), unit.end(), p) != unit.end();
      });
      const bool all_present = std::all_of(pin.parts.begin(), pin.parts.end(),
                                           [&](std::size_t p) { return present[p]; });
      if (in_unit && all_present) through.push_back(&pin);
    }
    return through;
  }

  // The pins whose parts are all among `parts` (sorted), pushed in one after another, in
  // order, with the parts `present` and the pins `pin_in` (by index into pins_) in place; each
  // is in place after it.
  std::vector<PinInsertion> PinsAmong(const std::vector<std::size_t>& parts,
                                      const std::vector<bool>& present,
                                      std::vector<bool>* pin_in) const {
    std::vector<PinInsertion> among;
    for (const HingePin& pin : pins_) {
      if (std::includes(parts.begin(), parts.end(), pin.parts.begin(), pin.parts.end())) {
        among.push_back(InsertPin(pin, present, *pin_in));
        (*pin_in)[Index(pin)] = true;
      }
    }
    return among;
  }

  std::size_t Index(const HingePin& pin) const { return &pin - pins_.data(); }

  // The pins in place while `unit` is placed or leaves with the parts `present`: those whose
  // parts are all present, none of them in `unit` (the pins through it go in after it).
  std::vector<bool> PinsInPlace(const std::vector<std::size_t>& unit,
                                const std::vector<bool>& present) const {
    std::vector<bool> in(pins_.size(), false);
    for (const HingePin& pin : pins_) {
      in[Index(pin)] = std::all_of(pin.parts.begin(), pin.parts.end(), [&](std::size_t p) {
        return present[p] && std::find(unit.begin(), unit.end(), p) == unit.end();
      });
    }
    return in;
  }

  // The parts `present` other than those of `unit`, then the pins `pin_in` (by index into
  // pins_), in order.
  std::vector<Obstacle> Obstacles(const std::vector<std::size_t>& unit,
                                  const std::vector<bool>& present,
                                  const std::vector<bool>& pin_in) const {
    std::vector<Obstacle> obstacles;
    for (std::size_t p = 0; p < present.size(); ++p) {
      if (present[p] && std::find(unit.begin(), unit.end(), p) == unit.end()) {
        obstacles.push_back({p, nullptr});
      }
    }
    for (const HingePin& pin : pins_) {
      if (pin_in[Index(pin)]) obstacles.push_back({pin.holes.front().part, &pin});
    }
    return obstacles;
  }

  const CollisionMesh& MeshOf(const Obstacle& o) const {
    return o.pin ? *o.pin->mesh : model_.part_mesh(o.part);
  }
  const RigidTransform& PoseOf(const Obstacle& o) const {
    return o.pin ? o.pin->X_WPin : state_.X_WP[o.part];
  }
  const Aabb& BoxOf(const Obstacle& o) const { return o.pin ? o.pin->box : boxes_[o.part]; }

  // What InsertionObstacle says of `o`.
  static InsertionObstacle Stop(const Obstacle& o, double travel, double short_by,
                                const Eigen::Vector3d& p_W) {
    InsertionObstacle stop;
    stop.part = o.part;
    stop.travel = travel;
    stop.short_by = short_by;
    stop.p_W = p_W;
    if (o.pin) stop.pin = o.pin->holes;
    return stop;
  }

  // `pin` pushed into its place along its axis from outside the parts `present` and the other
  // pins `pin_in` (by index into pins_), from the end its first hole's axis points away from
  // first, then from the other; the first clear attempt, else the one whose first stop is
  // nearest its place (the first of equals).
  PinInsertion InsertPin(const HingePin& pin, const std::vector<bool>& present,
                         const std::vector<bool>& pin_in) const {
    assert(!pin_in[Index(pin)]);  // a pin goes in once
    const std::vector<Obstacle> obstacles = Obstacles({}, present, pin_in);
    std::optional<PinInsertion> best;
    for (const double sense : {1.0, -1.0}) {
      PinInsertion attempt;
      attempt.holes = pin.holes;
      attempt.diameter = pin.diameter;
      attempt.ends_W = pin.ends_W;
      attempt.direction_W = sense * pin.X_WPin.RotateDirection(Eigen::Vector3d::UnitZ());
      attempt.travel = ClearingDistance(Extent(pin.box, -attempt.direction_W, false), obstacles,
                                        -attempt.direction_W);
      attempt.blocked_by = PinStops(pin, obstacles, attempt.direction_W, attempt.travel);
      attempt.clear = attempt.blocked_by.empty();
      if (attempt.clear) return attempt;
      if (!best || attempt.blocked_by.front().short_by < best->blocked_by.front().short_by) {
        best = std::move(attempt);
      }
    }
    return *best;
  }

  // Where each of `obstacles` first stops `pin` travelling `travel` along d into its place
  // (swept as Sweep sweeps a part, its place the seat), sorted by travel. Contacts inside the
  // pin's holes are its fit: they do not block.
  std::vector<InsertionObstacle> PinStops(const HingePin& pin,
                                          const std::vector<Obstacle>& obstacles,
                                          const Eigen::Vector3d& d, double travel) const {
    Aabb swept = pin.box;
    swept.Extend(Aabb{pin.box.min - travel * d, pin.box.max - travel * d});
    const RigidTransform X_WStart = RigidTransform::Translation(-travel * d) * pin.X_WPin;
    std::vector<InsertionObstacle> blocked;
    for (const Obstacle& o : obstacles) {
      if (!Grown(BoxOf(o)).Intersects(swept)) continue;
      std::vector<FeatureRef> fits;
      for (const FeatureRef h : pin.holes) {
        if (!o.pin && h.part == o.part) fits.push_back(h);
      }
      SweepOptions options;
      options.max_travel = travel;
      options.min_approach = min_approach_;
      if (!fits.empty()) {
        // The pin's mesh is built on its holes' circle; the hole's facets lie inside it.
        options.ignore = [this, fits](const Eigen::Vector3d& p_W) {
          return std::any_of(fits.begin(), fits.end(), [&](FeatureRef h) {
            const Feature& f = assembly_.feature(h);
            const double region = tolerance_ + MeshDeviation(assembly_, h.part, 0.5 * f.diameter);
            return InEngagementRegion(f, state_.X_WP[h.part], p_W, region);
          });
        };
      }
      const auto contact =
          FirstBlockingContact(*pin.mesh, X_WStart, MeshOf(o), PoseOf(o), d, options);
      if (!contact || contact->travel >= travel - tolerance_) continue;
      blocked.push_back(Stop(o, contact->travel, travel - contact->travel, contact->p_W));
    }
    SortByTravel(&blocked);
    return blocked;
  }

  // By travel, then by the part's id (a pin's first hole's part), parts before pins; in the
  // order found among equals.
  void SortByTravel(std::vector<InsertionObstacle>* blocked) const {
    std::stable_sort(blocked->begin(), blocked->end(),
                     [&](const InsertionObstacle& x, const InsertionObstacle& y) {
                       const std::string_view x_id = assembly_.part(x.part).id;
                       const std::string_view y_id = assembly_.part(y.part).id;
                       return std::tie(x.travel, x_id, x.pin) < std::tie(y.travel, y_id, y.pin);
                     });
  }

  // The parts carried along with `part`, among `eligible`: reachable through carrying pairs
  // and through the parts of rolling bearings (rings, elements and cages: bought as one).
  std::vector<std::size_t> Carried(std::size_t part, const std::vector<bool>& eligible) const {
    std::vector<std::size_t> found = {part};
    std::vector<bool> seen(assembly_.parts().size(), false);
    seen[part] = true;
    const auto reach = [&](std::size_t y) {
      if (!seen[y] && eligible[y]) {
        seen[y] = true;
        found.push_back(y);
      }
    };
    for (std::size_t k = 0; k < found.size(); ++k) {
      for (const Pair& pair : analysis_.pairs) {
        if (!Carries(pair)) continue;
        if (pair.a.part == found[k]) reach(pair.b.part);
        if (pair.b.part == found[k]) reach(pair.a.part);
      }
      for (const std::vector<std::size_t>& bearing : analysis_.bearings) {
        if (std::binary_search(bearing.begin(), bearing.end(), found[k])) {
          for (const std::size_t member : bearing) reach(member);
        }
      }
    }
    std::sort(found.begin() + 1, found.end());
    return {found.begin() + 1, found.end()};
  }

  Eigen::Vector3d WorldAxis(FeatureRef ref) const {
    return state_.X_WP[ref.part].RotateDirection(assembly_.feature(ref).axis);
  }

  std::optional<std::size_t> PairOf(FeatureRef x, FeatureRef y) const {
    for (std::size_t k = 0; k < analysis_.pairs.size(); ++k) {
      const Pair& p = analysis_.pairs[k];
      if ((p.a == x && p.b == y) || (p.a == y && p.b == x)) return k;
    }
    return std::nullopt;
  }

  // Whether `p` joins `moving` and `obstacle` through something that is there while they are
  // placed: not a pin that the file leaves out (PairSource::kImpliedPin), which goes through
  // the holes once both parts are in place, so that it neither holds a part nor makes room for
  // it on the way.
  static bool Engages(const Pair& p, std::size_t moving, std::size_t obstacle) {
    const bool between = (p.a.part == moving && p.b.part == obstacle) ||
                         (p.b.part == moving && p.a.part == obstacle);
    return between && p.source != PairSource::kImpliedPin;
  }

  // Contacts inside the engagement region of a pair between the moving part and the obstacle
  // are the designed engagement: for meshing teeth always (the meshes only approximate the
  // tooth flanks), for axial fits when the motion runs along the pair's axis (a thread
  // entering its nut); across the axis they are real obstacles (a bolt in a sliding part's way).
  // The region reaches as far beyond the features as the two meshes may lie off their surfaces
  // (MeshDeviation): a pin line-on-line in its bore meets the facets of the bore's chamfer
  // just outside it.
  std::function<bool(const Eigen::Vector3d&)> IgnoreFor(std::size_t moving, std::size_t obstacle,
                                                        const Eigen::Vector3d& d) const {
    std::vector<FeatureRef> regions;
    for (const Pair& p : analysis_.pairs) {
      if (!Engages(p, moving, obstacle)) continue;
      const FeatureRef theirs = p.a.part == obstacle ? p.a : p.b;
      if (!IsCoupling(p.type) &&
          std::abs(WorldAxis(theirs).dot(d)) < std::cos(assembly_.tolerance().angle)) {
        continue;
      }
      regions.push_back(theirs);
    }
    if (regions.empty()) return {};
    std::vector<double> grown;  // per region: how far beyond its feature it reaches
    for (const FeatureRef& r : regions) {
      const Feature& f = assembly_.feature(r);
      const double radius =
          IsAxialFit(f.kind) ? 0.5 * f.diameter : std::numeric_limits<double>::infinity();
      grown.push_back(tolerance_ + MeshDeviation(assembly_, moving, radius) +
                      MeshDeviation(assembly_, obstacle, radius));
    }
    return [this, regions, grown](const Eigen::Vector3d& p_W) {
      for (std::size_t k = 0; k < regions.size(); ++k) {
        const FeatureRef& r = regions[k];
        if (InEngagementRegion(assembly_.feature(r), state_.X_WP[r.part], p_W, grown[k])) {
          return true;
        }
      }
      return false;
    };
  }

  // A feature of `obstacle` in an axial fit (shaft, hole or thread pair) with `moving` whose
  // axis is not along d: the fit holds the part against that motion, whatever the meshes show
  // (tapped holes are rarely modelled, so a bolt sits inside its part's mesh).
  std::optional<FeatureRef> HeldAcross(std::size_t moving, std::size_t obstacle,
                                       const Eigen::Vector3d& d) const {
    for (const Pair& p : analysis_.pairs) {
      if (!Engages(p, moving, obstacle)) continue;
      if (!IsAxialFit(assembly_.feature(p.a).kind) || !IsAxialFit(assembly_.feature(p.b).kind)) {
        continue;
      }
      const FeatureRef theirs = p.a.part == obstacle ? p.a : p.b;
      if (std::abs(WorldAxis(theirs).dot(d)) < std::cos(assembly_.tolerance().angle)) {
        return theirs;
      }
    }
    return std::nullopt;
  }

  // `box` grown by the length tolerance on every side.
  Aabb Grown(Aabb box) const {
    box.min.array() -= tolerance_;
    box.max.array() += tolerance_;
    return box;
  }

  // The box that `group` (at its final poses shifted by `start_shift` along d) sweeps over
  // when it travels `travel` along d.
  Aabb SweptBox(const std::vector<std::size_t>& group, const Eigen::Vector3d& d, double start_shift,
                double travel) const {
    Aabb swept;
    for (const std::size_t m : group) {
      Aabb box = boxes_[m];
      box.min += start_shift * d;
      box.max += start_shift * d;
      swept.Extend(box);
      box.min += travel * d;
      box.max += travel * d;
      swept.Extend(box);
    }
    return swept;
  }

  // Where `obstacle` first stops `group` sweeping as Sweep says (`swept`: SweptBox), if it
  // does. A pin the file leaves out has no pairs: every contact with it counts.
  std::optional<InsertionObstacle> FirstStop(const std::vector<std::size_t>& group,
                                             const Obstacle& obstacle, const Aabb& swept,
                                             const Eigen::Vector3d& d, double start_shift,
                                             double travel, double seat_travel) const {
    if (!Grown(BoxOf(obstacle)).Intersects(swept)) return std::nullopt;
    std::optional<InsertionObstacle> first;
    for (const std::size_t m : group) {
      const auto held = obstacle.pin ? std::nullopt : HeldAcross(m, obstacle.part, d);
      if (held) {
        // Held from the start of a removal, or at the very end of an insertion.
        const double at = std::isfinite(seat_travel) ? seat_travel : 0.0;
        if (!first || at < first->travel) {
          const Eigen::Vector3d p_W = state_.X_WP[held->part] * assembly_.feature(*held).origin;
          first = Stop(obstacle, at, 0.0, p_W);
          first->held_by = held;
        }
        continue;
      }
      SweepOptions options;
      options.max_travel = travel;
      options.min_approach = min_approach_;
      if (!obstacle.pin) options.ignore = IgnoreFor(m, obstacle.part, d);
      const RigidTransform X_WM = RigidTransform::Translation(start_shift * d) * state_.X_WP[m];
      const auto contact = FirstBlockingContact(model_.part_mesh(m), X_WM, MeshOf(obstacle),
                                                PoseOf(obstacle), d, options);
      if (!contact || contact->travel >= seat_travel - tolerance_) continue;
      if (!first || contact->travel < first->travel) {
        first = Stop(obstacle, contact->travel, seat_travel - contact->travel, contact->p_W);
      }
    }
    return first;
  }

  // Sweeps `group` (at its final poses shifted by `start_shift` along d) by up to `travel`
  // along the unit `d` against `obstacles`; returns where each obstacle stops it, sorted by
  // travel. Contacts within the tolerance of `seat_travel` or beyond are the seat and do not
  // count.
  std::vector<InsertionObstacle> Sweep(const std::vector<std::size_t>& group,
                                       const std::vector<Obstacle>& obstacles,
                                       const Eigen::Vector3d& d, double start_shift, double travel,
                                       double seat_travel) const {
    const Aabb swept = SweptBox(group, d, start_shift, travel);
    std::vector<InsertionObstacle> blocked;
    for (const Obstacle& o : obstacles) {
      if (auto stop = FirstStop(group, o, swept, d, start_shift, travel, seat_travel)) {
        blocked.push_back(*stop);
      }
    }
    SortByTravel(&blocked);
    return blocked;
  }

  // Whether any of `obstacles` stops `group` leaving along d by `travel` (swept as Sweep
  // sweeps it, from its final poses, with no seat): the first stop found ends the search (a
  // removal only asks whether its way is clear).
  bool Stopped(const std::vector<std::size_t>& group, const std::vector<Obstacle>& obstacles,
               const Eigen::Vector3d& d, double travel) const {
    const double no_seat = std::numeric_limits<double>::infinity();
    const Aabb swept = SweptBox(group, d, 0.0, travel);
    return std::any_of(obstacles.begin(), obstacles.end(), [&](const Obstacle& o) {
      return FirstStop(group, o, swept, d, 0.0, travel, no_seat).has_value();
    });
  }

  // How far `group` leaves along d (swept as Sweep sweeps it, with no seat) before the first
  // of `obstacles` stops it: `travel` when none does. Stops looking once a stop within `enough`
  // is found (the caller only asks whether the group gets further than that). A branch and
  // bound: an obstacle cannot stop the group before their boxes meet, so the obstacles are
  // swept in the order in which the group's box meets theirs, each only as far as the nearest
  // stop found yet, and the first met no sooner than that ends the search. (The sweeps of
  // parts sliding past each other are long and find nothing: on the Onshape robot hand a best
  // attempt took a minute.)
  double FreeTravel(const std::vector<std::size_t>& group, const std::vector<Obstacle>& obstacles,
                    const Eigen::Vector3d& d, double travel, double enough) const {
    const double no_seat = std::numeric_limits<double>::infinity();
    const Aabb swept = SweptBox(group, d, 0.0, travel);
    const Aabb start = SweptBox(group, d, 0.0, 0.0);  // the group's box where it stands
    std::vector<std::pair<double, std::size_t>> met;  // travel at which the boxes meet, obstacle
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      const Obstacle& o = obstacles[k];
      const Aabb grown = Grown(BoxOf(o));
      if (!grown.Intersects(swept)) continue;
      // A fit across d holds the group from the start, wherever the boxes meet (FirstStop).
      for (const std::size_t m : group) {
        if (!o.pin && HeldAcross(m, o.part, d)) return 0.0;
      }
      if (const auto at = TravelToMeet(start, grown, d, travel)) met.emplace_back(*at, k);
    }
    std::sort(met.begin(), met.end());
    double free = travel;
    for (const auto& [at, k] : met) {
      if (at >= free || free <= enough) break;
      const auto stop =
          FirstStop(group, obstacles[k], SweptBox(group, d, 0.0, free), d, 0.0, free, no_seat);
      if (stop) free = std::min(free, stop->travel);
    }
    return free;
  }

  // The least (or, when `max`, the greatest) of p.d over the corners of `box`.
  static double Extent(const Aabb& box, const Eigen::Vector3d& d, bool max) {
    double best =
        max ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p((corner & 1) ? box.max.x() : box.min.x(),
                              (corner & 2) ? box.max.y() : box.min.y(),
                              (corner & 4) ? box.max.z() : box.min.z());
      best = max ? std::max(best, p.dot(d)) : std::min(best, p.dot(d));
    }
    return best;
  }

  // Distance along d that takes `group`'s boxes clear of `others`' boxes (plus a margin).
  double ClearingDistance(const std::vector<std::size_t>& group,
                          const std::vector<Obstacle>& others, const Eigen::Vector3d& d) const {
    double group_min = std::numeric_limits<double>::infinity();
    for (const std::size_t m : group) group_min = std::min(group_min, Extent(boxes_[m], d, false));
    return ClearingDistance(group_min, others, d);
  }

  // Distance along d that takes what reaches down to `lowest` along d clear of `others`' boxes
  // (plus a margin).
  double ClearingDistance(double lowest, const std::vector<Obstacle>& others,
                          const Eigen::Vector3d& d) const {
    double others_max = -std::numeric_limits<double>::infinity();
    for (const Obstacle& o : others) {
      others_max = std::max(others_max, Extent(BoxOf(o), d, true));
    }
    if (!std::isfinite(others_max)) return 0.0;
    return std::max(0.0, others_max - lowest) + 1.0 + tolerance_;
  }

  void CheckSteps(AssemblyPlan* plan) const {
    const std::size_t n = assembly_.parts().size();
    std::vector<bool> stepped(n, false);
    for (const AssemblyStep& s : assembly_.steps()) stepped[s.insert.part] = true;
    std::vector<bool> eligible(n);
    for (std::size_t p = 0; p < n; ++p) eligible[p] = !stepped[p] && !assembly_.part(p).ground;
    std::vector<bool> placed(n, true);
    std::vector<std::vector<std::size_t>> carried_by(assembly_.steps().size());
    for (std::size_t k = 0; k < assembly_.steps().size(); ++k) {
      const std::size_t part = assembly_.steps()[k].insert.part;
      placed[part] = false;
      carried_by[k] = Carried(part, eligible);
      for (const std::size_t c : carried_by[k]) {
        placed[c] = false;
        eligible[c] = false;
      }
    }
    for (std::size_t p = 0; p < n; ++p) {
      if (placed[p]) plan->base.push_back(p);
    }
    std::vector<bool> pin_in(pins_.size(), false);
    plan->base_pins = PinsAmong(plan->base, placed, &pin_in);
    for (std::size_t k = 0; k < assembly_.steps().size(); ++k) {
      Report(static_cast<double>(k) / assembly_.steps().size());
      const AssemblyStep& s = assembly_.steps()[k];
      InsertionStep step;
      step.part = s.insert.part;
      step.carried = carried_by[k];
      step.feature = s.insert;
      step.into = s.into;
      // Convex features and faces lead along their axis; a concave feature goes onto its
      // partner, against its own axis.
      const bool concave = IsConcave(assembly_.feature(s.insert).kind);
      step.direction_W = concave ? Eigen::Vector3d(-WorldAxis(s.insert)) : WorldAxis(s.insert);
      step.pair = PairOf(s.insert, s.into);
      std::vector<std::size_t> group = {step.part};
      group.insert(group.end(), step.carried.begin(), step.carried.end());
      const std::vector<Obstacle> obstacles = Obstacles(group, placed, pin_in);
      step.travel = ClearingDistance(group, obstacles, -step.direction_W);
      step.blocked_by =
          Sweep(group, obstacles, step.direction_W, -step.travel, step.travel, step.travel);
      AddClashesAtRest(group, placed, step.travel, &step.blocked_by);
      step.clear = step.blocked_by.empty();
      for (const std::size_t m : group) placed[m] = true;
      for (const HingePin* pin : PinsThrough(group, placed)) {
        step.pins.push_back(InsertPin(*pin, placed, pin_in));
        pin_in[Index(*pin)] = true;
      }
      plan->steps.push_back(step);
    }
  }

  // Candidate directions in which `unit` may leave, in order of preference, each with the
  // feature that suggests it: the axes of its features, the world's axes, then for each axis
  // the unit pivots on (a revolute or cylindrical pair with a part outside it) the way from the
  // axis to the centre of the unit's box, square to the axis, and the world's axes turned
  // square to it, both senses: a finger segment leaves its fork across the pin, along the
  // finger, whichever way the finger stands.
  std::vector<Direction> RemovalDirections(const std::vector<std::size_t>& unit) const {
    std::vector<Direction> dirs;
    auto add = [&](const Eigen::Vector3d& r, std::optional<FeatureRef> f) {
      for (const auto& [q, g] : dirs) {
        if (q.dot(r) >= std::cos(assembly_.tolerance().angle)) return;
      }
      dirs.emplace_back(r.normalized(), f);
    };
    for (const std::size_t p : unit) {
      const Part& part = assembly_.part(p);
      for (std::size_t f = 0; f < part.features.size(); ++f) {
        if (!HasDirection(part.features[f].kind)) continue;
        const FeatureRef ref{p, f};
        add(-WorldAxis(ref), ref);
        add(WorldAxis(ref), ref);
      }
    }
    for (int k = 0; k < 3; ++k) {
      add(Eigen::Vector3d::Unit(k), std::nullopt);
      add(-Eigen::Vector3d::Unit(k), std::nullopt);
    }
    Aabb box;
    for (const std::size_t p : unit) box.Extend(boxes_[p]);
    for (const Pair& pair : analysis_.pairs) {
      if (pair.type != PairType::kRevolute && pair.type != PairType::kCylindrical) continue;
      const bool a_in = std::find(unit.begin(), unit.end(), pair.a.part) != unit.end();
      const bool b_in = std::find(unit.begin(), unit.end(), pair.b.part) != unit.end();
      if (a_in == b_in) continue;
      const FeatureRef pivot = a_in ? pair.a : pair.b;
      const Eigen::Vector3d axis = WorldAxis(pivot);
      const Eigen::Vector3d out =
          box.center() - state_.X_WP[pivot.part] * assembly_.feature(pivot).origin;
      const Eigen::Vector3d away = out - out.dot(axis) * axis;
      if (away.norm() > tolerance_) {
        add(away.normalized(), std::nullopt);
        add(-away.normalized(), std::nullopt);
      }
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d across = Eigen::Vector3d::Unit(k) - axis(k) * axis;
        if (across.norm() < std::sin(assembly_.tolerance().angle)) continue;  // along the axis
        add(across.normalized(), std::nullopt);
        add(-across.normalized(), std::nullopt);
      }
    }
    return dirs;
  }

  void Search(AssemblyPlan* plan) const {
    const std::size_t n = assembly_.parts().size();
    // Units: parts that travel together (press fits, forced fixes).
    std::vector<bool> all(n, true);
    std::vector<std::size_t> unit_of(n, n);
    std::vector<std::vector<std::size_t>> units;
    for (std::size_t p = 0; p < n; ++p) {
      if (unit_of[p] != n) continue;
      std::vector<std::size_t> unit = {p};
      const auto carried = Carried(p, all);
      unit.insert(unit.end(), carried.begin(), carried.end());
      for (const std::size_t q : unit) unit_of[q] = units.size();
      units.push_back(unit);
    }
    std::vector<bool> base_unit(units.size(), false);
    bool any_ground = false;
    for (std::size_t p = 0; p < n; ++p) {
      if (assembly_.part(p).ground) {
        base_unit[unit_of[p]] = true;
        any_ground = true;
      }
    }
    if (!any_ground && n > 0) {
      std::size_t largest = 0;
      auto volume = [&](std::size_t p) { return boxes_[p].size().prod(); };
      for (std::size_t p = 1; p < n; ++p) {
        if (volume(p) > volume(largest)) largest = p;
      }
      base_unit[unit_of[largest]] = true;
    }
    std::vector<bool> present(n, true);
    std::vector<bool> done(units.size(), false);
    // Progress: the units removed, then those that cannot leave, each attempted once more.
    const double to_place =
        static_cast<double>(std::count(base_unit.begin(), base_unit.end(), false));
    std::size_t decided = 0;
    BlockerMemo memo;
    std::vector<InsertionStep> stuck_apart;
    std::vector<InsertionStep> removed = RemoveUnits(units, unit_of, base_unit, &present, &done,
                                                     &memo, &stuck_apart, [&](std::size_t count) {
                                                       decided += count;
                                                       Report(decided / to_place);
                                                     });
    // Removals become insertions, in reverse order.
    for (std::vector<InsertionStep>* list : {&removed, &stuck_apart}) {
      for (InsertionStep& s : *list) {
        if (s.apart_for) s.apart_for = removed.size() - 1 - *s.apart_for;
      }
    }
    std::vector<std::size_t> stuck;
    for (std::size_t u = 0; u < units.size(); ++u) {
      if (base_unit[u]) {
        plan->base.insert(plan->base.end(), units[u].begin(), units[u].end());
      } else if (!done[u]) {
        stuck.push_back(u);
      }
    }
    // Each unit that cannot leave is shown as its furthest attempt; with the removals over,
    // the attempts are independent of each other.
    plan->unplaced.resize(stuck.size());
    std::mutex reporting;
    ParallelFor(stuck.size(), [&](std::size_t k) {
      plan->unplaced[k] = BestAttempt(units[stuck[k]], present);
      const std::lock_guard<std::mutex> lock(reporting);
      Report(++decided / to_place);
    });
    plan->unplaced.insert(plan->unplaced.end(), stuck_apart.begin(), stuck_apart.end());
    std::sort(plan->base.begin(), plan->base.end());
    // The base's pins go in before anything else is there.
    std::vector<bool> base_only(n, false);
    for (const std::size_t p : plan->base) base_only[p] = true;
    std::vector<bool> pin_in(pins_.size(), false);
    plan->base_pins = PinsAmong(plan->base, base_only, &pin_in);
    plan->steps.assign(removed.rbegin(), removed.rend());
  }

  // Removes the units that are neither `done` nor of the base (`base_unit`) from the parts
  // `present`, one at a time, in passes over the units in order until a pass removes none; then,
  // given a `memo` (and `stuck_apart`), a sub-assembly (RemovableSubassembly) leaves as one and
  // the passes go on.
  // Returns the removals in order: a sub-assembly's removal, then the removals that take it
  // apart, `apart_for` the index of its removal among the removals; the best attempts of its
  // units that cannot be taken from it go to `stuck_apart` (`apart_for` likewise). Marks the
  // units removed `done` and their parts not `present`, and tells `removed` how many units each
  // removal took.
  std::vector<InsertionStep> RemoveUnits(const std::vector<std::vector<std::size_t>>& units,
                                         const std::vector<std::size_t>& unit_of,
                                         const std::vector<bool>& base_unit,
                                         std::vector<bool>* present, std::vector<bool>* done,
                                         BlockerMemo* memo, std::vector<InsertionStep>* stuck_apart,
                                         const std::function<void(std::size_t)>& removed) const {
    std::vector<InsertionStep> steps;
    for (bool progress = true; progress;) {
      progress = false;
      // A pass over the units in order, each tried with the parts that those before it left:
      // the units from `next` on are tried at once, the first of them that can leave goes, and
      // the pass goes on after it.
      for (std::size_t next = 0; next < units.size();) {
        std::vector<std::size_t> pending;
        for (std::size_t u = next; u < units.size(); ++u) {
          if (!(*done)[u] && !base_unit[u]) pending.push_back(u);
        }
        auto removable = FirstRemovable(pending, units, *present);
        if (!removable) break;
        auto& [u, step] = *removable;
        for (const std::size_t p : units[u]) (*present)[p] = false;
        (*done)[u] = true;
        steps.push_back(std::move(step));
        progress = true;
        if (removed) removed(1);
        next = u + 1;
      }
      if (progress) continue;
      if (!memo) break;
      assert(stuck_apart);
      auto sub = RemovableSubassembly(units, unit_of, base_unit, *done, *present, memo);
      if (!sub) break;
      for (const std::size_t u : sub->members) {
        (*done)[u] = true;
        for (const std::size_t p : units[u]) (*present)[p] = false;
      }
      // Put together apart for the removal's insertion (its index once the removals are
      // reversed into insertions: Search).
      for (InsertionStep& s : sub->apart) s.apart_for = steps.size();
      for (InsertionStep& s : sub->stuck) s.apart_for = steps.size();
      steps.push_back(std::move(sub->step));
      steps.insert(steps.end(), sub->apart.begin(), sub->apart.end());
      stuck_apart->insert(stuck_apart->end(), sub->stuck.begin(), sub->stuck.end());
      progress = true;
      if (removed) removed(sub->members.size());
    }
    return steps;
  }

  // What stops `unit` leaving along r (every stop on its way out, with no seat) among the parts
  // `present`: the parts, and for a pin the file leaves out the parts it goes through that are
  // not of the base (`in_base`; the pin then comes out with them, or before them); none when a
  // part of the base, or a pin through the base alone, stops it (the base is swept first: most
  // units tried are held by it). `by_pin` tells whether a pin stops it.
  std::optional<std::vector<std::size_t>> Blockers(const std::vector<std::size_t>& unit,
                                                   const Eigen::Vector3d& r,
                                                   const std::vector<bool>& present,
                                                   const std::vector<bool>& in_base,
                                                   bool* by_pin) const {
    std::vector<Obstacle> others = Obstacles(unit, present, PinsInPlace(unit, present));
    const double travel = ClearingDistance(unit, others, r);
    std::stable_partition(others.begin(), others.end(),
                          [&](const Obstacle& o) { return o.pin || in_base[o.part]; });
    const double no_seat = std::numeric_limits<double>::infinity();
    const Aabb swept = SweptBox(unit, r, 0.0, travel);
    std::vector<std::size_t> parts;
    for (const Obstacle& o : others) {
      if (!FirstStop(unit, o, swept, r, 0.0, travel, no_seat)) continue;
      if (o.pin) {
        *by_pin = true;
        const std::size_t before = parts.size();
        for (const std::size_t p : o.pin->parts) {
          if (!in_base[p]) parts.push_back(p);
        }
        if (parts.size() == before) return std::nullopt;
        continue;
      }
      if (in_base[o.part]) return std::nullopt;
      parts.push_back(o.part);
    }
    return parts;
  }

  // What stops unit `u` leaving along r (Blockers), from the memo when it is there: a list
  // found with more parts present loses those that have left since.
  std::optional<std::vector<std::size_t>> MemoBlockers(
      BlockerMemo* memo, const std::vector<std::vector<std::size_t>>& units, std::size_t u,
      const Eigen::Vector3d& r, const std::vector<bool>& present,
      const std::vector<bool>& in_base) const {
    const auto key = std::make_tuple(u, r.x(), r.y(), r.z());
    std::optional<std::optional<std::vector<std::size_t>>> known;
    {
      const std::lock_guard<std::mutex> lock(memo->mutex);
      const auto it = memo->blockers.find(key);
      if (it != memo->blockers.end()) known = it->second;
    }
    if (!known) {
      bool by_pin = false;
      known = Blockers(units[u], r, present, in_base, &by_pin);
      if (!by_pin) {  // the pins in place go as their parts leave: not kept
        const std::lock_guard<std::mutex> lock(memo->mutex);
        memo->blockers.emplace(key, *known);
      }
    }
    if (*known) {
      std::erase_if(**known, [&](std::size_t p) { return !present[p]; });
    }
    return *known;
  }

  // When no unit can leave alone: sets of units (none of the base) that can leave as one, each
  // a seed unit and, in turn, every unit that stops a unit of the set on its way out along one
  // of the seed's removal directions (the closure of the blocking relation along that
  // direction: Wilson and Latombe's non-directional blocking graph, "Geometric reasoning about
  // mechanical assembly", Artificial Intelligence 71, 1994): of the smallest that leave as one
  // (Apart), the first that comes apart down to its base, else the first.
  std::optional<Subassembly> RemovableSubassembly(
      const std::vector<std::vector<std::size_t>>& units, const std::vector<std::size_t>& unit_of,
      const std::vector<bool>& base_unit, const std::vector<bool>& done,
      const std::vector<bool>& present, BlockerMemo* memo) const {
    std::vector<bool> in_base(present.size(), false);
    for (std::size_t p = 0; p < present.size(); ++p) in_base[p] = base_unit[unit_of[p]];
    std::vector<std::size_t> seeds;
    for (std::size_t u = 0; u < units.size(); ++u) {
      if (!done[u] && !base_unit[u]) seeds.push_back(u);
    }
    // Per seed: each set of units found, with the direction it leaves in.
    std::vector<std::vector<std::pair<std::vector<std::size_t>, Direction>>> found(seeds.size());
    ParallelFor(seeds.size(), [&](std::size_t k) {
      for (const Direction& direction : RemovalDirections(units[seeds[k]])) {
        const Eigen::Vector3d& r = direction.first;
        std::vector<bool> in(units.size(), false);
        in[seeds[k]] = true;
        std::vector<std::size_t> members = {seeds[k]};
        bool held = false;  // by the base, or by a pin through the base alone
        for (std::size_t m = 0; !held && m < members.size(); ++m) {
          const auto blockers = MemoBlockers(memo, units, members[m], r, present, in_base);
          held = !blockers;
          for (const std::size_t b : blockers.value_or(std::vector<std::size_t>())) {
            if (!in[unit_of[b]]) {
              in[unit_of[b]] = true;
              members.push_back(unit_of[b]);
            }
          }
        }
        if (!held && members.size() > 1) {
          std::sort(members.begin(), members.end());
          found[k].emplace_back(members, direction);
        }
      }
    });
    std::vector<std::pair<std::vector<std::size_t>, Direction>> candidates;
    for (auto& f : found) candidates.insert(candidates.end(), f.begin(), f.end());
    // The smallest first, then in the order of their seeds; each set tried once. Of the sets
    // of the smallest size that leave, one that comes apart down to its base is preferred.
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.first.size() < b.first.size(); });
    std::set<std::vector<std::size_t>> tried;
    std::optional<Subassembly> with_stuck;
    for (const auto& [members, direction] : candidates) {
      if (with_stuck && members.size() > with_stuck->members.size()) break;
      if (!tried.insert(members).second) continue;
      std::optional<Subassembly> sub = Apart(units, unit_of, members, direction, present);
      if (sub && sub->stuck.empty()) return sub;
      if (sub && !with_stuck) with_stuck = std::move(sub);
    }
    return with_stuck;
  }

  // The sub-assembly of the units `members` leaving the parts `present` as one (along
  // `direction` first, then its own removal directions), if it can, and how it is put together
  // apart from the rest of the assembly: its units, the one with the largest box first (the
  // sub-assembly's base), are removed from it one at a time as the search removes them from the
  // assembly (with no sub-assembly inside it, and without the pins the file leaves out: those
  // through its parts go in after its insertion, with everything in place); those that cannot
  // leave it so stay with its base, each with its best attempt.
  std::optional<Subassembly> Apart(const std::vector<std::vector<std::size_t>>& units,
                                   const std::vector<std::size_t>& unit_of,
                                   std::vector<std::size_t> members, const Direction& direction,
                                   const std::vector<bool>& present) const {
    const auto volume = [&](std::size_t u) {
      Aabb box;
      for (const std::size_t p : units[u]) box.Extend(boxes_[p]);
      return box.size().prod();
    };
    // The largest first, then in order: the step names the base and carries the rest.
    std::stable_sort(members.begin(), members.end(),
                     [&](std::size_t a, std::size_t b) { return volume(a) > volume(b); });
    std::vector<std::size_t> group;
    for (const std::size_t u : members) group.insert(group.end(), units[u].begin(), units[u].end());
    std::optional<InsertionStep> step = TryRemove(group, present, direction);
    if (!step) return std::nullopt;
    Planner without_pins = *this;
    without_pins.pins_.clear();
    std::vector<bool> alone(present.size(), false);  // the sub-assembly's parts, by themselves
    for (const std::size_t p : group) alone[p] = true;
    std::vector<bool> base(units.size(), false), done(units.size(), true);
    base[members.front()] = true;
    for (const std::size_t u : members) done[u] = false;
    Subassembly sub;
    sub.apart = without_pins.RemoveUnits(units, unit_of, base, &alone, &done, nullptr, nullptr, {});
    for (const std::size_t u : members) {
      if (!done[u] && !base[u]) sub.stuck.push_back(without_pins.BestAttempt(units[u], alone));
    }
    step->subassembly = true;
    sub.members = std::move(members);
    sub.step = std::move(*step);
    return sub;
  }

  InsertionStep MakeStep(const std::vector<std::size_t>& unit, const Eigen::Vector3d& r,
                         const std::optional<FeatureRef>& feature,
                         const std::vector<bool>& present) const {
    InsertionStep step;
    step.part = unit.front();
    step.carried.assign(unit.begin() + 1, unit.end());
    step.direction_W = -r;
    step.feature = feature;
    if (feature) {
      // The relation this insertion creates: a pair of the feature with a part in place.
      for (std::size_t k = 0; k < analysis_.pairs.size(); ++k) {
        const Pair& p = analysis_.pairs[k];
        const FeatureRef other = p.a == *feature ? p.b : p.b == *feature ? p.a : *feature;
        if (other == *feature || !present[other.part]) continue;
        if (std::find(unit.begin(), unit.end(), other.part) != unit.end()) continue;
        step.into = other;
        step.pair = k;
        break;
      }
    }
    return step;
  }

  // The first of `unit`'s removal directions (`first`, if given, then RemovalDirections) in
  // which it can leave the parts `present`, the pins through it (PinsThrough) coming out first.
  std::optional<InsertionStep> TryRemove(const std::vector<std::size_t>& unit,
                                         const std::vector<bool>& present,
                                         const std::optional<Direction>& first = {}) const {
    const std::vector<bool> pin_in = PinsInPlace(unit, present);
    const std::vector<Obstacle> others = Obstacles(unit, present, pin_in);
    std::vector<Direction> directions = RemovalDirections(unit);
    if (first) directions.insert(directions.begin(), *first);
    for (const auto& [r, feature] : directions) {
      const double travel = ClearingDistance(unit, others, r);
      // Leaving: no seat at the far end, so every contact counts.
      if (Stopped(unit, others, r, travel)) {
        continue;
      }
      // The pins through the unit come out first; they are tried once the unit's own way out
      // is known, since most units tried cannot leave yet whatever their pins do.
      InsertionStep step = MakeStep(unit, r, feature, present);
      std::vector<bool> pins_after = pin_in;  // as the pins go in after the unit, in order
      for (const HingePin* pin : PinsThrough(unit, present)) {
        step.pins.push_back(InsertPin(*pin, present, pins_after));
        if (!step.pins.back().clear) return std::nullopt;
        pins_after[Index(*pin)] = true;
      }
      step.travel = travel;
      // A way out that starts in a clash is taken (the clash is the model's, reported as
      // such), but the insertion does not reach its place clear.
      AddClashesAtRest(unit, present, travel, &step.blocked_by);
      step.clear = step.blocked_by.empty();
      return step;
    }
    return std::nullopt;
  }

  // The first of `candidates` (units, in order) that can leave with the parts `present` as
  // they are, with its step. The candidates are tried on all cores; those after one that can
  // leave may be left untried, those before it are all tried, so the answer does not depend on
  // the threads' timing.
  std::optional<std::pair<std::size_t, InsertionStep>> FirstRemovable(
      const std::vector<std::size_t>& candidates,
      const std::vector<std::vector<std::size_t>>& units, const std::vector<bool>& present) const {
    std::vector<std::optional<InsertionStep>> steps(candidates.size());
    std::atomic<std::size_t> first{candidates.size()};
    ParallelFor(candidates.size(), [&](std::size_t k) {
      if (k > first) return;
      steps[k] = TryRemove(units[candidates[k]], present);
      if (!steps[k]) return;
      std::size_t known = first;
      while (k < known && !first.compare_exchange_weak(known, k)) {
      }
    });
    if (first == candidates.size()) return std::nullopt;
    return std::make_pair(candidates[first], std::move(*steps[first]));
  }

  // The removal direction that gets furthest (the first of those that get equally far),
  // reported as the insertion it would be.
  InsertionStep BestAttempt(const std::vector<std::size_t>& unit,
                            const std::vector<bool>& present) const {
    const std::vector<bool> pin_in = PinsInPlace(unit, present);
    const std::vector<Obstacle> others = Obstacles(unit, present, pin_in);
    std::optional<Direction> best;
    double best_free = -1.0, best_travel = 0.0;
    for (const auto& [r, feature] : RemovalDirections(unit)) {
      const double travel = ClearingDistance(unit, others, r);
      const double free = FreeTravel(unit, others, r, travel, best_free);
      if (free <= best_free) continue;
      best_free = free;
      best_travel = travel;
      best.emplace(r, feature);
    }
    const auto& [r, feature] = *best;
    InsertionStep step = MakeStep(unit, r, feature, present);
    step.travel = best_travel;
    auto blocked =
        Sweep(unit, others, r, 0.0, best_travel, std::numeric_limits<double>::infinity());
    // As an insertion: the obstacle is met `travel - free` after the start.
    for (InsertionObstacle& o : blocked) {
      o.short_by = o.travel;
      o.travel = best_travel - o.travel;
    }
    std::reverse(blocked.begin(), blocked.end());  // by insertion travel again
    step.blocked_by = std::move(blocked);
    AddClashesAtRest(unit, present, best_travel, &step.blocked_by);
    step.clear = step.blocked_by.empty();  // held by a pin that cannot come out
    std::vector<bool> pins_after = pin_in;
    for (const HingePin* pin : PinsThrough(unit, present)) {
      step.pins.push_back(InsertPin(*pin, present, pins_after));
      pins_after[Index(*pin)] = true;
    }
    return step;
  }

  void Report(double fraction) const {
    if (progress_) progress_(fraction);
  }

  const Assembly& assembly_;
  const Analysis& analysis_;
  const CollisionModel& model_;
  const std::function<void(double)>& progress_;
  AssemblyState state_;
  double tolerance_;
  double min_approach_;
  std::vector<Aabb> boxes_;
  std::vector<HingePin> pins_;
  std::vector<PartContact> clashes_;  // the clashes at rest, once Plan has found them
};

}  // namespace

AssemblyPlan PlanAssembly(const Assembly& assembly, const Analysis& analysis,
                          const CollisionModel& model,
                          const std::function<void(double)>& progress) {
  return Planner(assembly, analysis, model, progress).Plan();
}

}  // namespace mechanist
