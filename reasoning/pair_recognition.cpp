#include "reasoning/pair_recognition.h"

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <string>

#include "kernel/collision/grid_broad_phase.h"
#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

Recognizer::Recognizer(const Assembly& assembly, std::span<const RigidTransform> X_WP)
    : assembly_(assembly),
      X_WP_(X_WP),
      L_(assembly.tolerance().length),
      A_(assembly.tolerance().angle),
      near_L_(std::max(4 * L_, 0.5)),
      near_A_(std::max(4 * A_, 2.0 * kPi / 180.0)),
      rank_bits_(BitWidth(assembly.feature_count())) {
  // Reserved: the features refer to their axes in this array.
  axes_.reserve(assembly.feature_count());
  features_.reserve(assembly.feature_count());
  reach_.reserve(assembly.feature_count());
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    const Part& part = assembly.part(p);
    const Aabb part_box_W = TransformBox(X_WP[p], assembly.MeshBox(p));
    for (std::size_t i = 0; i < part.features.size(); ++i) {
      const Feature& f = part.features[i];
      axes_.push_back(f.WorldAxis(X_WP[p]));
      WorldFeature w{.f = f,
                     .ref = {p, i},
                     .axis = axes_.back(),
                     .normal_W = X_WP[p].RotateDirection(f.normal)};
      reach_.push_back(ReachBox(w, part_box_W));
      features_.push_back(w);
    }
  }
}

std::vector<AxisSegment> Recognizer::TakeAxes() {
  features_.clear();
  return std::move(axes_);
}

Recognition Recognizer::Run() {
  // About as many pairs as features in a mechanism (each joins two features; a gear may
  // mesh with several): reserved, so that the pairs are not copied as the vector grows.
  pairs_.reserve(features_.size());
  std::vector<std::uint32_t> parts(features_.size());
  for (std::size_t i = 0; i < features_.size(); ++i) {
    parts[i] = static_cast<std::uint32_t>(features_[i].ref.part);
  }
  for (const auto& [i, j] : OverlappingBoxPairs(reach_, parts)) Test(features_[i], features_[j]);
  AddBearings();
  AddSolidBearings();
  FixHubsOnFlats();
  FixHubsBySetscrewHoles();
  FixHubsOnBearingShafts();
  AddImpliedPins();
  AddLooseFits();
  AddPinsInHoles();
  SetCompliantPartsApart();
  ApplyOverrides();
  SettleImpliedPins();
  ReportLooseFits();
  ReportOneParts();
  const std::vector<Screwed> screwed = TightThreads();
  ApplySetscrews(screwed);
  if (2 * rank_bits_ + kSourceBits > 64) {
    throw std::length_error("pair recognition: too many features to sort pairs");
  }
  const auto unclamped = UnclampedParts(screwed);
  for (Pair& p : pairs_) ApplyClamp(p, screwed, unclamped);
  ReportSolidBearings();
  ClampSandwichedParts();
  FixEmbeddedParts();
  ReportUnconnected();
  Recognition out{Sorted(), std::move(diagnostics_), {}, std::move(bearings_)};
  std::sort(out.diagnostics.begin(), out.diagnostics.end(), DiagnosticLess);
  return out;
}

Aabb Recognizer::ReachBox(const WorldFeature& w, const Aabb& part_box_W) const {
  const Feature& f = w.f;
  const double margin = near_L_ + L_;
  double radius = 0.0;
  switch (f.kind) {
    case FeatureKind::kShaft:
    case FeatureKind::kHole:
    case FeatureKind::kThread:
    case FeatureKind::kTappedHole:
    case FeatureKind::kBall:
    case FeatureKind::kSocket:
      radius = f.diameter / 2;
      break;
    case FeatureKind::kSlot:
    case FeatureKind::kKey:
      radius = f.width / 2 + f.depth;
      break;
    case FeatureKind::kGear:
    case FeatureKind::kWormWheel:
      radius = f.PitchRadius() + 2 * f.module;
      break;
    case FeatureKind::kWorm:
      radius = f.pitch_diameter / 2 + 2 * f.module;
      break;
    case FeatureKind::kPinRing:
      radius = f.diameter / 2 + f.pin_diameter;
      break;
    case FeatureKind::kCycloidDisc:
      radius = f.eccentricity;  // reaches its ring's axis
      break;
    case FeatureKind::kRack:
      radius = 2 * f.module;
      break;
    case FeatureKind::kBevelGear:
      radius = f.OuterConeDistance() + f.module;  // the whole gear, seen from its apex
      break;
    case FeatureKind::kFace:
      if (f.width > 0 && f.height > 0) {
        radius = std::hypot(f.width, f.height) / 2;
      } else if (!part_box_W.empty()) {
        Aabb box = part_box_W;
        box.min.array() -= margin;
        box.max.array() += margin;
        return box;
      }
      break;  // a features-only part's face without extents reaches near its origin
  }
  Aabb box;
  box.Extend(w.axis.origin);
  box.Extend(w.axis.end());
  box.min.array() -= radius + margin;
  box.max.array() += radius + margin;
  if (f.kind != FeatureKind::kFace) return box;
  // A face's extents do not say which way they lie in its plane, so its circle around them is
  // far larger than the face (a disc's face reached the spacers beside it); a face on its
  // part's geometry cannot reach beyond the part.
  Aabb part_reach = part_box_W;  // empty for a part without a mesh
  part_reach.min.array() -= margin;
  part_reach.max.array() += margin;
  const Eigen::Array3d p = w.axis.origin.array();
  if ((p >= part_reach.min.array()).all() && (p <= part_reach.max.array()).all()) {
    box.min = box.min.cwiseMax(part_reach.min);
    box.max = box.max.cwiseMin(part_reach.max);
  }
  return box;
}

