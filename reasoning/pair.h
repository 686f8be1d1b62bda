#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "kernel/assembly/pair_type.h"
#include "kernel/features/feature_ref.h"
#include "reasoning/rational.h"

namespace mechanist {

/// Why a pair exists.
enum class PairSource : std::uint8_t {
  kRecognised,    ///< the features satisfy a row of the recognition table
  kOverride,      ///< forced by the file's `overrides`
  kClamp,         ///< a tight fastener through a clearance hole clamps the hole's part
  kSetscrew,      ///< a tight setscrew's tip bears on a shaft
  kInferred,      ///< the running mechanism's sweep found one part pushing the other along
  kImpliedPin,    ///< two coaxial holes with nothing in them: a pin the CAD file left out
  kBearing,       ///< a rolling bearing's rings, or a rolling element held with its outer ring
  kLooseFit,      ///< a shaft loose in its hole guiding a part that nothing else holds
  kOnePart,       ///< two bodies of one CAD part touching face to face: one piece
  kShaftFlat,     ///< a hub on a shaft's flat (a setscrew or D-bore not modelled)
  kImpliedFrame,  ///< a gear turning on an axle of the frame the file leaves out
  kSeated,        ///< faces that stop a part's only slide within a small play (SeatParts)
  kSetscrewHole,  ///< a hub with an empty radial hole into its bore (a setscrew not modelled)
  kEmbedded,      ///< a part in no other pair, sunk into another part's solid
  kBearingShaft,  ///< a hub held by nothing but a shaft that turns in bearings
  kCentred,       ///< a floating part centred on a wider hole's axis (CentreFloatingParts)
};

/// How a pair is held, where that matters to the user.
enum class PairFastening : std::uint8_t { kNone, kPressFit, kTight, kLoose, kClamp, kSetscrew };

std::string_view ToString(PairSource source);
/// "", "press_fit", "tight", "loose", "clamp", "setscrew".
std::string_view ToString(PairFastening fastening);

/// A kinematic relation between features `a` and `b` of two parts. For recognised pairs `a`
/// is the convex (inserted) feature, the worm, or the pinion; for gear pairs the one listed
/// first in the file.
struct Pair {
  // Ordered by alignment (88 bytes, with 32-bit feature references): an assembly of 100,000
  // parts has about as many pairs, and the analysis reads them several times.
  PairType type = PairType::kFixed;
  PairSource source = PairSource::kRecognised;
  PairFastening fastening = PairFastening::kNone;
  /// worm_gear: true when the wheel cannot drive the worm (lead angle below friction angle).
  bool self_locking = false;
  /// Relative degrees of freedom; empty for couplings (gear, worm_gear, rack_pinion,
  /// cycloidal).
  std::optional<int> dof;
  FeatureRef a, b;
  /// gear, worm_gear and cycloidal: b's angular rate about b's feature axis per unit rate of a
  /// about a's feature axis, relative to the body that carries both axes (exact).
  std::optional<Rational> ratio;
  /// screw: mm a advances along its axis per revolution of a about its axis, relative to b
  /// (positive for right-hand threads). rack_pinion: mm the rack (b) travels along its axis
  /// per revolution of the pinion (a) about its axis.
  std::optional<double> travel_per_revolution;
  /// kClamp and kSetscrew: the fastener's thread that makes the pair.
  std::optional<FeatureRef> via;
};

/// Relative DOF of a pair type (0 fixed ... 3 spherical/planar), empty for couplings.
std::optional<int> DegreesOfFreedom(PairType type);

}  // namespace mechanist
