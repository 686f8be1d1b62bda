#include "reasoning/seated_parts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "kernel/collision/collision_mesh.h"
#include "kernel/collision/collision_mesh_cache.h"
#include "kernel/collision/translational_sweep.h"
#include "kernel/geometry/aabb.h"
#include "kernel/solvers/linear_algebra.h"
#include "kernel/support/number_format.h"
#include "kernel/support/parallel_for.h"

namespace mechanist {
namespace {

// The relative twists (rotation; velocity of the point at the origin) of body B against S
// that the pairs between them allow: the null space of their velocity constraints, as
// columns. Points are taken from `p_WR` and in units of `scale`, so rotation and translation
// rows weigh alike.
Eigen::MatrixXd AllowedTwists(const Assembly& assembly, const std::vector<const Pair*>& pairs,
                              const Eigen::Vector3d& p_WR, double scale) {
  Eigen::MatrixXd rows(4 * pairs.size(), 6);
  Eigen::Index r = 0;
  auto add = [&](const Eigen::Vector3d& rotation, const Eigen::Vector3d& translation) {
    rows.row(r).head<3>() = rotation;
    rows.row(r).tail<3>() = translation;
    ++r;
  };
  for (const Pair* p : pairs) {
    const Part& part = assembly.part(p->a.part);
    const AxisSegment axis = assembly.feature(p->a).WorldAxis(part.X_WP);
    const Eigen::Vector3d u = axis.direction, q = (axis.origin - p_WR) / scale;
    const Eigen::Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
    // A point's velocity is v + w x q: its component along n is (q x n) . w + n . v.
    add(e1, Eigen::Vector3d::Zero());  // both: turning about u only
    add(e2, Eigen::Vector3d::Zero());
    if (p->type == PairType::kPlanar) {
      add(q.cross(u), u);
    } else {  // cylindrical: the axis' points move along it
      add(q.cross(e1), e1);
      add(q.cross(e2), e2);
    }
  }
  return NullSpace(rows.topRows(r), std::sin(assembly.tolerance().angle));
}

// mm: the unit of the constraints' lever arms, so that within a machine's size they weigh
// about as much as the unit rotation rows.
constexpr double kLeverArm = 100.0;

// The unit direction of the only pure translation among `twists`, if there is exactly one.
std::optional<Eigen::Vector3d> OnlyTranslation(const Eigen::MatrixXd& twists, double tolerance) {
  if (twists.cols() == 0) return std::nullopt;
  const Eigen::MatrixXd still = NullSpace(twists.topRows(3), tolerance);  // no rotation
  if (still.cols() != 1) return std::nullopt;
  const Eigen::Vector3d d = twists.bottomRows(3) * still;
  if (d.norm() <= tolerance) return std::nullopt;
  return d.normalized();
}

// The first part met on a slide, and after how far (mm).
struct Stop {
  double travel = 0.0;
  std::size_t part = 0;
};

// What a seat found: the moving body, its pairs with the seat, the parts that stop the slide
// and the play.
struct Seat {
  std::size_t body = 0;
  bool on_axis = false;  // cylindrical pairs made revolute; else planar pairs made fixed
  std::vector<std::size_t> pairs;
  std::set<std::size_t> stops;
  double play = 0.0;  // mm, both ways together
};

class Seater {
 public:
  // The bounds of every part's mesh are taken here, once for each distinct mesh, so that the
  // sweeps (Travel) only read.
  explicit Seater(const Assembly& assembly)
      : assembly_(assembly), min_approach_(std::sin(assembly.tolerance().angle)) {
    for (const Part& part : assembly.parts()) {
      if (!part.HasGeometry()) continue;
      auto [it, added] = bounds_.try_emplace(part.mesh.get());
      if (added) it->second = part.mesh->Bounds();
    }
  }

