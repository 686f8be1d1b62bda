// Collision kernel: static intersection and contact classification against a brute-force
// oracle over all triangle pairs, analytic depths, and the translational sweep against the
// static test on either side of the contact it reports and, on fine meshes of balls and rods,
// against the travels at which the spheres and cylinders through and inside them touch.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "kernel/collision/broad_phase.h"
#include "kernel/collision/collision_mesh.h"
#include "kernel/collision/collision_mesh_cache.h"
#include "kernel/collision/mesh_contact.h"
#include "kernel/collision/translational_sweep.h"
#include "kernel/geometry/exact_predicates.h"
#include "kernel/mesh/mesh_builder.h"
#include "kernel/mesh/winding_number.h"

namespace mechanist {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::shared_ptr<const CollisionMesh> Box(double x, double y, double z) {
  Region2d r;
  r.outer = {{-x / 2, -y / 2}, {x / 2, -y / 2}, {x / 2, y / 2}, {-x / 2, y / 2}};
  return std::make_shared<CollisionMesh>(
      std::make_shared<TriangleMesh>(ExtrudeRegion(r, -z / 2, z / 2)));
}

std::shared_ptr<const CollisionMesh> Cylinder(double radius, double z0, double z1, int segments,
                                              double phase = 0.0) {
  Region2d r;
  for (int i = 0; i < segments; ++i) {
    const double a = phase + 2 * kPi * i / segments;
    r.outer.push_back({radius * std::cos(a), radius * std::sin(a)});
  }
  return std::make_shared<CollisionMesh>(std::make_shared<TriangleMesh>(ExtrudeRegion(r, z0, z1)));
}

// A plate with a round hole through it (z in [0, t]).
std::shared_ptr<const CollisionMesh> HoledPlate(double size, double t, double radius,
                                                int segments) {
  Region2d r;
  r.outer = {
      {-size / 2, -size / 2}, {size / 2, -size / 2}, {size / 2, size / 2}, {-size / 2, size / 2}};
  r.holes.push_back(CircleRing({0, 0}, radius, segments));
  return std::make_shared<CollisionMesh>(std::make_shared<TriangleMesh>(ExtrudeRegion(r, 0, t)));
}

// The oracle: every triangle pair, exact, on the same coordinates as the contract says.
bool BruteForceIntersect(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                         const RigidTransform& X_WB) {
  const auto vb = ExpressVertices(b.mesh(), X_WA.inverse() * X_WB);
  const auto& va = a.mesh().vertices;
  for (const auto& f : a.mesh().faces) {
    for (const auto& g : b.mesh().faces) {
      if (TrianglesIntersect(va[f[0]], va[f[1]], va[f[2]], vb[g[0]], vb[g[1]], vb[g[2]])) {
        return true;
      }
    }
  }
  return false;
}

RigidTransform RandomPose(std::mt19937& rng, double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d axis(u(rng), u(rng), u(rng) + 1e-3);
  return RigidTransform::Translation(spread * Eigen::Vector3d(u(rng), u(rng), u(rng))) *
         RigidTransform::AxisAngle(axis, kPi * u(rng));
}

TEST(CollisionMesh, ClosedBoxHasConvexEdgesAndContainsItsCentre) {
  const auto box = Box(2, 3, 4);
  EXPECT_TRUE(box->closed());
  EXPECT_TRUE(box->Contains({0.1, 0.2, 0.3}));
  EXPECT_FALSE(box->Contains({1.2, 0, 0}));
  EXPECT_FALSE(box->Contains({1.0, 0.5, 0.5})) << "a point on a face is not inside";
  int convex = 0, flat = 0;
  for (std::size_t e = 0; e < box->edges().size(); ++e) {
    const int c = box->EdgeConvexity(static_cast<std::int32_t>(e));
    convex += c == 1;
    flat += c == 0;
    EXPECT_NE(c, -1);
  }
  EXPECT_EQ(convex, 12);  // the cube's edges; the others are face diagonals
  EXPECT_EQ(flat, static_cast<int>(box->edges().size()) - 12);
  EXPECT_NEAR(box->ClosestPoint({0, 0, 5}).distance, 3.0, 1e-12);
  EXPECT_NEAR(box->ClosestPoint({0.5, 0, 0}).distance, 0.5, 1e-12);
}

TEST(CollisionMesh, HoledPlateContainsMaterialButNotTheHole) {
  const auto plate = HoledPlate(20, 5, 3, 32);
  EXPECT_TRUE(plate->closed());
  EXPECT_FALSE(plate->Contains({0, 0, 2.5}));
  EXPECT_FALSE(plate->Contains({0, 0, 5})) << "in the hole's mouth, on the top face's plane";
  EXPECT_TRUE(plate->Contains({6, 0, 2.5}));
  EXPECT_TRUE(plate->Contains({-9, 9, 0.1}));
}

// A solid that is not closed: a finely meshed ball with one triangle missing (as in a CAD
// tessellation with a crack), which goes to `missing`, and a holed plate, in one mesh.
std::shared_ptr<const CollisionMesh> CrackedSolids(std::array<Eigen::Vector3d, 3>* missing) {
  TriangleMesh ball = MakeUvSphere(10, 60, 120);
  const auto& t = ball.faces[3000];
  *missing = {ball.vertices[t[0]], ball.vertices[t[1]], ball.vertices[t[2]]};
  ball.faces.erase(ball.faces.begin() + 3000);
  Region2d r;
  r.outer = {{-30, -15}, {30, -15}, {30, 15}, {-30, 15}};
  r.holes.push_back(CircleRing({0, 0}, 6, 64));
  ball.Append(ExtrudeRegion(r, 12, 20));
  return std::make_shared<CollisionMesh>(std::make_shared<TriangleMesh>(std::move(ball)));
}

TEST(CollisionMesh, WindingNumberByTheHierarchyStaysWithinItsBoundAndContainsIsExact) {
  // Oracle: the exact sum over every triangle (WindingNumber), at points spread over the box
  // and at points just off the faces (where the inside test of contacts is asked).
  std::array<Eigen::Vector3d, 3> missing;
  const auto solids = CrackedSolids(&missing);
  ASSERT_FALSE(solids->closed());
  ASSERT_TRUE(solids->solid());
  ASSERT_GT(solids->mesh().faces.size(), 14000u);
  std::mt19937 random(3);
  Aabb box = solids->bounds();
  box.min.array() -= 10;
  box.max.array() += 10;
  std::uniform_real_distribution<double> x(box.min.x(), box.max.x()), y(box.min.y(), box.max.y()),
      z(box.min.z(), box.max.z()), side(-0.05, 0.05);
  std::uniform_int_distribution<std::int32_t> face(
      0, static_cast<std::int32_t>(solids->mesh().faces.size()) - 1);
  int inside = 0, estimated = 0;
  double worst_bound = 0.0;
  for (int i = 0; i < 800; ++i) {
    Eigen::Vector3d p(x(random), y(random), z(random));
    if (i % 2) {
      const std::int32_t f = face(random);
      const auto [a, b, c] = solids->Triangle(f);
      p = (a + b + c) / 3.0 + side(random) * solids->face_normals()[f];
    }
    const double exact = WindingNumber(solids->mesh(), p);
    const CollisionMesh::WindingEstimate fast = solids->WindingNumberAt(p);
    EXPECT_LE(std::abs(fast.value - exact), fast.error_bound + 1e-12) << p.transpose();
    worst_bound = std::max(worst_bound, fast.error_bound);
    estimated += fast.error_bound > 0.0;
    EXPECT_EQ(solids->Contains(p), std::abs(exact) >= 0.5) << p.transpose();
    inside += std::abs(exact) >= 0.5;
  }
  EXPECT_GT(estimated, 700);  // the expansions were used
  EXPECT_LT(worst_bound, 0.1);
  EXPECT_GT(inside, 200);  // both answers are asked for
  EXPECT_LT(inside, 600);
  // In the opening the winding number is a half (the rest of a closed surface seen from one
  // of its faces), which no estimate can tell from the threshold: Contains must still give
  // the exact sum's answer.
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 200; ++i) {
    const auto& [a, b, c] = missing;
    double u = unit(random), v = unit(random);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Eigen::Vector3d p = a + u * (b - a) + v * (c - a);
    const double exact = WindingNumber(solids->mesh(), p);
    ASSERT_NEAR(std::abs(exact), 0.5, 1e-9);
    EXPECT_EQ(solids->Contains(p), std::abs(exact) >= 0.5) << p.transpose();
  }
}

