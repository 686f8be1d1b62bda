// Feature recognition on meshes whose truth is known by construction: the part library's
// gears, rings, racks and shafts, turned to arbitrary poses.

#include "kernel/features/feature_recognition.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cycloid_outline.h"
#include "kernel/features/involute_gear.h"
#include "kernel/features/part_library.h"
#include "kernel/mesh/mesh_builder.h"
#include "spring_mesh.h"

namespace mechanist {
namespace {

// The mesh moved by X (features are then expected along X's rotated axes).
TriangleMesh Moved(TriangleMesh mesh, const RigidTransform& X) {
  for (Eigen::Vector3d& v : mesh.vertices) v = X * v;
  return mesh;
}

const RecognizedFeature* Find(const MeshFeatures& found, FeatureKind kind) {
  for (const RecognizedFeature& r : found.features) {
    if (r.feature.kind == kind) return &r;
  }
  return nullptr;
}

double DistanceToAxis(const Feature& f, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = p - f.origin;
  return (d - d.dot(f.axis) * f.axis).norm();
}

TEST(FeatureRecognition, LibrarySpurGearsComeOutExactly) {
  const RigidTransform X = RigidTransform::FromQuaternion(
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())),
      {12, -4, 7});
  for (const auto& [teeth, module] : std::vector<std::pair<int, double>>{
           {6, 1.0}, {12, 0.5}, {17, 1.0}, {20, 1.5}, {31, 2.0}, {57, 0.8}, {80, 1.25}}) {
    SpurGearSpec spec;
    spec.teeth = teeth;
    spec.module = module;
    spec.face_width = 6;
    spec.bore_diameter = module * teeth * 0.3;
    const MeshFeatures found = RecognizeFeatures(Moved(MakeLibraryPart(spec).mesh, X));
    const RecognizedFeature* gear = Find(found, FeatureKind::kGear);
    ASSERT_NE(gear, nullptr) << teeth << " teeth: " << (found.notes.empty() ? "" : found.notes[0]);
    EXPECT_EQ(gear->feature.teeth, teeth);
    EXPECT_EQ(gear->feature.module, module) << teeth;
    EXPECT_FALSE(gear->feature.internal);
    const Eigen::Vector3d axis = X.RotateDirection(Eigen::Vector3d::UnitZ());
    EXPECT_GT(std::abs(gear->feature.axis.dot(axis)), 1 - 1e-9);
    EXPECT_LT(DistanceToAxis(gear->feature, X * Eigen::Vector3d::Zero()), 1e-6);
    EXPECT_NEAR(gear->feature.length, 6.0, 1e-9);
    const RecognizedFeature* bore = Find(found, FeatureKind::kHole);
    ASSERT_NE(bore, nullptr) << teeth;
    EXPECT_EQ(bore->feature.id, "bore");
    EXPECT_NEAR(bore->feature.diameter, spec.bore_diameter, 1e-3 * spec.bore_diameter);
  }
}

