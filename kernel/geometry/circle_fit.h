#pragma once

#include <Eigen/Core>
#include <span>

namespace mechanist {

/// A circle fitted to points in a plane.
struct FittedCircle {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0.0;
  double rms = 0.0;  ///< root mean square of the points' distances from the circle
};

/// Kasa's algebraic circle fit (I. Kasa, 1976): x^2 + y^2 + D x + E y + F = 0 by least
/// squares over `points` (at least three, not all on a line, for a meaningful circle; a
/// negative squared radius gives radius 0). Units are the points'.
FittedCircle FitCircle(std::span<const Eigen::Vector2d> points);

}  // namespace mechanist