TEST(CollisionMeshCache, BuildCachesEachDistinctMeshAndKeepsThoseCachedWhichFindGives) {
  Region2d square;
  square.outer = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<std::shared_ptr<const TriangleMesh>> meshes;
  for (int k = 1; k <= 5; ++k) {
    meshes.push_back(std::make_shared<TriangleMesh>(ExtrudeRegion(square, 0, k)));
  }
  auto open = std::make_shared<TriangleMesh>(*meshes[0]);
  open->faces.pop_back();  // a box with one triangle missing: not closed(), solid() by winding
  meshes.push_back(open);

  CollisionMeshCache cache;
  EXPECT_EQ(cache.Find(meshes[1].get()), nullptr) << "Find builds nothing";
  const CollisionMesh* built_lazily = &cache.Get(meshes[1]);
  EXPECT_EQ(cache.Find(meshes[1].get()), built_lazily);
  EXPECT_EQ(cache.Find(meshes[2].get()), nullptr);
  std::vector<std::shared_ptr<const TriangleMesh>> with_repeats = meshes;
  with_repeats.insert(with_repeats.end(), meshes.begin(), meshes.end());
  EXPECT_EQ(cache.size(), 1u);
  cache.Build(with_repeats);
  EXPECT_EQ(cache.size(), meshes.size()) << "each distinct mesh built once";
  EXPECT_EQ(&cache.Get(meshes[1]), built_lazily) << "a cached mesh is kept, not rebuilt";
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    const CollisionMesh& got = cache.Get(meshes[k]);
    const CollisionMesh direct(meshes[k]);
    EXPECT_EQ(&got.mesh(), meshes[k].get());
    EXPECT_EQ(got.closed(), direct.closed());
    EXPECT_EQ(got.solid(), direct.solid());
    EXPECT_EQ(got.edges().size(), direct.edges().size());
    EXPECT_EQ(got.bounds().max, direct.bounds().max);
    cache.Build({meshes[k]});
    EXPECT_EQ(&cache.Get(meshes[k]), &got);
    EXPECT_EQ(cache.Find(meshes[k].get()), &got);
  }
  EXPECT_TRUE(cache.Get(meshes[4]).closed());
  EXPECT_DOUBLE_EQ(cache.Get(meshes[4]).bounds().max.z(), 5.0);
  EXPECT_FALSE(cache.Get(open).closed());
  EXPECT_TRUE(cache.Get(open).solid());
  EXPECT_EQ(cache.size(), meshes.size());
}