TEST(FeatureRecognition, HelicalGearsGiveTheirHelixAngleAndHandFromTheirSections) {
  // Library helical gears (their sections turn by z tan(b) / r), turned to a skew pose, of
  // either hand; an undercut-range pinion of 8 teeth among them.
  const RigidTransform X = RigidTransform::FromQuaternion(
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())),
      {12, -4, 7});
  struct Case {
    int teeth;
    double module, helix_deg, face_width;
  };
  for (const Case& c : std::vector<Case>{
           {8, 1.0, 20, 8}, {20, 2.0, -15, 16}, {31, 1.5, 30, 12}, {57, 0.8, -25, 10}}) {
    SpurGearSpec spec;
    spec.teeth = c.teeth;
    spec.module = c.module;
    spec.face_width = c.face_width;
    spec.bore_diameter = c.module * c.teeth * 0.3;
    spec.helix_angle = c.helix_deg * M_PI / 180;
    const MeshFeatures found = RecognizeFeatures(Moved(MakeLibraryPart(spec).mesh, X));
    const RecognizedFeature* gear = Find(found, FeatureKind::kGear);
    ASSERT_NE(gear, nullptr) << c.teeth << " teeth";
    EXPECT_EQ(gear->feature.teeth, c.teeth);
    EXPECT_EQ(gear->feature.module, c.module) << c.teeth;
    EXPECT_FALSE(gear->feature.internal);
    // The hand does not depend on which way the axis points.
    EXPECT_NEAR(gear->feature.helix_angle * 180 / M_PI, c.helix_deg, 0.05)
        << c.teeth << ": " << gear->detail;
    const Eigen::Vector3d axis = X.RotateDirection(Eigen::Vector3d::UnitZ());
    EXPECT_GT(std::abs(gear->feature.axis.dot(axis)), 1 - 1e-9);
    EXPECT_LT(DistanceToAxis(gear->feature, X * Eigen::Vector3d::Zero()), 1e-3);
    EXPECT_NEAR(gear->feature.length, c.face_width, 1e-6);
    EXPECT_NE(gear->detail.find(c.helix_deg > 0 ? "right hand" : "left hand"), std::string::npos)
        << gear->detail;
  }
}

// A straight bevel gear of `teeth` and heel module `module` with pitch angle `pitch_angle`
// (radians) about +z, its pitch cone's apex at the origin: the involute outline of a spur gear
// of that module (addendum m, dedendum 1.25 m) across the axis at the heel, L cos(angle) from
// the apex (L = m z / (2 sin(angle))), joined by straight walls to the same outline scaled
// toward the apex by 2/3 at the toe, with a bore.
TriangleMesh BevelGearMesh(int teeth, double module, double pitch_angle) {
  InvoluteOutlineSpec spec;
  spec.teeth = teeth;
  spec.module = module;
  spec.pressure_angle = 20 * M_PI / 180;
  spec.addendum = module;
  spec.dedendum = 1.25 * module;
  spec.max_arc_step = 2 * M_PI / teeth / 8;
  const Ring2d heel = Oriented(InvoluteOutline(spec), true);
  const double L = module * teeth / (2 * std::sin(pitch_angle)), toe = 2.0 / 3.0;
  Ring2d inner = heel;
  for (Eigen::Vector2d& p : inner) p *= toe;
  const Ring2d bore =
      Oriented(CircleRing(Eigen::Vector2d::Zero(), 0.1 * module * teeth, 48), false);
  MeshBuilder b;
  const double z0 = toe * L * std::cos(pitch_angle), z1 = L * std::cos(pitch_angle);
  const MeshBuilder::Indices outer0 = b.AddRing(inner, z0), outer1 = b.AddRing(heel, z1);
  const MeshBuilder::Indices hole0 = b.AddRing(bore, z0), hole1 = b.AddRing(bore, z1);
  b.AddWall(outer0, outer1);
  b.AddWall(hole0, hole1);
  b.AddCap(outer0, {hole0}, /*facing_up=*/false);
  b.AddCap(outer1, {hole1}, /*facing_up=*/true);
  return b.Release();
}

