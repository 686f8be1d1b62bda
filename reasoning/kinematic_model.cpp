#include "reasoning/kinematic_model.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "kernel/geometry/line_geometry.h"
#include "kernel/support/radix_sort.h"

namespace mechanist {
namespace {

constexpr double kTwoPi = 6.283185307179586;
// Carriers are looked for among a body's joints only up to this many: a frame that holds
// thousands of shafts is found through the shafts' own joints instead.
constexpr std::size_t kCarrierScanLimit = 64;
bool IsLowerPair(PairType t) {
  switch (t) {
    case PairType::kRevolute:
    case PairType::kCylindrical:
    case PairType::kScrew:
    case PairType::kPrismatic:
    case PairType::kPinSlot:
    case PairType::kSpherical:
    case PairType::kPlanar:
      return true;
    default:
      return false;
  }
}

/// Unit vectors e1, e2 completing `u` to a right-handed frame, chosen from the world axis least
/// aligned with u so that the choice is deterministic.
void Complete(const Eigen::Vector3d& u, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  Eigen::Vector3d w = Eigen::Vector3d::UnitX();
  if (std::abs(u.y()) < std::abs(u(0)) && std::abs(u.y()) <= std::abs(u.z())) {
    w = Eigen::Vector3d::UnitY();
  } else if (std::abs(u.z()) < std::abs(u(0))) {
    w = Eigen::Vector3d::UnitZ();
  }
  e1 = u.cross(w).normalized();
  e2 = u.cross(e1);
}

}  // namespace

KinematicModel::KinematicModel(const Assembly& assembly, const std::vector<Pair>& pairs,
                               const std::vector<Subassembly>& subassemblies,
                               const std::vector<std::size_t>& subassembly_of,
                               std::vector<AxisSegment> axes_W)
    : assembly_(assembly),
      cos_tol_(std::cos(assembly.tolerance().angle)),
      sin_tol_(std::sin(assembly.tolerance().angle)),
      length_tol_(assembly.tolerance().length),
      body_of_part_(subassembly_of),
      axes_(std::move(axes_W)) {
  const bool has_ground = !subassemblies.empty() && subassemblies.front().ground;
  const std::size_t bodies = subassemblies.size() + (has_ground ? 0 : 1);
  ground_ = has_ground ? 0 : subassemblies.size();
  parent_joint_.assign(bodies, std::nullopt);
  // Every feature's world axis, once (the rows and the motion descriptions ask for them many
  // times), unless recognition gave them: a read of every part and feature fewer.
  if (axes_.empty()) {
    axes_.reserve(assembly.feature_count());
    for (const Part& part : assembly.parts()) {
      for (const Feature& f : part.features) axes_.push_back(f.WorldAxis(part.X_WP));
    }
  } else if (axes_.size() != assembly.feature_count()) {
    throw std::invalid_argument(fmt::format("KinematicModel: {} world axes for {} features",
                                            axes_.size(), assembly.feature_count()));
  }
  BuildJoints(pairs);
  std::vector<std::pair<std::size_t, std::size_t>> joints_by_body;  // (body, joint)
  joints_by_body.reserve(2 * joints_.size());
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    joints_by_body.emplace_back(joints_[k].body_a, k);
    joints_by_body.emplace_back(joints_[k].body_b, k);
  }
  joints_of_ = CompressedRows<std::size_t>(bodies, joints_by_body);
  BuildTree();
  BuildRows(pairs);
}

const AxisSegment& KinematicModel::WorldAxis(FeatureRef f) const {
  return axes_[assembly_.FeatureIndex(f)];
}

ExactReal KinematicModel::Dot(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  const double d = a.dot(b);
  if (d >= cos_tol_) return Rational(1);
  if (d <= -cos_tol_) return Rational(-1);
  if (std::abs(d) <= sin_tol_) return Rational(0);
  return ExactReal::Approximate(d);
}

