#include "reasoning/motion.h"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "kernel/collision/collision_mesh_cache.h"
#include "kernel/collision/rotational_symmetry.h"
#include "kernel/geometry/line_geometry.h"
#include "kernel/support/compressed_rows.h"
#include "kernel/support/enum_names.h"
#include "kernel/support/number_format.h"
#include "reasoning/kinematic_model.h"
#include "reasoning/linear_system.h"

namespace mechanist {
namespace {

constexpr double kTolerance = 1e-9;
constexpr double kTwoPi = 6.283185307179586;

constexpr EnumNames<MotionKind, 4> kMotionKindNames{{
    {MotionKind::kNone, "none"},
    {MotionKind::kRotation, "rotation"},
    {MotionKind::kTranslation, "translation"},
    {MotionKind::kScrew, "screw"},
}};

}  // namespace

/// The velocity analysis of one assembly: its model, its constraint rows reduced once, and
/// the scenarios (drivers, drags, a joint's range) solved on copies of that reduction.
class MotionModel {
 public:
  MotionModel(const Assembly& assembly, const std::vector<Pair>& pairs,
              std::shared_ptr<const PairGraph> graph, std::vector<AxisSegment> axes_W = {})
      : assembly_(assembly),
        graph_(std::move(graph)),
        model_(assembly, pairs, graph_->Subassemblies(), graph_->SubassemblyOf(),
               std::move(axes_W)),
        structural_(model_.freedoms().size(), kTolerance),
        mm_per_length_(ExactReal::FromDecimal(assembly.units().mm_per_length)) {
    std::vector<std::pair<std::size_t, std::size_t>> parts;  // (body, part)
    parts.reserve(assembly.parts().size());
    for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
      parts.emplace_back(model_.body_of_part(p), p);
    }
    parts_of_body_ = CompressedRows<std::size_t>(model_.body_count(), parts);
    for (const ConstraintRow& row : model_.rows()) {
      outcomes_.push_back(structural_.AddRow(row.terms));
    }
    has_pair_.assign(model_.body_count(), false);
    on_faces_.assign(model_.body_count(), true);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      if (pairs[i].type == PairType::kWormGear) {
        worms_.emplace(i, pairs[i]);
        self_locking_worms_ |= pairs[i].self_locking;
      }
      const std::size_t a = model_.body_of_part(pairs[i].a.part);
      const std::size_t b = model_.body_of_part(pairs[i].b.part);
      has_pair_[a] = has_pair_[b] = true;
      if (a != b && pairs[i].type != PairType::kPlanar) on_faces_[a] = on_faces_[b] = false;
    }
  }

  const KinematicModel& model() const { return model_; }
  const LinearSystem& structural() const { return structural_; }
  const std::vector<LinearSystem::Outcome>& outcomes() const { return outcomes_; }

  /// Solves `imposed` (with the given labels for messages); `system` receives the scenario's
  /// system, for its free motions.
  DrivenMotion Solve(const std::vector<ImposedMotion>& imposed,
                     const std::vector<std::string>& labels, LinearSystem* system = nullptr) const {
    std::vector<ExactReal> x;
    DrivenMotion motion = SolveRates(imposed, labels, x, system);
    Describe(x, motion);
    return motion;
  }

  /// The rates `x` of the model's freedoms under `imposed`, and whether they are possible.
  DrivenMotion SolveRates(const std::vector<ImposedMotion>& imposed,
                          const std::vector<std::string>& labels, std::vector<ExactReal>& x,
                          LinearSystem* system = nullptr) const {
    DrivenMotion motion;
    LinearSystem s = structural_;
    std::vector<std::size_t> locked_worms = BackDrivenWorms(imposed);
    for (std::size_t w : locked_worms) s.AddRow(WormLock(w));
    for (std::size_t i = 0; i < imposed.size() && motion.possible; ++i) {
      const LinearSystem::Row row = ImposedRow(imposed[i]);
      if (s.AddRow(row, ExactReal::FromDecimal(imposed[i].rate)) !=
          LinearSystem::Outcome::kInconsistent) {
        continue;
      }
      motion.possible = false;
      LinearSystem free = structural_;
      LinearSystem unlocked = structural_;
      for (std::size_t w : locked_worms) unlocked.AddRow(WormLock(w));
      if (free.AddRow(row, Rational(1)) == LinearSystem::Outcome::kInconsistent) {
        motion.reason = fmt::format("{} cannot move: the pairs lock its motion", labels[i]);
      } else if (unlocked.AddRow(row, Rational(1)) == LinearSystem::Outcome::kInconsistent) {
        motion.reason = fmt::format(
            "{} cannot move: it would drive worm gear {} from its wheel, and that worm gear is "
            "not back-drivable",
            labels[i], WormName(locked_worms.front()));
      } else {
        motion.contradiction = true;
        motion.reason = fmt::format("{} contradicts {}: they drive the same freedom", labels[i],
                                    i == 1 ? labels[0] : "the other drivers");
      }
    }
    for (std::size_t i = 0; i < imposed.size() && motion.possible; ++i) {
      if (!imposed[i].about_line) continue;
      // Each freedom that would move the axis' line held still where the pairs allow it, in
      // the model's order: one exact row each (the rates stay exact), not kept when it
      // contradicts the others (LinearSystem::AddRow).
      for (const std::size_t f : LineFreedoms(imposed[i])) s.AddRow({{f, Rational(1)}});
    }
    x = motion.possible ? s.Solve() : std::vector<ExactReal>(model_.freedoms().size());
    if (system) *system = std::move(s);
    return motion;
  }

  /// The imposed motion's feature, for messages.
  std::string Label(const ImposedMotion& m) const { return assembly_.FeatureName(m.feature); }

  /// "a/f + b/g" for a worm gear pair.
  std::string WormName(std::size_t pair) const {
    const Pair& p = worms_.at(pair);
    return fmt::format("{} + {}", assembly_.FeatureName(p.a), assembly_.FeatureName(p.b));
  }

  /// Whether a part of `body` is in a pair (with a part of another body or of its own).
  bool HasPair(std::size_t body) const { return has_pair_[body]; }

  /// Whether `body` is held to the others by face contacts (planar pairs) alone, when it has a
  /// pair: a part resting on faces, which something the file leaves out fastens.
  bool OnFacesAlone(std::size_t body) const { return has_pair_[body] && on_faces_[body]; }

  /// The parts of a body, ascending.
  std::span<const std::size_t> PartsOf(std::size_t body) const { return parts_of_body_[body]; }

  /// Fills `motion`'s part and feature motions from the freedoms' rates `x`.
  void Describe(const std::vector<ExactReal>& x, DrivenMotion& motion) const {
    std::vector<Eigen::Vector3d> omega, v;
    model_.Twists(x, omega, v);
    const std::size_t ground = model_.ground();
    const std::size_t parts = assembly_.parts().size();
    // Appended, not resized then assigned: at 100,000 parts the motions (17 MB) leave the
    // cache between a fill and an assignment, and would be written to memory twice.
    motion.parts.clear();
    motion.parts.reserve(parts);
    std::vector<std::size_t> start{0};  // per part: its first rate
    start.reserve(parts + 1);
    std::vector<FeatureRate> rates;
    rates.reserve(assembly_.feature_count());
    for (std::size_t p = 0; p < parts; ++p) {
      const std::size_t body = model_.body_of_part(p);
      // From the compact tables, not the Part: a read of every part fewer.
      for (std::size_t f = 0; f < assembly_.FeatureCount(p); ++f) {
        const AxisSegment& axis = model_.WorldAxis({p, f});
        rates.push_back(
            {model_.AngularRate(body, ground, axis.direction, x),
             model_.LinearRate(body, ground, axis.origin, axis.direction, x) / mm_per_length_});
      }
      motion.parts.push_back(Classify(p, omega[body], v[body],
                                      std::span<const FeatureRate>(rates).subspan(start.back())));
      motion.parts.back().path = Path(body, x);
      start.push_back(rates.size());
    }
    motion.features = CompressedRows<FeatureRate>(std::move(start), std::move(rates));
  }

 private:
  LinearSystem::Row ImposedRow(const ImposedMotion& m) const {
    const std::size_t body = model_.body_of_part(m.feature.part);
    const std::size_t reference =
        m.relative_to ? model_.body_of_part(*m.relative_to) : model_.ground();
    const AxisSegment axis = model_.WorldAxis(m.feature);
    return m.rotation ? model_.Angular(body, reference, axis.direction)
                      : model_.Linear(body, reference, axis.origin, axis.direction);
  }

  /// The freedoms whose motion would move `m`'s axis' line (ImposedMotion::about_line): for
  /// a rotation, those that move the axis' origin (across the axis or along it); for a
  /// translation, those that turn the part. Ascending.
  std::vector<std::size_t> LineFreedoms(const ImposedMotion& m) const {
    const std::size_t body = model_.body_of_part(m.feature.part);
    const std::size_t reference =
        m.relative_to ? model_.body_of_part(*m.relative_to) : model_.ground();
    const AxisSegment axis = model_.WorldAxis(m.feature);
    const Eigen::Vector3d d = axis.direction.normalized();
    const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
    std::vector<std::map<std::size_t, double>> rates;  // per direction, by freedom
    double largest = 0.0;
    for (const Eigen::Vector3d& e : {u, v, d}) {
      std::map<std::size_t, double>& rate = rates.emplace_back();
      for (const LinearSystem::Term& t : m.rotation ? model_.Linear(body, reference, axis.origin, e)
                                                    : model_.Angular(body, reference, e)) {
        rate[t.variable] += t.coefficient.value();
      }
      for (const auto& [f, r] : rate) largest = std::max(largest, std::abs(r));
    }
    std::set<std::size_t> moving;
    for (const auto& rate : rates) {
      for (const auto& [f, r] : rate) {
        if (std::abs(r) > kTolerance * (1 + largest)) moving.insert(f);
      }
    }
    return {moving.begin(), moving.end()};
  }

  /// The worm's rotation relative to the body carrying both axes, held at zero.
  LinearSystem::Row WormLock(std::size_t pair) const {
    const Pair& p = worms_.at(pair);
    const std::size_t carrier = *model_.CommonCarrier(p.a, p.b);
    return model_.Angular(model_.body_of_part(p.a.part), carrier, model_.WorldAxis(p.a).direction);
  }

  /// Self-locking worm gears that the imposed motions would reach from the wheel's side first:
  /// breadth-first from the driven parts over the pair graph, a body at a time (a body reached
  /// through one of its parts is reached), not out of the ground.
  std::vector<std::size_t> BackDrivenWorms(const std::vector<ImposedMotion>& imposed) const {
    if (!self_locking_worms_) return {};
    std::vector<bool> reached(model_.body_count(), false);
    std::vector<std::size_t> from, locked;
    for (const ImposedMotion& m : imposed) {
      from.push_back(m.feature.part);
      reached[model_.body_of_part(m.feature.part)] = true;
    }
    graph_->Reachable(from, [&](std::size_t pair, std::size_t at, std::size_t to) {
      const std::size_t body = model_.body_of_part(at), other = model_.body_of_part(to);
      if (body == other) return true;
      if (body == model_.ground()) return false;
      const auto worm = worms_.find(pair);
      const Pair* p = worm == worms_.end() ? nullptr : &worm->second;
      const bool into_worm = p && p->self_locking && body == model_.body_of_part(p->b.part) &&
                             other == model_.body_of_part(p->a.part);
      if (into_worm && !reached[other] && model_.CommonCarrier(p->a, p->b)) {
        locked.push_back(pair);
        return false;
      }
      reached[other] = true;
      return true;
    });
    std::sort(locked.begin(), locked.end());
    return locked;
  }

  // The screws of the joints from the ground to `body`, ground first.
  ScrewPath Path(std::size_t body, const std::vector<ExactReal>& x) const {
    ScrewPath path;  // collected from the body down, then reversed: one allocation per part
    std::vector<ScrewMotion>& chain = path.screws;
    for (std::optional<std::size_t> b = body; b && *b != model_.ground();
         b = model_.ParentBody(*b)) {
      const Eigen::Matrix<double, 6, 1> t = model_.RelativeTwist(*b, x);
      const Eigen::Vector3d omega = t.head<3>(), v = t.tail<3>();
      ScrewMotion m;
      if (omega.norm() > kTolerance) {
        const Eigen::Vector3d w = kTwoPi * omega;
        m.axis_W = omega.normalized();
        m.turns_per_unit = omega.norm();
        m.point_W = w.cross(v) / w.squaredNorm();
        m.travel_per_unit = v.dot(m.axis_W);
      } else if (v.norm() > kTolerance) {
        m.axis_W = v.normalized();
        m.travel_per_unit = v.norm();
      }
      if (!m.still()) chain.push_back(m);
    }
    std::reverse(chain.begin(), chain.end());
    return path;
  }

  PartMotion Classify(std::size_t p, const Eigen::Vector3d& omega, const Eigen::Vector3d& v_WO,
                      std::span<const FeatureRate> rates) const {
    PartMotion m;
    const bool turns = omega.norm() > kTolerance;
    if (!turns && v_WO.norm() <= kTolerance) return m;
    const Eigen::Vector3d axis = turns ? omega.normalized() : v_WO.normalized();
    // Of the features along the motion, the first by id (within a part, name order is id
    // order), so that the file's order of features does not change the report.
    for (std::size_t f = 0; f < assembly_.FeatureCount(p); ++f) {
      const AxisSegment a = model_.WorldAxis({p, f});
      const ExactReal along = model_.Dot(a.direction, axis);
      if (!along.is_exact() || along.exact()->is_zero()) continue;
      if (m.axis_feature &&
          assembly_.FeatureNameRank(*m.axis_feature) <= assembly_.FeatureNameRank({p, f})) {
        continue;
      }
      m.axis_feature = FeatureRef{p, f};
      m.axis_W = a.direction;
      m.rotation = rates[f].rotation;
      m.translation = rates[f].translation;
    }
    if (!m.axis_feature) {
      // No feature along the motion: the axis with its largest component positive.
      Eigen::Index largest;
      axis.cwiseAbs().maxCoeff(&largest);
      m.axis_W = axis(largest) < 0 ? -axis : axis;
      m.rotation = ExactReal::Approximate(omega.dot(m.axis_W));
      m.translation = ExactReal::Approximate(v_WO.dot(m.axis_W)) / mm_per_length_;
    }
    if (turns) {
      const Eigen::Vector3d w = kTwoPi * omega;
      m.point_W = w.cross(v_WO) / w.squaredNorm();
      m.kind = m.translation.IsZero(kTolerance) ? MotionKind::kRotation : MotionKind::kScrew;
    } else {
      m.kind = MotionKind::kTranslation;
      m.point_W = assembly_.part(p).X_WP.translation();
    }
    return m;
  }

  const Assembly& assembly_;
  std::shared_ptr<const PairGraph> graph_;
  std::map<std::size_t, Pair> worms_;  // the worm gear pairs, by index: the model keeps no
                                       // reference to its analysis' pairs, which may move
  KinematicModel model_;
  LinearSystem structural_;
  std::vector<LinearSystem::Outcome> outcomes_;
  CompressedRows<std::size_t> parts_of_body_;
  ExactReal mm_per_length_;          // reports give lengths in the file's units
  bool self_locking_worms_ = false;  // whether any worm gear pair is self-locking
  std::vector<bool> has_pair_;       // per body: HasPair
  std::vector<bool> on_faces_;       // per body: no pair but planar ones with another body
};