TEST(MeshContact, AgreesWithBruteForceOnRandomPoses) {
  std::mt19937 rng(7);
  const auto a = Box(4, 2, 1);
  const auto b = Cylinder(1, -1, 1, 12);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const RigidTransform X_WA = RandomPose(rng, 1.0), X_WB = RandomPose(rng, 3.0);
    const bool expected = BruteForceIntersect(*a, X_WA, *b, X_WB);
    ASSERT_EQ(SurfacesIntersect(*a, X_WA, *b, X_WB), expected) << "pose " << i;
    hits += expected;
  }
  EXPECT_GT(hits, 40);
  EXPECT_LT(hits, 360);
}

TEST(MeshContact, TouchingConfigurationsAgreeWithBruteForce) {
  // Coincident faces, shared edges and corners: exactly representable poses.
  const auto a = Box(2, 2, 2);
  const std::vector<Eigen::Vector3d> offsets = {{2, 0, 0},   {2, 2, 0},         {2, 2, 2},
                                                {2, 1, 0.5}, {2.0000001, 0, 0}, {1.9999999, 0, 0},
                                                {0, 0, 2},   {1, 1, 2},         {0.5, -0.25, 2}};
  for (const auto& o : offsets) {
    const RigidTransform X_WB = RigidTransform::Translation(o);
    EXPECT_EQ(SurfacesIntersect(*a, {}, *a, X_WB), BruteForceIntersect(*a, {}, *a, X_WB))
        << o.transpose();
  }
  EXPECT_TRUE(SurfacesIntersect(*a, {}, *a, RigidTransform::Translation({2, 0, 0})));
  EXPECT_FALSE(SurfacesIntersect(*a, {}, *a, RigidTransform::Translation({2.0000001, 0, 0})));
}

TEST(MeshContact, FaceContactIsTouchingAndOverlapIsPenetratingByItsDepth) {
  const auto a = Box(2, 2, 2);
  const double tol = 0.05;
  const ContactMeasure touch =
      MeasureContact(*a, {}, *a, RigidTransform::Translation({2, 0, 0}), tol);
  EXPECT_EQ(touch.kind, ContactMeasure::Kind::kTouching);
  EXPECT_LE(touch.depth, 1e-9);

  const ContactMeasure deep =
      MeasureContact(*a, {}, *a, RigidTransform::Translation({1.3, 0.2, 0.1}), tol);
  EXPECT_EQ(deep.kind, ContactMeasure::Kind::kPenetrating);
  // The overlap is 0.7 thick along x: the deepest surface point inside the other box lies
  // 0.7 from its surface (a corner region at most 0.7 deep), never more.
  EXPECT_LE(deep.depth, 0.7 + 1e-9);
  EXPECT_GE(deep.depth, 0.7 - deep.depth_bound - 1e-9);

  const ContactMeasure shallow =
      MeasureContact(*a, {}, *a, RigidTransform::Translation({1.97, 0, 0}), tol);
  EXPECT_EQ(shallow.kind, ContactMeasure::Kind::kTouching) << shallow.depth;
  EXPECT_NEAR(shallow.depth, 0.03, 1e-9);
}

TEST(MeshContact, ContainedPartIsPenetratingEvenWithoutSurfaceContact) {
  const auto big = Box(10, 10, 10);
  const auto small = Box(1, 1, 1);
  const RigidTransform X_WS = RigidTransform::Translation({1, 0.5, 0});
  EXPECT_FALSE(SurfacesIntersect(*big, {}, *small, X_WS));
  const ContactMeasure m = MeasureContact(*big, {}, *small, X_WS, 0.05);
  EXPECT_EQ(m.contained, 2);
  EXPECT_EQ(m.kind, ContactMeasure::Kind::kPenetrating);
  // Deepest vertex of the small box: (-0.5+1, ...) corners; distance to the big box's surface
  // is 5 - max(|x|,|y|,|z|) minimised over axes: the corner (1.5, 1, 0.5) is 3.5 from x = 5;
  // the corner (0.5, 0, -0.5) is 4.5 from the nearest face.
  EXPECT_NEAR(m.depth, 4.5, 1e-9);
  EXPECT_EQ(MeasureContact(*small, X_WS, *big, {}, 0.05).contained, 1);
}

