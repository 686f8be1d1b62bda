// The collision kernel on data nobody here wrote: FCL's env and rob meshes
// (../shared/data/fcl), 1,000 random poses against a brute-force exact oracle, and 100
// insertion sweeps of rob through env checked against the static test around each contact.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "io/mesh_reader.h"
#include "kernel/collision/collision_mesh.h"
#include "kernel/collision/mesh_contact.h"
#include "kernel/collision/translational_sweep.h"
#include "kernel/geometry/exact_predicates.h"

namespace mechanist {
namespace {

std::shared_ptr<const CollisionMesh> Load(const char* name) {
  return std::make_shared<CollisionMesh>(std::make_shared<TriangleMesh>(
      ReadMesh(std::string(MECHANIST_SHARED_DATA) + "/fcl/" + name)));
}

// All triangle pairs, exact, with a box test first (it only skips pairs whose boxes are apart,
// which cannot intersect).
bool BruteForce(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                const RigidTransform& X_WB) {
  const auto vb = ExpressVertices(b.mesh(), X_WA.inverse() * X_WB);
  const auto& va = a.mesh().vertices;
  std::vector<Aabb> boxes_b;
  for (const auto& g : b.mesh().faces) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.Extend(vb[g[k]]);
    boxes_b.push_back(box);
  }
  for (const auto& f : a.mesh().faces) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.Extend(va[f[k]]);
    for (std::size_t j = 0; j < boxes_b.size(); ++j) {
      if (!box.Intersects(boxes_b[j])) continue;
      const auto& g = b.mesh().faces[j];
      if (TrianglesIntersect(va[f[0]], va[f[1]], va[f[2]], vb[g[0]], vb[g[1]], vb[g[2]])) {
        return true;
      }
    }
  }
  return false;
}

// The poses of the data's README: translations uniform in [-3000, 3000]^2 x [0, 3000],
// rotations from three uniform Euler angles.
std::vector<RigidTransform> Poses(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> xy(-3000, 3000), z(0, 3000), angle(-M_PI, M_PI);
  std::vector<RigidTransform> poses;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d p(xy(rng), xy(rng), z(rng));
    const double a = angle(rng), b = angle(rng), c = angle(rng);
    poses.push_back(RigidTransform::Translation(p) *
                    RigidTransform::AxisAngle(Eigen::Vector3d::UnitZ(), a) *
                    RigidTransform::AxisAngle(Eigen::Vector3d::UnitY(), b) *
                    RigidTransform::AxisAngle(Eigen::Vector3d::UnitX(), c));
  }
  return poses;
}

TEST(FclMeshes, ThousandPosesAgreeWithBruteForce) {
  const auto env = Load("env.obj");
  const auto rob = Load("rob.obj");
  ASSERT_EQ(env->mesh().faces.size(), 2180u);
  ASSERT_EQ(rob->mesh().faces.size(), 216u);
  int colliding = 0;
  const auto poses = Poses(1000, 2026);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const bool expected = BruteForce(*env, {}, *rob, poses[i]);
    ASSERT_EQ(SurfacesIntersect(*env, {}, *rob, poses[i]), expected) << "pose " << i;
    colliding += expected;
  }
  // The data's README reports about 56% colliding for such poses.
  EXPECT_GT(colliding, 400);
  EXPECT_LT(colliding, 700);
}

TEST(FclMeshes, InsertionSweepsOfRobThroughEnvStopAtTheFirstContact) {
  const auto env = Load("env.obj");
  const auto rob = Load("rob.obj");
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1, 1);
  int swept = 0, contacts = 0;
  for (const RigidTransform& start : Poses(400, 99)) {
    if (swept == 100) break;
    if (SurfacesIntersect(*env, {}, *rob, start)) continue;
    ++swept;
    // Toward the environment's centre, with some spread.
    Eigen::Vector3d d = (env->bounds().center() - start.translation()).normalized() +
                        0.3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    d.normalize();
    SweepOptions options;
    options.max_travel = 6000;
    const auto c = FirstBlockingContact(*rob, start, *env, {}, d, options);
    auto at = [&](double s) { return RigidTransform::Translation(s * d) * start; };
    if (c) {
      ++contacts;
      EXPECT_FALSE(SurfacesIntersect(*env, {}, *rob, at(c->travel - 1e-4))) << swept;
      EXPECT_TRUE(SurfacesIntersect(*env, {}, *rob, at(c->travel + 1e-4))) << swept;
    } else {
      for (int k = 0; k <= 600; ++k) {
        ASSERT_FALSE(SurfacesIntersect(*env, {}, *rob, at(6000.0 * k / 600))) << swept;
      }
    }
  }
  EXPECT_EQ(swept, 100);
  EXPECT_GT(contacts, 30);
}

}  // namespace
}  // namespace mechanist
