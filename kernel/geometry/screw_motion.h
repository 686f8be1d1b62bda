#pragma once

#include <Eigen/Core>

#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// A rigid motion driven by a parameter s (a driver's revolutions or travel): per unit of s,
/// `turns_per_unit` revolutions about the line through point_W along axis_W (right-hand rule)
/// and `travel_per_unit` mm along axis_W. A rotation, a translation, a screw, or no motion.
struct ScrewMotion {
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();  ///< unit
  double turns_per_unit = 0.0;
  double travel_per_unit = 0.0;  ///< mm

  bool still() const { return turns_per_unit == 0.0 && travel_per_unit == 0.0; }
  /// The displacement after s: a pose X_WP at s = 0 becomes At(s) * X_WP.
  RigidTransform At(double s) const;
  /// The largest speed (mm per unit s) of a point at most `radius` mm from the axis:
  /// 2 pi |turns| radius + |travel|.
  double SpeedBound(double radius) const;
};

}  // namespace mechanist
