#pragma once

#include <cstddef>

#include "kernel/collision/collision_mesh.h"
#include "kernel/geometry/rigid_transform.h"
#include "kernel/geometry/screw_path.h"

namespace mechanist {

/// The outcome of a swept check of two parts.
struct MotionSweepResult {
  enum class Status {
    kClear,     ///< they never come within the tolerance for s in [0, s_max]
    kContact,   ///< they do, first at `s`
    kUndecided  ///< the step budget ran out at `s` (they stayed barely clear for long)
  };
  Status status = Status::kClear;
  double s = 0.0;         ///< driver parameter at the contact (or where the budget ran out)
  double distance = 0.0;  ///< mm between the surfaces at `s`
  /// Contact: the midpoint of the closest points at `s` (world, mm).
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  std::size_t steps = 0;
};

/// Sweeps two parts, each moving along its ScrewPath from its pose at s = 0, over s in
/// [0, s_max], by conservative advancement (Mirtich 1996): at each step the surface distance d
/// (SurfaceDistance) is computed and s advances by (d - tolerance / 2) / v, where v bounds how
/// fast any point of either part moves (ScrewPath::SpeedBound over the part's bounding
/// sphere). No point can close more than d - tolerance / 2 in that step, so the parts never
/// touch unseen: the distance stays above tolerance / 2 between the steps, and a contact is
/// reported at the first step where the distance is at most `tolerance` (before any touch; a
/// brief approach to between tolerance / 2 and tolerance inside a step may pass unreported).
/// The steps shrink where the parts are close and grow where they are far apart (and with
/// the arc's deviation from its chord, through v). A mesh without faces meets nothing.
MotionSweepResult SweepMotion(const CollisionMesh& a, const RigidTransform& X_WA,
                              const ScrewPath& motion_a, const CollisionMesh& b,
                              const RigidTransform& X_WB, const ScrewPath& motion_b, double s_max,
                              double tolerance, std::size_t max_steps = 20000);

}  // namespace mechanist