TEST(FeatureRecognition, StraightBevelGearsGiveTheirTeethModulePitchAngleAndApex) {
  const RigidTransform X = RigidTransform::FromQuaternion(
      Eigen::Quaterniond(Eigen::AngleAxisd(0.9, Eigen::Vector3d(-1, 2, 1).normalized())),
      {3, 5, -8});
  struct Case {
    int teeth;
    double module, pitch_deg;
  };
  for (const Case& c : std::vector<Case>{{12, 2.0, 21.8}, {20, 1.5, 45}, {36, 1.0, 68.2}}) {
    const MeshFeatures found =
        RecognizeFeatures(Moved(BevelGearMesh(c.teeth, c.module, c.pitch_deg * M_PI / 180), X));
    const RecognizedFeature* gear = Find(found, FeatureKind::kBevelGear);
    ASSERT_NE(gear, nullptr) << c.teeth << " teeth";
    EXPECT_EQ(Find(found, FeatureKind::kGear), nullptr);
    EXPECT_EQ(gear->feature.teeth, c.teeth);
    EXPECT_EQ(gear->feature.module, c.module);
    EXPECT_NEAR(gear->feature.pitch_angle * 180 / M_PI, c.pitch_deg, 0.1) << gear->detail;
    // From the apex into the gear.
    EXPECT_GT(gear->feature.axis.dot(X.RotateDirection(Eigen::Vector3d::UnitZ())), 1 - 1e-6);
    EXPECT_LT((gear->feature.origin - X * Eigen::Vector3d::Zero()).norm(), 0.02) << c.teeth;
  }
  // A tapered knob with six lobes and a bore, r = R (1 + 0.05 cos 6 theta) shrinking toward
  // one apex, sized so that its "pitch radius" at the heel, a 2.25th of its depth below its
  // lobes, is that of 6 teeth of module 4 (R = 11.933): far shallower than a gear's teeth
  // (at least 0.85 x 2.25 x 4 cos 50 = 4.9 mm; it has 1.19), so no gear.
  Ring2d knob, small;
  for (int k = 0; k < 240; ++k) {
    const double t = 2 * M_PI * k / 240;
    knob.push_back(11.933 * (1 + 0.05 * std::cos(6 * t)) *
                   Eigen::Vector2d(std::cos(t), std::sin(t)));
    small.push_back(knob.back() * 0.6);
  }
  {
    const Ring2d bore = Oriented(CircleRing(Eigen::Vector2d::Zero(), 3, 32), false);
    MeshBuilder b;
    const MeshBuilder::Indices o0 = b.AddRing(small, 6), o1 = b.AddRing(knob, 10);
    const MeshBuilder::Indices h0 = b.AddRing(bore, 6), h1 = b.AddRing(bore, 10);
    b.AddWall(o0, o1);
    b.AddWall(h0, h1);
    b.AddCap(o0, {h0}, /*facing_up=*/false);
    b.AddCap(o1, {h1}, /*facing_up=*/true);
    const MeshFeatures found = RecognizeFeatures(b.Release());
    EXPECT_EQ(Find(found, FeatureKind::kBevelGear), nullptr);
    EXPECT_EQ(Find(found, FeatureKind::kGear), nullptr);
  }
  // A spur gear's tip and root do not shrink: it stays a spur gear.
  SpurGearSpec spur;
  spur.teeth = 20;
  spur.module = 1.5;
  spur.face_width = 10;
  spur.bore_diameter = 6;
  spur.helix_angle = 10 * M_PI / 180;  // not prismatic: the section path
  const MeshFeatures helical = RecognizeFeatures(MakeLibraryPart(spur).mesh);
  EXPECT_EQ(Find(helical, FeatureKind::kBevelGear), nullptr);
  EXPECT_NE(Find(helical, FeatureKind::kGear), nullptr);
}

