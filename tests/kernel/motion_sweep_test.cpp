// Surface distance against all triangle pairs, and the conservative-advancement sweep of
// turning parts against the analytic first-contact angle and against dense sampling.
#include "kernel/collision/motion_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "kernel/collision/collision_mesh.h"
#include "kernel/collision/mesh_distance.h"
#include "kernel/geometry/triangle_geometry.h"
#include "kernel/mesh/mesh_builder.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::shared_ptr<const CollisionMesh> Box(double x0, double x1, double y0, double y1, double z0,
                                         double z1) {
  Region2d r;
  r.outer = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  return std::make_shared<CollisionMesh>(std::make_shared<TriangleMesh>(ExtrudeRegion(r, z0, z1)));
}

std::shared_ptr<const CollisionMesh> Post(double radius, int segments) {
  return std::make_shared<CollisionMesh>(std::make_shared<TriangleMesh>(
      ExtrudeRegion({CircleRing({0, 0}, radius, segments), {}}, 0, 20)));
}

// Brute force over all vertex-triangle pairs both ways (exact enough for these convex
// shapes apart: their closest pair always involves a vertex, or an edge pair, checked too).
double BruteDistance(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                     const RigidTransform& X_WB) {
  double best = std::numeric_limits<double>::infinity();
  auto world = [](const CollisionMesh& m, const RigidTransform& X, std::int32_t f) {
    auto t = m.Triangle(f);
    for (auto& v : t) v = X * v;
    return t;
  };
  for (std::int32_t f = 0; f < static_cast<std::int32_t>(a.mesh().faces.size()); ++f) {
    const auto ta = world(a, X_WA, f);
    for (std::int32_t g = 0; g < static_cast<std::int32_t>(b.mesh().faces.size()); ++g) {
      const auto tb = world(b, X_WB, g);
      for (int i = 0; i < 3; ++i) {
        best = std::min(best, (ClosestPointOnTriangle(ta[i], tb[0], tb[1], tb[2]) - ta[i]).norm());
        best = std::min(best, (ClosestPointOnTriangle(tb[i], ta[0], ta[1], ta[2]) - tb[i]).norm());
        // Edge pairs, by fine sampling of one edge against the other triangle.
        for (int k = 0; k <= 20; ++k) {
          const Eigen::Vector3d p = ta[i] + (ta[(i + 1) % 3] - ta[i]) * (k / 20.0);
          best = std::min(best, (ClosestPointOnTriangle(p, tb[0], tb[1], tb[2]) - p).norm());
        }
      }
    }
  }
  return best;
}

TEST(SurfaceDistance, AgreesWithBruteForceOnRandomPoses) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto a = Box(-2, 2, -1, 1, 0, 1);
  const auto b = Post(1, 10);
  for (int i = 0; i < 60; ++i) {
    const RigidTransform X_WB =
        RigidTransform::Translation({6 * u(rng), 6 * u(rng), 6 * u(rng)}) *
        RigidTransform::AxisAngle({u(rng), u(rng), u(rng) + 2}, kPi * u(rng));
    const double d = SurfaceDistance(*a, {}, *b, X_WB);
    const double brute = BruteDistance(*a, {}, *b, X_WB);
    // The sampled edges of the oracle can only overestimate, by at most the sampling step's
    // effect; SurfaceDistance is exact up to rounding and 0 where the surfaces meet.
    EXPECT_LE(d, brute + 1e-9) << i;
    if (d > 0) {
      EXPECT_GE(d, brute - 0.05) << i;
    }
  }
}