void Recognizer::Test(const WorldFeature& x, const WorldFeature& y) {
  using K = FeatureKind;
  const K a = x.f.kind, b = y.f.kind;
  auto is = [&](K p, K q) { return a == p && b == q; };
  auto either = [&](K p, K q, auto rule) {
    if (is(p, q))
      rule(x, y);
    else if (is(q, p))
      rule(y, x);
  };
  either(K::kShaft, K::kHole, [this](auto& s, auto& h) {
    ShaftHole(s, h);
    const double offset = DistanceToLine(s.axis.origin, h.axis.origin, h.axis.direction);
    if (h.f.diameter - s.f.diameter > 2 * L_ && offset > L_ &&
        offset <= (h.f.diameter - s.f.diameter) / 2 + L_ &&
        AngleBetweenLines(s.axis.direction, h.axis.direction) <= A_) {
      pin_hole_candidates_.emplace_back(&s, &h);
    }
  });
  either(K::kThread, K::kHole, [this](auto& t, auto& h) { ThreadHole(t, h); });
  either(K::kThread, K::kTappedHole, [this](auto& t, auto& h) { ThreadTapped(t, h); });
  either(K::kShaft, K::kSlot, [this](auto& s, auto& sl) { PinSlot(s, sl); });
  either(K::kKey, K::kSlot, [this](auto& k, auto& sl) { KeySlot(k, sl); });
  either(K::kWorm, K::kWormWheel, [this](auto& w, auto& g) { WormWheel(w, g); });
  // An external gear serves as a worm wheel: one found on a mesh or a STEP solid's
  // tessellation is a gear, as a throated wheel's sections show no single module.
  either(K::kWorm, K::kGear, [this](auto& w, auto& g) {
    if (!g.f.internal) WormWheel(w, g);
  });
  either(K::kGear, K::kRack, [this](auto& g, auto& r) { GearRack(g, r); });
  either(K::kBall, K::kSocket, [this](auto& b, auto& s) { BallSocket(b, s); });
  either(K::kCycloidDisc, K::kPinRing, [this](auto& d, auto& r) { CycloidPins(d, r); });
  if (is(K::kGear, K::kGear)) GearGear(x, y);
  if (is(K::kBevelGear, K::kBevelGear)) BevelBevel(x, y);
  if (is(K::kThread, K::kShaft)) setscrew_candidates_.emplace_back(&x, &y);
  if (is(K::kShaft, K::kThread)) setscrew_candidates_.emplace_back(&y, &x);
  if (is(K::kFace, K::kFace)) FaceFace(x, y);
  if (is(K::kHole, K::kHole)) hole_candidates_.emplace_back(&x, &y);
}

void Recognizer::AddPair(PairType type, const WorldFeature& a, const WorldFeature& b,
                         PairFastening fastening) {
  Pair p;
  p.type = type;
  p.a = a.ref;
  p.b = b.ref;
  p.fastening = fastening;
  p.dof = DegreesOfFreedom(type);
  SetCoupling(p, a, b);
  pairs_.push_back(p);
  if (type == PairType::kFixed && fastening == PairFastening::kTight) {
    tight_.push_back({Index(a.ref), b.ref});
  }
}

