#include "kernel/geometry/aabb.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace mechanist {
namespace {

/// The box of the eight corners of `box_P` mapped by X_WP, computed independently of
/// TransformBox.
Aabb BoxOfTransformedCorners(const RigidTransform& X_WP, const Aabb& box_P) {
  Aabb box_W;
  for (double x : {box_P.min.x(), box_P.max.x()}) {
    for (double y : {box_P.min.y(), box_P.max.y()}) {
      for (double z : {box_P.min.z(), box_P.max.z()}) box_W.Extend(X_WP * Eigen::Vector3d(x, y, z));
    }
  }
  return box_W;
}

TEST(Aabb, DefaultIsEmpty) {
  const Aabb box;
  EXPECT_TRUE(box.empty());
  EXPECT_EQ(box.size(), Eigen::Vector3d::Zero());
  EXPECT_FALSE(box.Intersects(box));
}

TEST(Aabb, ExtendingAnEmptyBoxByAPointGivesThatPoint) {
  Aabb box;
  const Eigen::Vector3d p(1, -2, 3);
  box.Extend(p);
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.min, p);
  EXPECT_EQ(box.max, p);
  EXPECT_EQ(box.size(), Eigen::Vector3d::Zero());
  EXPECT_EQ(box.center(), p);
  EXPECT_TRUE(box.Intersects(box));
}

TEST(Aabb, ExtendingByAnEmptyBoxChangesNothing) {
  Aabb box;
  box.Extend(Eigen::Vector3d(0, 0, 0));
  box.Extend(Eigen::Vector3d(1, 2, 3));
  const Aabb before = box;
  box.Extend(Aabb());
  EXPECT_EQ(box.min, before.min);
  EXPECT_EQ(box.max, before.max);
  EXPECT_EQ(box.size(), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(box.center(), Eigen::Vector3d(0.5, 1, 1.5));
}

TEST(Aabb, IntersectsWhenOverlappingOrTouching) {
  Aabb a, b, c;
  a.Extend(Eigen::Vector3d(0, 0, 0));
  a.Extend(Eigen::Vector3d(1, 1, 1));
  b.Extend(Eigen::Vector3d(1, 0.5, 0.5));  // touches a's x = 1 face
  b.Extend(Eigen::Vector3d(2, 2, 2));
  c.Extend(Eigen::Vector3d(0, 1.001, 0));  // separated along y only
  c.Extend(Eigen::Vector3d(1, 2, 1));
  EXPECT_TRUE(a.Intersects(b));
  EXPECT_TRUE(b.Intersects(a));
  EXPECT_FALSE(a.Intersects(c));
  EXPECT_FALSE(c.Intersects(a));
  EXPECT_FALSE(a.Intersects(Aabb()));
}

TEST(Aabb, TransformBoxOfAnEmptyBoxIsEmpty) {
  const RigidTransform X =
      RigidTransform::AxisAngleAbout(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 1, 0), 0.5);
  EXPECT_TRUE(TransformBox(X, Aabb()).empty());
}

TEST(Aabb, TransformBoxByIdentityOrTranslation) {
  Aabb box;
  box.Extend(Eigen::Vector3d(-1, 0, 2));
  box.Extend(Eigen::Vector3d(3, 4, 5));
  const Aabb same = TransformBox(RigidTransform(), box);
  EXPECT_EQ(same.min, box.min);
  EXPECT_EQ(same.max, box.max);
  const Aabb moved = TransformBox(RigidTransform::Translation(Eigen::Vector3d(10, 20, 30)), box);
  EXPECT_EQ(moved.min, Eigen::Vector3d(9, 20, 32));
  EXPECT_EQ(moved.max, Eigen::Vector3d(13, 24, 35));
}

TEST(Aabb, TransformBoxContainsTheTransformedCloudAndIsTheCornersBox) {
  std::mt19937 engine(7);
  std::normal_distribution<double> normal;
  auto random_vector = [&](double scale) {
    return Eigen::Vector3d(scale * normal(engine), scale * normal(engine), scale * normal(engine));
  };
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Eigen::Vector3d> cloud_P;
    Aabb box_P;
    for (int i = 0; i < 200; ++i) {
      cloud_P.push_back(random_vector(10.0) + Eigen::Vector3d(5, -3, 1));
      box_P.Extend(cloud_P.back());
    }
    const RigidTransform X_WP = RigidTransform::FromQuaternion(
        Eigen::Quaterniond(normal(engine), normal(engine), normal(engine), normal(engine)),
        random_vector(100.0));
    const Aabb box_W = TransformBox(X_WP, box_P);
    ASSERT_FALSE(box_W.empty());
    for (const Eigen::Vector3d& p_P : cloud_P) {
      const Eigen::Vector3d p_W = X_WP * p_P;
      EXPECT_TRUE((p_W.array() >= box_W.min.array() - 1e-9).all()) << "trial " << trial;
      EXPECT_TRUE((p_W.array() <= box_W.max.array() + 1e-9).all()) << "trial " << trial;
    }
    const Aabb corners_W = BoxOfTransformedCorners(X_WP, box_P);
    EXPECT_LE((box_W.min - corners_W.min).norm(), 1e-9) << "trial " << trial;
    EXPECT_LE((box_W.max - corners_W.max).norm(), 1e-9) << "trial " << trial;
  }
}

}  // namespace
}  // namespace mechanist