namespace {

std::vector<ImposedMotion> DriverMotions(const Assembly& assembly) {
  std::vector<ImposedMotion> imposed;
  for (const Driver& d : assembly.drivers()) {
    imposed.push_back({d.feature, d.motion == Driver::Motion::kRotation, d.rate, d.relative_to});
  }
  return imposed;
}

/// The bodies that a sparse velocity vector moves: the subtrees below its joints.
std::vector<std::size_t> MovedBodies(const KinematicModel& model,
                                     const CompressedRows<std::size_t>& children,
                                     const LinearSystem::Row& vector) {
  std::vector<std::size_t> bodies;
  std::vector<std::size_t> stack;
  for (const LinearSystem::Term& t : vector) {
    const Joint& j = model.joints()[model.freedoms()[t.variable].joint];
    const std::size_t child =
        model.parent_joint(j.body_a) && &model.joints()[*model.parent_joint(j.body_a)] == &j
            ? j.body_a
            : j.body_b;
    stack.push_back(child);
  }
  while (!stack.empty()) {
    const std::size_t b = stack.back();
    stack.pop_back();
    bodies.push_back(b);
    for (std::size_t c : children[b]) stack.push_back(c);
  }
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  return bodies;
}

/// Which parts are round about a line, their meshes prepared once (built only for the parts
/// of bodies whose pairs let them turn alone, a few in a mechanism).
class RoundParts {
 public:
  explicit RoundParts(const Assembly& assembly) : assembly_(assembly) {}

