#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace mechanist::testing {

/// Writes a STEP file (AP214, no product names) of three solids built with Open CASCADE, whose
/// faces the tests know by construction:
/// - a 40 x 40 x 10 mm block (corner at the origin) with a 6 mm through hole along z at
///   (20, 20), countersunk 90 degrees to 12 mm at its top (the cone from z = 7 up);
/// - a 5 mm shaft along z at (60, 20) from z = 20 to 40 with a conical point of 5 mm below it
///   (included angle 2 atan(2.5 / 5));
/// - a 10 mm ball at (0, 60, 5).
/// Throws std::runtime_error when it cannot write the file.
void WriteConesAndBallStep(const std::filesystem::path& file);

/// Writes a STEP file (AP214, no product names) of a ball joint's cup: a 20 mm cube (corner at
/// the origin) with a spherical socket of `diameter` mm whose centre lies 2 mm below the middle
/// of its top face, so that it holds more than half a ball. Throws std::runtime_error when it
/// cannot write the file.
void WriteSocketBlockStep(const std::filesystem::path& file, double diameter);

/// Writes a STEP file (AP214, no product names) of two external spur gears as a CAD system
/// exports them, meshed along x: `teeth_a` teeth about the z axis and `teeth_b` about
/// (m (z_a + z_b) / 2, 0), module `module`, 20 degrees pressure angle, addendum m, dedendum
/// 1.25 m, 10 mm face width from z = 0, each with a bore of 0.3 times its pitch diameter. The
/// tooth outline is drawn with B-spline curves (each involute flank interpolated through 12
/// points; the tip and root arcs likewise), so that the flanks are free-form faces, and gear b
/// is turned by half a tooth so that the teeth mesh. Throws std::runtime_error when it cannot
/// write the file.
void WriteSpurGearPairStep(const std::filesystem::path& file, int teeth_a, int teeth_b,
                           double module);

/// As WriteSpurGearPairStep for helical gears of normal module `module`: gear a of helix angle
/// `helix` (radians, positive right-hand), gear b of the opposite hand, at the transverse
/// centre distance m (z_a + z_b) / (2 cos(helix)). Each gear is a loft through its transverse
/// outline at five heights, so that its flanks are B-spline surfaces twisted along the helix.
/// Throws std::runtime_error when it cannot build or write.
void WriteHelicalGearPairStep(const std::filesystem::path& file, int teeth_a, int teeth_b,
                              double module, double helix);

/// Writes a STEP file (AP214, no product names) of a cylindrical worm and its wheel: the worm
/// of `starts` threads of axial module `module`, hand right or left, pitch diameter 10 m,
/// addendum m, dedendum 1.25 m, flanks at 20 degrees in the axial section, 6 pi m long along
/// +x, centred over the wheel's face width at z = 5 and at y = -m (10 + z_wheel) / 2; the wheel
/// a spur gear of `wheel_teeth` teeth and module `module` about +z (as in
/// WriteSpurGearPairStep, straight teeth: a test fixture, not a meshing worm wheel). The worm
/// is a ruled loft (B-spline faces) through its transverse section at 32 heights per lead.
/// Throws std::runtime_error when it cannot build or write.
void WriteWormAndWheelStep(const std::filesystem::path& file, int starts, bool right,
                           int wheel_teeth, double module);

/// Writes a STEP file (AP214, no product names) of two bevel gears of module `module` (at the
/// heel) on shafts at right angles, their pitch cones' apex at the origin: `teeth_a` teeth
/// about +z, `teeth_b` about +x, pitch angles atan(z_a / z_b) and atan(z_b / z_a), spiral
/// angles `spiral_a` and `spiral_b` (radians, positive for a right hand: the teeth turn about
/// the axis the right-hand way going away from the apex; opposite hands mesh). Each is a loft
/// (B-spline faces) of its outline at the heel, a spur gear's of the same teeth and module
/// (addendum m, dedendum 1.25 m) in the plane across its axis at the outer cone distance
/// L = m z / (2 sin(pitch angle)), scaled toward the apex down to L - L / 3 (face width L / 3):
/// straight, a ruled loft of the two; spiral, a smooth one through sections turned so that the
/// teeth keep the spiral angle along the pitch cone. A bore of 0.3 times the toe's pitch
/// diameter. Throws std::runtime_error when it cannot build or write.
void WriteBevelGearPairStep(const std::filesystem::path& file, int teeth_a, int teeth_b,
                            double module, double spiral_a = 0.0, double spiral_b = 0.0);

