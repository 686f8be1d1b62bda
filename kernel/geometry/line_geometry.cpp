#include "kernel/geometry/line_geometry.h"

#include <algorithm>
#include <cmath>

namespace mechanist {

double AngleBetweenLines(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  // atan2 of |u x v| and |u . v| stays accurate for nearly parallel lines, unlike acos.
  return std::atan2(u.cross(v).norm(), std::abs(u.dot(v)));
}

double DistanceToLine(const Eigen::Vector3d& p, const Eigen::Vector3d& origin,
                      const Eigen::Vector3d& direction) {
  const Eigen::Vector3d d = p - origin;
  return (d - d.dot(direction) * direction).norm();
}

LineLineClosest ClosestPointsOfLines(const Eigen::Vector3d& a, const Eigen::Vector3d& u,
                                     const Eigen::Vector3d& b, const Eigen::Vector3d& v) {
  const Eigen::Vector3d w = a - b;
  const double uv = u.dot(v);
  const double denominator = 1.0 - uv * uv;
  LineLineClosest c;
  if (denominator < 1e-14) {
    c.s = 0.0;
    c.t = w.dot(v);
  } else {
    const double uw = u.dot(w), vw = v.dot(w);
    c.s = (uv * vw - uw) / denominator;
    c.t = (vw - uv * uw) / denominator;
  }
  c.distance = ((a + c.s * u) - (b + c.t * v)).norm();
  return c;
}

double AxialOverlap(const AxisSegment& a, const AxisSegment& b) {
  const double b0 = (b.origin - a.origin).dot(a.direction);
  const double b1 = (b.end() - a.origin).dot(a.direction);
  return std::min(a.length, std::max(b0, b1)) - std::max(0.0, std::min(b0, b1));
}

bool Engaged(const AxisSegment& convex, const AxisSegment& concave, bool concave_through,
             double length_tolerance, double angle_tolerance) {
  return AxialOverlap(convex, concave) > length_tolerance &&
         AngleBetweenLines(convex.direction, concave.direction) <= angle_tolerance &&
         DistanceToLine(convex.origin, concave.origin, concave.direction) <= length_tolerance &&
         DistanceToLine(concave.origin, convex.origin, convex.direction) <= length_tolerance &&
         (convex.direction.dot(concave.direction) >= 0 || concave_through);
}

}  // namespace mechanist