void KinematicModel::BuildJoints(const std::vector<Pair>& pairs) {
  std::vector<Joint> candidates;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    if (!IsLowerPair(p.type)) continue;
    Joint j;
    j.pair = i;
    j.type = p.type;
    j.body_a = body_of_part_[p.a.part];
    j.body_b = body_of_part_[p.b.part];
    if (j.body_a == j.body_b) continue;
    const AxisSegment a = WorldAxis(p.a);
    const AxisSegment b = WorldAxis(p.b);
    j.point_W = a.origin;
    j.axis_W = a.direction;
    if (p.type == PairType::kPrismatic)
      j.axis_W = b.direction.dot(a.direction) < 0 ? -b.direction : b.direction;
    if (p.type == PairType::kPinSlot) j.slide_W = b.direction;
    if (p.type == PairType::kScrew) {
      j.lead = ExactReal::FromDecimal(p.travel_per_revolution.value_or(0.0));
    }
    candidates.push_back(j);
  }
  // A shaft in two coaxial bearings of one part is one joint, not a redundant pair: a joint is
  // dropped when an earlier kept joint between the same two bodies has its type and axis. The
  // joints are grouped by their two bodies with a stable radix sort (in pair order within a
  // group; the ground may have a joint with every other body), not by a map of lists.
  const int body_bits = BitWidth(parent_joint_.size());
  if (2 * body_bits > 64) throw std::length_error("KinematicModel: too many bodies");
  struct Key {
    std::uint64_t bodies;
    std::size_t candidate;
  };
  std::vector<Key> keys;
  keys.reserve(candidates.size());
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const Joint& j = candidates[c];
    keys.push_back(
        {std::uint64_t{std::min(j.body_a, j.body_b)} << body_bits | std::max(j.body_a, j.body_b),
         c});
  }
  RadixSort(keys, 2 * body_bits, [](const Key& k) { return k.bodies; });
  auto same = [&](const Joint& o, const Joint& j) {
    // Two threads on one axis are two constraints unless their leads agree: never merged.
    if (o.type != j.type || j.type == PairType::kScrew) return false;
    if (std::abs(o.axis_W.dot(j.axis_W)) < cos_tol_) return false;
    return j.type == PairType::kPrismatic ||
           DistanceToLine(j.point_W, o.point_W, o.axis_W) <= length_tol_;
  };
  std::vector<bool> duplicate(candidates.size(), false);
  for (std::size_t begin = 0, end = 0; begin < keys.size(); begin = end) {
    while (end < keys.size() && keys[end].bodies == keys[begin].bodies) ++end;
    for (std::size_t k = begin + 1; k < end; ++k) {
      const std::size_t c = keys[k].candidate;
      for (std::size_t e = begin; e < k && !duplicate[c]; ++e) {
        const std::size_t earlier = keys[e].candidate;
        duplicate[c] = !duplicate[earlier] && same(candidates[earlier], candidates[c]);
      }
    }
  }
  // Kept in place, not copied into a second array.
  std::size_t kept = 0;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!duplicate[c]) candidates[kept++] = std::move(candidates[c]);
  }
  candidates.resize(kept);
  joints_ = std::move(candidates);
}

