#include "kernel/geometry/screw_motion.h"

#include <cmath>

namespace mechanist {

namespace {
constexpr double kTwoPi = 6.283185307179586;
}  // namespace

RigidTransform ScrewMotion::At(double s) const {
  if (still()) return RigidTransform();
  return RigidTransform::Translation(s * travel_per_unit * axis_W) *
         RigidTransform::AxisAngleAbout(point_W, axis_W, kTwoPi * turns_per_unit * s);
}

double ScrewMotion::SpeedBound(double radius) const {
  return kTwoPi * std::abs(turns_per_unit) * radius + std::abs(travel_per_unit);
}

}  // namespace mechanist
