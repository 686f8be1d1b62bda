#pragma once

#include <Eigen/Core>

#include "kernel/features/feature.h"

namespace mechanist {

/// Angle in radians, in [0, pi/2], between the lines with unit directions `u` and `v`
/// (sense ignored).
double AngleBetweenLines(const Eigen::Vector3d& u, const Eigen::Vector3d& v);

/// Distance from point `p` to the infinite line through `origin` with unit `direction`.
double DistanceToLine(const Eigen::Vector3d& p, const Eigen::Vector3d& origin,
                      const Eigen::Vector3d& direction);

/// The closest points of two infinite lines (origins a, b; unit directions u, v):
/// `s` and `t` are the parameters along each line, `distance` the length of the common
/// perpendicular. For parallel lines s = 0 and t is the foot of a's origin on b.
struct LineLineClosest {
  double s = 0.0, t = 0.0;
  double distance = 0.0;
};
LineLineClosest ClosestPointsOfLines(const Eigen::Vector3d& a, const Eigen::Vector3d& u,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& v);

/// Length of the overlap of two axis segments measured along `a`'s direction (each segment's
/// extent projected on a's line); negative when they are apart (minus the gap).
double AxialOverlap(const AxisSegment& a, const AxisSegment& b);

/// Whether a convex feature's axis (a shaft's, a thread's) `convex` lies in a concave one's
/// (a hole's) `concave`: overlapping along the axis by more than `length_tolerance` (mm), at most
/// `angle_tolerance` (radians) apart, each origin within `length_tolerance` of the other's line,
/// and pointing the same way unless the concave feature goes through (a blind hole has a sense).
bool Engaged(const AxisSegment& convex, const AxisSegment& concave, bool concave_through,
             double length_tolerance, double angle_tolerance);

}  // namespace mechanist
