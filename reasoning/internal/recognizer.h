#pragma once

// The pair recogniser shared by the files of pair recognition (not installed): the features at
// their world poses, the fit rules' thresholds, and the Recognizer, whose rules live one file
// per kind of fit (axial_fits.cpp, slot_fits.cpp, gear_fits.cpp, surface_fits.cpp,
// bearing_fits.cpp), its side
// effects (overrides, implied pins, clamps, setscrews) in recognition_side_effects.cpp and its
// core (broad phase, dispatch, output) in reasoning/pair_recognition.cpp.

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

#include "kernel/geometry/line_geometry.h"
#include "kernel/support/number_format.h"
#include "kernel/support/radix_sort.h"
#include "reasoning/pair_recognition.h"

namespace mechanist::internal {

inline constexpr double kPi = 3.14159265358979323846;
/// Beyond these the features do not touch, so they make no pair and no near miss (the spec is
/// silent; the values are documented in the README): a shaft more than 5% of the hole's
/// diameter smaller than its hole (it passes through) or larger (beyond any interference fit,
/// a few tenths of a percent, or a CAD model's exaggerated one: it surrounds the hole, as a
/// bearing's outer ring does its inner ring's bore), a clearance hole more than 1.3 times the
/// thread (ISO 273's coarse series is at most 1.25), a thread under 0.6 times a tapped hole
/// (M3 in M4 is a near miss, M10 in M30 passes through).
inline constexpr double kMaxShaftClearance = 0.05;
/// A shaft up to this fraction of its hole's diameter smaller still guides a part that nothing
/// else holds (a print-in-place hinge's pins, printed with clearance): AddLooseFits.
inline constexpr double kMaxLooseClearance = 0.1;
inline constexpr double kMaxClearanceHoleRatio = 1.3;
// Two coaxial empty holes of two parts are a pivot whose pin the file leaves out when their
// diameters differ by at most this fraction of the larger (a press-fit bore and a running one)
// and at most kMaxImpliedPinGap mm of axis lies between them (the parts' faces meet there), or
// up to a diameter when no rod of another part runs along them (knuckles spaced on one rod).
inline constexpr double kMaxImpliedPinDifference = 0.2;
inline constexpr double kMaxImpliedPinGap = 0.5;
inline constexpr double kMinThreadDiameterRatio = 0.6;

/// A feature at its world pose (its reach box is kept apart, for the broad phase).
struct WorldFeature {
  const Feature& f;  ///< as the assembly holds it
  FeatureRef ref;
  const AxisSegment& axis;  ///< world; held in the recogniser's array of axes, handed out
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();
};

inline std::string Mm(double x) { return FormatNumber(x) + " mm"; }
inline std::string Deg(double radians) { return FormatNumber(radians * 180.0 / kPi) + " deg"; }

/// Recognises the pairs of an assembly at given poses (see RecognizePairs).
class Recognizer {
  /// A tight thread, by FeatureIndex, and the tapped hole or nut it is fixed in.
  struct Screwed {
    std::size_t thread;
    FeatureRef hole;
  };

 public:
  /// At poses `X_WP`, one per part.
  Recognizer(const Assembly& assembly, std::span<const RigidTransform> X_WP);

  /// The world axes, once Run has finished with them.
  std::vector<AxisSegment> TakeAxes();

  Recognition Run();

 private:
  // ---- broad phase (pair_recognition.cpp; the grid is kernel/grid_broad_phase) ----

  Aabb ReachBox(const WorldFeature& w, const Aabb& part_box_W) const;

  // ---- dispatch (pair_recognition.cpp) ----

  void Test(const WorldFeature& x, const WorldFeature& y);

  // ---- output helpers (pair_recognition.cpp) ----

  std::string Name(const WorldFeature& w) const { return assembly_.FeatureName(w.ref); }
  /// Whether x's name comes before y's, without building names.
  bool NameLess(const WorldFeature& x, const WorldFeature& y) const {
    return assembly_.FeatureNameRank(x.ref) < assembly_.FeatureNameRank(y.ref);
  }

  void AddPair(PairType type, const WorldFeature& a, const WorldFeature& b,
               PairFastening fastening = PairFastening::kNone);

  /// The coupling parameters of a screw, gear, worm_gear or rack_pinion pair from its
  /// features' kinds, parameters and world axes; the same for recognised and forced pairs.
  /// Features of other kinds (a forced "gear" between two shafts) leave them unset.
  void SetCoupling(Pair& p, const WorldFeature& a, const WorldFeature& b) const;