/// Writes a STEP file (AP214, no product names) of a housing with a ring gear cut into it and
/// a pinion inside: a block of 2.5 m (z_ring + 10) square, 10 mm thick from z = 0, centred on
/// the z axis, with 4 bolt holes of 0.6 m z_ring / 4 near its corners and the ring gear's tooth
/// spaces (`ring_teeth` teeth of module `module`, tips 1 m inside the pitch circle, roots 1.25 m
/// outside, as B-spline curves) cut through it; a spur gear of `pinion_teeth` as
/// WriteSpurGearPairStep draws it at m (z_ring - z_pinion) / 2 along x. Throws
/// std::runtime_error when it cannot build or write.
void WriteRingGearHousingStep(const std::filesystem::path& file, int ring_teeth, int pinion_teeth,
                              double module);

/// Writes a STEP file (AP214, no product names) of a rack and pinion as a CAD system exports
/// them: a straight rack of `rack_teeth` teeth along +x from x = 0 (20 degree flanks, pitch
/// line y = 0, teeth toward +y, 10 mm face width from z = 0, all faces planes) and a spur gear
/// of `pinion_teeth` as WriteSpurGearPairStep draws it, its axis along z through the rack's
/// middle at y = m z / 2. Throws std::runtime_error when it cannot write.
void WriteRackAndPinionStep(const std::filesystem::path& file, int pinion_teeth, double module,
                            int rack_teeth);

/// Writes a STEP file (AP214, no product names) of a deep-groove ball bearing with a 6002's
/// dimensions as a vendor's model has it, axis z, mid-plane z = 0: an inner ring (bore 15 mm,
/// land 20.5 mm), an outer ring (land 26.7 mm, outside 32 mm), both 9 mm wide with a toroidal
/// raceway of radius 0.52 times the ball's about the 23.5 mm pitch circle, and `balls` balls of
/// 4.762 mm on that circle, each a solid of its own; `copies` such bearings side by side, the
/// k-th (from 0) moved 9 k mm along z; with `cage`, each with a cage between the lands (a
/// ring 21.2 to 25.8 mm across from z = -3 to 3, with a 5 mm pocket at each ball). Throws
/// std::runtime_error when it cannot write.
void WriteBallBearingStep(const std::filesystem::path& file, int balls, int copies = 1,
                          bool cage = false);

/// Writes a STEP file (AP214, no product names) of the 6002 of WriteBallBearingStep in three
/// solids, as vendors often give it: the inner ring, the outer ring, and its 9 balls fused with
/// a cage (a ring 22 to 25 mm across from z = -1.5 to 1.5 through their middles) into one
/// solid. Throws std::runtime_error when it cannot write.
void WriteThreeSolidBallBearingStep(const std::filesystem::path& file);

/// Writes a STEP file (AP214, no product names) of a cylindrical roller bearing (an NU type,
/// 25 x 52 x 15 mm), axis z, mid-plane z = 0: an inner ring (bore 25 mm, raceway 32 mm), an
/// outer ring (raceway 45 mm between two 3 mm flanges of bore 39 mm, outside 52 mm), and 13
/// rollers of 6.5 x 8 mm on a 38.5 mm pitch circle, each a solid of its own. Throws
/// std::runtime_error when it cannot write.
void WriteRollerBearingStep(const std::filesystem::path& file);

/// What WriteTaperedRollerBearingStep adds to or changes in its bearing.
struct TaperedRollerBearingOptions {
  /// A cage: a conical band 1.6 mm thick across the rollers' pitch cone from z = -6.5 to 6.5
  /// (flat ends), with a window 0.3 mm wider than each roller all round.
  bool cage = false;
  /// Each roller's large end a spherical cap about the apex through the end's rim (0.08 mm
  /// high), as it bears on the rib of a real bearing's cone: one flat end only.
  bool domed_rollers = false;
  /// No inner ring: its raceway and rib cut into a 25 mm shaft from z = -30 to 30, with a 5 mm
  /// centre hole 10 mm deep in its end at z = 30.
  bool raceway_on_shaft = false;
};

