#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "kernel/features/feature.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// A feature found in a mesh, with how well the mesh fits it.
struct RecognizedFeature {
  Feature feature;  ///< in the mesh's frame (mm)
  /// mm: a cylinder's rms distance of its outline's vertices from the fitted circle; a gear's
  /// or rack's difference between the module estimated from its tooth depth (or a rack's
  /// pitch) and the standard module it was rounded to, at the pitch circle or over a tooth.
  double fit_error = 0.0;
  std::string detail;  ///< how it was found, in words
};

/// What RecognizeFeatures found.
struct MeshFeatures {
  /// The extrusion axis (unit, mesh frame): every face lies along it or across it.
  std::optional<Eigen::Vector3d> axis;
  std::vector<RecognizedFeature> features;
  /// The number of sides of a convex polygonal outline of 3 to 8 sides (a hexagonal, square or
  /// rectangular nut's outside), or 0.
  int polygon_sides = 0;
  std::vector<std::string> notes;  ///< what was not recognised, and why
};

/// ISO 54 modules, first and second choice (mm), ascending.
const std::vector<double>& StandardModules();

/// What RecognizeFeatures looks for.
enum class MeshRecognition {
  kAll,    ///< every feature it knows
  kTeeth,  ///< gears, bevel gears, worms, racks and cycloidal discs (and the extrusion axis'
           ///< outlines they are found among)
};

/// Recognises the features of a prismatic part (an extrusion: a spur gear, a ring gear, a
/// rack, a shaft, a plate with holes along one axis) from its mesh alone:
/// - the axis is the eigenvector of the area-weighted normal matrix sum(a n n^T) along or across
///   which 95% or more of the area faces (caps along it, walls across it);
/// - the walls fall into closed outlines (faces sharing vertices); each outline is projected
///   onto the plane across the axis;
/// - an outline whose vertices lie on a circle (Kasa's algebraic fit, rms under 1% of the
///   radius, at least 12 vertices, no gap over 40 degrees) is a cylinder, convex (a shaft) when
///   its walls face away from the centre, concave (a hole, through the part) when they face it;
/// - an outline whose radius about its centre repeats z times around (the largest Fourier
///   coefficient of the radius over 4096 angles, the profile matching itself turned by
///   360/z degrees) with a tooth depth h and tip radius that fit an involute gear
///   (module m = h / 2.25 rounded to the nearest ISO 54 module within 3%, profile shift
///   between -1 and 1.2) is a spur gear, internal when the teeth face the centre;
/// - a convex outline that is long and repeats along its length on one side, with the same
///   module from its pitch (pitch / pi) and its depth, is a rack (teeth toward that side, the
///   pitch line one module below the tips).
/// The walls across every other principal direction and coordinate axis, and across the axis
/// of every cylindrical patch (faces joined across edges where the normals turn by less than
/// 30 degrees whose normals all lie across one direction and turn), are searched for cylinders
/// only: an L-bracket's holes in both legs, a hole drilled at any angle, a part that is no
/// prism. Deterministic.
/// A part that is not prismatic gets a note saying so.
/// With `what` kTeeth, only the toothed and lobed features are looked for: the other
/// directions' cylinders are skipped (what a STEP solid's exact faces already give).
MeshFeatures RecognizeFeatures(const TriangleMesh& mesh,
                               MeshRecognition what = MeshRecognition::kAll);

}  // namespace mechanist