TEST(FeatureRecognition, WormsGiveTheirStartsModuleHandAndPitchDiameter) {
  // Library worms (a trapezoidal thread of 20 degree flanks, axial pitch pi m) in a skew pose.
  const RigidTransform X = RigidTransform::FromQuaternion(
      Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d(2, -1, 3).normalized())),
      {-6, 2, 9});
  struct Case {
    int starts;
    double module, pitch_diameter, length;
    Hand hand;
  };
  for (const Case& c : std::vector<Case>{{1, 1.0, 10, 30, Hand::kRight},
                                         {2, 2.0, 20, 50, Hand::kLeft},
                                         {3, 1.5, 18, 40, Hand::kRight},
                                         {4, 0.8, 12, 25, Hand::kLeft}}) {
    WormSpec spec;
    spec.starts = c.starts;
    spec.module = c.module;
    spec.pitch_diameter = c.pitch_diameter;
    spec.length = c.length;
    spec.bore_diameter = 0.3 * c.pitch_diameter;
    spec.hand = c.hand;
    const MeshFeatures found = RecognizeFeatures(Moved(MakeLibraryPart(spec).mesh, X));
    const RecognizedFeature* worm = Find(found, FeatureKind::kWorm);
    ASSERT_NE(worm, nullptr) << c.starts << " starts";
    EXPECT_EQ(worm->feature.starts, c.starts) << worm->detail;
    EXPECT_EQ(worm->feature.module, c.module) << worm->detail;
    EXPECT_EQ(worm->feature.hand, c.hand) << worm->detail;
    EXPECT_NEAR(worm->feature.pitch_diameter, c.pitch_diameter, 0.05 * c.module) << worm->detail;
    const Eigen::Vector3d axis = X.RotateDirection(Eigen::Vector3d::UnitZ());
    EXPECT_GT(std::abs(worm->feature.axis.dot(axis)), 1 - 1e-6);
    EXPECT_LT(DistanceToAxis(worm->feature, X * Eigen::Vector3d::Zero()), 0.01 * c.module);
    EXPECT_NEAR(worm->feature.length, c.length, 1e-3);
    EXPECT_EQ(Find(found, FeatureKind::kGear), nullptr);
  }
  // A plain shaft, a helical gear and springs, open and closely wound, are no worm.
  ShaftSpec shaft;
  shaft.diameter = 10;
  shaft.length = 40;
  EXPECT_EQ(Find(RecognizeFeatures(MakeLibraryPart(shaft).mesh), FeatureKind::kWorm), nullptr);
  SpurGearSpec helical;
  helical.teeth = 20;
  helical.module = 1.5;
  helical.face_width = 10;
  helical.bore_diameter = 6;
  helical.helix_angle = 20 * M_PI / 180;
  EXPECT_EQ(Find(RecognizeFeatures(MakeLibraryPart(helical).mesh), FeatureKind::kWorm), nullptr);
  for (const double pitch : {4.0, 1.5}) {
    EXPECT_EQ(Find(RecognizeFeatures(testing::SpringMesh(6, 1.5, pitch, 8)), FeatureKind::kWorm),
              nullptr)
        << pitch;
  }
}

TEST(FeatureRecognition, SpurTeethBesideAHubAreFoundInSections) {
  // A spur gear fused to a tapered hub: no longer a prism, its teeth still show in sections
  // across the axis, with no helix.
  SpurGearSpec spec;
  spec.teeth = 24;
  spec.module = 1.5;
  spec.face_width = 10;
  TriangleMesh gear = MakeLibraryPart(spec).mesh;
  RadialGrid hub;
  hub.radius = [](double, double z) { return 10 - 0.2 * (z - 10); };
  hub.angular_segments = 48;
  hub.axial_segments = 4;
  hub.z0 = 10, hub.z1 = 25;  // on the teeth's top face
  const TriangleMesh boss = MakeRadialGridSolid(hub);
  const int base = static_cast<int>(gear.vertices.size());
  gear.vertices.insert(gear.vertices.end(), boss.vertices.begin(), boss.vertices.end());
  for (auto f : boss.faces) gear.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  const MeshFeatures found = RecognizeFeatures(gear);
  EXPECT_FALSE(found.axis.has_value());  // not prismatic
  const RecognizedFeature* teeth = Find(found, FeatureKind::kGear);
  ASSERT_NE(teeth, nullptr);
  EXPECT_EQ(teeth->feature.teeth, 24);
  EXPECT_EQ(teeth->feature.module, 1.5);
  EXPECT_EQ(teeth->feature.helix_angle, 0.0);
  EXPECT_NEAR(teeth->feature.origin.z(), 0.0, 1e-9);
  EXPECT_NEAR(teeth->feature.length, 10.0, 25.0 / 24 + 1e-9);  // to one coarse section
  EXPECT_NE(teeth->detail.find("spur gear from"), std::string::npos) << teeth->detail;
}

