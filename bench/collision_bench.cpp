// The collision kernel against FCL (Debian's libfcl-dev, OBBRSS hierarchies; used here only),
// on FCL's own test meshes (../shared/data/fcl): 1,000 random poses of rob against env, every
// answer also checked against a brute-force exact oracle; 100 insertion sweeps of rob through
// env; and the scale case, a synthetic assembly of 1,000 parts and about one million triangles
// checked for interference (broad phase, exact narrow phase, contact measure).
//
// Usage: collision_bench [data_dir]   (default: the repository's ../shared/data)

#include <fcl/fcl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

#include "io/mesh_reader.h"
#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_mesh.h"
#include "kernel/collision/collision_model.h"
#include "kernel/collision/mesh_contact.h"
#include "kernel/collision/translational_sweep.h"
#include "kernel/geometry/exact_predicates.h"
#include "kernel/mesh/mesh_builder.h"
#include "reasoning/interference.h"

namespace mechanist {
namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// The poses of the data's README (as the unit test draws them).
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

bool BruteForce(const CollisionMesh& a, const CollisionMesh& b, const RigidTransform& X_AB) {
  const auto vb = ExpressVertices(b.mesh(), X_AB);
  const auto& va = a.mesh().vertices;
  for (const auto& f : a.mesh().faces) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.Extend(va[f[k]]);
    for (const auto& g : b.mesh().faces) {
      Aabb other;
      for (int k = 0; k < 3; ++k) other.Extend(vb[g[k]]);
      if (box.Intersects(other) &&
          TrianglesIntersect(va[f[0]], va[f[1]], va[f[2]], vb[g[0]], vb[g[1]], vb[g[2]])) {
        return true;
      }
    }
  }
  return false;
}

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> FclModel(const TriangleMesh& mesh) {
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> vertices(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  for (const auto& f : mesh.faces) triangles.emplace_back(f[0], f[1], f[2]);
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  return model;
}

fcl::Transform3d FclPose(const RigidTransform& X) {
  fcl::Transform3d t = fcl::Transform3d::Identity();
  t.linear() = X.rotation();
  t.translation() = X.translation();
  return t;
}

void FclComparison(const std::string& data) {
  const auto env = std::make_shared<CollisionMesh>(
      std::make_shared<TriangleMesh>(ReadMesh(data + "/fcl/env.obj")));
  const auto rob = std::make_shared<CollisionMesh>(
      std::make_shared<TriangleMesh>(ReadMesh(data + "/fcl/rob.obj")));
  const auto poses = Poses(1000, 2026);

  const auto fcl_env = FclModel(env->mesh());
  const auto fcl_rob = FclModel(rob->mesh());
  fcl::CollisionObjectd env_object(fcl_env, fcl::Transform3d::Identity());
  fcl::CollisionObjectd rob_object(fcl_rob, fcl::Transform3d::Identity());

  std::vector<char> ours(poses.size()), theirs(poses.size()), truth(poses.size());
  double best_ours = 1e9, best_fcl = 1e9;
  for (int repeat = 0; repeat < 5; ++repeat) {
    auto start = Clock::now();
    for (std::size_t i = 0; i < poses.size(); ++i) {
      ours[i] = SurfacesIntersect(*env, {}, *rob, poses[i]);
    }
    best_ours = std::min(best_ours, Seconds(start));
    start = Clock::now();
    for (std::size_t i = 0; i < poses.size(); ++i) {
      rob_object.setTransform(FclPose(poses[i]));
      fcl::CollisionRequestd request;
      fcl::CollisionResultd result;
      fcl::collide(&env_object, &rob_object, request, result);
      theirs[i] = result.isCollision();
    }
    best_fcl = std::min(best_fcl, Seconds(start));
  }
  const auto start = Clock::now();
  for (std::size_t i = 0; i < poses.size(); ++i) truth[i] = BruteForce(*env, *rob, poses[i]);
  const double brute = Seconds(start);
  int colliding = 0, ours_wrong = 0, fcl_wrong = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    colliding += truth[i];
    ours_wrong += ours[i] != truth[i];
    fcl_wrong += theirs[i] != truth[i];
  }
  std::printf("fcl meshes: %zu poses of rob (216 triangles) against env (2180), %d colliding\n",
              poses.size(), colliding);
  std::printf("  mechanist (exact):   %8.2f us/pose, %d answers differ from brute force\n",
              1e6 * best_ours / poses.size(), ours_wrong);
  std::printf("  FCL 0.7 OBBRSS:      %8.2f us/pose, %d answers differ from brute force\n",
              1e6 * best_fcl / poses.size(), fcl_wrong);
  std::printf("  brute force oracle:  %8.2f us/pose\n", 1e6 * brute / poses.size());
  std::printf("  ratio mechanist / FCL: %.2f (best of 5 runs each)\n", best_ours / best_fcl);

  // Insertion sweeps: rob from a free pose toward env's centre.
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1, 1);
  int swept = 0, contacts = 0, oracle_failures = 0;
  double sweep_time = 0;
  for (const RigidTransform& from : Poses(400, 99)) {
    if (swept == 100) break;
    if (SurfacesIntersect(*env, {}, *rob, from)) continue;
    ++swept;
    Eigen::Vector3d d = (env->bounds().center() - from.translation()).normalized() +
                        0.3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    d.normalize();
    SweepOptions options;
    options.max_travel = 6000;
    const auto t0 = Clock::now();
    const auto c = FirstBlockingContact(*rob, from, *env, {}, d, options);
    sweep_time += Seconds(t0);
    auto at = [&](double s) { return RigidTransform::Translation(s * d) * from; };
    if (c) {
      ++contacts;
      oracle_failures += SurfacesIntersect(*env, {}, *rob, at(c->travel - 1e-4)) ||
                         !SurfacesIntersect(*env, {}, *rob, at(c->travel + 1e-4));
    }
  }
  std::printf(
      "sweeps: %d insertion sweeps of rob through env, %d stop at a contact, %.1f us "
      "per sweep, %d disagree with the static test around the contact\n",
      swept, contacts, 1e6 * sweep_time / swept, oracle_failures);
}