void Recognizer::SetCoupling(Pair& p, const WorldFeature& a, const WorldFeature& b) const {
  using K = FeatureKind;
  const Feature& fa = a.f;
  const Feature& fb = b.f;
  if (p.type == PairType::kScrew && fa.kind == K::kThread) {
    p.travel_per_revolution = fa.starts * fa.pitch * (fa.hand == Hand::kRight ? 1.0 : -1.0);
  } else if (p.type == PairType::kGear && fa.kind == K::kGear && fb.kind == K::kGear) {
    Rational ratio(fa.teeth, fb.teeth);
    if (!fa.internal && !fb.internal) ratio = -ratio;
    // Rates are about each feature's own axis: opposite axes flip the sign.
    if (a.axis.direction.dot(b.axis.direction) < 0) ratio = -ratio;
    p.ratio = ratio;
  } else if (p.type == PairType::kBevelGear && fa.kind == K::kBevelGear &&
             fb.kind == K::kBevelGear) {
    // About axes pointing from the common apex into each gear, the pitch line's point moves
    // by w_a x d on one and w_b x d on the other: opposite senses, so always negative.
    p.ratio = -Rational(fa.teeth, fb.teeth);
  } else if (p.type == PairType::kCycloidal && fa.kind == K::kCycloidDisc &&
             fb.kind == K::kPinRing) {
    // As an internal pair, the disc the pinion (lobes) and the ring the ring (pins).
    Rational ratio(fa.teeth, fb.teeth);
    if (a.axis.direction.dot(b.axis.direction) < 0) ratio = -ratio;
    p.ratio = ratio;
  } else if (p.type == PairType::kPinsInHoles) {
    // The holes' part turns as the pins' part does, about parallel axes.
    p.ratio = Rational(a.axis.direction.dot(b.axis.direction) < 0 ? -1 : 1);
  } else if (p.type == PairType::kWormGear && fa.kind == K::kWorm &&
             (fb.kind == K::kWormWheel || fb.kind == K::kGear)) {
    const LineLineClosest c =
        ClosestPointsOfLines(a.axis.origin, a.axis.direction, b.axis.origin, b.axis.direction);
    const Eigen::Vector3d n =
        ((b.axis.origin + c.t * b.axis.direction) - (a.axis.origin + c.s * a.axis.direction))
            .normalized();
    // The wheel's teeth at the contact move like a nut on the worm: for a right-hand worm
    // turning positively they move along -u_worm (derivation in the README).
    const double side = b.axis.direction.cross(n).dot(a.axis.direction);
    const int hand = fa.hand == Hand::kRight ? 1 : -1;
    p.ratio = Rational(hand * (side > 0 ? 1 : -1) * fa.starts, fb.teeth);
    const double lead_angle = std::atan(fa.starts * fa.module / fa.pitch_diameter);
    p.self_locking = lead_angle < std::atan(assembly_.friction());
  } else if (p.type == PairType::kRackPinion && fa.kind == K::kGear && fb.kind == K::kRack) {
    p.travel_per_revolution =
        -kPi * fa.module * fa.teeth * a.axis.direction.cross(b.normal_W).dot(b.axis.direction);
  }
}

void Recognizer::Near(const char* code, const WorldFeature& a, const WorldFeature& b,
                      const std::string& message) {
  diagnostics_.push_back(
      {Severity::kWarning,
       code,
       fmt::format("{} {} and {} {}: {}; so no pair joins them", ToString(a.f.kind), Name(a),
                   ToString(b.f.kind), Name(b), message),
       {std::string(assembly_.PartId(a.ref.part)), std::string(assembly_.PartId(b.ref.part))},
       {Name(a), Name(b)}});
}

std::uint64_t Recognizer::Key(const Pair& p) const {
  return (std::uint64_t{assembly_.FeatureNameRank(p.a)} << rank_bits_ |
          assembly_.FeatureNameRank(p.b))
             << kSourceBits |
         static_cast<std::uint64_t>(p.source);
}

std::vector<Pair> Recognizer::Sorted() {
  std::vector<SortKey> keys;
  keys.reserve(pairs_.size());
  for (std::size_t i = 0; i < pairs_.size(); ++i) keys.push_back({Key(pairs_[i]), i});
  RadixSort(keys, 2 * rank_bits_ + kSourceBits,
            [](const SortKey& k) { return k.names_and_source; });
  std::vector<Pair> sorted;
  sorted.reserve(pairs_.size());
  for (const SortKey& k : keys) sorted.push_back(std::move(pairs_[k.pair]));
  return sorted;
}

}  // namespace mechanist::internal

namespace mechanist {
namespace {

using internal::Recognizer;

Recognition Recognize(const Assembly& assembly, std::span<const RigidTransform> X_WP) {
  Recognizer recognizer(assembly, X_WP);
  Recognition out = recognizer.Run();
  out.axes_W = recognizer.TakeAxes();
  return out;
}

}  // namespace

Recognition RecognizePairs(const Assembly& assembly, const AssemblyState& state) {
  if (state.X_WP.size() != assembly.parts().size()) {
    throw std::invalid_argument(fmt::format("RecognizePairs: {} poses for {} parts",
                                            state.X_WP.size(), assembly.parts().size()));
  }
  return Recognize(assembly, state.X_WP);
}

Recognition RecognizePairs(const Assembly& assembly) {
  return Recognize(assembly, assembly.FilePoses());
}

std::optional<Diagnostic> UnconnectedParts(const Assembly& assembly,
                                           const std::vector<Pair>& pairs) {
  std::vector<bool> connected(assembly.parts().size(), false);
  for (const Pair& p : pairs) connected[p.a.part] = connected[p.b.part] = true;
  std::vector<std::string> parts;
  for (std::size_t i = 0; i < connected.size(); ++i) {
    if (connected[i] || assembly.IsGround(i) || assembly.IsCompliant(i)) continue;
    parts.emplace_back(assembly.PartId(i));
  }
  if (parts.empty()) return std::nullopt;
  std::sort(parts.begin(), parts.end());
  const bool one = parts.size() == 1;
  std::string message =
      fmt::format("{} '{}' {} in no pair: nothing holds or guides {}", one ? "part" : "parts",
                  fmt::join(parts, "', '"), one ? "is" : "are", one ? "it" : "them");
  return Diagnostic{
      Severity::kWarning, "part_unconnected", std::move(message), std::move(parts), {}};
}

}  // namespace mechanist