void KinematicModel::AddFreedoms(std::size_t joint) {
  Joint& j = joints_[joint];
  const std::size_t first = freedoms_.size();
  auto add = [&](Freedom::Kind kind, const Eigen::Vector3d& point, const Eigen::Vector3d& dir) {
    Freedom f;
    f.kind = kind;
    f.point_W = point;
    f.direction_W = dir;
    f.lead = kind == Freedom::Kind::kScrew ? j.lead : ExactReal();
    f.joint = joint;
    freedoms_.push_back(f);
  };
  using K = Freedom::Kind;
  const Eigen::Vector3d& p = j.point_W;
  const Eigen::Vector3d& u = j.axis_W;
  Eigen::Vector3d e1, e2;
  Complete(u, e1, e2);
  if (!j.pair) {  // floating
    for (int i = 0; i < 3; ++i) add(K::kRotation, p, Eigen::Vector3d::Unit(i));
    for (int i = 0; i < 3; ++i) add(K::kTranslation, p, Eigen::Vector3d::Unit(i));
  } else {
    switch (j.type) {
      case PairType::kRevolute:
        add(K::kRotation, p, u);
        break;
      case PairType::kCylindrical:
        add(K::kRotation, p, u);
        add(K::kTranslation, p, u);
        break;
      case PairType::kScrew:
        add(K::kScrew, p, u);
        break;
      case PairType::kPrismatic:
        add(K::kTranslation, p, u);
        break;
      case PairType::kPinSlot:
        add(K::kRotation, p, u);
        add(K::kTranslation, p, j.slide_W);
        break;
      case PairType::kSpherical:
        for (int i = 0; i < 3; ++i) add(K::kRotation, p, Eigen::Vector3d::Unit(i));
        break;
      case PairType::kPlanar:
        add(K::kRotation, p, u);
        add(K::kTranslation, p, e1);
        add(K::kTranslation, p, e2);
        break;
      default:
        break;
    }
  }
  j.freedoms = {first, freedoms_.size()};
}

void KinematicModel::BuildTree() {
  const std::size_t bodies = parent_joint_.size();
  std::vector<bool> seen(bodies, false);
  auto grow = [&](std::size_t root) {
    std::deque<std::size_t> queue{root};
    seen[root] = true;
    while (!queue.empty()) {
      const std::size_t body = queue.front();
      queue.pop_front();
      order_.push_back(body);
      for (std::size_t k : joints_of_[body]) {
        Joint& j = joints_[k];
        const std::size_t other = j.body_a == body ? j.body_b : j.body_a;
        if (seen[other]) continue;
        seen[other] = true;
        j.in_tree = true;
        j.child = other;
        parent_joint_[other] = k;
        AddFreedoms(k);
        queue.push_back(other);
      }
    }
  };
  grow(ground_);
  std::vector<std::size_t> first_part(bodies, body_of_part_.size());
  for (std::size_t part = body_of_part_.size(); part-- > 0;) first_part[body_of_part_[part]] = part;
  for (std::size_t body = 0; body < bodies; ++body) {
    if (seen[body]) continue;
    // A compliant part alone (a spring: its pairs are dropped) moves with nothing and adds no
    // freedom: it has no joint, as the ground has none.
    if (first_part[body] < body_of_part_.size() && assembly_.IsCompliant(first_part[body])) {
      continue;
    }
    // Nothing holds this body to the ground: it floats, six freedoms about its first part.
    Joint j;
    j.body_a = body;
    j.body_b = ground_;
    j.in_tree = true;
    j.child = body;
    if (first_part[body] < body_of_part_.size()) {
      j.point_W = assembly_.part(first_part[body]).X_WP.translation();
    }
    joints_.push_back(j);
    parent_joint_[body] = joints_.size() - 1;
    AddFreedoms(joints_.size() - 1);
    grow(body);
  }
}

template <typename Measure, typename Sink>
void KinematicModel::ForPath(std::size_t body, double sign, const Measure& measure,
                             Sink&& sink) const {
  while (parent_joint_[body]) {
    const Joint& j = joints_[*parent_joint_[body]];
    const bool forward = body == j.body_a;  // twist(a) = twist(b) + freedoms
    const ExactReal s = Rational(forward == (sign > 0) ? 1 : -1);
    for (std::size_t f : j.freedoms) sink(f, s * measure(freedoms_[f]));
    body = forward ? j.body_b : j.body_a;
  }
}

ExactReal KinematicModel::AngularOf(const Freedom& f, const Eigen::Vector3d& d) const {
  return f.kind == Freedom::Kind::kTranslation ? ExactReal() : Dot(f.direction_W, d);
}

