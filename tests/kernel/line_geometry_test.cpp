#include "kernel/geometry/line_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mechanist {
namespace {

constexpr double kL = 0.05;              // mm
constexpr double kA = 0.5 * M_PI / 180;  // radians

AxisSegment Segment(Eigen::Vector3d origin, Eigen::Vector3d direction, double length) {
  return {origin, direction.normalized(), length};
}

TEST(LineGeometry, AxialOverlapIsTheCommonLengthOrMinusTheGap) {
  const AxisSegment a = Segment({0, 0, 0}, {0, 0, 1}, 10);
  EXPECT_DOUBLE_EQ(AxialOverlap(a, Segment({1, 0, 4}, {0, 0, 1}, 20)), 6.0);
  EXPECT_DOUBLE_EQ(AxialOverlap(a, Segment({0, 0, 15}, {0, 0, -1}, 3)), -2.0);
}

TEST(LineGeometry, AShaftInAHoleIsEngagedOnlyWhenCoaxialOverlappingAndOfTheHolesSense) {
  const AxisSegment hole = Segment({0, 0, 0}, {0, 0, 1}, 10);  // into the material: +z
  EXPECT_TRUE(Engaged(Segment({0, 0, 5}, {0, 0, 1}, 10), hole, false, kL, kA));
  // Touching end to end is not engagement; nor is an overlap within the length tolerance.
  EXPECT_FALSE(Engaged(Segment({0, 0, 10}, {0, 0, 1}, 5), hole, false, kL, kA));
  EXPECT_FALSE(Engaged(Segment({0, 0, 9.97}, {0, 0, 1}, 5), hole, false, kL, kA));
  // Off the axis or tilted, beyond each tolerance.
  EXPECT_FALSE(Engaged(Segment({0.06, 0, 5}, {0, 0, 1}, 10), hole, false, kL, kA));
  EXPECT_TRUE(Engaged(Segment({0.04, 0, 5}, {0, 0, 1}, 10), hole, false, kL, kA));
  const double tilt = 0.6 * M_PI / 180;
  EXPECT_FALSE(
      Engaged(Segment({0, 0, 0.5}, {std::sin(tilt), 0, std::cos(tilt)}, 5), hole, false, kL, kA));
  // A shaft pointing out of a blind hole is reversed; through a through hole either way fits.
  const AxisSegment reversed = Segment({0, 0, 8}, {0, 0, -1}, 10);
  EXPECT_FALSE(Engaged(reversed, hole, false, kL, kA));
  EXPECT_TRUE(Engaged(reversed, hole, true, kL, kA));
}

}  // namespace
}  // namespace mechanist