  /// Whether part p's mesh is a solid of revolution about the world line through p_W along
  /// axis_W, within twice the STEP mesher's chordal deviation (0.1% of a part's size, at least
  /// 0.01 mm): 0.2% of its box's diagonal, at least 0.02 mm. A part without a mesh is not.
  bool IsRound(std::size_t p, const Eigen::Vector3d& p_W, const Eigen::Vector3d& axis_W) {
    const Part& part = assembly_.part(p);
    if (!part.mesh || part.mesh->faces.empty()) return false;
    const RigidTransform X_PW = part.X_WP.inverse();
    const Eigen::Vector3d p_P = X_PW * p_W, axis_P = X_PW.RotateDirection(axis_W);
    const double tolerance = std::max(0.002 * part.mesh->Bounds().size().norm(), 0.02);
    // Most parts that fail, fail this without a hierarchy (a lever with its pivot at one end).
    if (!ReachesEquallyAround(*part.mesh, p_P, axis_P, tolerance)) return false;
    return IsRoundAbout(meshes_.Get(part.mesh), p_P, axis_P, tolerance);
  }

 private:
  const Assembly& assembly_;
  CollisionMeshCache meshes_;
};

/// A body that can turn alone about a line around which each of its parts is round: an idle
/// spin (a wheel, a bearing, a spacer turning in place), which moves nothing else.
struct IdleSpin {
  std::size_t body = 0;
  std::size_t pair = 0;   ///< the revolute or cylindrical pair whose axis it turns about
  std::size_t other = 0;  ///< the body of that pair's other part
};

/// Whether the pair lets its part on `axis` turn about that line (through axis.origin along
/// axis.direction) while the other part stays still: a revolute or cylindrical pair on the
/// line, a face contact across it, a ball joint centred on it.
bool AllowsTurnAbout(const Assembly& assembly, const KinematicModel& model, const Pair& pair,
                     const AxisSegment& axis) {
  const AxisSegment& f = model.WorldAxis(pair.a);
  const bool along = AngleBetweenLines(f.direction, axis.direction) <= assembly.tolerance().angle;
  const bool on_line =
      DistanceToLine(f.origin, axis.origin, axis.direction) <= assembly.tolerance().length;
  switch (pair.type) {
    case PairType::kRevolute:
    case PairType::kCylindrical:
      return along && on_line;
    case PairType::kPlanar:
      return along;
    case PairType::kSpherical:
      return on_line;
    default:
      return false;
  }
}

/// The bodies of `model` that can turn alone about the axis of one of their revolute or
/// cylindrical pairs with another body (every other pair they have with other bodies allows
/// that turn, AllowsTurnAbout) and whose parts are all round about it (RoundParts): found on
/// the geometry, whatever the basis the free motions are given in. One per body, about its
/// first such pair's axis.
std::vector<IdleSpin> FindIdleSpins(const Assembly& assembly, const std::vector<Pair>& pairs,
                                    const KinematicModel& model, const MotionModel& motion_model) {
  std::vector<std::pair<std::size_t, std::size_t>> entries;  // (body, pair) across bodies
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::size_t a = model.body_of_part(pairs[i].a.part);
    const std::size_t b = model.body_of_part(pairs[i].b.part);
    if (a == b) continue;
    entries.emplace_back(a, i);
    entries.emplace_back(b, i);
  }
  const CompressedRows<std::size_t> pairs_of(model.body_count(), entries);
  std::vector<IdleSpin> spins;
  RoundParts round_parts(assembly);
  for (std::size_t body = 0; body < model.body_count(); ++body) {
    if (body == model.ground()) continue;
    for (std::size_t candidate : pairs_of[body]) {
      const Pair& pair = pairs[candidate];
      if (pair.type != PairType::kRevolute && pair.type != PairType::kCylindrical) continue;
      const AxisSegment& axis = model.WorldAxis(pair.a);
      const auto allows = [&](std::size_t i) {
        return AllowsTurnAbout(assembly, model, pairs[i], axis);
      };
      if (!std::all_of(pairs_of[body].begin(), pairs_of[body].end(), allows)) continue;
      const std::span<const std::size_t> parts = motion_model.PartsOf(body);
      const auto round = [&](std::size_t p) {
        return round_parts.IsRound(p, axis.origin, axis.direction);
      };
      if (!std::all_of(parts.begin(), parts.end(), round)) continue;
      const std::size_t a = model.body_of_part(pair.a.part);
      spins.push_back({body, candidate, a == body ? model.body_of_part(pair.b.part) : a});
      break;
    }
  }
  return spins;
}

