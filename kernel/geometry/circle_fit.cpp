#include "kernel/geometry/circle_fit.h"

#include <algorithm>
#include <cmath>

#include "kernel/solvers/linear_algebra.h"

namespace mechanist {

FittedCircle FitCircle(std::span<const Eigen::Vector2d> points) {
  Eigen::MatrixXd A(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    A.row(static_cast<Eigen::Index>(i)) << points[i].x(), points[i].y(), 1.0;
    b[static_cast<Eigen::Index>(i)] = -points[i].squaredNorm();
  }
  const Eigen::Vector3d s = LinearLeastSquares(A, b);
  FittedCircle c;
  c.center = Eigen::Vector2d(-s[0] / 2, -s[1] / 2);
  c.radius = std::sqrt(std::max(0.0, c.center.squaredNorm() - s[2]));
  double sum = 0.0;
  for (const Eigen::Vector2d& q : points) sum += std::pow((q - c.center).norm() - c.radius, 2);
  c.rms = std::sqrt(sum / static_cast<double>(points.size()));
  return c;
}

}  // namespace mechanist