  void Near(const char* code, const WorldFeature& a, const WorldFeature& b,
            const std::string& message);

  // ---- axial fits (axial_fits.cpp) ----

  /// Common gate of the axial fits: true when the convex feature `c` sits in the concave
  /// feature `h` (collinear, engaged, inserted with the right sense); reports the near
  /// misses otherwise.
  bool Seated(const WorldFeature& c, const WorldFeature& h);
  /// Seated's geometry alone (collinear, engaged, the right sense), reporting nothing.
  bool Collinear(const WorldFeature& c, const WorldFeature& h) const;

  void ShaftHole(const WorldFeature& s, const WorldFeature& h);

  void ThreadHole(const WorldFeature& t, const WorldFeature& h);

  void ThreadTapped(const WorldFeature& t, const WorldFeature& h);

  // ---- slots (slot_fits.cpp) ----

  void PinSlot(const WorldFeature& s, const WorldFeature& sl);

  void KeySlot(const WorldFeature& k, const WorldFeature& sl);

  // ---- gearing (gear_fits.cpp) ----

  bool SameModule(double m1, double m2) const {
    return std::abs(m1 - m2) <= 1e-6 * std::max(m1, m2);
  }

  void GearGear(const WorldFeature& x, const WorldFeature& y);

  /// Two bevel gears (spec): a common apex, the same module, pitch angles that sum to the
  /// angle between the axes, equal spiral angles of opposite hands, and pitch-cone faces that
  /// overlap along the common pitch line. Off by less than the near-miss windows:
  /// `bevel_apex`, `bevel_module_mismatch`, `bevel_pitch_angles`, `bevel_spiral_mismatch`,
  /// `bevel_cone_distance`.
  void BevelBevel(const WorldFeature& x, const WorldFeature& y);

  /// A cycloid disc in its pin ring (spec): parallel axes offset by the disc's eccentricity,
  /// one pin more than lobes, overlapping along the axis. Off by less than the near-miss
  /// windows: `cycloid_eccentricity`, `cycloid_pin_count`.
  void CycloidPins(const WorldFeature& disc, const WorldFeature& ring);

  /// A worm and its wheel (spec), or an external gear serving as one: axes square, the same
  /// module, centre distance (pitch diameter + m z) / 2. Off by less than the near-miss
  /// windows: `worm_module_mismatch`, `worm_axes_not_perpendicular`, `worm_center_distance`.
  void WormWheel(const WorldFeature& w, const WorldFeature& g);

  void GearRack(const WorldFeature& g, const WorldFeature& r);

  // ---- spheres and faces (surface_fits.cpp) ----

  void BallSocket(const WorldFeature& b, const WorldFeature& s);

  /// Two faces touching (coplanar, opposite normals, overlapping): a planar pair, or a fixed
  /// one (source one_part) between two bodies of one CAD part (Part::body_of).
  void FaceFace(const WorldFeature& x, const WorldFeature& y);

  // ---- rolling bearings (bearing_fits.cpp) ----