TEST(FeatureRecognition, RingGearsAreInternalAndRacksRunAlongTheirTeeth) {
  RingGearSpec ring;
  ring.teeth = 40;
  ring.module = 1;
  ring.face_width = 10;
  ring.outer_diameter = 52;
  const MeshFeatures r = RecognizeFeatures(MakeLibraryPart(ring).mesh);
  const RecognizedFeature* teeth = Find(r, FeatureKind::kGear);
  ASSERT_NE(teeth, nullptr);
  EXPECT_EQ(teeth->feature.teeth, 40);
  EXPECT_EQ(teeth->feature.module, 1.0);
  EXPECT_TRUE(teeth->feature.internal);
  // Its outside is a convex cylinder (it could be pressed into a housing's bore).
  const RecognizedFeature* outside = Find(r, FeatureKind::kShaft);
  ASSERT_NE(outside, nullptr);
  EXPECT_NEAR(outside->feature.diameter, 52.0, 0.01);

  RackSpec rack;
  rack.module = 2;
  rack.length = 20 * M_PI * 2;
  rack.face_width = 8;
  const MeshFeatures k = RecognizeFeatures(MakeLibraryPart(rack).mesh);
  const RecognizedFeature* rt = Find(k, FeatureKind::kRack);
  ASSERT_NE(rt, nullptr) << (k.notes.empty() ? "" : k.notes[0]);
  EXPECT_EQ(rt->feature.module, 2.0);
  EXPECT_GT(rt->feature.axis.dot(Eigen::Vector3d::UnitX()), 1 - 1e-9);
  EXPECT_GT(rt->feature.normal.dot(Eigen::Vector3d::UnitY()), 1 - 1e-9);
  // The pitch line is y = 0, at the middle of the face width.
  EXPECT_NEAR(rt->feature.origin.y(), 0.0, 1e-6);
  EXPECT_NEAR(rt->feature.origin.z(), 0.0, 1e-9);
  EXPECT_NEAR(rt->feature.length, rack.length, 1e-6);
}

TEST(FeatureRecognition, ShaftsAndPlatesWithHoles) {
  ShaftSpec shaft;
  shaft.diameter = 6;
  shaft.length = 40;
  const MeshFeatures s = RecognizeFeatures(MakeLibraryPart(shaft).mesh);
  const RecognizedFeature* f = Find(s, FeatureKind::kShaft);
  ASSERT_NE(f, nullptr);
  EXPECT_NEAR(f->feature.diameter, 6.0, 1e-9);
  EXPECT_NEAR(f->feature.length, 40.0, 1e-9);

  PlateSpec plate;
  plate.length = 60;
  plate.width = 40;
  plate.thickness = 5;
  plate.holes = {{"a", Eigen::Vector2d(-20, 0), 6.6}, {"b", Eigen::Vector2d(15, 10), 3.4}};
  const MeshFeatures p = RecognizeFeatures(MakeLibraryPart(plate).mesh);
  std::vector<double> diameters;
  for (const RecognizedFeature& r : p.features) {
    ASSERT_EQ(r.feature.kind, FeatureKind::kHole);
    EXPECT_TRUE(r.feature.through);
    diameters.push_back(r.feature.diameter);
  }
  std::sort(diameters.begin(), diameters.end());
  ASSERT_EQ(diameters.size(), 2u);
  EXPECT_NEAR(diameters[0], 3.4, 1e-9);
  EXPECT_NEAR(diameters[1], 6.6, 1e-9);
}