ExactReal KinematicModel::LinearOf(const Freedom& f, const Eigen::Vector3d& p,
                                   const Eigen::Vector3d& d) const {
  if (f.kind == Freedom::Kind::kTranslation) return Dot(f.direction_W, d);
  // The velocity of p along d from one revolution per second about the line (q, u):
  // 2 pi (u x (p - q)) . d, exactly zero when p is on the line or d is along it.
  const Eigen::Vector3d& u = f.direction_W;
  const Eigen::Vector3d r = p - f.point_W;
  ExactReal lever;
  const double value = u.cross(r).dot(d);
  if (std::abs(u.dot(d)) < cos_tol_ && (r - r.dot(u) * u).norm() > length_tol_ &&
      std::abs(value) > length_tol_) {
    lever = ExactReal::Approximate(kTwoPi * value);
  }
  if (f.kind == Freedom::Kind::kScrew) lever += f.lead * Dot(u, d);
  return lever;
}

LinearSystem::Row KinematicModel::Angular(std::size_t a, std::size_t b,
                                          const Eigen::Vector3d& d) const {
  LinearSystem::Row terms;
  auto measure = [&](const Freedom& f) { return AngularOf(f, d); };
  auto add = [&](std::size_t f, ExactReal c) { terms.push_back({f, std::move(c)}); };
  ForPath(a, 1, measure, add);
  ForPath(b, -1, measure, add);
  return terms;
}

void KinematicModel::AppendAngular(LinearSystem::Row& row, std::size_t a, std::size_t b,
                                   const Eigen::Vector3d& d, const ExactReal& scale) const {
  auto measure = [&](const Freedom& f) { return AngularOf(f, d); };
  auto add = [&](std::size_t f, const ExactReal& c) { row.push_back({f, scale * c}); };
  ForPath(a, 1, measure, add);
  ForPath(b, -1, measure, add);
}

LinearSystem::Row KinematicModel::Linear(std::size_t a, std::size_t b, const Eigen::Vector3d& p,
                                         const Eigen::Vector3d& d) const {
  LinearSystem::Row terms;
  auto measure = [&](const Freedom& f) { return LinearOf(f, p, d); };
  auto add = [&](std::size_t f, ExactReal c) { terms.push_back({f, std::move(c)}); };
  ForPath(a, 1, measure, add);
  ForPath(b, -1, measure, add);
  return terms;
}

ExactReal KinematicModel::AngularRate(std::size_t a, std::size_t b, const Eigen::Vector3d& d,
                                      const std::vector<ExactReal>& x) const {
  ExactReal sum;
  auto measure = [&](const Freedom& f) { return AngularOf(f, d); };
  auto add = [&](std::size_t f, const ExactReal& c) { sum += c * x[f]; };
  ForPath(a, 1, measure, add);
  ForPath(b, -1, measure, add);
  return sum;
}

ExactReal KinematicModel::LinearRate(std::size_t a, std::size_t b, const Eigen::Vector3d& p,
                                     const Eigen::Vector3d& d,
                                     const std::vector<ExactReal>& x) const {
  ExactReal sum;
  auto measure = [&](const Freedom& f) { return LinearOf(f, p, d); };
  auto add = [&](std::size_t f, const ExactReal& c) { sum += c * x[f]; };
  ForPath(a, 1, measure, add);
  ForPath(b, -1, measure, add);
  return sum;
}

std::vector<LinearSystem::Row> KinematicModel::JointConstraints(const Joint& j, std::size_t a,
                                                                std::size_t b) const {
  const Eigen::Vector3d& p = j.point_W;
  const Eigen::Vector3d& u = j.axis_W;
  Eigen::Vector3d e1, e2;
  Complete(u, e1, e2);
  std::vector<LinearSystem::Row> rows;
  auto angular = [&](const Eigen::Vector3d& d) { rows.push_back(Angular(a, b, d)); };
  auto linear = [&](const Eigen::Vector3d& d) { rows.push_back(Linear(a, b, p, d)); };
  switch (j.type) {
    case PairType::kRevolute:
      angular(e1), angular(e2), linear(e1), linear(e2), linear(u);
      break;
    case PairType::kCylindrical:
      angular(e1), angular(e2), linear(e1), linear(e2);
      break;
    case PairType::kScrew: {
      angular(e1), angular(e2), linear(e1), linear(e2);
      LinearSystem::Row advance = Linear(a, b, p, u);
      AppendAngular(advance, a, b, u, -j.lead);
      rows.push_back(std::move(advance));
      break;
    }
    case PairType::kPrismatic:
      angular(u), angular(e1), angular(e2), linear(e1), linear(e2);
      break;
    case PairType::kPinSlot: {
      const Eigen::Vector3d m = u.cross(j.slide_W).normalized();
      angular(j.slide_W), angular(m), linear(u), linear(m);
      break;
    }
    case PairType::kSpherical:
      for (int i = 0; i < 3; ++i) linear(Eigen::Vector3d::Unit(i));
      break;
    case PairType::kPlanar:
      angular(e1), angular(e2), linear(u);
      break;
    default:
      break;
  }
  return rows;
}

