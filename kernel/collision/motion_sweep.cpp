#include "kernel/collision/motion_sweep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernel/collision/mesh_distance.h"

namespace mechanist {
namespace {

// The bounding sphere of the mesh at X_WM: the centre of its world box and the farthest vertex.
std::pair<Eigen::Vector3d, double> Sphere(const CollisionMesh& mesh, const RigidTransform& X_WM) {
  const Eigen::Vector3d center = X_WM * mesh.bounds().center();
  double radius = 0.0;
  for (const Eigen::Vector3d& v : mesh.mesh().vertices) {
    radius = std::max(radius, (X_WM * v - center).norm());
  }
  return {center, radius};
}

}  // namespace

MotionSweepResult SweepMotion(const CollisionMesh& a, const RigidTransform& X_WA,
                              const ScrewPath& motion_a, const CollisionMesh& b,
                              const RigidTransform& X_WB, const ScrewPath& motion_b, double s_max,
                              double tolerance, std::size_t max_steps) {
  if (!(tolerance > 0.0) || !(s_max >= 0.0) || !std::isfinite(s_max)) {
    throw std::invalid_argument("SweepMotion: need tolerance > 0 and a finite s_max >= 0");
  }
  MotionSweepResult result;
  if (a.mesh().faces.empty() || b.mesh().faces.empty()) return result;
  const auto [center_a, radius_a] = Sphere(a, X_WA);
  const auto [center_b, radius_b] = Sphere(b, X_WB);
  const double speed = motion_a.SpeedBound(center_a, radius_a, s_max) +
                       motion_b.SpeedBound(center_b, radius_b, s_max);
  double s = 0.0;
  for (;;) {
    const double d = SurfaceDistance(
        a, motion_a.At(s) * X_WA, b, motion_b.At(s) * X_WB,
        speed > 0 ? speed * (s_max - s) + tolerance : std::numeric_limits<double>::infinity(),
        &result.p_W);
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
