#include "kernel/geometry/polygon_triangulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mechanist {
namespace {

using Triangles = std::vector<std::array<std::int32_t, 3>>;

constexpr double kPi = std::numbers::pi;

Ring2d Square(double x0, double y0, double size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

Ring2d Circle(double cx, double cy, double r, int n) {
  Ring2d ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    ring.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return ring;
}

// Checks that `triangles` tile the polygon: every triangle counter-clockwise with positive
// area, areas summing to the polygon's, n + 2h - 2 triangles, and the directed edges forming
// exactly the rings (outer counter-clockwise, holes clockwise) plus interior edges used once
// in each direction. Together these rule out overlaps, gaps and cracks.
void ExpectTiles(const Ring2d& outer, const std::vector<Ring2d>& holes,
                 const Triangles& triangles) {
  std::vector<Eigen::Vector2d> points = outer;
  std::vector<std::pair<std::size_t, std::size_t>> ring_ranges = {{0, outer.size()}};
  double expected_area = std::abs(SignedArea(outer));
  for (const Ring2d& hole : holes) {
    ring_ranges.emplace_back(points.size(), hole.size());
    points.insert(points.end(), hole.begin(), hole.end());
    expected_area -= std::abs(SignedArea(hole));
  }
  ASSERT_EQ(triangles.size(), points.size() + 2 * holes.size() - 2);

  double area = 0.0;
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(t[k], 0);
      ASSERT_LT(t[k], static_cast<int>(points.size()));
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
    const Eigen::Vector2d u = points[t[1]] - points[t[0]], v = points[t[2]] - points[t[0]];
    const double twice = u.x() * v.y() - u.y() * v.x();
    EXPECT_GT(twice, 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
    area += twice / 2.0;
  }
  EXPECT_NEAR(area, expected_area, 1e-9 * expected_area);

  // Boundary edges in the region's orientation (interior on the left).
  std::map<std::pair<int, int>, int> boundary;
  for (std::size_t r = 0; r < ring_ranges.size(); ++r) {
    const auto [first, size] = ring_ranges[r];
    const Ring2d ring(points.begin() + first, points.begin() + first + size);
    const bool counter_clockwise = SignedArea(ring) > 0.0;
    const bool keep = (r == 0) == counter_clockwise;
    for (std::size_t i = 0; i < size; ++i) {
      const int a = static_cast<int>(first + i), b = static_cast<int>(first + (i + 1) % size);
      boundary[keep ? std::pair(a, b) : std::pair(b, a)] = 1;
    }
  }
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used twice";
    const bool interior = directed.count({edge.second, edge.first}) > 0;
    EXPECT_NE(interior, boundary.count(edge) > 0)
        << "edge " << edge.first << "-" << edge.second << " is neither boundary nor interior";
  }
  for (const auto& [edge, count] : boundary) {
    EXPECT_EQ(directed.count(edge), 1u) << "boundary edge " << edge.first << "-" << edge.second;
  }
}

TEST(PolygonTriangulation, SquareWithOneHole) {
  const Ring2d outer = Square(0, 0, 10);
  const std::vector<Ring2d> holes = {Circle(5, 5, 2, 32)};
  ExpectTiles(outer, holes, TriangulatePolygon(outer, holes));
}

TEST(PolygonTriangulation, SquareWithTwoHoles) {
  const Ring2d outer = Square(0, 0, 10);
  const std::vector<Ring2d> holes = {Circle(3, 5, 1.5, 24), Square(6, 2, 3)};
  ExpectTiles(outer, holes, TriangulatePolygon(outer, holes));
}

TEST(PolygonTriangulation, SquareWithFiveHoles) {
  // The first two holes share their leftmost x (a tie in the left-to-right order of
  // bridging); the third's leftmost vertex is a corner.
  const Ring2d outer = Square(-10, -10, 20);
  const std::vector<Ring2d> holes = {Circle(-6, -6, 2, 16), Circle(-6, 6, 2, 16), Square(-1, -1, 2),
                                     Square(5, -8, 3), Circle(6, 6, 2.5, 40)};
  ExpectTiles(outer, holes, TriangulatePolygon(outer, holes));
}

TEST(PolygonTriangulation, ConcaveOuterRing) {
  // A comb: five teeth on a bar, many reflex corners.
  Ring2d comb = {{0, 0}, {11, 0}, {11, 5}};
  for (int k = 4; k >= 0; --k) {
    comb.push_back({2.0 * k + 2, 5});
    comb.push_back({2.0 * k + 2, 1});
    comb.push_back({2.0 * k + 1, 1});
    comb.push_back({2.0 * k + 1, 5});
  }
  comb.push_back({0, 5});
  ExpectTiles(comb, {}, TriangulatePolygon(comb, {}));
}

TEST(PolygonTriangulation, ConcaveOuterRingWithHole) {
  // A star with a hole at its centre.
  Ring2d star;
  for (int i = 0; i < 14; ++i) {
    const double a = kPi * i / 7, r = i % 2 == 0 ? 10.0 : 4.0;
    star.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const std::vector<Ring2d> holes = {Circle(0, 0, 2, 20)};
  ExpectTiles(star, holes, TriangulatePolygon(star, holes));
}

TEST(PolygonTriangulation, AcceptsEitherOrientation) {
  Ring2d outer = Square(0, 0, 4);
  Ring2d hole = Circle(2, 2, 1, 12);
  std::reverse(outer.begin(), outer.end());
  std::reverse(hole.begin(), hole.end());
  ExpectTiles(outer, {hole}, TriangulatePolygon(outer, {hole}));
}

TEST(PolygonTriangulation, KeepsCollinearVertices) {
  // Vertices in the middle of straight edges are shared with neighbouring faces in a mesh:
  // they must all be used, without zero-area triangles.
  const Ring2d outer = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {1.5, 2}, {0, 2}, {0, 1}};
  ExpectTiles(outer, {}, TriangulatePolygon(outer, {}));
}

TEST(PolygonTriangulation, NoEdgeThroughAVertex) {
  // A hexagon of 21 across flats with a diamond hole of circumradius 7: the diamond's top
  // vertex lies exactly on the chord between two hexagon corners, so that chord must not
  // become an edge (it would leave a zero-area triangle).
  const double s = 21.0, R = s / std::sqrt(3.0);
  Ring2d hexagon;
  for (int i = 0; i < 6; ++i)
    hexagon.push_back(R * Eigen::Vector2d(std::cos(i * kPi / 3), std::sin(i * kPi / 3)));
  const Ring2d diamond = {{7, 0}, {0, 7}, {-7, 0}, {0, -7}};
  ExpectTiles(hexagon, {diamond}, TriangulatePolygon(hexagon, {diamond}));
}

TEST(PolygonTriangulation, RejectsBadInput) {
  EXPECT_THROW(TriangulatePolygon({{0, 0}, {1, 0}}), std::invalid_argument);
  EXPECT_THROW(TriangulatePolygon({{0, 0}, {1, 0}, {2, 0}}), std::invalid_argument);
  EXPECT_THROW(TriangulatePolygon(Square(0, 0, 1), {Square(5, 5, 1)}), std::invalid_argument);
}

}  // namespace
}  // namespace mechanist