TEST(FeatureRecognition, AnLBracketsHolesAreFoundAlongBothOfTheirAxes) {
  LBracketSpec spec;
  spec.length = 80;
  spec.height = 60;
  spec.width = 40;
  spec.thickness = 5;
  spec.base_holes = {{"", Eigen::Vector2d(50, 0), 8}, {"", Eigen::Vector2d(70, 10), 6}};
  spec.upright_holes = {{"", Eigen::Vector2d(0, 40), 10}};
  const LibraryPart part = MakeLibraryPart(spec);
  const MeshFeatures found = RecognizeFeatures(part.mesh);
  // Its holes run along z (base) and x (upright): at most one of them along an extrusion axis.
  // Each library hole is found: same diameter, on the same axis line, through the same wall.
  for (const Feature& truth : part.features) {
    if (truth.kind != FeatureKind::kHole) continue;
    bool matched = false;
    for (const RecognizedFeature& r : found.features) {
      const Feature& f = r.feature;
      matched =
          matched ||
          (f.kind == FeatureKind::kHole && std::abs(f.diameter - truth.diameter) < 1e-6 &&
           std::abs(std::abs(f.axis.dot(truth.axis)) - 1) < 1e-9 &&
           DistanceToAxis(f, truth.origin) < 1e-6 && std::abs(f.length - truth.length) < 1e-6);
    }
    EXPECT_TRUE(matched) << truth.id;
  }
  EXPECT_EQ(found.features.size(), 3u);
}

// Appends `extra` to `mesh` (separate shells: recognition needs no closed mesh).
void Append(TriangleMesh& mesh, const TriangleMesh& extra) {
  const auto offset = static_cast<std::int32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), extra.vertices.begin(), extra.vertices.end());
  for (const auto& f : extra.faces)
    mesh.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
}

// A tube wall of `segments` facets along z from 0 to `length`: facing out (a boss, a shaft)
// or in (a bore).
TriangleMesh Tube(double radius, double length, int segments, bool facing_out) {
  MeshBuilder builder;
  const Ring2d ring = Oriented(CircleRing(Eigen::Vector2d::Zero(), radius, segments), facing_out);
  builder.AddWall(builder.AddRing(ring, 0), builder.AddRing(ring, length));
  return builder.Release();
}