bool KinematicModel::Carries(std::size_t body, FeatureRef f) const {
  if (body == body_of_part_[f.part]) return true;
  const AxisSegment axis = WorldAxis(f);
  const bool slides = assembly_.kind(f) == FeatureKind::kRack;
  auto carried_by = [&](const Joint& j) {
    if (std::abs(j.axis_W.dot(axis.direction)) < cos_tol_) return false;
    if (slides) return j.type == PairType::kPrismatic;
    if (j.type != PairType::kRevolute && j.type != PairType::kCylindrical &&
        j.type != PairType::kScrew && j.type != PairType::kPinSlot) {
      return false;
    }
    return DistanceToLine(j.point_W, axis.origin, axis.direction) <= length_tol_;
  };
  // The body carries f's axis when f's body turns about that line relative to it: a joint
  // between the two along the axis, or joints of both to one third body along the same line
  // (a sun and a carrier on the same fixed axle). A collinear joint elsewhere (the pin of
  // another stage's planet) does not count.
  const std::size_t target = body_of_part_[f.part];
  auto other = [](const Joint& j, std::size_t b) { return j.body_a == b ? j.body_b : j.body_a; };
  const std::span<const std::size_t> theirs = joints_of_[target];
  // A direct joint is found from f's side first: a frame's list of joints is long, a moving
  // body's short.
  for (std::size_t k = 0; k < theirs.size() && k < kCarrierScanLimit; ++k) {
    const Joint& t = joints_[theirs[k]];
    if (other(t, target) == body && carried_by(t)) return true;
  }
  // Bodies the carrier turns against about f's axis (on the stack: asked for every coupling).
  std::array<std::size_t, kCarrierScanLimit> vias;
  std::size_t via_count = 0;
  const std::span<const std::size_t> own = joints_of_[body];
  for (std::size_t i = 0; i < own.size() && i < kCarrierScanLimit; ++i) {
    const Joint& j = joints_[own[i]];
    if (!carried_by(j)) continue;
    const std::size_t via = other(j, body);
    if (via == target) return true;
    vias[via_count++] = via;
  }
  const auto vias_end = vias.begin() + static_cast<std::ptrdiff_t>(via_count);
  for (std::size_t k = 0; k < theirs.size() && k < kCarrierScanLimit && via_count > 0; ++k) {
    const Joint& t = joints_[theirs[k]];
    if (std::find(vias.begin(), vias_end, other(t, target)) != vias_end && carried_by(t)) {
      return true;
    }
  }
  return false;
}

std::optional<std::size_t> KinematicModel::CommonCarrier(FeatureRef f, FeatureRef g) const {
  // On the stack: asked for every coupling.
  std::array<std::size_t, 3 + 2 * kCarrierScanLimit> candidates{ground_, body_of_part_[f.part],
                                                                body_of_part_[g.part]};
  std::size_t count = 3;
  for (std::size_t own : {body_of_part_[f.part], body_of_part_[g.part]}) {
    const std::span<const std::size_t> js = joints_of_[own];
    for (std::size_t i = 0; i < js.size() && i < kCarrierScanLimit; ++i) {
      const Joint& j = joints_[js[i]];
      candidates[count++] = j.body_a == own ? j.body_b : j.body_a;
    }
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (Carries(candidates[k], f) && Carries(candidates[k], g)) return candidates[k];
  }
  return std::nullopt;
}