// 1,000 parts of about 1,000 triangles each (a tessellated cylinder), on a 10 x 10 x 10 grid
// with a pitch equal to the diameter: each part touches its neighbours in x and y, and every
// 50th part is shifted so that it penetrates its neighbour.
void Scale() {
  std::vector<Part> parts;
  const double r = 5.0;
  int triangles = 0;
  for (int i = 0; i < 1000; ++i) {
    RadialGrid grid;
    grid.radius = [r](double, double) { return r; };
    grid.angular_segments = 50;
    grid.axial_segments = 9;
    grid.z0 = 0;
    grid.z1 = 9.5;
    Part p;
    p.id = "p" + std::to_string(i);
    auto mesh = std::make_shared<TriangleMesh>(MakeRadialGridSolid(grid));
    triangles += static_cast<int>(mesh->faces.size());
    p.mesh = mesh;
    const double shift = i % 50 == 0 ? 1.0 : 0.0;
    p.X_WP = RigidTransform::Translation(
        {2 * r * (i % 10) + shift, 2 * r * ((i / 10) % 10), 10.0 * (i / 100)});
    parts.push_back(std::move(p));
  }
  AssemblySpec spec;
  spec.name = "scale";
  spec.parts = std::move(parts);
  const Assembly assembly(std::move(spec));
  const auto start = Clock::now();
  const CollisionModel model(assembly);
  const double build = Seconds(start);
  const auto contacts = FindContacts(assembly, InitialState(assembly), model, {});
  const double total = Seconds(start);
  int clashes = 0, touching = 0;
  for (const auto& c : contacts) {
    clashes += c.verdict == ContactVerdict::kClash;
    touching += c.verdict == ContactVerdict::kTouching;
  }
  std::printf(
      "scale: %zu parts, %d triangles: interference in %.2f s (hierarchies %.2f s), "
      "%d clashes, %d touching\n",
      assembly.parts().size(), triangles, total, build, clashes, touching);
}

}  // namespace
}  // namespace mechanist

int main(int argc, char** argv) {
  const std::string data = argc > 1 ? argv[1] : MECHANIST_SHARED_DATA;
  mechanist::FclComparison(data);
  mechanist::Scale();
  return 0;
}