// "a", "a and b", "a, b and c".
std::string Enumeration(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += i == 0 ? "" : i + 1 == items.size() ? " and " : ", ";
    out += items[i];
  }
  return out;
}

// The freedom `variable` in words, its axis named by the pair's first feature, or, given the
// body that makes the motion, by the feature it moves against (the seat, not the foot).
std::string FreedomWords(const Assembly& assembly, const std::vector<Pair>& pairs,
                         const KinematicModel& model, std::size_t variable,
                         std::optional<std::size_t> moving_body = std::nullopt) {
  const Freedom& f = model.freedoms()[variable];
  const Joint& j = model.joints()[f.joint];
  static const char* kAxes[] = {"x", "y", "z"};
  std::string axis;
  if (!j.pair) {
    Eigen::Index i;
    f.direction_W.cwiseAbs().maxCoeff(&i);
    axis = fmt::format("the world {} axis", kAxes[i]);
  } else {
    const Pair& pair = pairs[*j.pair];
    const bool a_moves = moving_body && model.body_of_part(pair.a.part) == *moving_body;
    axis = fmt::format("{}'s axis", assembly.FeatureName(a_moves ? pair.b : pair.a));
  }
  switch (f.kind) {
    case Freedom::Kind::kRotation:
      return fmt::format("turns about {}", axis);
    case Freedom::Kind::kTranslation:
      return fmt::format("slides along {}", axis);
    case Freedom::Kind::kScrew:
      return fmt::format("screws along {}", axis);
  }
  return "";
}

// A free motion in words, with the pair that carries it: `child`'s motion relative to the
// other body of the joint of `variable` (its freedom, of a pair), `twist` as
// KinematicModel::BodyTwist gives it, `moved` (by body) the bodies the motion moves. A turn
// is named by the axis of a pair between a moved and an unmoved body on the turn's line (the
// freedom's own pair first, then `child`'s), and by that line when none lies there; a slide
// by the freedom's pair's axis when it runs along it, and by its direction otherwise. A
// planar pair's face places no turn (a block on a table turns about any point of it) and no
// slide runs along its normal: a turn on the face alone is about the face's normal, a slide
// on it along a direction.
std::pair<std::string, std::size_t> FreeMotionWords(const Assembly& assembly,
                                                    const std::vector<Pair>& pairs,
                                                    const KinematicModel& model,
                                                    std::size_t variable, std::size_t child,
                                                    const Eigen::Matrix<double, 6, 1>& twist,
                                                    const std::vector<bool>& moved) {
  const Freedom& f = model.freedoms()[variable];
  const std::size_t own = *model.joints()[f.joint].pair;
  const bool planar = pairs[own].type == PairType::kPlanar;
  // The feature of `pair` that does not move with `child` (the one it moves about or along).
  const auto still = [&](std::size_t pair) {
    const Pair& p = pairs[pair];
    return model.body_of_part(p.a.part) == child ? p.b : p.a;
  };
  const auto vector_words = [](const Eigen::Vector3d& v) {
    return fmt::format("({}, {}, {})", FormatNumber(v.x()), FormatNumber(v.y()),
                       FormatNumber(v.z()));
  };
  // A direction of either sense, said with its largest component positive.
  const auto unsigned_words = [&](const Eigen::Vector3d& d) {
    Eigen::Index i;
    d.cwiseAbs().maxCoeff(&i);
    return vector_words(d(i) < 0 ? Eigen::Vector3d(-d) : d);
  };
  const Eigen::Vector3d omega = twist.head<3>(), v_O = twist.tail<3>();
  // The freedom's own rate is 1 in its basis motion, so `child` moves; should it not, the
  // freedom alone names the motion.
  if (f.kind == Freedom::Kind::kScrew || twist.norm() <= kTolerance) {
    return {FreedomWords(assembly, pairs, model, variable, child), own};
  }
  // Lines are the same within the file's tolerances, as pairs are recognised.
  const double length = assembly.tolerance().length;
  const double cosine = std::cos(assembly.tolerance().angle);
  const auto parallel = [&](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
    return std::abs(u.dot(v)) >= cosine;
  };
  if (omega.norm() <= kTolerance) {
    const Eigen::Vector3d d = v_O.normalized();
    if (!planar && parallel(d, f.direction_W)) {
      return {FreedomWords(assembly, pairs, model, variable, child), own};
    }
    return {fmt::format("slides along {}{}", unsigned_words(d),
                        planar ? fmt::format(" on {}", assembly.FeatureName(still(own))) : ""),
            own};
  }
  // The turn's line: the point where the velocity runs along the axis (v = v_O + 2 pi w x p).
  const Eigen::Vector3d d = omega.normalized();
  const Eigen::Vector3d p_W = omega.cross(v_O) / (kTwoPi * omega.squaredNorm());
  const auto on_line = [&](FeatureRef feature) {
    if (assembly.feature(feature).kind == FeatureKind::kFace) return false;
    const AxisSegment& axis = model.WorldAxis(feature);
    const Eigen::Vector3d offset = axis.origin - p_W;
    return parallel(axis.direction, d) && (offset - offset.dot(d) * d).norm() <= length;
  };
  if (on_line(still(own))) return {FreedomWords(assembly, pairs, model, variable, child), own};
  // `child`'s own pairs first, then any between a moved and an unmoved body.
  for (const bool of_child : {true, false}) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const std::size_t a = model.body_of_part(pairs[i].a.part);
      const std::size_t b = model.body_of_part(pairs[i].b.part);
      if (moved[a] == moved[b] || (of_child && a != child && b != child)) continue;
      const FeatureRef axis = moved[a] ? pairs[i].b : pairs[i].a;
      if (on_line(axis)) {
        return {fmt::format("turns about {}'s axis", assembly.FeatureName(axis)), i};
      }
    }
  }
  if (planar) {
    return {fmt::format("turns about {}'s normal", assembly.FeatureName(still(own))), own};
  }
  return {
      fmt::format("turns about the line through {} along {}", vector_words(p_W), unsigned_words(d)),
      own};
}