TEST(MeshContact, FacetedPinInHoleOfItsDiameterIsTouching) {
  // Same nominal diameter, different facet counts: the facets cross by r (1 - cos(pi/n)).
  const auto pin = Cylinder(3, -2, 8, 24, 0.1);
  const auto plate = HoledPlate(20, 5, 3, 32);
  const ContactMeasure m = MeasureContact(*pin, {}, *plate, {}, 0.05);
  EXPECT_GT(m.crossing_pairs, 0u);
  EXPECT_EQ(m.kind, ContactMeasure::Kind::kTouching) << m.depth;
  EXPECT_LT(m.depth, 3 * (1 - std::cos(kPi / 24)) + 1e-9);
  // A pin 0.4 mm too large is a penetration of about 0.2 mm.
  const auto fat = Cylinder(3.2, -2, 8, 64);
  const ContactMeasure f = MeasureContact(*fat, {}, *plate, {}, 0.05);
  EXPECT_EQ(f.kind, ContactMeasure::Kind::kPenetrating);
  EXPECT_NEAR(f.depth, 0.2, 0.02);
}

// Boxes [x0, x1] x [y0, y1] x [z0, z1] in one mesh, as a multi-body part exported as one file:
// closed shells that share faces. `soup`: every triangle with its own corners, as in an STL
// file, so that the shells' coincident edges make the mesh not closed by its edges.
// `mesh`'s faces in their order, each with three vertices of its own (a triangle soup).
std::shared_ptr<TriangleMesh> Soup(const TriangleMesh& mesh) {
  auto soup = std::make_shared<TriangleMesh>();
  for (const TriangleMesh::Face& f : mesh.faces) {
    const auto n = static_cast<std::int32_t>(soup->vertices.size());
    for (int k = 0; k < 3; ++k) soup->vertices.push_back(mesh.vertices[f[k]]);
    soup->faces.push_back({n, n + 1, n + 2});
  }
  return soup;
}

std::shared_ptr<const CollisionMesh> Boxes(const std::vector<std::array<double, 6>>& boxes,
                                           bool soup) {
  TriangleMesh shells;
  for (const auto& [x0, x1, y0, y1, z0, z1] : boxes) {
    Region2d r;
    r.outer = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    shells.Append(ExtrudeRegion(r, z0, z1));
  }
  return std::make_shared<CollisionMesh>(soup ? Soup(shells)
                                              : std::make_shared<TriangleMesh>(shells));
}

// A pocket: a floor 1 mm thick and four walls standing on it, each its own box.
std::shared_ptr<const CollisionMesh> Pocket(bool soup) {
  return Boxes({{-5, 5, -5, 5, 0, 1},
                {-5, -4, -5, 5, 1, 4},
                {4, 5, -5, 5, 1, 4},
                {-4, 4, -5, -4, 1, 4},
                {-4, 4, 4, 5, 1, 4}},
               soup);
}

TEST(MeshContact, MultiShellMeshesHaveAnInsideByTheirWindingNumber) {
  for (const bool soup : {false, true}) {
    SCOPED_TRACE(soup ? "a triangle soup" : "shells with their own vertices");
    const auto pocket = Pocket(soup);
    EXPECT_EQ(pocket->closed(), !soup);
    EXPECT_TRUE(pocket->solid());
    EXPECT_TRUE(pocket->Contains({0, 0, 0.5}));   // in the floor
    EXPECT_TRUE(pocket->Contains({-4.5, 0, 2}));  // in a wall, above the floor's top face
    EXPECT_FALSE(pocket->Contains({0, 0, 2}));    // in the pocket
    EXPECT_FALSE(pocket->Contains({0, 0, -1}));   // below it
    // A pin resting on the pocket's floor touches it (before: a clash, of unknown depth for
    // the soup).
    const auto pin = Boxes({{-1, 1, -1, 1, 1, 6}}, soup);
    const ContactMeasure rest = MeasureContact(*pin, {}, *pocket, {}, 0.05);
    EXPECT_EQ(rest.kind, ContactMeasure::Kind::kTouching) << rest.depth;
    EXPECT_LE(rest.depth, 1e-9);
    // Pushed 0.3 mm into the floor it penetrates by 0.3 mm, measured.
    const ContactMeasure pushed =
        MeasureContact(*pin, RigidTransform::Translation({0, 0, -0.3}), *pocket, {}, 0.05);
    EXPECT_EQ(pushed.kind, ContactMeasure::Kind::kPenetrating);
    EXPECT_NEAR(pushed.depth, 0.3, 1e-9);
    // Two plates side by side resting on a frame of two rails, each mesh two shells.
    const auto plates = Boxes({{0, 5, 0, 10, 1, 2}, {5, 10, 0, 10, 1, 2}}, soup);
    const auto rails = Boxes({{0, 10, 0, 1, 0, 1}, {0, 10, 9, 10, 0, 1}}, soup);
    EXPECT_EQ(MeasureContact(*plates, {}, *rails, {}, 0.05).kind, ContactMeasure::Kind::kTouching);
  }
}