  // How far the parts `moving` travel along d before a part of `obstacles` stops them, up to
  // kMaxSeatPlay; empty when nothing does, or a part has no mesh. Obstacles beyond the moving
  // parts' reach (their bounds grown by kMaxSeatPlay) are not swept. The meshes it sweeps
  // (AppendSwept) must have been built (BuildMeshes); it only reads, so that several threads
  // may sweep at once.
  std::optional<Stop> Travel(const std::vector<std::size_t>& moving,
                             const std::vector<std::size_t>& obstacles,
                             const Eigen::Vector3d& d) const {
    const std::optional<Aabb> reach_W = Reach(moving);
    if (!reach_W) return std::nullopt;
    SweepOptions options;
    options.max_travel = kMaxSeatPlay;
    options.min_approach = min_approach_;
    std::optional<Stop> first;
    for (std::size_t m : moving) {
      const CollisionMesh* mesh_m = Mesh(m);
      for (std::size_t o : obstacles) {
        if (!InReach(o, *reach_W)) continue;
        const CollisionMesh* mesh_o = Mesh(o);
        const std::optional<SweepContact> contact = FirstBlockingContact(
            *mesh_m, assembly_.part(m).X_WP, *mesh_o, assembly_.part(o).X_WP, d, options);
        if (contact && (!first || contact->travel < first->travel)) {
          first = Stop{contact->travel, o};
        }
      }
    }
    return first;
  }

  // Appends to `meshes` those that Travel(moving, obstacles, d) sweeps, whatever d.
  void AppendSwept(const std::vector<std::size_t>& moving,
                   const std::vector<std::size_t>& obstacles,
                   std::vector<std::shared_ptr<const TriangleMesh>>* meshes) const {
    const std::optional<Aabb> reach_W = Reach(moving);
    if (!reach_W) return;
    for (std::size_t m : moving) meshes->push_back(assembly_.part(m).mesh);
    for (std::size_t o : obstacles) {
      if (InReach(o, *reach_W)) meshes->push_back(assembly_.part(o).mesh);
    }
  }

  // Builds the collision meshes of `meshes` on all cores, for the Travel calls.
  void BuildMeshes(const std::vector<std::shared_ptr<const TriangleMesh>>& meshes) {
    meshes_.Build(meshes);
  }

  // Whether feature f lies within its part's mesh's bounds: the mesh is the part's shape
  // where the pair is (a stand-in mesh far from the features says nothing about the seat).
  bool OnMesh(FeatureRef f) const {
    if (!assembly_.part(f.part).HasGeometry()) return false;
    const Aabb& box_P = Bounds(f.part);
    const Eigen::Vector3d p = assembly_.feature(f).origin;
    const double margin = assembly_.tolerance().length;
    return (p.array() >= box_P.min.array() - margin).all() &&
           (p.array() <= box_P.max.array() + margin).all();
  }

 private:
  // The bounds of part `part`'s mesh, which it must have, in its frame and in the world's.
  const Aabb& Bounds(std::size_t part) const { return bounds_.at(assembly_.part(part).mesh.get()); }
  Aabb BoundsInWorld(std::size_t part) const {
    return TransformBox(assembly_.part(part).X_WP, Bounds(part));
  }
  // The world box that the parts `moving` can sweep (their bounds grown by kMaxSeatPlay and
  // the length tolerance); empty when one of them has no mesh.
  std::optional<Aabb> Reach(const std::vector<std::size_t>& moving) const {
    Aabb reach_W;
    for (std::size_t m : moving) {
      if (!assembly_.part(m).HasGeometry()) return std::nullopt;
      reach_W.Extend(BoundsInWorld(m));
    }
    reach_W.min.array() -= kMaxSeatPlay + assembly_.tolerance().length;
    reach_W.max.array() += kMaxSeatPlay + assembly_.tolerance().length;
    return reach_W;
  }
  // Whether part `obstacle` has a mesh within `reach_W` (Reach).
  bool InReach(std::size_t obstacle, const Aabb& reach_W) const {
    return assembly_.part(obstacle).HasGeometry() && BoundsInWorld(obstacle).Intersects(reach_W);
  }

  // The collision mesh of part `part`, built by BuildMeshes (a CollisionModel would build every
  // part's, most of them never swept here).
  const CollisionMesh* Mesh(std::size_t part) const {
    const CollisionMesh* mesh = meshes_.Find(assembly_.part(part).mesh.get());
    if (mesh == nullptr) throw std::logic_error("SeatParts: a swept mesh was not built");
    return mesh;
  }

