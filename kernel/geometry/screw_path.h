#pragma once

#include <Eigen/Core>
#include <vector>

#include "kernel/geometry/rigid_transform.h"
#include "kernel/geometry/screw_motion.h"

namespace mechanist {

/// The finite motion of a part driven by a parameter s: a chain of screw motions, the first
/// about an axis fixed in the world and each next one about an axis carried by the motions
/// before it (a planet turning on its pin while the carrier turns). Every screw is given by
/// its axis at s = 0 and its constant rate per unit s, so the part's displacement after s is
/// S_1(s) S_2(s) ... S_k(s): each joint's motion applied in the frame that its parent has
/// carried. Empty: a still part.
struct ScrewPath {
  std::vector<ScrewMotion> screws;  ///< from the ground outward

  ScrewPath() = default;
  /// A single screw about a fixed axis.
  ScrewPath(const ScrewMotion& single) {  // NOLINT: a fixed-axis motion is a path
    if (!single.still()) screws.push_back(single);
  }

  bool still() const { return screws.empty(); }
  /// The displacement after s: a pose X_WP at s = 0 becomes At(s) * X_WP.
  RigidTransform At(double s) const;
  /// An upper bound on the speed (mm per unit s) of any point of a body that lies, at s = 0,
  /// within the sphere (center_W, radius), for s in [0, s_max]: each screw contributes
  /// 2 pi |turns| times the largest distance a point can have from its (carried) axis, plus
  /// |travel|. The body is rigid, so that distance is at most the centre's, grown by how far
  /// the inner screws can carry the centre (a turn by angle a moves a point r from its axis
  /// along a chord of at most min(2, a) r), plus `radius`.
  double SpeedBound(const Eigen::Vector3d& center_W, double radius, double s_max) const;
};

}  // namespace mechanist