TEST(MeshContact, AnOpenSheetHasNoInsideAndItsDepthIsUnknown) {
  auto sheet = std::make_shared<TriangleMesh>();
  sheet->vertices = {{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}};
  sheet->faces = {{0, 1, 2}, {0, 2, 3}};
  const CollisionMesh open(sheet);
  EXPECT_FALSE(open.solid());
  const auto box = Box(2, 2, 2);
  const ContactMeasure m = MeasureContact(open, {}, *box, {}, 0.05);
  EXPECT_EQ(m.kind, ContactMeasure::Kind::kPenetrating);
  EXPECT_TRUE(std::isinf(m.depth));
  EXPECT_TRUE(m.open[0]);
  EXPECT_FALSE(m.open[1]);
}

TEST(TranslationalSweep, FirstContactOfBoxesIsTheGap) {
  const auto a = Box(2, 2, 2);
  SweepOptions options;
  options.max_travel = 10;
  const auto c = FirstBlockingContact(*a, {}, *a, RigidTransform::Translation({5, 0.3, 0.2}),
                                      Eigen::Vector3d::UnitX(), options);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->travel, 3.0, 1e-12);
  EXPECT_NEAR(c->approach, 1.0, 1e-12);
  // Moving away, or sliding past with a face in common, is free.
  EXPECT_FALSE(FirstBlockingContact(*a, {}, *a, RigidTransform::Translation({5, 0, 0}),
                                    -Eigen::Vector3d::UnitX(), options));
  EXPECT_FALSE(FirstBlockingContact(*a, {}, *a, RigidTransform::Translation({0, 2, 0}),
                                    Eigen::Vector3d::UnitX(), options));
  // Too short a travel.
  options.max_travel = 2.9;
  EXPECT_FALSE(FirstBlockingContact(*a, {}, *a, RigidTransform::Translation({5, 0.3, 0.2}),
                                    Eigen::Vector3d::UnitX(), options));
}

TEST(TranslationalSweep, APartLeavesASolidThatMeetsItselfAlongAnEdge) {
  // Two boxes on one corner edge, welded there: four faces on that edge, so the mesh is not
  // closed, but every edge is run once each way (as where a CAD tessellation's faces touch).
  const auto solid = Boxes({{0, 1, 0, 1, 0, 1}, {1, 2, 1, 2, 0, 1}}, true);
  EXPECT_FALSE(solid->closed());
  EXPECT_TRUE(solid->oriented());
  const auto lid = Boxes({{0.2, 0.8, 0.2, 0.8, 1, 2}}, false);
  SweepOptions options;
  options.max_travel = 5;
  // Resting on its top face, the lid leaves upward freely (before: blocked where it stood, as
  // by a two-sided sheet) and is stopped at once downward.
  EXPECT_FALSE(FirstBlockingContact(*lid, {}, *solid, {}, Eigen::Vector3d::UnitZ(), options));
  const auto down = FirstBlockingContact(*lid, {}, *solid, {}, -Eigen::Vector3d::UnitZ(), options);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->travel, 0.0);
  // With one face turned over it is not oriented: two-sided, the touch where it stands blocks.
  auto mesh = std::make_shared<TriangleMesh>(solid->mesh());
  std::swap(mesh->faces.front()[1], mesh->faces.front()[2]);
  const CollisionMesh turned(mesh);
  EXPECT_FALSE(turned.oriented());
  EXPECT_TRUE(FirstBlockingContact(*lid, {}, turned, {}, Eigen::Vector3d::UnitZ(), options));
  // With the second box wound inside out every edge still runs both ways, but its faces point
  // into it: not oriented either.
  auto inverted = std::make_shared<TriangleMesh>(solid->mesh());
  for (std::size_t f = inverted->faces.size() / 2; f < inverted->faces.size(); ++f) {
    std::swap(inverted->faces[f][1], inverted->faces[f][2]);
  }
  const CollisionMesh inside_out(inverted);
  EXPECT_FALSE(inside_out.oriented());
}