  /// Rolling bearings as they are sold (README, "Real CAD exports"): three or more parts that
  /// are each one rolling element of one size (within the length tolerance): a ball, or a
  /// roller (one shaft and faces across its axis: its ends) lying along the bearing's axis;
  /// their centres on a circle (the pitch circle, fitted in the plane of the centres by Kasa's
  /// algebraic fit, every centre within the length tolerance of it), neighbours at most four
  /// diameters apart. The inner ring is the part with a shaft coaxial with the circle between
  /// the elements' inner side and the pitch circle (a ball raceway's land, a roller raceway, or
  /// the shaft a needle bearing without an inner ring runs on), the outer ring the part with
  /// such a hole outside the circle, both reaching the elements' plane within a ball radius
  /// or half a roller. The rings make a revolute pair (source bearing) and no other pair
  /// between them (a land is never a press fit); each element is held with the outer ring (a
  /// fixed pair, source bearing: its spin and orbit are not modelled, and it adds no freedom),
  /// and makes no other pair. Tapered and barrel rollers (two round flat ends, of different or
  /// equal sizes, and nothing else: their cones and tori give no feature) whose axes lie in
  /// planes through the circle's axis at one inclination of at most 45 deg (a tapered
  /// roller's leans) are a tapered or spherical roller bearing's, between the nearest bore
  /// inside them (or the shaft their inner raceway is cut into, ShaftUnderRollers) and the
  /// nearest outside cylinder outside them; such a roller may have one flat end and a domed
  /// other, measured on its mesh. Three or more balls in one part (fused with their cage) are
  /// a ball set, each ball an element. Balls on an inner ring's land with no bore at their
  /// outer side run in a self-aligning bearing's spherical raceway: its outer ring is the
  /// nearest outside cylinder beyond them. Elements of one size on
  /// circles side by side along their axis are split into rows; rows between the same rings
  /// are one (double-row) bearing. Balls, or rollers along radii, between two washers are a
  /// thrust bearing (FindThrustWashers). One info diagnostic `bearing` per bearing gives its
  /// kind (ball, self-aligning ball, tapered roller, spherical or barrel roller, cylindrical
  /// roller, needle roller: rollers 2.5 diameters long or more; thrust), its rows of elements
  /// and size (bore
  /// x outside diameter x width, mm). Before the implied pins and the overrides.
  void AddBearings();
  /// A row of a bearing's rolling elements on their pitch circle, and its rings (AddBearings).
  struct BearingRow;
  /// Checks the row's elements lie as a bearing's do (rollers along its axis, or along radii
  /// between a thrust bearing's washers; tapered and barrel rollers leaning towards it at one
  /// angle) and finds its rings' features (AddBearings): whether it found both, on two parts.
  bool FindBearingRings(BearingRow& row) const;
  /// A thrust bearing's washers for `row` (balls, or rollers along radii; `in_row`: their
  /// parts): on each side of the elements' plane, the nearest flat face of another part
  /// square to the axis, centred on it, reaching across the pitch circle and facing the
  /// elements within their radius of the plane, on a part with a bore on the axis; the
  /// washer with the smaller bore is the inner ring (the shaft washer). Whether it found two.
  bool FindThrustWashers(BearingRow& row, const std::set<std::size_t>& in_row) const;
  /// The shaft that rollers found by their ends run on when no bore lies inside them (the
  /// inner raceway cut into the shaft), thinner than `inside` mm in radius; `in_row`: their
  /// parts. Nothing when no part's mesh reaches them.
  const WorldFeature* ShaftUnderRollers(const BearingRow& row, const std::set<std::size_t>& in_row,
                                        double inside) const;
  /// The pairs and the `bearing` info of one bearing: `rows` (one or more) between the same
  /// rings. Parts wholly between the rings (cages, seals, shields; their meshes at the
  /// recognition's poses) are held with the outer ring too.
  void AddBearing(std::span<const BearingRow> rows);

  /// Bearings modelled as one solid (vendor parts): a part whose outside cylinder and bore
  /// are coaxial and span the same length, with two flat faces or more at each end (the inner
  /// ring's and the outer ring's: a washer or spacer has one). Fitted like a bearing: its
  /// outside in a bore of its size is fixed there and a shaft in its bore turns (the
  /// cylindrical pair becomes revolute: the bearing locates it along the axis), all source
  /// bearing; each is kept in solid_bearings_ for ReportSolidBearings. After AddBearings.
  void AddSolidBearings();

  /// One info `bearing` per bearing of one solid. A bolt that clamps its bore (a fixed pair,
  /// source clamp, on the bore: an axle bolt through a wheel's bearings) holds the inner ring,
  /// so the part turns with the bolt and its seats turn on it: the fitted pairs become
  /// revolute. After the clamps.
  void ReportSolidBearings();

  /// A part on a shaft with a flat (a face of the shaft's part across the axis direction,
  /// inside its radius, within the bore's span) cannot turn on it: a setscrew on the flat or a
  /// D-shaped bore the file does not model. The cylindrical pair becomes fixed (source
  /// shaft_flat), with one info `shaft_flat` per pair.
  void FixHubsOnFlats();

  /// A hub on a shaft (a cylindrical pair) with a radial hole that opens into its bore within
  /// the shaft's reach (its axis across the shaft's and through it, no wider than the bore)
  /// and has nothing in it, when nothing but the shaft's part and face contacts holds the
  /// hub: a shaft collar whose setscrew the file leaves out. The pair becomes fixed (source
  /// setscrew_hole), with one info `setscrew_hole` per pair. A bushing with an oil hole is
  /// held in its housing, so it is left turning. After FixHubsOnFlats.
  void FixHubsBySetscrewHoles();

  /// A hub on a shaft (a cylindrical pair) that nothing but the shaft's rigid body holds
  /// (apart from face contacts and the meshes of its teeth, which couple turns and hold
  /// nothing; bodies are parts joined by fixed pairs so far), when that body
  /// turns in a bearing on the shaft's axis (a revolute pair, source bearing, to a third
  /// body): a pendulum, crank, pulley or gear on a shaft carried by bearings turns with it,
  /// by a key, setscrew, glue or press fit the file leaves out (a part meant to turn on the
  /// shaft would need no bearing under it). The pair becomes fixed (source bearing_shaft),
  /// with one info `bearing_shaft` per pair. After FixHubsBySetscrewHoles.
  void FixHubsOnBearingShafts();