TEST(FeatureRecognition, CylindersAtAnyAngleAreFoundFromTheirOwnFacets) {
  // A box whose principal directions are the coordinate axes, with a bore and a boss along
  // directions that are neither: only the facets' own normals give their axes.
  Region2d rect;
  rect.outer = {{-50, -30}, {50, -30}, {50, 30}, {-50, 30}};
  TriangleMesh mesh = ExtrudeRegion(rect, -20, 20);
  auto pose = [](const Eigen::Vector3d& axis, const Eigen::Vector3d& at) {
    return RigidTransform(ShortestRotation(Eigen::Vector3d::UnitZ(), axis), at);
  };
  const RigidTransform X_bore = pose(Eigen::Vector3d(1, 2, 3).normalized(), {5, -3, 2});
  const RigidTransform X_boss = pose(Eigen::Vector3d(-2, 1, 0.5).normalized(), {-20, 10, -4});
  // The truth: the tubes' z axes where the poses put them.
  const Eigen::Vector3d bore_axis = X_bore.RotateDirection(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d boss_axis = X_boss.RotateDirection(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d bore_at = X_bore.translation(), boss_at = X_boss.translation();
  Append(mesh, Moved(Tube(5, 30, 32, false), X_bore));
  Append(mesh, Moved(Tube(3, 12, 24, true), X_boss));
  const MeshFeatures found = RecognizeFeatures(mesh);
  const RecognizedFeature* hole = Find(found, FeatureKind::kHole);
  const RecognizedFeature* shaft = Find(found, FeatureKind::kShaft);
  ASSERT_NE(hole, nullptr);
  ASSERT_NE(shaft, nullptr);
  EXPECT_NEAR(std::abs(hole->feature.axis.dot(bore_axis)), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(shaft->feature.axis.dot(boss_axis)), 1.0, 1e-12);
  // Origins are rounded to 1e-6 mm (what float meshes resolve).
  EXPECT_LT(DistanceToAxis(hole->feature, bore_at), 1e-6);
  EXPECT_LT(DistanceToAxis(shaft->feature, boss_at), 1e-6);
  // The vertices lie on the circles: diameters and lengths exact.
  EXPECT_NEAR(hole->feature.diameter, 10.0, 1e-9);
  EXPECT_NEAR(shaft->feature.diameter, 6.0, 1e-9);
  EXPECT_NEAR(hole->feature.length, 30.0, 1e-9);
  EXPECT_NEAR(shaft->feature.length, 12.0, 1e-9);
  EXPECT_EQ(found.features.size(), 2u);
}

TEST(FeatureRecognition, ConesGiveNoCylinderAxis) {
  // A cone's facets turn about its axis but lean toward it: no direction is across them all.
  MeshBuilder builder;
  const Ring2d small = CircleRing(Eigen::Vector2d::Zero(), 2, 32);
  const Ring2d large = CircleRing(Eigen::Vector2d::Zero(), 6, 32);
  builder.AddWall(builder.AddRing(small, 0), builder.AddRing(large, 4));
  const TriangleMesh cone =
      Moved(builder.Release(),
            RigidTransform(
                Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix(),
                Eigen::Vector3d(1, 2, 3)));
  EXPECT_TRUE(RecognizeFeatures(cone).features.empty());
}

TEST(FeatureRecognition, ABallHasNoFeatures) {
  const MeshFeatures ball = RecognizeFeatures(MakeUvSphere(5.0, 12, 24));
  EXPECT_TRUE(ball.features.empty());
  EXPECT_FALSE(ball.axis.has_value());
  ASSERT_FALSE(ball.notes.empty());
  EXPECT_NE(ball.notes[0].find("not prismatic"), std::string::npos);
}

}  // namespace
}  // namespace mechanist