TEST(TranslationalSweep, AnEdgeOfFourFacesStopsWhateverEntersThere) {
  // Two wedges along the z axis, welded on it: one fills the angles 0 to 90 degrees about it,
  // the other 135 to 180. The first wedge's face on the plane x = 0 is listed first, then the
  // second wedge's faces on the axis: the first two faces on the axis belong to different
  // wedges, so the angle between them is no angle of the solid; an edge of more than two
  // faces has none (CollisionMesh::EdgeConvexity 0): a point that reaches a face across it
  // enters. (The earlier pairing happens to stop the tip here too: this pins the behaviour.)
  const auto wedge = [](const std::vector<Eigen::Vector2d>& outline) {
    Region2d r;
    r.outer = outline;
    return ExtrudeRegion(r, 0, 1);
  };
  TriangleMesh shells = wedge({{0, 0}, {1, 0}, {0, 1}});
  shells.Append(wedge({{0, 0}, {-1, 1}, {-1, 0}}));
  const auto rank = [&shells](const TriangleMesh::Face& f) {
    const auto on_axis = [&](const Eigen::Vector3d& p) { return p.head<2>().isZero(); };
    int axis_corners = 0;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const std::int32_t v : f) {
      axis_corners += on_axis(shells.vertices[v]);
      centroid += shells.vertices[v] / 3;
    }
    if (axis_corners < 2) return 2;
    return std::abs(centroid.x()) < 1e-12 ? 0 : centroid.x() < 0 ? 1 : 2;
  };
  TriangleMesh ordered = shells;
  std::stable_sort(ordered.faces.begin(), ordered.faces.end(),
                   [&](const auto& f, const auto& g) { return rank(f) < rank(g); });
  const CollisionMesh wedges(Soup(ordered));
  EXPECT_FALSE(wedges.closed());
  EXPECT_TRUE(wedges.oriented());
  // A thin tetrahedron, tip first, from 330 degrees through the axis toward 150 degrees: it
  // enters the second wedge where its tip crosses the axis, after 2 mm.
  const double angle = 150 * kPi / 180;
  const Eigen::Vector3d d(std::cos(angle), std::sin(angle), 0);
  const Eigen::Vector3d tip = Eigen::Vector3d(0, 0, 0.5) - 2 * d;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), side = d.cross(up);
  auto tetrahedron = std::make_shared<TriangleMesh>();
  tetrahedron->vertices = {tip, tip - d + 0.2 * up, tip - d - 0.1 * up + 0.17 * side,
                           tip - d - 0.1 * up - 0.17 * side};
  tetrahedron->faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  const CollisionMesh moving(tetrahedron);
  ASSERT_TRUE(moving.closed());
  SweepOptions options;
  options.max_travel = 5;
  const auto c = FirstBlockingContact(moving, {}, wedges, {}, d, options);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->travel, 2.0, 1e-9);
}

TEST(TranslationalSweep, EdgeMeetsEdgeWhereTheGeometrySays) {
  // A box turned 45 degrees about z moves along x toward a box turned 45 degrees about x... the
  // first contact is edge on edge: the moving box's vertical edge at x = sqrt(2) meets the
  // other's horizontal edge along x at y = 0.
  const auto a = Box(2, 2, 2);
  const RigidTransform X_WM = RigidTransform::AxisAngle(Eigen::Vector3d::UnitZ(), kPi / 4);
  const RigidTransform X_WO = RigidTransform::Translation({6, 0, 0}) *
                              RigidTransform::AxisAngle(Eigen::Vector3d::UnitZ(), kPi / 4) *
                              RigidTransform::AxisAngle(Eigen::Vector3d::UnitX(), kPi / 4);
  SweepOptions options;
  options.max_travel = 10;
  const auto c = FirstBlockingContact(*a, X_WM, *a, X_WO, Eigen::Vector3d::UnitX(), options);
  ASSERT_TRUE(c);
  EXPECT_FALSE(SurfacesIntersect(*a, RigidTransform::Translation({c->travel - 1e-6, 0, 0}) * X_WM,
                                 *a, X_WO));
  EXPECT_TRUE(SurfacesIntersect(*a, RigidTransform::Translation({c->travel + 1e-6, 0, 0}) * X_WM,
                                *a, X_WO));
}

// Property against the exact static test: just before the reported travel the meshes are
// apart, just after they intersect; with no contact reported, no sampled travel intersects.
TEST(TranslationalSweep, AgreesWithStaticTestOnRandomSweeps) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto moving = Cylinder(0.8, -1, 1, 10);
  const auto obstacle = Box(3, 1, 2);
  int contacts = 0;
  for (int i = 0; i < 150; ++i) {
    const RigidTransform X_WO = RandomPose(rng, 1.0);
    RigidTransform X_WM = RandomPose(rng, 6.0);
    if (SurfacesIntersect(*moving, X_WM, *obstacle, X_WO) ||
        MeasureContact(*moving, X_WM, *obstacle, X_WO, 0).contained) {
      continue;
    }
    // Aim roughly at the obstacle so that about half of the sweeps hit.
    Eigen::Vector3d d = (X_WO.translation() - X_WM.translation()).normalized() +
                        0.4 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    d.normalize();
    SweepOptions options;
    options.max_travel = 15;
    const auto c = FirstBlockingContact(*moving, X_WM, *obstacle, X_WO, d, options);
    auto at = [&](double s) { return RigidTransform::Translation(s * d) * X_WM; };
    if (c) {
      ++contacts;
      EXPECT_FALSE(SurfacesIntersect(*moving, at(c->travel - 1e-7), *obstacle, X_WO)) << i;
      EXPECT_TRUE(SurfacesIntersect(*moving, at(c->travel + 1e-7), *obstacle, X_WO)) << i;
    } else {
      for (int k = 0; k <= 300; ++k) {
        ASSERT_FALSE(SurfacesIntersect(*moving, at(15.0 * k / 300), *obstacle, X_WO))
            << "sweep " << i << " missed a contact at travel " << 15.0 * k / 300;
      }
    }
  }
  EXPECT_GT(contacts, 20);
}

