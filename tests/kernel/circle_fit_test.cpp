#include "kernel/geometry/circle_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mechanist {
namespace {

TEST(FitCircle, PointsOnACircleGiveItExactly) {
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < 7; ++k) {
    const double a = 0.3 + k * 0.7;  // an arc, unevenly spread
    points.emplace_back(5 + 2.5 * std::cos(a), -3 + 2.5 * std::sin(a));
  }
  const FittedCircle c = FitCircle(points);
  EXPECT_NEAR(c.center.x(), 5, 1e-12);
  EXPECT_NEAR(c.center.y(), -3, 1e-12);
  EXPECT_NEAR(c.radius, 2.5, 1e-12);
  EXPECT_NEAR(c.rms, 0, 1e-12);
}

TEST(FitCircle, TheRmsIsTheDistanceOfPointsOffTheCircle) {
  // A square's corners lie on a circle; its edge midpoints pulled in by 0.1 do not.
  std::vector<Eigen::Vector2d> points = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  const FittedCircle corners = FitCircle(points);
  EXPECT_NEAR(corners.radius, std::sqrt(2.0), 1e-12);
  points.insert(points.end(), {{1.3, 0}, {0, 1.3}, {-1.3, 0}, {0, -1.3}});
  const FittedCircle both = FitCircle(points);
  EXPECT_NEAR(both.center.norm(), 0, 1e-12);  // symmetric
  // Brute force: the rms of the distances from the fitted circle.
  double sum = 0;
  for (const Eigen::Vector2d& p : points) sum += std::pow(p.norm() - both.radius, 2);
  EXPECT_NEAR(both.rms, std::sqrt(sum / points.size()), 1e-12);
  EXPECT_GT(both.rms, 0.01);
}

}  // namespace
}  // namespace mechanist