/// Writes a STEP file (AP214, no product names) of a tapered roller bearing (a 30205's bore
/// and outside, 25 x 52 x 16 mm), axis z, each part a solid of revolution: an inner ring
/// (cone) from z = -8 to 8 with a 25 mm bore, a conical raceway of half-angle 12.5 deg and a
/// 38 mm rib at its large end; an outer ring (cup) from z = -7 to 5.5 with a conical raceway
/// of half-angle 17.5 deg and a 52 mm outside; and 15 tapered rollers 12 mm long with flat
/// ends, half-angle 2.5 deg, their axes at 15 deg to z, their mid-points on a 39 mm pitch
/// circle in z = 0. The rollers' and raceways' cones share their apex on the axis (z =
/// -72.775), as in every tapered roller bearing. `options` add a cage, domed rollers, or put
/// the raceway on a shaft. Throws std::runtime_error when it cannot write.
void WriteTaperedRollerBearingStep(const std::filesystem::path& file,
                                   const TaperedRollerBearingOptions& options = {});

/// Writes a STEP file (AP214, no product names) of a double-row deep-groove ball bearing
/// (25 x 52 x 20 mm), axis z: an inner ring (bore 25 mm, lands 35 mm) and an outer ring
/// (lands 42 mm, outside 52 mm) from z = -10 to 10, each with two toroidal raceways of radius
/// 0.52 times the ball's about the 38.5 mm pitch circle in z = -4.5 and 4.5, and 12 balls of
/// 7.144 mm in each row, each a solid of its own. Throws std::runtime_error when it cannot
/// write.
void WriteDoubleRowBallBearingStep(const std::filesystem::path& file);

/// Writes a STEP file (AP214, no product names) of a spherical roller bearing (a 22205's
/// bore, outside and width, 25 x 52 x 18 mm), axis z: an inner ring (bore 25 mm, outside
/// 30.6 mm) and an outer ring (outside 52 mm, a spherical raceway of radius 23.5 mm about the
/// origin) from z = -9 to 9, and two rows of 14 barrel rollers 7 mm long (6 mm flat ends,
/// 6.5 mm at the middle) whose centres lie on a 39 mm pitch circle at z = +-19.5 tan 13 deg,
/// their axes at 13 deg to z in the plane through z, square to the line from the origin to
/// their centres. With `guide_ring`, a ring between the rows too (20.5 to 22.5 mm in radius,
/// from z = -0.8 to 0.8), as E-type bearings have. Throws std::runtime_error when it cannot
/// write.
void WriteSphericalRollerBearingStep(const std::filesystem::path& file, bool guide_ring = false);

/// Writes a STEP file (AP214, no product names) of a self-aligning ball bearing (a 1205's bore,
/// outside and width, 25 x 52 x 15 mm), axis z: an inner ring (bore 25 mm, lands 34 mm) with
/// two toroidal raceways of radius 0.52 times the ball's about the 38.5 mm pitch circle in
/// z = -3.6 and 3.6, an outer ring (outside 52 mm) whose raceway is one sphere about the
/// origin touching every ball, both from z = -7.5 to 7.5, and 13 balls of 7.144 mm in each
/// row, the rows staggered by half a ball's spacing, each ball a solid of its own. Throws
/// std::runtime_error when it cannot write.
void WriteSelfAligningBallBearingStep(const std::filesystem::path& file);

/// Writes a STEP file (AP214, no product names) of a thrust ball bearing (a 51105, 25 x 42 x
/// 11 mm), axis z: a shaft washer (bore 25 mm, outside 42 mm) from z = -5.5 to -1.5 and a
/// housing washer (bore 27 mm, outside 42 mm) from z = 1.5 to 5.5, each with a toroidal
/// groove of radius 0.53 times the ball's about the 33.5 mm pitch circle in z = 0, and 12
/// balls of 6.35 mm on that circle, each a solid of its own; with `cage`, a flat ring cage
/// between the washers (25.8 to 41 mm across, z = -1 to 1, a 6.6 mm pocket at each ball).
/// Throws std::runtime_error when it cannot write.
void WriteThrustBallBearingStep(const std::filesystem::path& file, bool cage = false);