// Radius of the largest ball about the origin inside every face's plane of a convex mesh.
double InscribedRadius(const TriangleMesh& mesh) {
  double radius = std::numeric_limits<double>::infinity();
  for (const auto& f : mesh.faces) {
    const Eigen::Vector3d &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]],
                          &c = mesh.vertices[f[2]];
    radius = std::min(radius, std::abs((b - a).cross(c - a).normalized().dot(a)));
  }
  return radius;
}

// Two finely meshed balls (hierarchies many levels deep) swept at each other from far apart
// along random directions, most of them oblique to the meshes' edges: each mesh lies between
// the sphere through its vertices and the one inside its faces, so the first contact falls
// between the travels at which those spheres touch, and a ball passing wider than the outer
// spheres meets nothing; the exact static test finds the meshes apart just before the contact
// and intersecting just after it. A face of the obstacle that the sweep reaches but the
// hierarchy's pruning drops would show as a later contact or none.
TEST(TranslationalSweep, FineBallsMeetWhereTheirSpheresSay) {
  const TriangleMesh ball_m = MakeUvSphere(10, 30, 60), ball_o = MakeUvSphere(6, 24, 48);
  const CollisionMesh moving(std::make_shared<TriangleMesh>(ball_m));
  const CollisionMesh obstacle(std::make_shared<TriangleMesh>(ball_o));
  const double outer = 10 + 6, inner = InscribedRadius(ball_m) + InscribedRadius(ball_o);
  ASSERT_GT(inner, 0.99 * outer);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int contacts = 0, misses = 0;
  for (int i = 0; i < 200; ++i) {
    const RigidTransform X_WO = RandomPose(rng, 5.0);
    const Eigen::Vector3d d = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const Eigen::Vector3d across = d.cross(Eigen::Vector3d(u(rng), u(rng), u(rng))).normalized();
    const double offset = 24.0 * std::abs(u(rng));  // the centres' distance across d
    const Eigen::Vector3d p_WMo = X_WO.translation() - 100.0 * d + offset * across;
    const RigidTransform X_WM =
        RigidTransform::Translation(p_WMo) * RandomPose(rng, 0.0);  // turned about its centre
    SweepOptions options;
    options.max_travel = 200;
    const auto c = FirstBlockingContact(moving, X_WM, obstacle, X_WO, d, options);
    // Travel at which spheres about the centres whose radii sum to r touch.
    const auto touch = [&](double r) { return 100.0 - std::sqrt(r * r - offset * offset); };
    auto at = [&](double s) { return RigidTransform::Translation(s * d) * X_WM; };
    if (offset < inner) {
      ASSERT_TRUE(c) << "sweep " << i << " passes " << offset << " mm off the centre";
      EXPECT_GE(c->travel, touch(outer) - 1e-9) << i;
      EXPECT_LE(c->travel, touch(inner) + 1e-9) << i;
      EXPECT_FALSE(SurfacesIntersect(moving, at(c->travel - 1e-7), obstacle, X_WO)) << i;
      EXPECT_TRUE(SurfacesIntersect(moving, at(c->travel + 1e-7), obstacle, X_WO)) << i;
      ++contacts;
    } else if (offset > outer) {
      EXPECT_FALSE(c) << "sweep " << i << " passes " << offset << " mm off the centre";
      ++misses;
    } else if (c) {
      EXPECT_GE(c->travel, touch(outer) - 1e-9) << i;
    }
  }
  EXPECT_GT(contacts, 100);
  EXPECT_GT(misses, 40);
}