// Cylindrical fits placed as a lead screw in its nut with the thread left out of the file: in
// every undriven motion the shaft's body turns about the fit's axis without sliding along it,
// and the bore's body slides along it without turning. A screw pair there would tie the slide
// to the turn by its lead, which the file does not give, so the mobility counts the two apart.
// The shaft must be longer than the bore, for the nut to travel on it, and the slide must stay
// free while the turn is held (no thread or rack ties them already). `structural`: the
// undriven system; `twists`: per body, the (normalised) twists relative to the ground of its
// basis motions. One warning per pair of bodies, on its first fit in name order.
std::vector<Diagnostic> FindUnthreadedNuts(
    const Assembly& assembly, const std::vector<Pair>& pairs, const KinematicModel& model,
    const LinearSystem& structural,
    const std::vector<std::vector<Eigen::Matrix<double, 6, 1>>>& twists) {
  // Whether some motion of `body` turns it about the line (or moves the line along itself):
  // the twist's angular rate about it (or the velocity of a point on it along it).
  const auto moves = [&](std::size_t body, const AxisSegment& line, bool turn) {
    return std::any_of(twists[body].begin(), twists[body].end(), [&](const auto& twist) {
      const Eigen::Vector3d omega = twist.template head<3>();
      const Eigen::Vector3d v = twist.template tail<3>() + kTwoPi * omega.cross(line.origin);
      return std::abs((turn ? omega : v).dot(line.direction)) > kTolerance;
    });
  };
  std::map<std::pair<std::size_t, std::size_t>, std::pair<FeatureRef, FeatureRef>> nuts;
  for (const Pair& pair : pairs) {
    if (pair.type != PairType::kCylindrical || pair.source != PairSource::kRecognised) continue;
    const bool a_is_shaft = assembly.feature(pair.a).kind == FeatureKind::kShaft;
    const FeatureRef shaft = a_is_shaft ? pair.a : pair.b, bore = a_is_shaft ? pair.b : pair.a;
    if (assembly.feature(shaft).kind != FeatureKind::kShaft ||
        assembly.feature(bore).kind != FeatureKind::kHole ||
        assembly.feature(shaft).length <= assembly.feature(bore).length) {
      continue;
    }
    const std::size_t screw = model.body_of_part(shaft.part), nut = model.body_of_part(bore.part);
    const AxisSegment& line = model.WorldAxis(shaft);
    if (screw == nut || !moves(screw, line, true) || moves(screw, line, false) ||
        !moves(nut, line, false) || moves(nut, line, true)) {
      continue;
    }
    LinearSystem turn_held = structural;
    turn_held.AddRow(model.Angular(screw, model.ground(), line.direction));
    if (turn_held.AddRow(model.Linear(nut, model.ground(), line.origin, line.direction)) !=
        LinearSystem::Outcome::kIndependent) {
      continue;
    }
    const auto [it, added] = nuts.try_emplace({screw, nut}, shaft, bore);
    if (!added && assembly.FeatureNameRank(bore) < assembly.FeatureNameRank(it->second.second)) {
      it->second = {shaft, bore};
    }
  }
  std::vector<Diagnostic> found;
  for (const auto& entry : nuts) {
    const auto& [shaft, bore] = entry.second;
    found.push_back(
        {Severity::kWarning,
         "unthreaded_nut",
         fmt::format(
             "{} ({} mm) rides on {}, which turns in place while {} slides along it without "
             "turning: a lead screw in its nut, with the thread not modelled? The turn and the "
             "slide are counted as two motions; the override {{\"pair\": [\"{}\", \"{}\"], "
             "\"type\": \"screw\", \"lead\": L}}, L the length one turn advances, couples them",
             assembly.FeatureName(bore), FormatNumber(assembly.feature(bore).diameter),
             assembly.FeatureName(shaft), assembly.PartId(bore.part), assembly.FeatureName(shaft),
             assembly.FeatureName(bore)),
         {std::string(assembly.PartId(shaft.part)), std::string(assembly.PartId(bore.part))},
         {assembly.FeatureName(shaft), assembly.FeatureName(bore)}});
  }
  return found;
}

}  // namespace

std::string_view ToString(MotionKind kind) { return NameOf(kMotionKindNames, kind); }

const DrivenMotion* MotionAnalysis::ForExpectations() const {
  return driven.empty() ? nullptr : &driven.back();
}

DrivenMotion SolveImposed(const MotionAnalysis& motion, const std::vector<ImposedMotion>& imposed) {
  if (!motion.model)
    throw std::invalid_argument("SolveImposed: a motion analysis without its model");
  std::vector<std::string> labels;
  for (const ImposedMotion& m : imposed) labels.push_back(motion.model->Label(m));
  return motion.model->Solve(imposed, labels);
}

