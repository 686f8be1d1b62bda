#include "kernel/geometry/exact_predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <random>

namespace mechanist {
namespace {

using V = Eigen::Vector3d;
using I3 = std::array<std::int64_t, 3>;

// Exact orientation predicates on small integer points (no rounding at all), as an oracle
// independent of CGAL.
std::int64_t Orient(const I3& a, const I3& b, const I3& c, const I3& d) {
  const std::int64_t ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const std::int64_t vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const std::int64_t wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const std::int64_t det =
      ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
  return (det > 0) - (det < 0);
}

using I2 = std::array<std::int64_t, 2>;

std::int64_t Orient2(const I2& a, const I2& b, const I2& c) {
  const std::int64_t det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return (det > 0) - (det < 0);
}

bool OnSegment2(const I2& p, const I2& a, const I2& b) {
  return Orient2(a, b, p) == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

bool Segments2Meet(const I2& p, const I2& q, const I2& a, const I2& b) {
  const std::int64_t o1 = Orient2(p, q, a), o2 = Orient2(p, q, b);
  const std::int64_t o3 = Orient2(a, b, p), o4 = Orient2(a, b, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return OnSegment2(a, p, q) || OnSegment2(b, p, q) || OnSegment2(p, a, b) || OnSegment2(q, a, b);
}

// The closed segment [p, q] (p != q) against the proper closed triangle (a, b, c).
bool OracleMeets(const I3& p, const I3& q, const I3& a, const I3& b, const I3& c) {
  const std::int64_t sp = Orient(a, b, c, p), sq = Orient(a, b, c, q);
  if (sp * sq > 0) return false;
  if (sp != 0 || sq != 0) {
    // The segment reaches the plane: it meets the triangle where its line passes through it.
    const std::int64_t s1 = Orient(p, q, a, b), s2 = Orient(p, q, b, c), s3 = Orient(p, q, c, a);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  }
  // Coplanar: in 2D, dropping the normal's largest coordinate.
  const std::int64_t n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                             (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                             (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
  int drop = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(n[k]) > std::abs(n[drop])) drop = k;
  }
  auto flat = [&](const I3& x) { return I2{x[(drop + 1) % 3], x[(drop + 2) % 3]}; };
  const I2 p2 = flat(p), q2 = flat(q), a2 = flat(a), b2 = flat(b), c2 = flat(c);
  const std::int64_t o1 = Orient2(a2, b2, p2), o2 = Orient2(b2, c2, p2), o3 = Orient2(c2, a2, p2);
  const bool p_inside = (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
  return p_inside || Segments2Meet(p2, q2, a2, b2) || Segments2Meet(p2, q2, b2, c2) ||
         Segments2Meet(p2, q2, c2, a2);
}

V D(const I3& x) { return V(double(x[0]), double(x[1]), double(x[2])); }

TEST(SegmentIntersectsTriangle, AgreesWithExactIntegerOrientationsOnSmallGridPoints) {
  // Coordinates in -2..2 make many touching, coplanar and collinear cases.
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  auto point = [&] { return I3{coordinate(random), coordinate(random), coordinate(random)}; };
  int tried = 0, met = 0, coplanar = 0;
  while (tried < 20000) {
    const I3 p = point(), q = point(), a = point(), b = point(), c = point();
    if (p == q) continue;
    const std::int64_t n_ab_ac[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                                     (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                                     (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    if (n_ab_ac[0] == 0 && n_ab_ac[1] == 0 && n_ab_ac[2] == 0) continue;  // degenerate triangle
    ++tried;
    const bool expected = OracleMeets(p, q, a, b, c);
    met += expected;
    coplanar += Orient(a, b, c, p) == 0 && Orient(a, b, c, q) == 0;
    ASSERT_EQ(SegmentIntersectsTriangle(D(p), D(q), D(a), D(b), D(c)), expected)
        << "p (" << p[0] << " " << p[1] << " " << p[2] << ") q (" << q[0] << " " << q[1] << " "
        << q[2] << ") a (" << a[0] << " " << a[1] << " " << a[2] << ") b (" << b[0] << " " << b[1]
        << " " << b[2] << ") c (" << c[0] << " " << c[1] << " " << c[2] << ")";
  }
  // Both answers and the coplanar branch were exercised.
  EXPECT_GT(met, 2000);
  EXPECT_LT(met, 18000);
  EXPECT_GT(coplanar, 100);
}

TEST(SegmentIntersectsTriangle, AgreesWithTheTriangleTestOnAFlatTriangleAtRandomPoints) {
  // The same question asked as two triangles, (p, q, q) against (a, b, c): points off the grid
  // (so that the plane filter's bound, not exact integers, decides), near-coplanar ones, point
  // segments and degenerate triangles among them.
  std::mt19937 random(9);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  std::uniform_real_distribution<double> jitter(-1e-9, 1e-9);
  std::uniform_int_distribution<int> kind(0, 9);
  auto point = [&] {
    V x(coordinate(random), coordinate(random), coordinate(random));
    x += V(jitter(random), jitter(random), jitter(random)) * (kind(random) < 5 ? 1.0 : 1e6);
    return x;
  };
  int met = 0;
  for (int i = 0; i < 20000; ++i) {
    const V a = point(), b = point(), c = point();
    const V p = point(), q = kind(random) == 0 ? p : point();
    const bool expected = TrianglesIntersect(p, q, q, a, b, c);
    met += expected;
    ASSERT_EQ(SegmentIntersectsTriangle(p, q, a, b, c), expected)
        << "p " << p.transpose() << " q " << q.transpose() << " a " << a.transpose() << " b "
        << b.transpose() << " c " << c.transpose();
  }
  EXPECT_GT(met, 1000);
}

TEST(SegmentIntersectsTriangle, TakesAPointSegmentAndADegenerateTriangle) {
  const V a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // A segment of no length: a point, on the triangle or off it.
  EXPECT_TRUE(SegmentIntersectsTriangle(V(0.5, 0.5, 0), V(0.5, 0.5, 0), a, b, c));
  EXPECT_TRUE(SegmentIntersectsTriangle(V(1, 1, 0), V(1, 1, 0), a, b, c));  // on the edge bc
  EXPECT_FALSE(SegmentIntersectsTriangle(V(1.5, 1.5, 0), V(1.5, 1.5, 0), a, b, c));
  EXPECT_FALSE(SegmentIntersectsTriangle(V(0.5, 0.5, 1), V(0.5, 0.5, 1), a, b, c));
  // A triangle flattened onto a segment is that segment.
  const V e(4, 0, 0);
  EXPECT_TRUE(SegmentIntersectsTriangle(V(1, -1, 0), V(1, 1, 0), a, b, e));
  EXPECT_TRUE(SegmentIntersectsTriangle(V(3, 0, -1), V(3, 0, 1), a, b, e));
  EXPECT_FALSE(SegmentIntersectsTriangle(V(5, -1, 0), V(5, 1, 0), a, b, e));
  EXPECT_FALSE(SegmentIntersectsTriangle(V(1, 1, -1), V(1, 1, 1), a, b, e));
}

}  // namespace
}  // namespace mechanist