  /// A hub on a shaft: a recognised cylindrical pair of a shaft `s` in a hole `h`, and where
  /// the hole spans along the shaft's axis (mm from the shaft's origin, lo <= hi).
  struct HubOnShaft {
    const WorldFeature& s;
    const WorldFeature& h;
    double lo = 0.0, hi = 0.0;
  };
  /// `p` as a hub on a shaft, if it is one.
  std::optional<HubOnShaft> AsHubOnShaft(const Pair& p) const;

  // ---- overrides and side effects (recognition_side_effects.cpp; the order of the
  // pairs in pair_recognition.cpp) ----

  std::size_t Index(FeatureRef ref) const { return assembly_.FeatureIndex(ref); }
  const WorldFeature& At(FeatureRef ref) const { return features_[Index(ref)]; }

  static bool SameFeatures(const Pair& p, FeatureRef f, FeatureRef g) {
    return (p.a == f && p.b == g) || (p.a == g && p.b == f);
  }

  void ApplyOverrides();

  /// Implied pins (README, "Real CAD exports"): a revolute pair between two holes of two
  /// parts that are collinear, of diameters within kMaxImpliedPinDifference, overlapping or at
  /// most kMaxImpliedPinGap apart along the axis (a diameter when no other part's shaft or
  /// thread runs along them), when no shaft or thread sits in either and no rolling bearing
  /// joins the two parts: the hinge of two parts whose pin or screw the CAD file leaves out.
  /// Before the overrides, so that an override forbids or replaces one as any pair.
  void AddImpliedPins();

  /// Loose fits: a shaft more than kMaxShaftClearance but at most kMaxLooseClearance of the
  /// hole's diameter smaller, collinear and engaged, makes its pair (source `loose_fit`) when
  /// one of the two parts is in no other pair but face contacts: nothing else guides it, so
  /// the fit does (a print-in-place hinge; a washer on a shaft between two faces). Revolute
  /// when shafts of one part enter the hole from both ends (a knuckle between two pin stubs
  /// cannot slide off them). After the implied pins, before the overrides.
  void AddLooseFits();

  /// Pins in holes (pair `pins_in_holes`, README "Real CAD exports"): three or more shafts of
  /// one part, of one diameter and parallel, on a circle across their axes, each in a hole of
  /// another part, all holes of one larger diameter, parallel, overlapping the pins along the
  /// axis, each pin's axis off its hole's by the radial clearance (touching the wall), the same
  /// offset for every pin: the holes' part keeps the pins' part's orientation about the axis
  /// while it orbits (a cycloidal reducer's disc and its output). One coupling per two parts,
  /// between the first pin and its hole, and one info `pins_in_holes`. After the loose fits,
  /// before the overrides.
  void AddPinsInHoles();

  /// One info diagnostic `loose_fit` per two parts that loose fits join, naming the features
  /// and the radial clearance.
  void ReportLooseFits();

  /// One info diagnostic `one_part` per CAD part whose bodies the one_part pairs hold together.
  void ReportOneParts();

  /// Compliant parts (springs, belts, hoses) join no pair: the pairs their features would make
  /// are dropped, and one info diagnostic `compliant_part` per such part names the parts it
  /// touches (those pairs' other parts). Before the overrides, which may still force a pair.
  void SetCompliantPartsApart();

  /// Settles the implied pins left after the overrides, per two parts they join: holes on one
  /// pin (parallel, each one's middle nearer the other's axis than the two pins' radii: out of
  /// line on one rod rather than two pins side by side) are a hinge (revolute pairs); two or
  /// more pins (parallel ones apart, or crossing) let neither part turn, and become one fixed
  /// pair, on the holes whose names sort first. One info diagnostic `implied_pin` per two parts
  /// names the holes and each pin's diameter (its smallest hole's).
  void SettleImpliedPins();

  /// The tapped hole or nut each tight thread is fixed in, the first by name when there are
  /// several (not the first found, which depends on the broad phase), by thread.
  std::vector<Screwed> TightThreads();

  /// The tapped hole or nut the thread of FeatureIndex `thread` is fixed in, if it is tight.
  static const FeatureRef* ScrewedInto(const std::vector<Screwed>& screwed, std::size_t thread);

