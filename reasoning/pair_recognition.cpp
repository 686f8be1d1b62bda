#include "reasoning/pair_recognition.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "kernel/grid_broad_phase.h"
#include "kernel/line_geometry.h"
#include "kernel/number_format.h"
#include "kernel/radix_sort.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Beyond these the features do not touch, so they make no pair and no near miss (the spec is
/// silent; the values are documented in the README): a shaft more than 5% of the hole's
/// diameter smaller than its hole (it passes through) or larger (beyond any interference fit,
/// a few tenths of a percent, or a CAD model's exaggerated one: it surrounds the hole, as a
/// bearing's outer ring does its inner ring's bore), a clearance hole more than 1.3 times the
/// thread (ISO 273's coarse series is at most 1.25), a thread under 0.6 times a tapped hole
/// (M3 in M4 is a near miss, M10 in M30 passes through).
constexpr double kMaxShaftClearance = 0.05;
constexpr double kMaxClearanceHoleRatio = 1.3;
// Two coaxial empty holes of two parts are a pivot whose pin the file leaves out when their
// diameters differ by at most this fraction of the larger (a press-fit bore and a running one)
// and at most kMaxImpliedPinGap mm of axis lies between them (the parts' faces meet there).
constexpr double kMaxImpliedPinDifference = 0.2;
constexpr double kMaxImpliedPinGap = 0.5;
constexpr double kMinThreadDiameterRatio = 0.6;

/// A feature at its world pose (its reach box is kept apart, for the broad phase).
struct WorldFeature {
  const Feature& f;  ///< as the assembly holds it
  FeatureRef ref;
  const AxisSegment& axis;  ///< world; held in the recogniser's array of axes, handed out
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();
};

std::string Mm(double x) { return FormatNumber(x) + " mm"; }
std::string Deg(double radians) { return FormatNumber(radians * 180.0 / kPi) + " deg"; }

class Recognizer {
  /// A tight thread, by FeatureIndex, and the tapped hole or nut it is fixed in.
  struct Screwed {
    std::size_t thread;
    FeatureRef hole;
  };

 public:
  /// At poses `X_WP`, one per part.
  Recognizer(const Assembly& assembly, std::span<const RigidTransform> X_WP)
      : assembly_(assembly),
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

  /// The world axes, once Run has finished with them.
  std::vector<AxisSegment> TakeAxes() {
    features_.clear();
    return std::move(axes_);
  }

  Recognition Run() {
    // About as many pairs as features in a mechanism (each joins two features; a gear may
    // mesh with several): reserved, so that the pairs are not copied as the vector grows.
    pairs_.reserve(features_.size());
    std::vector<std::uint32_t> parts(features_.size());
    for (std::size_t i = 0; i < features_.size(); ++i) {
      parts[i] = static_cast<std::uint32_t>(features_[i].ref.part);
    }
    for (const auto& [i, j] : OverlappingBoxPairs(reach_, parts)) Test(features_[i], features_[j]);
    AddImpliedPins();
    SetCompliantPartsApart();
    ApplyOverrides();
    ReportImpliedPins();
    const std::vector<Screwed> screwed = TightThreads();
    ApplySetscrews(screwed);
    if (2 * rank_bits_ + kSourceBits > 64) {
      throw std::length_error("pair recognition: too many features to sort pairs");
    }
    for (Pair& p : pairs_) ApplyClamp(p, screwed);
    ReportUnconnected();
    Recognition out{Sorted(), std::move(diagnostics_), {}};
    std::sort(out.diagnostics.begin(), out.diagnostics.end(), DiagnosticLess);
    return out;
  }

 private:
  // ---- broad phase ----

  Aabb ReachBox(const WorldFeature& w, const Aabb& part_box_W) const {
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
        radius = f.module * f.teeth / 2 + 2 * f.module;
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
    return box;
  }

  // ---- dispatch ----

  void Test(const WorldFeature& x, const WorldFeature& y) {
    using K = FeatureKind;
    const K a = x.f.kind, b = y.f.kind;
    auto is = [&](K p, K q) { return a == p && b == q; };
    auto either = [&](K p, K q, auto rule) {
      if (is(p, q))
        rule(x, y);
      else if (is(q, p))
        rule(y, x);
    };
    either(K::kShaft, K::kHole, [this](auto& s, auto& h) { ShaftHole(s, h); });
    either(K::kThread, K::kHole, [this](auto& t, auto& h) { ThreadHole(t, h); });
    either(K::kThread, K::kTappedHole, [this](auto& t, auto& h) { ThreadTapped(t, h); });
    either(K::kShaft, K::kSlot, [this](auto& s, auto& sl) { PinSlot(s, sl); });
    either(K::kKey, K::kSlot, [this](auto& k, auto& sl) { KeySlot(k, sl); });
    either(K::kWorm, K::kWormWheel, [this](auto& w, auto& g) { WormWheel(w, g); });
    either(K::kGear, K::kRack, [this](auto& g, auto& r) { GearRack(g, r); });
    either(K::kBall, K::kSocket, [this](auto& b, auto& s) { BallSocket(b, s); });
    either(K::kCycloidDisc, K::kPinRing, [this](auto& d, auto& r) { CycloidPins(d, r); });
    if (is(K::kGear, K::kGear)) GearGear(x, y);
    if (is(K::kThread, K::kShaft)) setscrew_candidates_.emplace_back(&x, &y);
    if (is(K::kShaft, K::kThread)) setscrew_candidates_.emplace_back(&y, &x);
    if (is(K::kFace, K::kFace)) FaceFace(x, y);
    if (is(K::kHole, K::kHole)) hole_candidates_.emplace_back(&x, &y);
  }