MotionAnalysis AnalyzeMotion(const Assembly& assembly, const std::vector<Pair>& pairs,
                             std::shared_ptr<const PairGraph> graph,
                             std::vector<AxisSegment> axes_W) {
  MotionAnalysis result;
  result.model =
      std::make_shared<const MotionModel>(assembly, pairs, std::move(graph), std::move(axes_W));
  const MotionModel& motion_model = *result.model;
  const KinematicModel& model = motion_model.model();
  result.diagnostics = model.diagnostics();
  Mobility& mobility = result.mobility;
  mobility.dof = static_cast<int>(motion_model.structural().nullity());

  auto part_ids = [&](const std::vector<std::size_t>& parts) {
    std::vector<std::string> ids;
    for (std::size_t p : parts) ids.emplace_back(assembly.PartId(p));
    return ids;
  };
  // Built in place (an initializer list would copy each name once more).
  auto pair_parts = [&](std::size_t pair) {
    std::vector<std::string> ids;
    ids.reserve(2);
    ids.emplace_back(assembly.PartId(pairs[pair].a.part));
    ids.emplace_back(assembly.PartId(pairs[pair].b.part));
    return ids;
  };
  auto pair_features = [&](std::size_t pair) {
    std::vector<std::string> names;
    names.reserve(2);
    names.push_back(assembly.FeatureName(pairs[pair].a));
    names.push_back(assembly.FeatureName(pairs[pair].b));
    return names;
  };

  // Redundant constraints, per pair.
  std::vector<int> redundant(pairs.size(), 0);
  for (std::size_t r = 0; r < model.rows().size(); ++r) {
    if (motion_model.outcomes()[r] == LinearSystem::Outcome::kRedundant)
      ++redundant[model.rows()[r].pair];
  }
  // Face contacts over-constrain whatever rests on several faces (a motor flange on a plate):
  // their redundant constraints are said once per two parts, not once per face.
  struct Faces {
    int count = 0;
    std::size_t a = 0, b = 0;  // the two parts
    std::vector<std::string> parts, features;
  };
  std::map<std::pair<std::size_t, std::size_t>, Faces> faces_of_parts;  // by part ranks
  for (std::size_t pair = 0; pair < pairs.size(); ++pair) {
    const int count = redundant[pair];
    if (count == 0) continue;
    mobility.redundant += count;
    mobility.redundant_pairs.push_back({pair, count});
    if (pairs[pair].type == PairType::kPlanar) {
      const std::size_t a = assembly.PartRank(pairs[pair].a.part);
      const std::size_t b = assembly.PartRank(pairs[pair].b.part);
      Faces& faces = faces_of_parts[std::minmax(a, b)];
      faces.count += count;
      if (faces.parts.empty()) {
        faces.parts = pair_parts(pair);
        faces.a = pairs[pair].a.part;
        faces.b = pairs[pair].b.part;
      }
      for (std::string& f : pair_features(pair)) faces.features.push_back(std::move(f));
      continue;
    }
    // The features' names once, for the message and the list (an over-constrained grid of
    // 100,000 parts names 20,000 pairs).
    std::vector<std::string> features = pair_features(pair);
    std::string message = fmt::format(
        "{} pair {} + {}: {} of its constraints {} implied by the other pairs (over-constrained: "
        "it must be made accurately)",
        ToString(pairs[pair].type), features[0], features[1], count, count == 1 ? "is" : "are");
    result.diagnostics.push_back({Severity::kInfo, "redundant_constraints", std::move(message),
                                  pair_parts(pair), std::move(features)});
  }
  // Alike findings of one part with several others (five servos each in a pocket of one
  // forearm) are one: by part, number of contacts and of constraints, the largest groups first.
  using FacesKey = std::tuple<std::size_t, std::size_t, int>;  // part rank, contacts, constraints
  std::map<FacesKey, std::vector<Faces*>> faces_alike;
  for (auto& [ranks, faces] : faces_of_parts) {
    const std::size_t contacts = faces.features.size() / 2;
    faces_alike[{ranks.first, contacts, faces.count}].push_back(&faces);
    faces_alike[{ranks.second, contacts, faces.count}].push_back(&faces);
  }
  std::vector<std::pair<FacesKey, std::vector<Faces*>>> groups(faces_alike.begin(),
                                                               faces_alike.end());
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& x, const auto& y) { return x.second.size() > y.second.size(); });
  std::set<const Faces*> said;
  for (auto& [key, members] : groups) {
    std::erase_if(members, [&](const Faces* f) { return said.count(f) > 0; });
    if (members.empty()) continue;
    const auto [rank, contacts, count] = key;
    said.insert(members.begin(), members.end());
    if (members.size() == 1) {
      Faces& faces = *members.front();
      std::string message = fmt::format(
          "face contact{} of {} and {} ({}): {} of their constraints {} implied by the other "
          "pairs (over-constrained: they must be made accurately)",
          contacts > 1 ? "s" : "", faces.parts[0], faces.parts[1], contacts, faces.count,
          faces.count == 1 ? "is" : "are");
      result.diagnostics.push_back({Severity::kInfo, "redundant_constraints", std::move(message),
                                    std::move(faces.parts), std::move(faces.features)});
      continue;
    }
    std::vector<std::string> parts = {{}}, features;
    for (Faces* faces : members) {
      const bool a_shared = assembly.PartRank(faces->a) == rank;
      parts.front() = assembly.PartId(a_shared ? faces->a : faces->b);
      parts.emplace_back(assembly.PartId(a_shared ? faces->b : faces->a));
      for (std::string& f : faces->features) features.push_back(std::move(f));
    }
    const std::string& shared = parts.front();
    std::sort(parts.begin() + 1, parts.end());
    std::string message = fmt::format(
        "face contact{} of {} with {} parts, {} ({} each): {} of each one's constraints {} "
        "implied by the other pairs (over-constrained: they must be made accurately)",
        contacts > 1 ? "s" : "", shared, members.size(),
        Enumeration(std::vector<std::string>(parts.begin() + 1, parts.end())), contacts, count,
        count == 1 ? "is" : "are");
    result.diagnostics.push_back({Severity::kInfo, "redundant_constraints", std::move(message),
                                  std::move(parts), std::move(features)});
  }

  // Allowable motion per part and jams, from the undriven motions.
  std::vector<std::pair<std::size_t, std::size_t>> tree_edges;  // (parent, child)
  for (std::size_t body : model.order()) {
    if (const auto& j = model.parent_joint(body)) {
      const Joint& joint = model.joints()[*j];
      tree_edges.emplace_back(joint.body_a == body ? joint.body_b : joint.body_a, body);
    }
  }
  const CompressedRows<std::size_t> children(model.body_count(), tree_edges);
  std::vector<bool> moves(model.freedoms().size(), false);
  std::vector<std::vector<Eigen::Matrix<double, 6, 1>>> body_twists(model.body_count());
  // One basis motion's rates, dense for lookup and cleared after it (a mechanism of 100,000
  // parts may have a thousand basis motions).
  std::vector<double> x(model.freedoms().size(), 0.0);
  for (const LinearSystem::Row& n : motion_model.structural().NullSpace()) {
    for (const LinearSystem::Term& t : n) {
      moves[t.variable] = true;
      x[t.variable] = t.coefficient.value();
    }
    const auto rate = [&](std::size_t k) { return x[k]; };
    for (std::size_t body : MovedBodies(model, children, n)) {
      const Eigen::Matrix<double, 6, 1> twist = model.BodyTwist(body, rate);
      if (twist.norm() > kTolerance) body_twists[body].push_back(twist.normalized());
    }
    for (const LinearSystem::Term& t : n) x[t.variable] = 0.0;
  }
  std::vector<int> body_freedoms(model.body_count(), 0);
  for (std::size_t b = 0; b < model.body_count(); ++b) {
    if (body_twists[b].empty()) continue;
    // The rank of the stacked twists; a body moved by few of them needs no heap.
    const auto rank = [&](auto m) {
      for (std::size_t i = 0; i < body_twists[b].size(); ++i) {
        m.row(static_cast<Eigen::Index>(i)) = body_twists[b][i].transpose();
      }
      Eigen::FullPivLU<decltype(m)> lu(m);
      lu.setThreshold(1e-9);
      return static_cast<int>(lu.rank());
    };
    const auto n = static_cast<Eigen::Index>(body_twists[b].size());
    constexpr int kFew = 12;
    body_freedoms[b] = n <= kFew ? rank(Eigen::Matrix<double, Eigen::Dynamic, 6, 0, kFew, 6>(n, 6))
                                 : rank(Eigen::MatrixXd(n, 6));
  }
  for (Diagnostic& d :
       FindUnthreadedNuts(assembly, pairs, model, motion_model.structural(), body_twists)) {
    result.diagnostics.push_back(std::move(d));
  }
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    mobility.part_freedoms.push_back(body_freedoms[model.body_of_part(p)]);
  }
  // Jams: per pair, the freedoms every undriven motion leaves at zero while the contacts
  // alone (the pairs without the couplings) let them move: three gears meshing in a ring. A
  // freedom the contacts lock is a part located, not jammed (two dowels, a thrust face, a
  // shoulder). A face contact's slides and turns, and a cylindrical fit's slide, held by the
  // other pairs are how thrust faces and shoulders work: no jam either.
  std::vector<bool> contacts_move(model.freedoms().size(), false);
  const bool coupled =
      std::any_of(model.rows().begin(), model.rows().end(),
                  [&](const ConstraintRow& r) { return IsCoupling(pairs[r.pair].type); });
  if (coupled) {
    LinearSystem contacts(model.freedoms().size(), kTolerance);
    for (const ConstraintRow& row : model.rows()) {
      if (!IsCoupling(pairs[row.pair].type)) contacts.AddRow(row.terms);
    }
    for (const LinearSystem::Row& n : contacts.NullSpace()) {
      for (const LinearSystem::Term& t : n) contacts_move[t.variable] = true;
    }
  }
  std::vector<std::string> locked(model.joints().size());
  for (std::size_t k = 0; k < model.freedoms().size(); ++k) {
    const Freedom& f = model.freedoms()[k];
    const Joint& j = model.joints()[f.joint];
    if (moves[k] || !contacts_move[k] || !j.pair) continue;
    const PairType type = pairs[*j.pair].type;
    if (type == PairType::kPlanar ||
        (type == PairType::kCylindrical && f.kind == Freedom::Kind::kTranslation)) {
      continue;
    }
    locked[f.joint] +=
        (locked[f.joint].empty() ? "" : "; ") + FreedomWords(assembly, pairs, model, k);
  }
  for (std::size_t i = 0; i < locked.size(); ++i) {
    if (locked[i].empty()) continue;
    const std::size_t pair = *model.joints()[i].pair;
    result.diagnostics.push_back(
        {Severity::kWarning, "jam",
         fmt::format("{} pair {} + {} cannot move as it allows ({}): the other pairs lock it",
                     ToString(pairs[pair].type), assembly.FeatureName(pairs[pair].a),
                     assembly.FeatureName(pairs[pair].b), locked[i]),
         pair_parts(pair), pair_features(pair)});
  }

  // Drivers: each alone at unit rate, then all at their rates.
  const std::vector<ImposedMotion> imposed = DriverMotions(assembly);
  std::vector<std::string> labels;
  for (const Driver& d : assembly.drivers()) labels.push_back(fmt::format("driver {}", d.id));
  // The system with the drivers' rows, for the free motions (the structural one when there is
  // no driver; filled by the solve below otherwise, not copied first).
  LinearSystem driven_system(0, kTolerance);
  // With one driver, its motion at its rate is its motion at unit rate scaled (velocities
  // are linear in the drivers' rates), so it has no combined entry, and the unit-rate system
  // has the free motions of the rate's (a zero rate holds the driver either way).
  const bool one_driver = imposed.size() == 1;
  for (std::size_t i = 0; i < imposed.size(); ++i) {
    // Driver i first, at unit rate (one revolution, or one of the file's length units: rates
    // are mm inside), then the others held still.
    std::vector<ImposedMotion> alone{imposed[i]};
    std::vector<std::string> names{labels[i]};
    const double unit = imposed[i].rotation ? 1.0 : assembly.units().mm_per_length;
    alone.front().rate = unit;
    for (std::size_t k = 0; k < imposed.size(); ++k) {
      if (k == i) continue;
      alone.push_back(imposed[k]);
      alone.back().rate = 0.0;
      names.push_back(labels[k]);
    }
    std::vector<ExactReal> x;
    DrivenMotion m =
        motion_model.SolveRates(alone, names, x, one_driver ? &driven_system : nullptr);
    motion_model.Describe(x, m);
    m.driver = i;
    result.driven.push_back(std::move(m));
  }
  if (imposed.size() > 1)
    result.driven.push_back(motion_model.Solve(imposed, labels, &driven_system));
  for (const DrivenMotion& m : result.driven) {
    // Per driver, a locked driver; together, contradicting drivers (a driver held still while
    // another drives its freedom is no finding of its own).
    if (m.possible || (m.driver.has_value() == m.contradiction)) continue;
    std::vector<std::string> parts;
    if (m.driver) parts.push_back(assembly.part(assembly.drivers()[*m.driver].feature.part).id);
    result.diagnostics.push_back({Severity::kError,
                                  m.contradiction ? "drivers_contradict" : "driver_locked",
                                  m.reason,
                                  parts,
                                  {}});
  }

  // Free motions: what the drivers leave undetermined, one per free variable (the freedom
  // that basis motion sets at 1, the others following it). A floating body is one free motion
  // with all its freedoms; a body with no pair at all is reported as unconnected already.
  std::vector<bool> reported(model.joints().size(), false);
  const LinearSystem& unheld_system = imposed.empty() ? motion_model.structural() : driven_system;
  // Idle spins are free motions of their own (each turns one body, the rest still): held
  // here, so that the basis below gives the others, and listed after them.
  std::vector<IdleSpin> spins = FindIdleSpins(assembly, pairs, model, motion_model);
  std::optional<LinearSystem> spins_held;
  if (!spins.empty()) {
    spins_held = unheld_system;
    std::erase_if(spins, [&](const IdleSpin& spin) {
      const Eigen::Vector3d& axis_W = model.WorldAxis(pairs[spin.pair].a).direction;
      // Not independent: a driver turns or holds it, so it is no free motion.
      return spins_held->AddRow(model.Angular(spin.body, spin.other, axis_W)) !=
             LinearSystem::Outcome::kIndependent;
    });
  }
  const LinearSystem& free_system = spins_held ? *spins_held : unheld_system;
  const std::vector<LinearSystem::Row> basis = free_system.NullSpace();
  const std::vector<std::size_t> free_variables = free_system.FreeVariables();
  // The warnings, said once per part with all its free motions, and once for all the parts
  // whose free motions read alike (five servos resting on one face).
  struct Unheld {
    std::size_t part = 0;
    bool on_faces = false;             // held by face contacts alone
    std::vector<std::string> motions;  // distinct, in the order found
    std::vector<std::size_t> moved;    // the parts that move with it
    std::vector<std::string> features;
  };
  std::map<std::size_t, Unheld> unheld;  // by part rank
  // Parts are named by id, so that the file's order of parts changes nothing.
  const auto by_id = [&](std::size_t x, std::size_t y) {
    return assembly.PartRank(x) < assembly.PartRank(y);
  };
  // A body's motion is said of its main part (MainPart, the first by id among equals).
  const auto main_part = [&](std::size_t body) {
    const std::span<const std::size_t> own = motion_model.PartsOf(body);
    std::vector<std::size_t> parts(own.begin(), own.end());
    std::sort(parts.begin(), parts.end(), by_id);
    return parts.empty() ? 0 : MainPart(assembly, parts);
  };
  std::vector<bool> moved(model.body_count(), false);  // by the basis motion at hand, cleared
  for (std::size_t k = 0; k < basis.size(); ++k) {
    const LinearSystem::Row& n = basis[k];
    if (n.empty()) continue;
    const Freedom& f = model.freedoms()[free_variables[k]];
    const Joint& j = model.joints()[f.joint];
    if (!j.pair && reported[f.joint]) continue;
    reported[f.joint] = true;
    FreeMotion free;
    free.pair = j.pair;
    const std::size_t child =
        model.parent_joint(j.body_a) && *model.parent_joint(j.body_a) == f.joint ? j.body_a
                                                                                 : j.body_b;
    std::size_t maker = child;  // the body said to make the motion
    const std::vector<std::size_t> moved_bodies = MovedBodies(model, children, n);
    for (std::size_t body : moved_bodies) {
      moved[body] = true;
      for (std::size_t p : motion_model.PartsOf(body)) free.parts.push_back(p);
    }
    if (j.pair) {
      for (const LinearSystem::Term& t : n) x[t.variable] = t.coefficient.value();
      const auto rate = [&](std::size_t v) { return x[v]; };
      const std::size_t other = child == j.body_a ? j.body_b : j.body_a;
      std::tie(free.freedom, *free.pair) =
          FreeMotionWords(assembly, pairs, model, free_variables[k], child,
                          model.BodyTwist(child, rate) - model.BodyTwist(other, rate), moved);
      // Named by another moved body's pair (a lead screw's turn that carries its washer
      // along): that body makes the motion.
      if (*free.pair != *j.pair) {
        const Pair& naming = pairs[*free.pair];
        for (const std::size_t part : {naming.a.part, naming.b.part}) {
          const std::size_t body = model.body_of_part(part);
          if (body != child && moved[body]) maker = body;
        }
      }
      for (const LinearSystem::Term& t : n) x[t.variable] = 0.0;
    } else {
      free.freedom = "floats: no pair holds it";
    }
    for (std::size_t body : moved_bodies) moved[body] = false;
    std::sort(free.parts.begin(), free.parts.end(), by_id);
    free.part = main_part(maker);
    if (motion_model.HasPair(maker)) {
      Unheld& u = unheld[assembly.PartRank(free.part)];
      u.part = free.part;
      u.on_faces = motion_model.OnFacesAlone(maker);
      mobility.on_faces += u.on_faces ? 1 : 0;
      u.moved.insert(u.moved.end(), free.parts.begin(), free.parts.end());
      const std::string motion =
          free.pair ? fmt::format("{} ({} pair)", free.freedom, ToString(pairs[*free.pair].type))
                    : free.freedom;
      if (std::find(u.motions.begin(), u.motions.end(), motion) == u.motions.end()) {
        u.motions.push_back(motion);
      }
      if (free.pair) {
        for (std::string& name : pair_features(*free.pair)) {
          if (std::find(u.features.begin(), u.features.end(), name) == u.features.end()) {
            u.features.push_back(std::move(name));
          }
        }
      }
    }
    mobility.free_motions.push_back(std::move(free));
  }
  // Motions, and whether the parts rest on faces alone -> part ranks.
  std::map<std::pair<std::vector<std::string>, bool>, std::vector<std::size_t>> alike;
  for (const auto& [rank, u] : unheld) alike[{u.motions, u.on_faces}].push_back(rank);
  for (const auto& [key, ranks] : alike) {
    const auto& [motions, on_faces] = key;
    std::vector<std::string> named, features;
    std::vector<std::size_t> moved;
    for (std::size_t rank : ranks) {
      const Unheld& u = unheld.at(rank);
      named.emplace_back(assembly.PartId(u.part));
      moved.insert(moved.end(), u.moved.begin(), u.moved.end());
      features.insert(features.end(), u.features.begin(), u.features.end());
    }
    std::sort(moved.begin(), moved.end(), by_id);
    moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    const std::string what = Enumeration(motions), who = Enumeration(named);
    const bool several = named.size() > 1;
    // A body nothing holds to the ground is missing something whatever the drivers. A pair's
    // freedom is a motion the mechanism allows: a finding only when the file says what drives
    // it (a CAD export has no drivers, and its joints' motions are what it is for).
    const bool floats = features.empty();
    const bool finding = floats || !imposed.empty();
    // A part that rests on faces and nothing else is held there by what the file leaves out
    // (screws, glue), not moved by the mechanism: say so, for the designer to fasten it.
    const char* allowed =
        on_faces ? "held by face contacts alone, which nothing in the file fastens (screws or "
                   "glue not modelled?)"
                 : "a motion the mechanism allows (the file has no driver)";
    std::string message = fmt::format(
        "{}{}{}{}: {}", several ? fmt::format("{} parts, ", named.size()) : "", who,
        several ? ", each " : " ", what,
        finding ? fmt::format("nothing drives or holds {}",
                              motions.size() > 1 || several ? "these motions" : "this motion")
                : allowed);
    result.diagnostics.push_back({finding ? Severity::kWarning : Severity::kInfo, "free_motion",
                                  std::move(message), part_ids(moved), std::move(features)});
  }
  // Idle spins, all in one info whatever the drivers: turning a round part in place changes
  // nothing a designer would fix (fourteen rollers say so once).
  std::map<std::size_t, FreeMotion> idle;  // by part rank
  for (const IdleSpin& spin : spins) {
    FreeMotion free;
    const std::span<const std::size_t> own = motion_model.PartsOf(spin.body);
    free.parts.assign(own.begin(), own.end());
    std::sort(free.parts.begin(), free.parts.end(), by_id);
    free.part = MainPart(assembly, free.parts);
    free.pair = spin.pair;
    const Pair& pair = pairs[spin.pair];
    const FeatureRef& axis = model.body_of_part(pair.a.part) == spin.body ? pair.b : pair.a;
    free.freedom = fmt::format("turns about {}'s axis", assembly.FeatureName(axis));
    free.idle = true;
    idle.emplace(assembly.PartRank(free.part), std::move(free));
  }
  if (!idle.empty()) {
    std::vector<std::string> named, features;
    std::vector<std::size_t> moved;
    for (const auto& [rank, free] : idle) {
      named.emplace_back(assembly.PartId(free.part));
      moved.insert(moved.end(), free.parts.begin(), free.parts.end());
      for (std::string& name : pair_features(*free.pair)) features.push_back(std::move(name));
    }
    std::sort(moved.begin(), moved.end(), by_id);
    const FreeMotion& first = idle.begin()->second;
    std::string message =
        idle.size() > 1
            ? fmt::format(
                  "{} parts, {}, each turns idly about its own axis: each is round "
                  "about it",
                  named.size(), Enumeration(named))
            : fmt::format("{} {} ({} pair), idly: it is round about that axis", named.front(),
                          first.freedom, ToString(pairs[*first.pair].type));
    message += fmt::format(
        ", so the turn moves nothing else (a wheel, a bearing, a spacer, or a shaft whose drive "
        "the file does not show; the mobility counts {} among its idle spins)",
        idle.size() > 1 ? "these" : "it");
    result.diagnostics.push_back(
        {Severity::kInfo, "idle_spin", std::move(message), part_ids(moved), std::move(features)});
  }
  mobility.idle = static_cast<int>(idle.size());
  for (auto& [rank, free] : idle) mobility.free_motions.push_back(std::move(free));
  return result;
}

}  // namespace mechanist
