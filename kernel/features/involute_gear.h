#pragma once

#include "kernel/geometry/polygon_triangulation.h"

namespace mechanist {

/// The involute function inv(alpha) = tan(alpha) - alpha (radians).
double Involute(double alpha);

/// The outline of a toothed ring of involute teeth about the origin, in the plane: for an
/// external gear its teeth; for an internal (ring) gear the tooth spaces, which have the same
/// shape (space width at the pitch circle equal to the tooth width of the mating gear).
///
/// Every tooth has thickness pi m / 2 along the pitch circle of radius m z / 2 and involute
/// flanks of the base circle r_b = r_p cos(pressure_angle). At a radius r >= r_b its flank
/// lies at the polar angle
///   theta(r) = pi / (2 z) + inv(pressure_angle) - inv(acos(r_b / r))
/// either side of the tooth's centre line. Where the root circle is below the base circle the
/// flank continues radially from the base circle down to the root. Tooth k is centred on the
/// polar angle 2 pi k / z (tooth 0 on +x).
struct InvoluteOutlineSpec {
  int teeth = 0;
  double module = 0.0;          ///< mm
  double pressure_angle = 0.0;  ///< radians
  double addendum = 0.0;        ///< mm: tip circle radius minus pitch radius
  double dedendum = 0.0;        ///< mm: pitch radius minus root circle radius
  /// Largest polar angle (radians) between neighbouring vertices on the tip and root arcs.
  double max_arc_step = 0.0;
  /// Vertices per involute flank, both ends included, evenly spaced in the roll angle
  /// t = sqrt((r / r_b)^2 - 1).
  int flank_points = 8;
};

/// The outline of `spec` as a counter-clockwise ring: per tooth the root corner (if the root is
/// below the base circle), the involute flank, the tip arc, the other flank and the root arc to
/// the next tooth. Throws std::invalid_argument when the teeth would be pointed (the flanks
/// meet below the tip circle), overlap at the root, the root circle is not above the centre,
/// the tip is below the base circle or a parameter is out of range.
Ring2d InvoluteOutline(const InvoluteOutlineSpec& spec);

}  // namespace mechanist