  // ---- output helpers ----

  std::string Name(const WorldFeature& w) const { return assembly_.FeatureName(w.ref); }
  /// Whether x's name comes before y's, without building names.
  bool NameLess(const WorldFeature& x, const WorldFeature& y) const {
    return assembly_.FeatureNameRank(x.ref) < assembly_.FeatureNameRank(y.ref);
  }

  void AddPair(PairType type, const WorldFeature& a, const WorldFeature& b,
               PairFastening fastening = PairFastening::kNone) {
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

  /// The coupling parameters of a screw, gear, worm_gear or rack_pinion pair from its
  /// features' kinds, parameters and world axes; the same for recognised and forced pairs.
  /// Features of other kinds (a forced "gear" between two shafts) leave them unset.
  void SetCoupling(Pair& p, const WorldFeature& a, const WorldFeature& b) const {
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
    } else if (p.type == PairType::kCycloidal && fa.kind == K::kCycloidDisc &&
               fb.kind == K::kPinRing) {
      // As an internal pair, the disc the pinion (lobes) and the ring the ring (pins).
      Rational ratio(fa.teeth, fb.teeth);
      if (a.axis.direction.dot(b.axis.direction) < 0) ratio = -ratio;
      p.ratio = ratio;
    } else if (p.type == PairType::kWormGear && fa.kind == K::kWorm && fb.kind == K::kWormWheel) {
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

  void Near(const char* code, const WorldFeature& a, const WorldFeature& b,
            const std::string& message) {
    diagnostics_.push_back(
        {Severity::kWarning,
         code,
         std::string(ToString(a.f.kind)) + " " + Name(a) + " and " +
             std::string(ToString(b.f.kind)) + " " + Name(b) + ": " + message,
         {std::string(assembly_.PartId(a.ref.part)), std::string(assembly_.PartId(b.ref.part))},
         {Name(a), Name(b)}});
  }

  // ---- axial fits ----

  /// Common gate of the axial fits: true when the convex feature `c` sits in the concave
  /// feature `h` (collinear, engaged, inserted with the right sense); reports the near
  /// misses otherwise.
  bool Seated(const WorldFeature& c, const WorldFeature& h) {
    const double overlap = AxialOverlap(c.axis, h.axis);
    if (overlap <= L_) return false;
    const double angle = AngleBetweenLines(c.axis.direction, h.axis.direction);
    const double offset = std::max(DistanceToLine(c.axis.origin, h.axis.origin, h.axis.direction),
                                   DistanceToLine(h.axis.origin, c.axis.origin, c.axis.direction));
    if (angle > A_ || offset > L_) {
      if (angle <= near_A_ && offset <= near_L_) {
        Near("axes_not_collinear", c, h,
             "axes are almost but not quite collinear: angle " + Deg(angle) + ", offset " +
                 Mm(offset) + " (required within " + Deg(A_) + " and " + Mm(L_) + ")");
      }
      return false;
    }
    if (c.axis.direction.dot(h.axis.direction) < 0 && !h.f.through) {
      Near("feature_sense_reversed", c, h,
           "collinear and overlapping, but the convex feature points out of the blind " +
               std::string(ToString(h.f.kind)) +
               " (a convex axis points toward its free end, a concave one into the material)");
      return false;
    }
    return true;
  }

  void ShaftHole(const WorldFeature& s, const WorldFeature& h) {
    // Far thinner or thicker than the hole, the shaft does not touch it (kMaxShaftClearance).
    if (std::abs(h.f.diameter - s.f.diameter) > kMaxShaftClearance * h.f.diameter + L_) return;
    if (!Seated(s, h)) return;
    if (s.f.diameter <= h.f.diameter + L_) {
      AddPair(s.f.retained || h.f.retained ? PairType::kRevolute : PairType::kCylindrical, s, h);
    } else if (h.f.retained) {
      Near("shaft_larger_than_hole", s, h,
           "shaft diameter " + Mm(s.f.diameter) + " is larger than the retained hole's " +
               Mm(h.f.diameter) + " (required at most hole + " + Mm(L_) +
               " for a part meant to turn)");
    } else {
      AddPair(PairType::kFixed, s, h, PairFastening::kPressFit);
    }
  }

  void ThreadHole(const WorldFeature& t, const WorldFeature& h) {
    if (h.f.diameter > kMaxClearanceHoleRatio * t.f.diameter + L_) return;
    if (!Seated(t, h)) return;
    if (h.f.diameter + L_ >= t.f.diameter) {
      AddPair(PairType::kCylindrical, t, h);
    } else {
      Near("hole_smaller_than_thread", t, h,
           "hole diameter " + Mm(h.f.diameter) + " is smaller than the thread's " +
               Mm(t.f.diameter) + " (required at least the thread's major diameter)");
    }
  }

  void ThreadTapped(const WorldFeature& t, const WorldFeature& h) {
    // A thread far smaller than the tapped hole passes through it (a spindle through the
    // bonnet's seat): neither a pair nor a near miss.
    if (std::min(t.f.diameter, h.f.diameter) <
        kMinThreadDiameterRatio * std::max(t.f.diameter, h.f.diameter)) {
      return;
    }
    if (!Seated(t, h)) return;
    std::vector<std::string> mismatches;
    if (std::abs(t.f.diameter - h.f.diameter) > L_) {
      mismatches.push_back("diameter: thread M" + FormatNumber(t.f.diameter) + ", tapped hole M" +
                           FormatNumber(h.f.diameter));
    }
    if (std::abs(t.f.pitch - h.f.pitch) > 1e-6 * std::max(t.f.pitch, h.f.pitch)) {
      mismatches.push_back("pitch: thread " + Mm(t.f.pitch) + ", tapped hole " + Mm(h.f.pitch));
    }
    if (t.f.starts != h.f.starts) {
      mismatches.push_back("starts: thread " + std::to_string(t.f.starts) + ", tapped hole " +
                           std::to_string(h.f.starts));
    }
    if (t.f.hand != h.f.hand) {
      mismatches.push_back(std::string("hand: thread ") +
                           (t.f.hand == Hand::kRight ? "right" : "left") + ", tapped hole " +
                           (h.f.hand == Hand::kRight ? "right" : "left"));
    }
    if (!mismatches.empty()) {
      std::string message = "threads do not match (required equal)";
      for (const std::string& m : mismatches) message += "; " + m;
      Near("thread_mismatch", t, h, message);
      return;
    }
    if (t.f.fastening == Fastening::kTight) {
      AddPair(PairType::kFixed, t, h, PairFastening::kTight);
    } else {
      AddPair(PairType::kScrew, t, h, PairFastening::kLoose);
    }
  }

  // ---- slots ----

  void PinSlot(const WorldFeature& s, const WorldFeature& sl) {
    const Eigen::Vector3d& n = sl.normal_W;
    if (AngleBetweenLines(s.axis.direction, n) > A_ || s.axis.direction.dot(n) <= 0) return;
    const LineLineClosest c =
        ClosestPointsOfLines(s.axis.origin, s.axis.direction, sl.axis.origin, sl.axis.direction);
    if (c.distance > L_ || c.t < -L_ || c.t > sl.axis.length + L_) return;
    if (c.s < -L_ - sl.f.depth || c.s > s.axis.length - L_) return;
    if (s.f.diameter <= sl.f.width + L_) {
      AddPair(PairType::kPinSlot, s, sl);
    } else {
      Near("pin_wider_than_slot", s, sl,
           "pin diameter " + Mm(s.f.diameter) + " is wider than the slot's " + Mm(sl.f.width) +
               " (required at most the slot width)");
    }
  }

  void KeySlot(const WorldFeature& k, const WorldFeature& sl) {
    if (AngleBetweenLines(k.axis.direction, sl.axis.direction) > A_) return;
    if (AngleBetweenLines(k.normal_W, sl.normal_W) > A_ || k.normal_W.dot(sl.normal_W) <= 0) {
      return;
    }
    const Eigen::Vector3d d = k.axis.origin - sl.axis.origin;
    const Eigen::Vector3d side = sl.axis.direction.cross(sl.normal_W);
    if (std::abs(d.dot(side)) > L_ || std::abs(d.dot(sl.normal_W)) > sl.f.depth + L_) return;
    if (AxialOverlap(k.axis, sl.axis) <= L_) return;
    if (k.f.width <= sl.f.width + L_) {
      AddPair(PairType::kPrismatic, k, sl);
    } else {
      Near("key_wider_than_slot", k, sl,
           "key width " + Mm(k.f.width) + " is wider than the slot's " + Mm(sl.f.width) +
               " (required at most the slot width)");
    }
  }

  // ---- gearing ----

  bool SameModule(double m1, double m2) const {
    return std::abs(m1 - m2) <= 1e-6 * std::max(m1, m2);
  }

  void GearGear(const WorldFeature& x, const WorldFeature& y) {
    if (x.f.internal && y.f.internal) return;
    // Order by name so that the pair and its ratio do not depend on the file's order.
    const bool swap = NameLess(y, x);
    const WorldFeature& g1 = swap ? y : x;
    const WorldFeature& g2 = swap ? x : y;
    if (AxialOverlap(g1.axis, g2.axis) <= L_) return;
    const Feature& f1 = g1.f;
    const Feature& f2 = g2.f;
    const double angle = AngleBetweenLines(g1.axis.direction, g2.axis.direction);
    const Eigen::Vector3d mid2 = g2.axis.origin + 0.5 * g2.axis.length * g2.axis.direction;
    const double d = DistanceToLine(mid2, g1.axis.origin, g1.axis.direction);
    const bool internal = f1.internal || f2.internal;
    const int z_internal = f1.internal ? f1.teeth : f2.teeth;
    const int z_external = f1.internal ? f2.teeth : f1.teeth;
    if (internal && z_internal <= z_external) return;  // a ring must be larger than its pinion
    // Helical gears mesh with equal helix angles, of opposite hands when external and the same
    // hand when internal; their centre distance takes the transverse module m / cos(helix).
    const double helix1 = assembly_.feature(g1.ref).helix_angle;
    const double helix2 = assembly_.feature(g2.ref).helix_angle;
    const double cos_helix = std::cos(helix1);
    auto required = [&](double m) {
      const double transverse = m / cos_helix;
      return internal ? transverse * (z_internal - z_external) / 2
                      : transverse * (f1.teeth + f2.teeth) / 2;
    };
    const double m = f1.module;
    if (!SameModule(f1.module, f2.module)) {
      // Meant to mesh if the distance fits either gear's module.
      if (angle <= near_A_ && (std::abs(d - required(f1.module)) < f1.module ||
                               std::abs(d - required(f2.module)) < f2.module)) {
        Near("gear_module_mismatch", g1, g2,
             "modules differ: " + Mm(f1.module) + " and " + Mm(f2.module) + " (required equal)");
      }
      return;
    }
    const double a = required(m);
    const double error = std::abs(d - a);
    const double helix_error = std::abs(helix2 - (internal ? helix1 : -helix1));
    if (angle <= A_ && error <= L_ && helix_error > A_) {
      Near("gear_helix_mismatch", g1, g2,
           "helix angles " + Deg(helix1) + " and " + Deg(helix2) + " (required equal, " +
               (internal ? "of the same hand for an internal pair)" : "of opposite hands)"));
      return;
    }
    if (angle <= A_ && error <= L_) {
      AddPair(PairType::kGear, g1, g2);
      return;
    }
    if (error >= m) return;
    // The module across the teeth: m, or m / cos(helix) for helical gears.
    const std::string module =
        helix1 == 0.0 ? FormatNumber(m) : FormatNumber(m) + " / cos(" + Deg(helix1) + ")";
    const std::string formula = internal ? module + " x |" + std::to_string(f2.teeth) + " - " +
                                               std::to_string(f1.teeth) + "| / 2"
                                         : module + " x (" + std::to_string(f1.teeth) + " + " +
                                               std::to_string(f2.teeth) + ") / 2";
    if (angle > A_ && angle <= near_A_) {
      Near("gear_axes_not_parallel", g1, g2,
           "axes are " + Deg(angle) + " apart (required parallel within " + Deg(A_) + ")");
    } else if (angle <= A_) {
      Near("gear_center_distance", g1, g2,
           "centre distance " + Mm(d) + ", required " + Mm(a) + " = " + formula + " (off by " +
               Mm(d - a) + ", tolerance " + Mm(L_) + ")");
    }
  }

  /// A cycloid disc in its pin ring (spec): parallel axes offset by the disc's eccentricity,
  /// one pin more than lobes, overlapping along the axis. Off by less than the near-miss
  /// windows: `cycloid_eccentricity`, `cycloid_pin_count`.
  void CycloidPins(const WorldFeature& disc, const WorldFeature& ring) {
    if (AxialOverlap(disc.axis, ring.axis) <= L_) return;
    const double angle = AngleBetweenLines(disc.axis.direction, ring.axis.direction);
    if (angle > near_A_) return;
    const double e = assembly_.feature(disc.ref).eccentricity;
    const double offset = DistanceToLine(disc.axis.origin, ring.axis.origin, ring.axis.direction);
    if (std::abs(offset - e) > near_L_) return;
    if (ring.f.teeth != disc.f.teeth + 1) {
      Near("cycloid_pin_count", disc, ring,
           std::to_string(ring.f.teeth) + " pins for " + std::to_string(disc.f.teeth) +
               " lobes (required one pin more than lobes)");
      return;
    }
    if (angle > A_) {
      Near("cycloid_axes_not_parallel", disc, ring,
           "axes are " + Deg(angle) + " apart (required parallel within " + Deg(A_) + ")");
    } else if (std::abs(offset - e) > L_) {
      Near("cycloid_eccentricity", disc, ring,
           "the disc's axis is " + Mm(offset) + " from the ring's, required its eccentricity " +
               Mm(e) + " (off by " + Mm(offset - e) + ", tolerance " + Mm(L_) + ")");
    } else {
      AddPair(PairType::kCycloidal, disc, ring);
    }
  }

  void WormWheel(const WorldFeature& w, const WorldFeature& g) {
    const double angle = AngleBetweenLines(w.axis.direction, g.axis.direction);
    const LineLineClosest c =
        ClosestPointsOfLines(w.axis.origin, w.axis.direction, g.axis.origin, g.axis.direction);
    if (c.s < -L_ || c.s > w.axis.length + L_ || c.t < -L_ || c.t > g.axis.length + L_) return;
    const Feature& fw = w.f;
    const Feature& fg = g.f;
    if (!SameModule(fw.module, fg.module)) {
      const double a_worm = (fw.pitch_diameter + fw.module * fg.teeth) / 2;
      const double a_wheel = (fw.pitch_diameter + fg.module * fg.teeth) / 2;
      if (angle >= kPi / 2 - near_A_ && (std::abs(c.distance - a_worm) < fw.module ||
                                         std::abs(c.distance - a_wheel) < fg.module)) {
        Near("worm_module_mismatch", w, g,
             "modules differ: " + Mm(fw.module) + " and " + Mm(fg.module) + " (required equal)");
      }
      return;
    }
    const double a = (fw.pitch_diameter + fw.module * fg.teeth) / 2;
    const double error = std::abs(c.distance - a);
    if (angle >= kPi / 2 - A_ && error <= L_) {
      AddPair(PairType::kWormGear, w, g);
      return;
    }
    if (error >= fg.module) return;
    if (angle < kPi / 2 - A_ && angle >= kPi / 2 - near_A_) {
      Near("worm_axes_not_perpendicular", w, g,
           "axes are " + Deg(angle) + " apart (required 90 deg within " + Deg(A_) + ")");
    } else if (angle >= kPi / 2 - A_) {
      Near("worm_center_distance", w, g,
           "centre distance " + Mm(c.distance) + ", required " + Mm(a) + " = (" +
               FormatNumber(fw.pitch_diameter) + " + " + FormatNumber(fw.module) + " x " +
               std::to_string(fg.teeth) + ") / 2 (off by " + Mm(c.distance - a) + ", tolerance " +
               Mm(L_) + ")");
    }
  }

  void GearRack(const WorldFeature& g, const WorldFeature& r) {
    if (g.f.internal) return;
    const double to_axis = AngleBetweenLines(g.axis.direction, r.axis.direction);
    const double to_normal = AngleBetweenLines(g.axis.direction, r.normal_W);
    const LineLineClosest c =
        ClosestPointsOfLines(g.axis.origin, g.axis.direction, r.axis.origin, r.axis.direction);
    if (c.s < -L_ || c.s > g.axis.length + L_ || c.t < -L_ || c.t > r.axis.length + L_) return;
    const Eigen::Vector3d p_gear = g.axis.origin + c.s * g.axis.direction;
    const Eigen::Vector3d p_rack = r.axis.origin + c.t * r.axis.direction;
    if ((p_gear - p_rack).dot(r.normal_W) <= 0) return;  // the pinion is on the other side
    if (!SameModule(g.f.module, r.f.module)) {
      if (std::abs(c.distance - g.f.module * g.f.teeth / 2) < g.f.module ||
          std::abs(c.distance - r.f.module * g.f.teeth / 2) < r.f.module) {
        Near("rack_module_mismatch", g, r,
             "modules differ: " + Mm(g.f.module) + " and " + Mm(r.f.module) + " (required equal)");
      }
      return;
    }
    const double a = g.f.module * g.f.teeth / 2;
    const double error = std::abs(c.distance - a);
    const bool square = to_axis >= kPi / 2 - A_ && to_normal >= kPi / 2 - A_;
    if (square && error <= L_) {
      AddPair(PairType::kRackPinion, g, r);
    } else if (square && error < g.f.module) {
      Near("rack_pitch_line_distance", g, r,
           "pitch line at " + Mm(c.distance) + " from the pinion's axis, required " + Mm(a) +
               " = " + FormatNumber(g.f.module) + " x " + std::to_string(g.f.teeth) +
               " / 2 (off by " + Mm(c.distance - a) + ", tolerance " + Mm(L_) + ")");
    }
  }

  // ---- spheres and faces ----

  void BallSocket(const WorldFeature& b, const WorldFeature& s) {
    const double offset = (b.axis.origin - s.axis.origin).norm();
    const double difference = std::abs(b.f.diameter - s.f.diameter);
    if (offset <= L_ && difference <= L_) {
      AddPair(PairType::kSpherical, b, s);
    } else if (offset < std::min(b.f.diameter, s.f.diameter) / 2) {
      Near("ball_socket_mismatch", b, s,
           "centres " + Mm(offset) + " apart and diameters " + Mm(b.f.diameter) + " and " +
               Mm(s.f.diameter) + " (required same centre and diameter within " + Mm(L_) + ")");
    }
  }

  void FaceFace(const WorldFeature& x, const WorldFeature& y) {
    const Eigen::Vector3d& n1 = x.axis.direction;
    const Eigen::Vector3d& n2 = y.axis.direction;
    if (n1.dot(n2) >= 0 || AngleBetweenLines(n1, n2) > A_) return;
    const Eigen::Vector3d d = y.axis.origin - x.axis.origin;
    if (std::abs(d.dot(n1)) > L_) return;
    auto extent = [](const Feature& f) { return std::hypot(f.width, f.height) / 2; };
    if (x.f.width > 0 && x.f.height > 0 && y.f.width > 0 && y.f.height > 0) {
      const double in_plane = (d - d.dot(n1) * n1).norm();
      if (in_plane >= extent(x.f) + extent(y.f) - L_) return;
    }
    const bool swap = NameLess(y, x);
    AddPair(PairType::kPlanar, swap ? y : x, swap ? x : y);
  }

  // ---- overrides and side effects ----

  std::size_t Index(FeatureRef ref) const { return assembly_.FeatureIndex(ref); }
  const WorldFeature& At(FeatureRef ref) const { return features_[Index(ref)]; }

  static bool SameFeatures(const Pair& p, FeatureRef f, FeatureRef g) {
    return (p.a == f && p.b == g) || (p.a == g && p.b == f);
  }

  void ApplyOverrides() {
    for (const PairOverride& o : assembly_.overrides()) {
      std::erase_if(pairs_,
                    [&](const Pair& p) { return SameFeatures(p, o.features[0], o.features[1]); });
      std::erase_if(tight_, [&](const Screwed& t) {
        return (t.thread == Index(o.features[0]) && t.hole == o.features[1]) ||
               (t.thread == Index(o.features[1]) && t.hole == o.features[0]);
      });
      if (!o.type) continue;
      const WorldFeature* a = &At(o.features[0]);
      const WorldFeature* b = &At(o.features[1]);
      // The convex feature, the worm or the pinion first, as for recognised pairs.
      const auto kind_a = a->f.kind, kind_b = b->f.kind;
      if ((IsConcave(kind_a) && IsConvex(kind_b)) || kind_b == FeatureKind::kWorm ||
          kind_a == FeatureKind::kRack) {
        std::swap(a, b);
      }
      AddPair(*o.type, *a, *b);
      pairs_.back().source = PairSource::kOverride;
    }
  }

  /// Implied pins (README, "Real CAD exports"): a revolute pair between two holes of two
  /// parts that are collinear, of diameters within kMaxImpliedPinDifference, overlapping or at
  /// most kMaxImpliedPinGap apart along the axis, when no shaft or thread sits in either: the
  /// hinge of two parts whose pin or screw the CAD file leaves out. Before the overrides, so
  /// that an override forbids or replaces one as any pair.
  void AddImpliedPins() {
    if (hole_candidates_.empty()) return;
    std::vector<bool> filled(features_.size(), false);
    for (const Pair& p : pairs_) {
      const FeatureKind k = assembly_.kind(p.a);
      if (k == FeatureKind::kShaft || k == FeatureKind::kThread) filled[Index(p.b)] = true;
    }
    for (const auto& [x, y] : hole_candidates_) {
      if (filled[Index(x->ref)] || filled[Index(y->ref)]) continue;
      const double d_max = std::max(x->f.diameter, y->f.diameter);
      if (std::abs(x->f.diameter - y->f.diameter) > kMaxImpliedPinDifference * d_max + L_) {
        continue;
      }
      const double angle = AngleBetweenLines(x->axis.direction, y->axis.direction);
      const double offset =
          std::max(DistanceToLine(x->axis.origin, y->axis.origin, y->axis.direction),
                   DistanceToLine(y->axis.origin, x->axis.origin, x->axis.direction));
      if (angle > A_ || offset > L_) continue;
      if (AxialOverlap(x->axis, y->axis) < -kMaxImpliedPinGap - L_) continue;
      const bool x_first = NameLess(*x, *y);
      AddPair(PairType::kRevolute, x_first ? *x : *y, x_first ? *y : *x);
      pairs_.back().source = PairSource::kImpliedPin;
    }
  }

  /// Compliant parts (springs, belts, hoses) join no pair: the pairs their features would make
  /// are dropped, and one info diagnostic `compliant_part` per such part names the parts it
  /// touches (those pairs' other parts). Before the overrides, which may still force a pair.
  void SetCompliantPartsApart() {
    if (!assembly_.HasCompliantParts()) return;
    std::map<std::size_t, std::set<std::string>> touched;  // compliant part -> the others
    std::erase_if(pairs_, [&](const Pair& p) {
      const bool a = assembly_.IsCompliant(p.a.part), b = assembly_.IsCompliant(p.b.part);
      if (a) touched[p.a.part].insert(std::string(assembly_.PartId(p.b.part)));
      if (b) touched[p.b.part].insert(std::string(assembly_.PartId(p.a.part)));
      return a || b;
    });
    std::erase_if(tight_, [&](const Screwed& t) {
      return assembly_.IsCompliant(t.hole.part) ||
             assembly_.IsCompliant(features_[t.thread].ref.part);
    });
    for (std::size_t part = 0; part < assembly_.parts().size(); ++part) {
      if (!assembly_.IsCompliant(part)) continue;
      const std::set<std::string>& others = touched[part];
      std::string names;
      for (const std::string& o : others) names += (names.empty() ? "" : ", ") + o;
      std::vector<std::string> parts = {std::string(assembly_.PartId(part))};
      parts.insert(parts.end(), others.begin(), others.end());
      diagnostics_.push_back(
          {Severity::kInfo,
           "compliant_part",
           "part '" + parts.front() +
               "' is compliant (a spring, belt or hose): not a rigid link; " +
               (names.empty() ? "it touches no part by its features" : "it connects " + names),
           parts,
           {}});
    }
  }

  /// One info diagnostic `implied_pin` per two parts that implied pins join, naming the holes
  /// and the pin's diameter (the smaller hole's).
  void ReportImpliedPins() {
    std::map<std::pair<std::string, std::string>, std::vector<const Pair*>> by_parts;
    for (const Pair& p : pairs_) {
      if (p.source != PairSource::kImpliedPin) continue;
      std::string a(assembly_.PartId(p.a.part)), b(assembly_.PartId(p.b.part));
      if (b < a) std::swap(a, b);
      by_parts[{a, b}].push_back(&p);
    }
    for (const auto& [parts, pairs] : by_parts) {
      std::set<std::string> holes;
      double pin = std::numeric_limits<double>::infinity();
      for (const Pair* p : pairs) {
        for (const FeatureRef f : {p->a, p->b}) {
          holes.insert(assembly_.FeatureName(f));
          pin = std::min(pin, At(f).f.diameter);
        }
      }
      std::string names;
      for (const std::string& h : holes) names += (names.empty() ? "" : ", ") + h;
      diagnostics_.push_back({Severity::kInfo,
                              "implied_pin",
                              parts.first + " and " + parts.second + " turn on a pin of about " +
                                  Mm(pin) + " that the file does not model, in holes " + names +
                                  " (a revolute pair; an override of type none forbids it)",
                              {parts.first, parts.second},
                              {holes.begin(), holes.end()}});
    }
  }

  /// The tapped hole or nut each tight thread is fixed in, the first by name when there are
  /// several (not the first found, which depends on the broad phase), by thread.
  std::vector<Screwed> TightThreads() {
    RadixSort(tight_, BitWidth(features_.size()), [](const Screwed& t) { return t.thread; });
    std::vector<Screwed> screwed;
    for (const Screwed& t : tight_) {
      if (screwed.empty() || screwed.back().thread != t.thread) {
        screwed.push_back(t);
      } else if (assembly_.FeatureNameRank(t.hole) <
                 assembly_.FeatureNameRank(screwed.back().hole)) {
        screwed.back().hole = t.hole;
      }
    }
    return screwed;
  }

  /// The tapped hole or nut the thread of FeatureIndex `thread` is fixed in, if it is tight.
  static const FeatureRef* ScrewedInto(const std::vector<Screwed>& screwed, std::size_t thread) {
    const auto it =
        std::lower_bound(screwed.begin(), screwed.end(), thread,
                         [](const Screwed& s, std::size_t index) { return s.thread < index; });
    return it != screwed.end() && it->thread == thread ? &it->hole : nullptr;
  }

  /// A tight thread fixed in a nut or tapped hole clamps the parts of its clearance holes.
  void ApplyClamp(Pair& p, const std::vector<Screwed>& screwed) const {
    if (p.type == PairType::kCylindrical && assembly_.kind(p.a) == FeatureKind::kThread &&
        assembly_.kind(p.b) == FeatureKind::kHole && ScrewedInto(screwed, Index(p.a))) {
      p.type = PairType::kFixed;
      p.dof = 0;
      p.source = PairSource::kClamp;
      p.fastening = PairFastening::kClamp;
      p.via = p.a;
    }
  }

  /// A tight thread in a tapped hole whose tip bears on a third part's shaft fixes the shaft.
  void ApplySetscrews(const std::vector<Screwed>& screwed) {
    for (const auto& [thread, s] : setscrew_candidates_) {
      const FeatureRef* hole = ScrewedInto(screwed, Index(thread->ref));
      if (!hole || s->ref.part == hole->part) continue;
      const Eigen::Vector3d tip = thread->axis.end();
      if (AngleBetweenLines(thread->axis.direction, s->axis.direction) < kPi / 2 - A_) continue;
      const double along = (tip - s->axis.origin).dot(s->axis.direction);
      if (along < -L_ || along > s->axis.length + L_) continue;
      const Eigen::Vector3d foot = s->axis.origin + along * s->axis.direction;
      if ((foot - tip).dot(thread->axis.direction) <= 0) continue;  // pointing away
      if (std::abs((foot - tip).norm() - s->f.diameter / 2) > L_) continue;
      Pair fixed;
      fixed.type = PairType::kFixed;
      fixed.a = s->ref;
      fixed.b = *hole;
      fixed.source = PairSource::kSetscrew;
      fixed.fastening = PairFastening::kSetscrew;
      fixed.dof = 0;
      fixed.via = thread->ref;
      pairs_.push_back(fixed);
    }
  }

  /// One warning `part_unconnected` naming every non-ground, rigid part in no pair (the nine
  /// balls of a bearing are one finding, not nine).
  void ReportUnconnected() {
    std::vector<bool> connected(assembly_.parts().size(), false);
    for (const Pair& p : pairs_) connected[p.a.part] = connected[p.b.part] = true;
    std::vector<std::string> parts;
    for (std::size_t i = 0; i < connected.size(); ++i) {
      if (connected[i] || assembly_.IsGround(i) || assembly_.IsCompliant(i)) continue;
      parts.emplace_back(assembly_.PartId(i));
    }
    if (parts.empty()) return;
    std::sort(parts.begin(), parts.end());
    std::string names;
    for (const std::string& p : parts) names += (names.empty() ? "'" : ", '") + p + "'";
    diagnostics_.push_back(
        {Severity::kWarning,
         "part_unconnected",
         (parts.size() == 1 ? "part " + names + " is" : "parts " + names + " are") +
             " in no pair: nothing holds or guides " + (parts.size() == 1 ? "it" : "them"),
         std::move(parts),
         {}});
  }

  /// A pair's place in the order of the pairs, and its index as found.
  struct SortKey {
    std::uint64_t names_and_source;
    std::size_t pair;
  };
  static constexpr int kSourceBits = 3;
  static_assert(static_cast<int>(PairSource::kInferred) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kImpliedPin) < (1 << kSourceBits));

  /// Pairs order by feature names, then source, then as found, not by indices, so that
  /// reordering the file changes nothing: the name ranks and the source packed in one key.
  std::uint64_t Key(const Pair& p) const {
    return (std::uint64_t{assembly_.FeatureNameRank(p.a)} << rank_bits_ |
            assembly_.FeatureNameRank(p.b))
               << kSourceBits |
           static_cast<std::uint64_t>(p.source);
  }

  /// The pairs in the order of their keys: a radix sort, linear at 100,000 parts.
  std::vector<Pair> Sorted() {
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

  const Assembly& assembly_;
  const double L_, A_, near_L_, near_A_;
  const int rank_bits_;                 ///< bits of a feature's name rank
  std::vector<AxisSegment> axes_;       ///< per Assembly::FeatureIndex: world axes
  std::vector<WorldFeature> features_;  ///< per Assembly::FeatureIndex
  /// Per Assembly::FeatureIndex: the box a feature can reach a partner from (apart from the
  /// features: the broad phase reads only these, several times).
  std::vector<Aabb> reach_;
  std::vector<Pair> pairs_;
  /// Tight fixed pairs as recognised: (thread's FeatureIndex, tapped hole or nut).
  std::vector<Screwed> tight_;
  std::vector<Diagnostic> diagnostics_;
  /// (thread, shaft) feature pairs whose reach boxes overlap: possible setscrew contacts.
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> setscrew_candidates_;
  /// Hole pairs whose reach boxes overlap: possible implied pins.
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> hole_candidates_;
};

Recognition Recognize(const Assembly& assembly, std::span<const RigidTransform> X_WP) {
  Recognizer recognizer(assembly, X_WP);
  Recognition out = recognizer.Run();
  out.axes_W = recognizer.TakeAxes();
  return out;
}

}  // namespace

Recognition RecognizePairs(const Assembly& assembly, const AssemblyState& state) {
  if (state.X_WP.size() != assembly.parts().size()) {
    throw std::invalid_argument("RecognizePairs: " + std::to_string(state.X_WP.size()) +
                                " poses for " + std::to_string(assembly.parts().size()) + " parts");
  }
  return Recognize(assembly, state.X_WP);
}

Recognition RecognizePairs(const Assembly& assembly) {
  return Recognize(assembly, assembly.FilePoses());
}

}  // namespace mechanist