/// Writes a STEP file (AP214, no product names) of a needle bearing without an inner ring on
/// its shaft, axis z: a 12 mm shaft from z = -20 to 20, a drawn cup (bore 16 mm, outside 19 mm,
/// from z = -6 to 6) and 18 needles of 2 x 10 mm on a 14 mm pitch circle, each a solid of its
/// own. Throws std::runtime_error when it cannot write.
void WriteNeedleBearingStep(const std::filesystem::path& file);

/// Writes a STEP file (AP214, no product names) of three 10 x 20 x 30 mm boxes as damaged
/// exports hold them, each its own solid, corners at x = 0, 50 and 100 (y = z = 0): a sound
/// one; one whose top face (z = 30) is turned over in its shell; one inside out (its shell's
/// faces all turned inwards). Throws std::runtime_error when it cannot write.
void WriteMisorientedBoxesStep(const std::filesystem::path& file);

/// How WriteStepVariant rewrites an assembly, as other exporters would write the same product.
enum class StepVariant {
  kInches,  ///< the product structure and names kept, lengths in inches
  kFlat,    ///< one compound of the solids in their places: no structure, no names
  kNested,  ///< the whole assembly three levels deeper, in unnamed assemblies
  /// the assembly's structure in `out`, each product's shape in a file of its own beside it
  /// (external references by bare file name); every other part file, by name, in inches, the
  /// rest and `out` in millimetres: parts that carry their own units
  kPartFiles,
  /// one file in millimetres whose every other solid's shape representation (by entity
  /// number) declares inches, its lengths rewritten in inches: parts that carry their own
  /// units in one file (Open CASCADE's writer gives one unit per file; this rewrites its text)
  kMixedUnits,
  kAp203,  ///< the product structure and names kept, in AP203 (config control design)
  kAp242,  ///< the product structure and names kept, in AP242 (model based 3D engineering)
};

/// Copies the STEP assembly `in` to `out` written as `variant` says (Open CASCADE's XCAF
/// reader and writer; kPartFiles writes more files beside `out`, and returns their names).
/// Throws std::runtime_error when it cannot read or write.
std::vector<std::string> WriteStepVariant(const std::filesystem::path& in,
                                          const std::filesystem::path& out, StepVariant variant);

/// Writes a STEP file (AP214, no product names) of a puck: a cylinder about z of `radius` and
/// `height` (mm) standing on z = 0, both its circular edges rounded with fillets of `fillet`
/// (tori), and, if `bspline`, every surface converted to a B-spline
/// (BRepBuilderAPI_NurbsConvert). Throws std::runtime_error when it cannot build or write.
void WritePuckStep(const std::filesystem::path& file, double radius, double height, double fillet,
                   bool bspline);

/// Copies the STEP assembly `in` to `out` with every surface of every solid converted to a
/// B-spline (Open CASCADE's BRepBuilderAPI_NurbsConvert), keeping the product structure and
/// names (XCAF reader and writer): a file as some exporters and healing steps write it.
/// Throws std::runtime_error when it cannot read or write.
void WriteNurbsCopy(const std::filesystem::path& in, const std::filesystem::path& out);

/// A STEP file read into Open CASCADE's model (StepData_StepModel), not transferred to shapes.
struct StepModelRead {
  int status = 0;       // the work library's: 0 read, -1 cannot be opened, 1 a syntax error
  std::string written;  // the model written back as Part 21 text (StepData_StepWriter), unless
                        // its global check has fails (Open CASCADE's writer hangs on some)
  int entities = 0;
  std::vector<int> error_entities;    // Open CASCADE's IsErrorEntity
  std::vector<int> unknown_entities;  // IsUnknownEntity
  /// The model's global check and each entity's, as "entity: fail|warning: text" lines.
  std::vector<std::string> checks;
  /// What the reader sent at information gravity and above, and its error reports sent as
  /// traces (those holding "ERR "), which mechanist's import shows.
  std::vector<std::string> messages;
};

/// `file` read by Open CASCADE's own parser (StepSelect_WorkLibrary, StepFile_Read) or, if
/// `mechanist_parser`, by the scanner mechanist reads STEP files with (Part21WorkLibrary).
StepModelRead ReadStepModel(const std::filesystem::path& file, bool mechanist_parser);

}  // namespace mechanist::testing