// An arm 6 wide turning about z sweeps toward a post 3 in radius at distance 25 on +y: its
// leading side reaches the post when 25 cos(theta) - 3 = 3.
TEST(SweepMotion, TurningArmMeetsThePostWhereTheGeometrySays) {
  const auto arm = Box(0, 35, -3, 3, 10, 14);
  const auto post = Post(3, 64);
  const RigidTransform X_WP = RigidTransform::Translation({0, 25, 5});
  ScrewMotion turn;
  turn.point_W = Eigen::Vector3d::Zero();
  turn.axis_W = Eigen::Vector3d::UnitZ();
  turn.turns_per_unit = 1.0;
  const double tolerance = 0.01;
  const MotionSweepResult r = SweepMotion(*arm, {}, turn, *post, X_WP, {}, 1.0, tolerance);
  ASSERT_EQ(r.status, MotionSweepResult::Status::kContact);
  const double expected = std::acos(6.0 / 25.0) / (2 * kPi);
  // The post is a 64-gon inscribed in its circle: contact comes at most that much later.
  EXPECT_NEAR(r.s, expected, 2e-4);
  EXPECT_LE(r.distance, tolerance);
  // The contact is on the post's surface, on the side facing the arm.
  const Eigen::Vector3d from_post = r.p_W - Eigen::Vector3d(0, 25, r.p_W.z());
  EXPECT_NEAR(from_post.norm(), 3.0, 0.02);
  EXPECT_GT(from_post.x(), 0.0);
  // Nothing was skipped: sampled densely before the contact, the parts stay apart.
  for (int k = 0; k < 400; ++k) {
    const double s = r.s * k / 400.0;
    EXPECT_GT(SurfaceDistance(*arm, turn.At(s), *post, X_WP), 0.5 * tolerance) << s;
  }
  // Turning the other way, the arm comes round to the post's other side: by symmetry about
  // the y axis, half a turn plus the same angle.
  turn.turns_per_unit = -1.0;
  const MotionSweepResult back = SweepMotion(*arm, {}, turn, *post, X_WP, {}, 1.0, tolerance);
  ASSERT_EQ(back.status, MotionSweepResult::Status::kContact);
  EXPECT_NEAR(back.s, 0.5 + expected, 2e-4);
  // Too short a run.
  turn.turns_per_unit = 1.0;
  EXPECT_EQ(SweepMotion(*arm, {}, turn, *post, X_WP, {}, 0.9 * expected, tolerance).status,
            MotionSweepResult::Status::kClear);
}

// The speed bound of a chain of screws holds for every point of the sphere at every s: checked
// by finite differences on random chains (a planet-like two-screw chain, and three screws).
TEST(ScrewPath, SpeedBoundHoldsAlongRandomChains) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 400; ++trial) {
    ScrewPath path;
    const int screws = 1 + trial % 3;
    for (int k = 0; k < screws; ++k) {
      ScrewMotion m;
      // Axes near the body, which is large: where the inner screws swing its far side round.
      m.point_W = 5 * Eigen::Vector3d(u(rng), u(rng), u(rng));
      m.axis_W = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      m.turns_per_unit = 2 * u(rng);
      m.travel_per_unit = 5 * u(rng);
      path.screws.push_back(m);
    }
    const Eigen::Vector3d center = 5 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const double radius = 30.0;
    const double s_max = 1.5;
    const double bound = path.SpeedBound(center, radius, s_max);
    for (int i = 0; i < 50; ++i) {
      const Eigen::Vector3d p0 =
          center + radius * Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
      const double s = s_max * (0.5 + 0.5 * u(rng));
      const double h = 1e-6;
      const double speed = ((path.At(s + h) * p0) - (path.At(s) * p0)).norm() / h;
      EXPECT_LE(speed, bound * (1 + 1e-6)) << "trial " << trial;
    }
  }
}

TEST(SweepMotion, ScrewMotionAdvancesAlongItsAxis) {
  // A block on a screw (one turn per unit, 10 mm travel per turn) rises toward a plate 30 mm
  // above: it arrives after 3 units less its own height.
  const auto block = Box(-1, 1, -1, 1, 0, 2);
  const auto plate = Box(-20, 20, -20, 20, 30, 31);
  ScrewMotion screw;
  screw.turns_per_unit = 1.0;
  screw.travel_per_unit = 10.0;
  const MotionSweepResult r = SweepMotion(*block, {}, screw, *plate, {}, {}, 5.0, 0.01);
  ASSERT_EQ(r.status, MotionSweepResult::Status::kContact);
  EXPECT_NEAR(r.s, 2.8, 0.002);
}

}  // namespace
}  // namespace mechanist