  const Assembly& assembly_;
  double min_approach_ = 0.0;
  CollisionMeshCache meshes_;
  std::map<const TriangleMesh*, Aabb> bounds_;
};

}  // namespace

Seating SeatParts(const Assembly& assembly, const MotionAnalysis& motion,
                  const std::vector<Subassembly>& subassemblies,
                  const std::vector<std::size_t>& subassembly_of, std::vector<Pair>* pairs) {
  Seating seating;
  if (!assembly.inference().seated_parts) return seating;
  std::set<std::size_t> moving_bodies;
  for (const FreeMotion& f : motion.mobility.free_motions) {
    if (f.pair) moving_bodies.insert(subassembly_of[f.part]);
  }
  if (moving_bodies.empty()) return seating;

  // The pairs of each moving body, by the body on their other side.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> between;
  for (std::size_t i = 0; i < pairs->size(); ++i) {
    const Pair& p = (*pairs)[i];
    const std::size_t a = subassembly_of[p.a.part], b = subassembly_of[p.b.part];
    if (a == b) continue;
    if (moving_bodies.count(a)) between[{a, b}].push_back(i);
    if (moving_bodies.count(b)) between[{b, a}].push_back(i);
  }
  // A moving body whose pairs with the body it rests `on` leave it a single slide (and, for
  // cylindrical pairs, a turn): their indices, and the slide's direction d (world).
  struct Candidate {
    std::size_t body = 0, on = 0;
    const std::vector<std::size_t>* pairs = nullptr;
    bool cylindrical = false;
    Eigen::Vector3d d;
  };
  Seater seater(assembly);
  const double tolerance = std::sin(assembly.tolerance().angle);
  std::vector<Candidate> candidates;
  for (const auto& [bodies, indices] : between) {
    std::vector<const Pair*> group;
    bool planar = true, cylindrical = true;
    for (std::size_t i : indices) {
      const Pair& p = (*pairs)[i];
      planar = planar && p.type == PairType::kPlanar;
      cylindrical = cylindrical && p.type == PairType::kCylindrical;
      group.push_back(&p);
    }
    if (!planar && !cylindrical) continue;
    if (!std::all_of(group.begin(), group.end(),
                     [&](const Pair* p) { return seater.OnMesh(p->a) && seater.OnMesh(p->b); })) {
      continue;
    }
    const Part& first = assembly.part(group.front()->a.part);
    const Eigen::Vector3d p_WR = assembly.feature(group.front()->a).WorldAxis(first.X_WP).origin;
    const Eigen::MatrixXd twists = AllowedTwists(assembly, group, p_WR, kLeverArm);
    // Planar pairs: a slide and nothing else. Cylindrical pairs: a turn and a slide.
    if (twists.cols() != (planar ? 1 : 2)) continue;
    const std::optional<Eigen::Vector3d> d = OnlyTranslation(twists, tolerance);
    if (!d) continue;
    candidates.push_back({bodies.first, bodies.second, &indices, cylindrical, *d});
  }
  std::vector<std::shared_ptr<const TriangleMesh>> swept;
  for (const Candidate& c : candidates) {
    seater.AppendSwept(subassemblies[c.body].parts, subassemblies[c.on].parts, &swept);
  }
  seater.BuildMeshes(swept);
  // The slides swept both ways, on all cores. When both bodies of a pair move, the pair is a
  // candidate twice, (a, b) and then (b, a), with the same pairs: the second is swept below
  // only when the first was not seated.
  struct Slide {
    std::optional<Stop> ahead, behind;
  };
  const auto sweep = [&](const Candidate& c) {
    const std::vector<std::size_t>& body_parts = subassemblies[c.body].parts;
    const std::vector<std::size_t>& seat_parts = subassemblies[c.on].parts;
    Slide slide;
    slide.ahead = seater.Travel(body_parts, seat_parts, c.d);
    if (slide.ahead) slide.behind = seater.Travel(body_parts, seat_parts, -c.d);
    return slide;
  };
  std::vector<bool> second(candidates.size(), false);
  std::set<std::size_t> first_pairs;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    second[k] = !first_pairs.insert(candidates[k].pairs->front()).second;
  }
  std::vector<Slide> slides(candidates.size());
  ParallelFor(candidates.size(), [&](std::size_t k) {
    if (!second[k]) slides[k] = sweep(candidates[k]);
  });