void KinematicModel::BuildRows(const std::vector<Pair>& pairs) {
  std::vector<const Joint*> off_tree(pairs.size(), nullptr);
  for (const Joint& j : joints_) {
    if (j.pair && !j.in_tree) off_tree[*j.pair] = &j;
  }
  auto coupling = [](const Pair& p) {
    return IsCoupling(p.type) &&
           (p.type == PairType::kRackPinion ? p.travel_per_revolution.has_value()
                                            : p.ratio.has_value());
  };
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    if (off_tree[i]) {
      for (auto& row : JointConstraints(*off_tree[i], off_tree[i]->body_a, off_tree[i]->body_b)) {
        rows_.push_back({std::move(row), i});
      }
      continue;
    }
    if (!coupling(p)) continue;
    const bool rack = p.type == PairType::kRackPinion;
    const std::size_t A = body_of_part_[p.a.part];
    const std::size_t B = body_of_part_[p.b.part];
    if (A == B) continue;
    const AxisSegment a = WorldAxis(p.a);
    const AxisSegment b = WorldAxis(p.b);
    if (p.type == PairType::kPinsInHoles) {
      // The parts keep one orientation about the axis whatever carries them: their rates
      // relative to any body, the ground here, are equal.
      LinearSystem::Row row = Angular(B, ground_, b.direction);
      AppendAngular(row, A, ground_, a.direction, -ExactReal(*p.ratio));
      rows_.push_back({std::move(row), i});
      continue;
    }
    if (const auto C = CommonCarrier(p.a, p.b)) {
      // Willis: rates relative to the carrier are in the pair's exact ratio.
      LinearSystem::Row row =
          rack ? Linear(B, *C, b.origin, b.direction) : Angular(B, *C, b.direction);
      const ExactReal ratio =
          rack ? ExactReal::Approximate(*p.travel_per_revolution) : ExactReal(*p.ratio);
      AppendAngular(row, A, *C, a.direction, -ratio);
      rows_.push_back({std::move(row), i});
      continue;
    }
    if (p.type == PairType::kWormGear) {
      diagnostics_.push_back(
          {Severity::kWarning,
           "coupling_without_carrier",
           fmt::format("worm gear {} + {}: no part carries both axes, so the motion analysis "
                       "leaves this coupling out",
                       assembly_.FeatureName(p.a), assembly_.FeatureName(p.b)),
           {std::string(assembly_.PartId(p.a.part)), std::string(assembly_.PartId(p.b.part))},
           {assembly_.FeatureName(p.a), assembly_.FeatureName(p.b)}});
      continue;
    }
    // No common carrier: the pitch points of both members move together along the tangent. A
    // cycloidal disc's pitch circle has the radius lobes x e (its ring's: pins x e, e apart).
    const Feature& fa = assembly_.feature(p.a);
    if (p.type == PairType::kBevelGear) {
      // Bevel gears roll on their pitch cones: the common pitch line leaves the apex between
      // the axes, at each gear's pitch angle from its axis; at mid-face it moves alike on both,
      // across the plane of the axes.
      const Feature& fb = assembly_.feature(p.b);
      const Eigen::Vector3d d =
          (std::sin(fb.pitch_angle) * a.direction + std::sin(fa.pitch_angle) * b.direction)
              .normalized();
      const double mid = fa.OuterConeDistance() - 0.5 * fa.length;
      rows_.push_back(
          {Linear(A, B, a.origin + mid * d, a.direction.cross(b.direction).normalized()), i});
      continue;
    }
    const bool cycloidal = p.type == PairType::kCycloidal;
    const double r = cycloidal ? fa.teeth * fa.eccentricity : fa.PitchRadius();
    Eigen::Vector3d n, tangent;
    if (rack) {
      const Eigen::Vector3d normal_W =
          assembly_.part(p.b.part).X_WP.RotateDirection(assembly_.feature(p.b).normal);
      n = -normal_W;
      tangent = b.direction;
    } else {
      const LineLineClosest c = ClosestPointsOfLines(a.origin, a.direction, b.origin, b.direction);
      n = ((b.origin + c.t * b.direction) - (a.origin + c.s * a.direction)).normalized();
      // A pinion inside a ring (a disc inside its pins) touches it on the side away from the
      // ring's centre.
      if (assembly_.feature(p.b).internal || cycloidal) n = -n;
      tangent = a.direction.cross(n);
    }
    rows_.push_back({Linear(A, B, a.origin + r * n, tangent), i});
  }
}