// Two finely meshed rods crossing at random angles, one swept onto the other along their
// common normal: their first contact is of side edges crossing (edge-edge), at a travel between
// those at which the cylinders through their corners and the ones inside their sides touch
// (the axes' distance then the sum of the radii), the meshes apart just before it and
// intersecting just after. A pruned-away edge shows as a later contact or none.
TEST(TranslationalSweep, CrossedRodsMeetWhereTheirCylindersSay) {
  constexpr int kSegments = 40;
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double inside = std::cos(kPi / kSegments);
  for (int i = 0; i < 100; ++i) {
    const auto moving = Cylinder(3, -60, 60, kSegments, kPi * u(rng));
    const auto obstacle = Cylinder(2, -60, 60, kSegments, kPi * u(rng));
    const RigidTransform X_WO = RandomPose(rng, 5.0);
    const Eigen::Vector3d axis_o = X_WO.RotateDirection(Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d across =
        axis_o.cross(Eigen::Vector3d(u(rng), u(rng), u(rng))).normalized();
    const double angle = kPi / 6 + kPi / 3 * std::abs(u(rng));  // 30 to 90 degrees
    const Eigen::Vector3d axis_m = std::cos(angle) * axis_o + std::sin(angle) * across;
    const Eigen::Vector3d normal = axis_o.cross(axis_m).normalized();
    // The axes' nearest points: 20 mm or less from each rod's middle, `gap` apart along normal.
    const double gap = 8.0 + 20.0 * std::abs(u(rng));
    const Eigen::Vector3d p_WOc = X_WO.translation() + 20.0 * u(rng) * axis_o;
    const RigidTransform X_WM =
        RigidTransform::FromZAxis(p_WOc + gap * normal + 20.0 * u(rng) * axis_m, axis_m);
    SweepOptions options;
    options.max_travel = 40;
    const auto c = FirstBlockingContact(*moving, X_WM, *obstacle, X_WO, -normal, options);
    ASSERT_TRUE(c) << "sweep " << i;
    EXPECT_EQ(c->kind, SweepContact::Kind::kEdgeEdge) << i;
    EXPECT_GE(c->travel, gap - (3 + 2) - 1e-9) << i;
    EXPECT_LE(c->travel, gap - (3 + 2) * inside + 1e-9) << i;
    auto at = [&](double s) { return RigidTransform::Translation(-s * normal) * X_WM; };
    EXPECT_FALSE(SurfacesIntersect(*moving, at(c->travel - 1e-7), *obstacle, X_WO)) << i;
    EXPECT_TRUE(SurfacesIntersect(*moving, at(c->travel + 1e-7), *obstacle, X_WO)) << i;
  }
}

TEST(TranslationalSweep, IgnoredRegionLetsAThreadIntoItsNut) {
  const auto pin = Cylinder(3, 0, 10, 24);
  const auto plate = HoledPlate(20, 5, 3, 32);
  // The pin starts above the plate and moves down into the hole: its rim crosses the hole's
  // facets, a contact of about 0.01 mm.
  const RigidTransform X_WM = RigidTransform::Translation({0, 0, 8});
  SweepOptions options;
  options.max_travel = 6;
  const auto blocked =
      FirstBlockingContact(*pin, X_WM, *plate, {}, -Eigen::Vector3d::UnitZ(), options);
  ASSERT_TRUE(blocked);
  EXPECT_NEAR(blocked->travel, 3.0, 1e-9);
  options.ignore = [](const Eigen::Vector3d& p_W) { return p_W.head<2>().norm() <= 3.05; };
  EXPECT_FALSE(FirstBlockingContact(*pin, X_WM, *plate, {}, -Eigen::Vector3d::UnitZ(), options));
}

TEST(BroadPhase, MatchesAllPairsOnRandomBoxes) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 100.0), s(0.1, 8.0);
  std::vector<Aabb> boxes(300);
  for (Aabb& b : boxes) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    b.Extend(p);
    b.Extend(p + Eigen::Vector3d(s(rng), s(rng), s(rng)));
  }
  boxes[17] = Aabb{};  // empty boxes never overlap
  std::vector<std::pair<std::size_t, std::size_t>> expected;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      Aabb gi = boxes[i];
      if (!gi.empty()) {
        gi.min.array() -= 0.5;
        gi.max.array() += 0.5;
      }
      Aabb gj = boxes[j];
      if (!gj.empty()) {
        gj.min.array() -= 0.5;
        gj.max.array() += 0.5;
      }
      if (gi.Intersects(gj)) expected.emplace_back(i, j);
    }
  }
  EXPECT_EQ(OverlappingBoxes(boxes, 0.5), expected);
  EXPECT_GT(expected.size(), 10u);
}

// Two box meshes are exactly their boxes: the separating-axis test must say "overlap" exactly
// when the solids meet (surfaces intersect, or one contains the other).
TEST(BoxesOverlap, IsExactForBoxSolids) {
  std::mt19937 rng(5);
  const auto a = Box(2, 4, 6);
  const auto b = Box(3, 1, 2);
  int overlaps = 0;
  for (int i = 0; i < 500; ++i) {
    const RigidTransform X_WA = RandomPose(rng, 2.0), X_WB = RandomPose(rng, 5.0);
    const bool meet = BruteForceIntersect(*a, X_WA, *b, X_WB) ||
                      MeasureContact(*a, X_WA, *b, X_WB, 0).contained != 0;
    ASSERT_EQ(BoxesOverlap(a->bounds(), b->bounds(), X_WA.inverse() * X_WB, 0), meet) << i;
    overlaps += meet;
  }
  EXPECT_GT(overlaps, 50);
  EXPECT_LT(overlaps, 450);
}

}  // namespace
}  // namespace mechanist