  std::vector<Seat> seats;
  std::vector<bool> seated(pairs->size(), false);  // a body pair is settled once, either way
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Candidate& c = candidates[k];
    const std::vector<std::size_t>& indices = *c.pairs;
    if (seated[indices.front()]) continue;
    if (second[k]) slides[k] = sweep(c);
    const std::optional<Stop>& ahead = slides[k].ahead;
    const std::optional<Stop>& behind = slides[k].behind;
    if (!ahead || !behind) continue;
    const double play = ahead->travel + behind->travel;
    if (play >= kMaxSeatPlay) continue;
    seats.push_back({c.body, c.cylindrical, indices, {ahead->part, behind->part}, play});
    for (std::size_t i : indices) seated[i] = true;
  }
  if (seats.empty()) return seating;

  // Reports, one per seat and kind, grouping the parts alike (five servos in one forearm).
  struct Group {
    std::vector<std::string> parts;
    std::set<std::string> features, stops;
    double play = 0.0;
  };
  std::map<std::tuple<bool, std::string>, Group> groups;
  std::vector<bool> drop(pairs->size(), false);
  std::vector<Pair> fixed;
  for (const Seat& s : seats) {
    // Named by the part the first pair seats it on (a forearm, a pivot screw).
    const Pair& front = (*pairs)[s.pairs.front()];
    const bool a_moves = subassembly_of[front.a.part] == s.body;
    Group& g =
        groups[{s.on_axis, std::string(assembly.PartId(a_moves ? front.b.part : front.a.part))}];
    g.parts.emplace_back(assembly.PartId(a_moves ? front.a.part : front.b.part));
    for (std::size_t part : s.stops) g.stops.insert(std::string(assembly.PartId(part)));
    for (std::size_t i : s.pairs) {
      const Pair& p = (*pairs)[i];
      g.features.insert(assembly.FeatureName(p.a));
      g.features.insert(assembly.FeatureName(p.b));
    }
    g.play = std::max(g.play, s.play);
    if (s.on_axis) {
      for (std::size_t i : s.pairs) {
        (*pairs)[i].type = PairType::kRevolute;
        (*pairs)[i].dof = DegreesOfFreedom(PairType::kRevolute);
        (*pairs)[i].source = PairSource::kSeated;
      }
    } else {
      for (std::size_t i : s.pairs) drop[i] = true;
      Pair held = front;
      held.type = PairType::kFixed;
      held.dof = DegreesOfFreedom(PairType::kFixed);
      held.source = PairSource::kSeated;
      fixed.push_back(held);
    }
  }
  std::size_t i = 0;
  std::erase_if(*pairs, [&](const Pair&) { return drop[i++]; });
  pairs->insert(pairs->end(), fixed.begin(), fixed.end());

  for (auto& [key, g] : groups) {
    const auto& [on_axis, seat] = key;
    std::sort(g.parts.begin(), g.parts.end());
    const bool several = g.parts.size() > 1;
    const std::string who =
        several ? fmt::format("{} parts, {}, each", g.parts.size(), fmt::join(g.parts, ", "))
                : g.parts.front();
    const std::string within =
        g.play <= assembly.tolerance().length
            ? std::string("at once")
            : fmt::format("within {} mm, both ways together", FormatNumber(g.play, 3));
    const std::string stops = fmt::format("{}", fmt::join(g.stops, " or "));
    const std::string message =
        on_axis ? fmt::format(
                      "{} turns on one axis with {} (cylindrical pairs), and {} stops "
                      "its slide along it {}: held along the axis, as in a fork (the "
                      "pairs taken as revolute; \"infer\": {{\"seated_parts\": false}} "
                      "leaves them cylindrical)",
                      who, seat, stops, within)
                : fmt::format(
                      "{} rests on faces of {} that leave it a single slide, and {} "
                      "stops it {}: seated, taken as fixed there (what holds it, screws "
                      "or glue, is not in the file; \"infer\": {{\"seated_parts\": "
                      "false}} leaves it on its faces)",
                      who, seat, stops, within);
    std::vector<std::string> parts = g.parts;
    parts.push_back(seat);
    seating.diagnostics.push_back({Severity::kInfo,
                                   on_axis ? "retained" : "seated",
                                   message,
                                   parts,
                                   {g.features.begin(), g.features.end()}});
  }
  seating.changed = true;
  return seating;
}

}  // namespace mechanist