namespace {

/// The twist of one joint's freedoms at their rates: (rev/s; velocity of the world origin).
Eigen::Matrix<double, 6, 1> JointTwist(const std::vector<Freedom>& freedoms, const Joint& j,
                                       const std::function<double(std::size_t)>& rate) {
  Eigen::Matrix<double, 6, 1> twist = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t k : j.freedoms) {
    const Freedom& f = freedoms[k];
    const double q = rate(k);
    if (q == 0.0) continue;
    if (f.kind == Freedom::Kind::kTranslation) {
      twist.tail<3>() += q * f.direction_W;
      continue;
    }
    twist.head<3>() += q * f.direction_W;
    twist.tail<3>() += q * kTwoPi * f.point_W.cross(f.direction_W);
    if (f.kind == Freedom::Kind::kScrew) twist.tail<3>() += q * f.lead.value() * f.direction_W;
  }
  return twist;
}

}  // namespace

void KinematicModel::Twists(const std::vector<ExactReal>& x, std::vector<Eigen::Vector3d>& omega_W,
                            std::vector<Eigen::Vector3d>& v_WO) const {
  omega_W.assign(body_count(), Eigen::Vector3d::Zero());
  v_WO.assign(body_count(), Eigen::Vector3d::Zero());
  const auto rate = [&](std::size_t k) { return x[k].value(); };
  for (std::size_t body : order_) {
    if (!parent_joint_[body]) continue;
    const Joint& j = joints_[*parent_joint_[body]];
    const bool forward = body == j.body_a;
    const std::size_t parent = forward ? j.body_b : j.body_a;
    const Eigen::Matrix<double, 6, 1> t = (forward ? 1.0 : -1.0) * JointTwist(freedoms_, j, rate);
    omega_W[body] = omega_W[parent] + t.head<3>();
    v_WO[body] = v_WO[parent] + t.tail<3>();
  }
}

Eigen::Matrix<double, 6, 1> KinematicModel::RelativeTwist(std::size_t body,
                                                          const std::vector<ExactReal>& x) const {
  if (!parent_joint_[body]) return Eigen::Matrix<double, 6, 1>::Zero();
  const Joint& j = joints_[*parent_joint_[body]];
  return (body == j.body_a ? 1.0 : -1.0) *
         JointTwist(freedoms_, j, [&](std::size_t k) { return x[k].value(); });
}

std::optional<std::size_t> KinematicModel::ParentBody(std::size_t body) const {
  if (!parent_joint_[body]) return std::nullopt;
  const Joint& j = joints_[*parent_joint_[body]];
  return body == j.body_a ? j.body_b : j.body_a;
}

Eigen::Matrix<double, 6, 1> KinematicModel::BodyTwist(
    std::size_t body, const std::function<double(std::size_t)>& rate) const {
  Eigen::Matrix<double, 6, 1> twist = Eigen::Matrix<double, 6, 1>::Zero();
  while (parent_joint_[body]) {
    const Joint& j = joints_[*parent_joint_[body]];
    const bool forward = body == j.body_a;
    twist += (forward ? 1.0 : -1.0) * JointTwist(freedoms_, j, rate);
    body = forward ? j.body_b : j.body_a;
  }
  return twist;
}

}  // namespace mechanist
