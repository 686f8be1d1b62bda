#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// The kinds of connection feature of the assembly format (spec, "Features").
enum class FeatureKind : std::uint8_t {
  kShaft,
  kHole,
  kThread,
  kTappedHole,
  kSlot,
  kKey,
  kGear,
  kWorm,
  kWormWheel,
  kRack,
  kBall,
  kSocket,
  kFace,
  kCycloidDisc,  ///< lobed disc of a cycloidal reducer
  kPinRing,      ///< pins on a circle that a cycloid disc rolls inside
  kBevelGear,    ///< straight or spiral bevel gear: `origin` its pitch cone's apex
};

/// The format's spelling of a kind ("tapped_hole").
std::string_view ToString(FeatureKind kind);
/// The kind spelled `name`, or nothing.
std::optional<FeatureKind> ParseFeatureKind(std::string_view name);
/// Every kind's spelling, comma-separated ("shaft, hole, ..."), for messages.
std::string FeatureKindNames();
/// Convex features lead into concave ones: shaft, thread, gear, bevel_gear, worm, worm_wheel,
/// key, ball.
bool IsConvex(FeatureKind kind);
/// Concave features receive convex ones: hole, tapped_hole, slot, socket.
bool IsConcave(FeatureKind kind);

enum class Hand { kRight, kLeft };
enum class Fastening { kTight, kLoose };

/// A feature's axis in some frame: the segment from `origin` along unit `direction` for
/// `length` millimetres.
struct AxisSegment {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;
  double length = 0.0;

  Eigen::Vector3d end() const { return origin + length * direction; }
};

/// A connection feature in its part's frame. Lengths are millimetres, whatever the file's
/// units; parameters a kind does not use keep their defaults. `axis` is a unit vector.
struct Feature {
  std::string id;
  FeatureKind kind = FeatureKind::kShaft;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< p_PO: in part coordinates
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   ///< unit, in part coordinates
  double length = 0.0;    ///< axial extent, mm (depth of a hole, face width of a gear)
  double diameter = 0.0;  ///< mm: shaft, hole, thread major, ball, socket
  double pitch = 0.0;     ///< mm: thread pitch (axial distance between adjacent threads)
  int starts = 1;         ///< thread or worm starts
  Hand hand = Hand::kRight;
  Fastening fastening = Fastening::kTight;
  bool through = false;   ///< hole or tapped hole open at both ends
  bool retained = false;  ///< axially held: a shaft-hole pair becomes revolute
  double width = 0.0;     ///< mm: slot or key width, face extent
  double height = 0.0;    ///< mm: face extent
  double depth = 0.0;     ///< mm: slot depth
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< unit or zero: slot, key, rack
  int teeth = 0;        ///< gear or worm wheel teeth, a cycloid disc's lobes, a pin ring's pins
  double module = 0.0;  ///< mm: gear module (axial module for a worm)
  double pitch_diameter = 0.0;  ///< mm: worm pitch diameter
  bool internal = false;        ///< ring gear
  /// Radians: a gear's helix angle, positive for a right-hand helix; 0 for a spur gear.
  double helix_angle = 0.0;
  double eccentricity = 0.0;  ///< mm: a cycloid disc's offset from the axis it orbits
  double pin_diameter = 0.0;  ///< mm: a pin ring's pins (`diameter` is its pin circle's)
  /// Radians: a bevel gear's pitch cone half-angle, in (0, pi/2]. Its outer cone distance is
  /// module x teeth / (2 sin(pitch_angle)); `length` is the face width along the cone.
  double pitch_angle = 0.0;
  /// Radians: a spiral bevel gear's spiral angle, positive for a right-hand spiral; 0 straight.
  double spiral_angle = 0.0;

  /// mm: a gear's pitch radius, module x teeth / (2 cos(helix_angle)) (the transverse module's
  /// for a helical gear); a worm wheel's or bevel gear's (at its outer end) likewise.
  double PitchRadius() const { return module * teeth / (2.0 * std::cos(helix_angle)); }

  /// mm: a bevel gear's outer cone distance, from the apex along the pitch line to the outer
  /// end of the teeth.
  double OuterConeDistance() const { return module * teeth / (2.0 * std::sin(pitch_angle)); }

  /// The axis segment in world coordinates for the part pose X_WP.
  AxisSegment WorldAxis(const RigidTransform& X_WP) const {
    return {X_WP * origin, X_WP.RotateDirection(axis), length};
  }
  /// The axis segment in part coordinates.
  AxisSegment LocalAxis() const { return {origin, axis, length}; }
};

/// mm: the distance at which two features mesh, in either order: a worm's axis from its
/// wheel's, (pitch_diameter + m z) / 2; a pinion's axis from a rack's pitch line, its pitch
/// radius; two gears' axes, m' (z1 + z2) / 2, or m' |z1 - z2| / 2 for an internal pair, with
/// the first gear's transverse module m' = m / cos(helix). Bevel gears have none (they share
/// an apex).
double MeshCentreDistance(const Feature& a, const Feature& b);

}  // namespace mechanist
