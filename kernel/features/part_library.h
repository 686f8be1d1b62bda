#pragma once

#include <Eigen/Core>
#include <string>
#include <variant>
#include <vector>

#include "kernel/features/feature.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// Generated standard parts (the seeds' object library). Every generator returns a closed,
/// outward-oriented mesh in the part's own frame and the part's features with fixed ids
/// (documented per spec below). All lengths are millimetres, angles radians. Generators throw
/// std::invalid_argument naming the parameter for non-positive sizes or impossible shapes
/// (a hole larger than its plate, a bore larger than the root circle).
///
/// `segments` is the number of facets of a full circle (0: choose from the size, at least 32).
/// The default is max(32, ceil(pi d / 1 mm)), at most 128, for the circle's diameter d (a gear's
/// tip diameter, a ring gear's outer diameter, a washer's outer diameter, each plate hole's
/// own). Circles are regular polygons inscribed in the circle, first vertex on +x; circular
/// arcs of gear outlines take at most 2 pi / segments per facet. A value of 1 or 2, or
/// negative, is an error. Error messages start with the kind's name: "spur_gear: ...".
///
/// Meshes are single closed shells (a bolt's head and shank included: the bearing face is the
/// hexagon with the shank's circle as a hole), except the L-bracket: two closed shells that
/// touch along z = thickness (see LBracketSpec). Features of kind face have their origin at the
/// face's centre, their axis along the outward normal and width/height the face's extents.

/// A through hole of a plate or bracket leg, at `center` in the face's 2-D coordinates.
struct LibraryHole {
  std::string id;  ///< feature id; empty: "hole1", "hole2", ... in order
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double diameter = 0.0;
};

/// Plate: box x in [-length/2, length/2], y in [-width/2, width/2], z in [0, thickness], with
/// through holes at (x, y). Features: each hole (hole, through, mouth on the top face, axis -z),
/// "top" (face, +z) and "bottom" (face, -z), width = length and height = width. Holes must lie
/// strictly inside the plate and apart from each other; feature ids must be unique.
struct PlateSpec {
  double length = 0.0, width = 0.0, thickness = 0.0;
  std::vector<LibraryHole> holes;
  int segments = 0;
};

/// L-bracket: a base leg x in [0, length], y in [-width/2, width/2], z in [0, thickness] and an
/// upright leg x in [0, thickness], z in [0, height]. Base holes at (x, y), ids "base_hole1"...;
/// upright holes at (y, z), ids "upright_hole1"... (mouth on the inner face x = thickness,
/// axis -x). Faces: "base_bottom" (-z), "base_top" (+z), "upright_outer" (-x),
/// "upright_inner" (+x).
///
/// The mesh is two closed shells touching along z = thickness: the base leg (the corner
/// included) and the upright above it, z in [thickness, height]. So base holes must lie beside
/// the upright (x - d/2 > thickness) and upright holes above the base (z - d/2 > thickness),
/// both strictly inside their leg's face.
struct LBracketSpec {
  double length = 0.0, height = 0.0, width = 0.0, thickness = 0.0;
  std::vector<LibraryHole> base_holes, upright_holes;
  int segments = 0;
};

/// Hex bolt: head z in [-head_height, 0], shank along +z from the head's bearing face (z = 0)
/// to z = length. Features: "thread" (thread, from z = length - thread_length to the tip, axis
/// +z), "shank" (shaft, z in [0, length - thread_length]; only when partly threaded), "head"
/// (face at z = 0, normal +z: the bearing face; width across flats, height across corners).
/// Defaults (0): ISO 4014/4017 head sizes, interpolated linearly between the listed sizes
/// M1.6 .. M36 and scaled in proportion to the nearest listed size outside them; pitch: the
/// ISO 261 coarse pitch of the largest listed nominal diameter not above `diameter` (M1 ..
/// M64). The hexagon's corners are on the x axis. The thread is modelled as a plain cylinder
/// of the nominal diameter; across_flats must exceed it.
struct HexBoltSpec {
  double diameter = 0.0, pitch = 0.0, length = 0.0;
  double thread_length = 0.0;  ///< 0: fully threaded
  double across_flats = 0.0, head_height = 0.0;
  Hand hand = Hand::kRight;
  Fastening fastening = Fastening::kTight;
  int segments = 0;
};

/// Hex nut: z in [0, thickness], across flats in the x-y plane (corners on the x axis), with a
/// plain bore of the nominal diameter. Features: "thread" (tapped hole, through, origin at
/// z = 0, axis +z), "bottom" (face, -z), "top" (face, +z). Default pitch as for HexBoltSpec.
struct HexNutSpec {
  double diameter = 0.0, pitch = 0.0;
  double across_flats = 0.0, thickness = 0.0;  ///< 0: ISO 4032 sizes
  Hand hand = Hand::kRight;
  int segments = 0;
};

/// Washer: annulus z in [0, thickness]. Features: "bore" (hole, through, origin z = 0, axis
/// +z), "bottom" (face, -z), "top" (face, +z).
struct WasherSpec {
  double inner_diameter = 0.0, outer_diameter = 0.0, thickness = 0.0;
  int segments = 0;
};

/// Setscrew: headless threaded cylinder z in [0, length]; the tip is at z = length. Default
/// pitch (0) as for HexBoltSpec.
/// Features: "thread" (thread, origin z = 0, axis +z toward the tip).
struct SetscrewSpec {
  double diameter = 0.0, pitch = 0.0, length = 0.0;
  Hand hand = Hand::kRight;
  Fastening fastening = Fastening::kTight;
  int segments = 0;
};

