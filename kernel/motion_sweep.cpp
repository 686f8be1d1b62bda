#include "kernel/motion_sweep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernel/mesh_distance.h"

namespace mechanist {
namespace {

// The largest distance of the mesh's vertices (at X_WM) from the motion's axis, mm.
double Radius(const CollisionMesh& mesh, const RigidTransform& X_WM, const ScrewMotion& m) {
  double r = 0.0;
  for (const Eigen::Vector3d& v : mesh.mesh().vertices) {
    const Eigen::Vector3d d = X_WM * v - m.point_W;
    r = std::max(r, (d - d.dot(m.axis_W) * m.axis_W).norm());
  }
  return r;
}

}  // namespace

MotionSweepResult SweepMotion(const CollisionMesh& a, const RigidTransform& X_WA,
                              const ScrewMotion& motion_a, const CollisionMesh& b,
                              const RigidTransform& X_WB, const ScrewMotion& motion_b, double s_max,
                              double tolerance, std::size_t max_steps) {
  if (!(tolerance > 0.0) || !(s_max >= 0.0) || !std::isfinite(s_max)) {
    throw std::invalid_argument("SweepMotion: need tolerance > 0 and a finite s_max >= 0");
  }
  // Rotation about an axis keeps every point's distance from it, and translation along it
  // too: the bounds hold for the whole motion.
  const double speed = motion_a.SpeedBound(Radius(a, X_WA, motion_a)) +
                       motion_b.SpeedBound(Radius(b, X_WB, motion_b));
  MotionSweepResult result;
  double s = 0.0;
  for (;;) {
    const double d = SurfaceDistance(
        a, motion_a.At(s) * X_WA, b, motion_b.At(s) * X_WB,
        speed > 0 ? speed * (s_max - s) + tolerance : std::numeric_limits<double>::infinity());
    result.s = s;
    result.distance = d;
    ++result.steps;
    if (d <= tolerance) {
      result.status = MotionSweepResult::Status::kContact;
      return result;
    }
    if (speed == 0.0) return result;  // no motion: never closer
    const double step = (d - 0.5 * tolerance) / speed;
    if (s + step > s_max) return result;
    if (result.steps >= max_steps) {
      result.status = MotionSweepResult::Status::kUndecided;
      return result;
    }
    s += step;
  }
}

}  // namespace mechanist