namespace mechanist {
namespace {

TEST(FeatureRecognition, CycloidalDiscsGiveTheirLobesAndEccentricity) {
  struct Disc {
    int pins;
    double R, r_p, e;
  };
  for (const Disc d : {Disc{7, 25, 3, 2}, Disc{11, 40, 4, 1.5}, Disc{16, 30, 2.5, 0.8}}) {
    Region2d region{testing::CycloidOutline(d.pins, d.R, d.r_p, d.e, 720), {}};
    region.holes.push_back(CircleRing(Eigen::Vector2d::Zero(), 5, 64));
    const RigidTransform X(
        Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
        Eigen::Vector3d(10, -20, 5));
    const MeshFeatures found = RecognizeFeatures(Moved(ExtrudeRegion(region, 0, 6), X));
    const RecognizedFeature* disc = Find(found, FeatureKind::kCycloidDisc);
    std::string what;
    for (const RecognizedFeature& r : found.features) what += r.detail + "\n";
    for (const std::string& n : found.notes) what += n + "\n";
    ASSERT_NE(disc, nullptr) << d.pins << "\n" << what;
    EXPECT_EQ(disc->feature.teeth, d.pins - 1);
    EXPECT_NEAR(disc->feature.eccentricity, d.e, 1e-3 * d.e) << disc->detail;
    EXPECT_NEAR(DistanceToAxis(disc->feature, X * Eigen::Vector3d::Zero()), 0.0, 1e-3);
    EXPECT_NEAR(std::abs(disc->feature.axis.dot(X.RotateDirection(Eigen::Vector3d::UnitZ()))), 1.0,
                1e-9);
    EXPECT_EQ(Find(found, FeatureKind::kGear), nullptr);
  }
}

TEST(FeatureRecognition, LookingForTeethOnlyFindsTheSameTeethAndSkipsOtherDirections) {
  // The oracle is the full recognition: kTeeth must give the same toothed and lobed features
  // (spur, helical, bevel, internal, rack, cycloidal) and no cylinder across another direction.
  auto toothed = [](const MeshFeatures& found) {
    std::vector<std::string> out;
    for (const RecognizedFeature& r : found.features) {
      const FeatureKind k = r.feature.kind;
      if (k == FeatureKind::kGear || k == FeatureKind::kBevelGear || k == FeatureKind::kWorm ||
          k == FeatureKind::kRack || k == FeatureKind::kCycloidDisc) {
        out.push_back(r.detail);
      }
    }
    return out;
  };
  SpurGearSpec helical;
  helical.teeth = 20;
  helical.module = 2;
  helical.face_width = 16;
  helical.bore_diameter = 12;
  helical.helix_angle = -15 * M_PI / 180;
  SpurGearSpec spur = helical;
  spur.helix_angle = 0;
  RingGearSpec ring;
  ring.teeth = 40;
  ring.module = 1;
  ring.face_width = 10;
  ring.outer_diameter = 52;
  RackSpec rack;
  rack.module = 2;
  rack.length = 20 * M_PI * 2;
  rack.face_width = 8;
  Region2d disc{testing::CycloidOutline(7, 25, 3, 2, 720), {}};
  disc.holes.push_back(CircleRing(Eigen::Vector2d::Zero(), 5, 64));
  const std::vector<TriangleMesh> meshes = {
      MakeLibraryPart(spur).mesh, MakeLibraryPart(helical).mesh,
      MakeLibraryPart(ring).mesh, MakeLibraryPart(rack).mesh,
      ExtrudeRegion(disc, 0, 6),  BevelGearMesh(30, 2, 60 * M_PI / 180)};
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const std::vector<std::string> all = toothed(RecognizeFeatures(meshes[i]));
    ASSERT_EQ(all.size(), 1u) << i;
    EXPECT_EQ(toothed(RecognizeFeatures(meshes[i], MeshRecognition::kTeeth)), all) << i;
  }

  // An L-bracket: its upright's hole runs across the extrusion axis, so only kAll finds it.
  LBracketSpec bracket;
  bracket.length = 80;
  bracket.height = 60;
  bracket.width = 40;
  bracket.thickness = 5;
  bracket.base_holes = {{"", Eigen::Vector2d(50, 0), 8}};
  bracket.upright_holes = {{"", Eigen::Vector2d(0, 40), 10}};
  const TriangleMesh l = MakeLibraryPart(bracket).mesh;
  EXPECT_EQ(RecognizeFeatures(l).features.size(), 2u);
  EXPECT_LT(RecognizeFeatures(l, MeshRecognition::kTeeth).features.size(), 2u);
}

TEST(FeatureRecognition, RoundedPolygonsAndLobedKnobsAreNoCycloidalDisc) {
  // A hexagon with rounded corners (a nut's outside, chamfered) and a star knob: lobed
  // outlines whose shape is not a ring of pins' envelope.
  Ring2d hexagon, knob;
  for (int i = 0; i < 360; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 360;
    const double sector = std::fmod(a, 3.14159265358979323846 / 3) - 3.14159265358979323846 / 6;
    const double r = std::min(10.0 / std::cos(sector), 11.0);
    hexagon.emplace_back(r * std::cos(a), r * std::sin(a));
    const double k = 20 + 2 * std::abs(std::sin(3 * a));
    knob.emplace_back(k * std::cos(a), k * std::sin(a));
  }
  for (const Ring2d& outline : {hexagon, knob}) {
    const MeshFeatures found = RecognizeFeatures(ExtrudeRegion(Region2d{outline, {}}, 0, 5));
    EXPECT_EQ(Find(found, FeatureKind::kCycloidDisc), nullptr);
  }
}

}  // namespace
}  // namespace mechanist