  /// The (thread FeatureIndex, part) of clearance holes a tight thread passes without clamping
  /// their part: a part that no chain of face contacts across the thread's axis, among the
  /// parts it passes, joins to the thread's own part (the head) or to a part it is fixed in (a
  /// nut; a rod has one at each end): a lever between the lugs of a clevis turns on the bolt
  /// that clamps the lugs. When neither head nor nut has such a contact (faces not
  /// recognised), none: it clamps them all.
  std::set<std::pair<std::size_t, std::size_t>> UnclampedParts(
      const std::vector<Screwed>& screwed) const;

  /// A tight thread fixed in a nut or tapped hole clamps the parts of its clearance holes,
  /// except those in `unclamped` (UnclampedParts).
  void ApplyClamp(Pair& p, const std::vector<Screwed>& screwed,
                  const std::set<std::pair<std::size_t, std::size_t>>& unclamped) const;

  /// A tight thread in a tapped hole whose tip bears on a third part's shaft fixes the shaft.
  void ApplySetscrews(const std::vector<Screwed>& screwed);

  /// A part that a tight thread's clamp stack (its own part, the parts it is fixed in and the
  /// parts it clamps) presses from both sides along the thread's axis is clamped too, though
  /// the thread does not pass through a hole of it: a plate between a bolt's head and a
  /// spacer whose boss fills the plate's hole, the bolt running through the boss. Its face
  /// contact with the stack on the side of +axis (the first by feature names) becomes fixed,
  /// source clamp; repeated until no part is added (a stack of such plates). The seat of a
  /// one-solid bearing whose bore is clamped touches the bearing's outer ring, which turns
  /// with it: no clamp. After ReportSolidBearings.
  void ClampSandwichedParts();

  /// Embedded parts (README, "Real CAD exports"): a non-ground, rigid part in no pair whose
  /// mesh penetrates another part's deeper than the length tolerance (MeasureContact: a
  /// connector sunk into a motor's end cap, an insert) is fixed to the part it goes deepest
  /// into (source `embedded`), on the two features nearest the deepest point, with one info
  /// `embedded` per host part. Off when the file's `infer` turns `embedded_parts` off.
  void FixEmbeddedParts();

  /// One warning `part_unconnected` naming every non-ground, rigid part in no pair (the nine
  /// balls of a bearing are one finding, not nine).
  void ReportUnconnected();

  /// A pair's place in the order of the pairs, and its index as found.
  struct SortKey {
    std::uint64_t names_and_source;
    std::size_t pair;
  };
  static constexpr int kSourceBits = 4;
  static_assert(static_cast<int>(PairSource::kInferred) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kImpliedPin) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kBearing) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kLooseFit) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kShaftFlat) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kImpliedFrame) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kSeated) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kSetscrewHole) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kBearingShaft) < (1 << kSourceBits));
  static_assert(static_cast<int>(PairSource::kCentred) < (1 << kSourceBits));

  /// Pairs order by feature names, then source, then as found, not by indices, so that
  /// reordering the file changes nothing: the name ranks and the source packed in one key.
  std::uint64_t Key(const Pair& p) const;

  /// The pairs in the order of their keys: a radix sort, linear at 100,000 parts.
  std::vector<Pair> Sorted();

  const Assembly& assembly_;
  const std::span<const RigidTransform> X_WP_;  ///< the poses recognised at, one per part
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
  /// A bearing of one solid (AddSolidBearings): its outside and bore, the parts it is fitted
  /// in and those turning in its bore (part indices).
  struct SolidBearing {
    FeatureRef outside, bore;
    std::set<std::size_t> seats, turning;
    /// Its bore clamped by a bolt, its seats turning on it (ReportSolidBearings).
    bool clamped = false;
  };
  std::vector<SolidBearing> solid_bearings_;
  /// Per rolling bearing recognised (AddBearings): its rings', elements' and cages' parts,
  /// ascending (Recognition::bearings).
  std::vector<std::vector<std::size_t>> bearings_;
  std::vector<Diagnostic> diagnostics_;
  /// (thread, shaft) feature pairs whose reach boxes overlap: possible setscrew contacts.
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> setscrew_candidates_;
  /// Hole pairs whose reach boxes overlap: possible implied pins.
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> hole_candidates_;
  /// (shaft, hole) pairs of different parts whose reach boxes overlap, the hole larger and
  /// parallel, the shaft's axis inside it off its axis: possible pins in holes.
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> pin_hole_candidates_;
  /// (shaft, hole) pairs too loose to touch: possible loose fits.
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> loose_candidates_;
};

}  // namespace mechanist::internal
