// Continuous collision queries: textbook cases with known answers (the public data set is
// checked in tests/io/ccd_data_test.cpp).
#include "kernel/collision/continuous_collision.h"

#include <gtest/gtest.h>

namespace mechanist {
namespace {

using V = Eigen::Vector3d;

TEST(VertexFaceCcd, PointThroughATriangleHitsIt) {
  const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(VertexFaceCcd(V(0.2, 0.2, 1), a, b, c, V(0.2, 0.2, -1), a, b, c), CcdAnswer::kContact);
  // Beside the triangle, or stopping short of it.
  EXPECT_EQ(VertexFaceCcd(V(0.8, 0.8, 1), a, b, c, V(0.8, 0.8, -1), a, b, c), CcdAnswer::kApart);
  EXPECT_EQ(VertexFaceCcd(V(0.2, 0.2, 1), a, b, c, V(0.2, 0.2, 1e-9), a, b, c), CcdAnswer::kApart);
  // Reaching it exactly at t = 1, on its edge.
  EXPECT_EQ(VertexFaceCcd(V(0.5, 0, 1), a, b, c, V(0.5, 0, 0), a, b, c), CcdAnswer::kContact);
  // Moving parallel to it above, and sliding in its plane into it.
  EXPECT_EQ(VertexFaceCcd(V(-1, 0.2, 1e-3), a, b, c, V(2, 0.2, 1e-3), a, b, c), CcdAnswer::kApart);
  EXPECT_EQ(VertexFaceCcd(V(-1, 0.2, 0), a, b, c, V(2, 0.2, 0), a, b, c), CcdAnswer::kContact);
  EXPECT_EQ(VertexFaceCcd(V(-1, 2, 0), a, b, c, V(2, 2, 0), a, b, c), CcdAnswer::kApart);
}

TEST(VertexFaceCcd, MovingTriangleSweepsOverAStillPoint) {
  // The triangle moves down through the still point, and turns while it does.
  const V p(0.25, 0.25, 0);
  EXPECT_EQ(VertexFaceCcd(p, V(0, 0, 1), V(1, 0, 1), V(0, 1, 1), p, V(0, 0, -1), V(1, 0, -1),
                          V(0, 1, -1)),
            CcdAnswer::kContact);
  // A triangle tilting about its edge a-c: its plane sweeps a wedge that never reaches the
  // point above it.
  EXPECT_EQ(VertexFaceCcd(V(0.2, 0.2, 1), V(0, 0, 0), V(1, 0, 2), V(0, 1, 0), V(0.2, 0.2, 1),
                          V(0, 0, 0), V(1, 0, -2), V(0, 1, 0)),
            CcdAnswer::kApart);
}

TEST(EdgeEdgeCcd, CrossingEdgesMeetParallelOnesDoNot) {
  // Edge along x at z = 1 moving down through an edge along y at z = 0.
  EXPECT_EQ(EdgeEdgeCcd(V(-1, 0, 1), V(1, 0, 1), V(0, -1, 0), V(0, 1, 0), V(-1, 0, -1), V(1, 0, -1),
                        V(0, -1, 0), V(0, 1, 0)),
            CcdAnswer::kContact);
  // The same, shifted so that the lines cross outside the edges.
  EXPECT_EQ(EdgeEdgeCcd(V(2, 0, 1), V(4, 0, 1), V(0, -1, 0), V(0, 1, 0), V(2, 0, -1), V(4, 0, -1),
                        V(0, -1, 0), V(0, 1, 0)),
            CcdAnswer::kApart);
  // Parallel edges moving toward each other but stopping 1e-9 apart.
  EXPECT_EQ(EdgeEdgeCcd(V(0, 0, 1), V(1, 0, 1), V(0, 0, 0), V(1, 0, 0), V(0, 0, 1e-9),
                        V(1, 0, 1e-9), V(0, 0, 0), V(1, 0, 0)),
            CcdAnswer::kApart);
  // Touching exactly at t = 1 end to end.
  EXPECT_EQ(EdgeEdgeCcd(V(-1, 0, 1), V(0, 0, 1), V(0, 0, 0), V(0, 1, 0), V(-1, 0, 0), V(0, 0, 0),
                        V(0, 0, 0), V(0, 1, 0)),
            CcdAnswer::kContact);
}

TEST(ExactRationalToDouble, AcceptsExactDoublesOnly) {
  EXPECT_EQ(ExactRationalToDouble("3", "4"), 0.75);
  EXPECT_EQ(ExactRationalToDouble("-6993057989032551", "4503599627370496"),
            -6993057989032551.0 / 4503599627370496.0);
  EXPECT_THROW(ExactRationalToDouble("1", "3"), std::invalid_argument);
  EXPECT_THROW(ExactRationalToDouble("1", "0"), std::invalid_argument);
  EXPECT_THROW(ExactRationalToDouble("x", "2"), std::invalid_argument);
}

}  // namespace
}  // namespace mechanist