/// Shaft: cylinder z in [0, length]. Features: "shaft" (shaft, origin z = 0, axis +z).
struct ShaftSpec {
  double diameter = 0.0, length = 0.0;
  bool retained = false;
  int segments = 0;
};

/// Spur gear with involute teeth (pressure angle 20 degrees unless set), z in [0, face_width],
/// axis +z through the origin. Features: "teeth" (gear, origin z = 0, axis +z), "bore" (hole,
/// through; only with a bore).
///
/// Outline (InvoluteOutline in kernel/features/involute_gear.h): addendum 1 m, dedendum 1.25 m,
/// tooth thickness pi m / 2 on the pitch circle, tooth 0 centred on +x; 8 points per involute
/// flank, evenly spaced in the roll angle; a radial flank from the base circle down to a root
/// circle below it (no undercut or fillet). At least 6 teeth; the bore must clear the faceted root
/// circle.
///
/// With a `helix_angle` b (radians, positive right-hand, |b| below 60 degrees) the gear is
/// helical: `module` and `pressure_angle` are the normal ones, the outline is the transverse
/// section's (module m / cos b, pressure angle atan(tan a / cos b), addendum m, dedendum
/// 1.25 m), turned about the axis by z tan(b) / r at height z (r = m teeth / (2 cos b), the
/// pitch radius), sampled in layers that turn by at most a sixteenth of a tooth; the teeth
/// feature carries the helix angle.
struct SpurGearSpec {
  int teeth = 0;
  double module = 0.0, face_width = 0.0;
  double bore_diameter = 0.0;  ///< 0: no bore
  double pressure_angle = 0.3490658503988659;
  int segments = 0;
  double helix_angle = 0.0;  ///< radians, positive right-hand; 0: a spur gear
};

/// Ring (internal) gear: involute tooth spaces cut into a ring of `outer_diameter`, z in
/// [0, face_width]. Features: "teeth" (gear, internal, origin z = 0, axis +z). The tooth spaces
/// are the outline of external teeth 1.25 m high above the pitch circle (the root) with their
/// root circle 1 m below it (the internal teeth's tips), space 0 centred on +x;
/// outer_diameter must clear the root circle.
struct RingGearSpec {
  int teeth = 0;
  double module = 0.0, face_width = 0.0, outer_diameter = 0.0;
  double pressure_angle = 0.3490658503988659;
  int segments = 0;
};

/// Worm: helical thread of `starts` starts, axial module `module`, around +z, z in [0, length].
/// Features: "worm" (worm, origin z = 0, axis +z), "bore" (hole, through; only with a bore).
///
/// Axial section: a trapezoidal thread of axial pitch pi m, thickness pi m / 2 on the pitch
/// line, 20 degree flanks, addendum m and dedendum 1.25 m about pitch_diameter / 2, a thread
/// centred on z = 0 at theta = 0. The surface is r(theta, z) = P(z - lead theta / (2 pi)) with
/// lead = starts pi m (z + lead theta / (2 pi) for a left hand), sampled on a grid of
/// `segments` angles (default: as for a circle of the tip diameter, at least 16 per start) and
/// axial steps of at most lead / segments, with flat end caps.
struct WormSpec {
  int starts = 1;
  double module = 0.0, pitch_diameter = 0.0, length = 0.0;
  double bore_diameter = 0.0;
  Hand hand = Hand::kRight;
  int segments = 0;
};

/// Worm wheel: straight involute teeth of the wheel's module (the throat is not modelled),
/// z in [0, face_width]. Features: "teeth" (worm_wheel, origin z = 0, axis +z), "bore" (only
/// with a bore). Outline as for SpurGearSpec at 20 degrees.
struct WormWheelSpec {
  int teeth = 0;
  double module = 0.0, face_width = 0.0;
  double bore_diameter = 0.0;
  int segments = 0;
};

/// Rack: teeth along +x from x = 0 to x = length, pitch line y = 0, teeth toward +y, body down
/// to y = -height, z in [-face_width/2, face_width/2]. Features: "teeth" (rack, origin 0, axis
/// +x, normal +y). Trapezoidal teeth of pitch pi m: tips at y = m, roots at y = -1.25 m, flanks
/// at the pressure angle crossing the pitch line a quarter pitch from the tooth's centre;
/// tooth k is centred on x = (k + 1/2) pi m, so a tooth space is centred on x = 0. The
/// profile is cut off at x = 0 and x = length.
struct RackSpec {
  double module = 0.0, length = 0.0, face_width = 0.0;
  /// body depth below the pitch line; 0: 2 modules + 2.25 modules (4.25 m); must exceed the
  /// dedendum 1.25 m
  double height = 0.0;
  double pressure_angle = 0.3490658503988659;
};

using LibrarySpec =
    std::variant<PlateSpec, LBracketSpec, HexBoltSpec, HexNutSpec, WasherSpec, SetscrewSpec,
                 ShaftSpec, SpurGearSpec, RingGearSpec, WormSpec, WormWheelSpec, RackSpec>;

/// A generated part: its mesh and features in its own frame.
struct LibraryPart {
  TriangleMesh mesh;
  std::vector<Feature> features;
};

/// Generates the part described by `spec`. Throws std::invalid_argument for bad parameters.
LibraryPart MakeLibraryPart(const LibrarySpec& spec);

/// The format's name of the spec's kind ("spur_gear", "hex_bolt", ...).
std::string LibraryKindName(const LibrarySpec& spec);

}  // namespace mechanist
