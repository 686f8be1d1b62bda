#include "kernel/features/part_library.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "kernel/mesh/mesh_check.h"

namespace mechanist {
namespace {

constexpr double kPi = std::numbers::pi;
const double kTwentyDegrees = 20.0 * kPi / 180.0;

// ---------------------------------------------------------------------------------------------
// Oracles and helpers, written from the documented geometry, not from the generators' code.

void ExpectSolid(const TriangleMesh& mesh) {
  const MeshCheck check = CheckMesh(mesh);
  std::string problems;
  for (const std::string& p : check.Problems()) problems += p + "; ";
  EXPECT_TRUE(check.ok()) << problems;
}

// V - E + F of a closed triangle mesh (E = 3F/2): 2 per sphere-like shell, minus 2 per
// through hole.
long EulerCharacteristic(const TriangleMesh& mesh) {
  return static_cast<long>(mesh.vertices.size()) - static_cast<long>(mesh.faces.size()) / 2;
}

const Feature& Find(const LibraryPart& part, const std::string& id) {
  static const Feature missing;
  for (const Feature& f : part.features) {
    if (f.id == id) return f;
  }
  ADD_FAILURE() << "no feature " << id;
  return missing;
}

void ExpectAxial(const Feature& f, FeatureKind kind, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& axis, double length) {
  EXPECT_EQ(f.kind, kind) << f.id;
  EXPECT_NEAR(f.axis.norm(), 1.0, 1e-12) << f.id;
  EXPECT_LT((f.axis - axis).norm(), 1e-12) << f.id << " axis " << f.axis.transpose();
  EXPECT_LT((f.origin - origin).norm(), 1e-9) << f.id << " origin " << f.origin.transpose();
  EXPECT_NEAR(f.length, length, 1e-9) << f.id;
}

void ExpectBox(const TriangleMesh& mesh, const Eigen::Vector3d& min, const Eigen::Vector3d& max,
               double tolerance = 1e-9) {
  const Aabb box = mesh.Bounds();
  EXPECT_LT((box.min - min).cwiseAbs().maxCoeff(), tolerance) << box.min.transpose();
  EXPECT_LT((box.max - max).cwiseAbs().maxCoeff(), tolerance) << box.max.transpose();
}

// The box of a solid of circular section: the regular n-gon inscribed in radius r, first
// vertex on +x, reaches x = r exactly and the other sides within r (1 - cos(pi / n)).
void ExpectRoundBox(const TriangleMesh& mesh, double r, int n, double z0, double z1) {
  ExpectBox(mesh, {-r, -r, z0}, {r, r, z1}, r * (1 - std::cos(kPi / n)) + 1e-12);
  EXPECT_NEAR(mesh.Bounds().max.x(), r, 1e-12);
}

// Area of the regular n-gon inscribed in a circle of radius r.
double InscribedArea(double r, int n) { return n / 2.0 * r * r * std::sin(2.0 * kPi / n); }

// The documented default facet count for a circle of diameter d.
int DefaultSegments(double d) { return std::clamp(static_cast<int>(std::ceil(kPi * d)), 32, 128); }

double HexagonArea(double across_flats) {
  return std::sqrt(3.0) / 2.0 * across_flats * across_flats;
}

std::string Message(const std::function<void()>& make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument thrown)";
}

double Simpson(const std::function<double(double)>& f, double a, double b, int intervals) {
  const double h = (b - a) / intervals;
  double sum = f(a) + f(b);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
}

double Inv(double alpha) { return std::tan(alpha) - alpha; }

// An involute toothing's outline (teeth of an external gear, or the tooth spaces of a ring
// gear): z teeth of module m, tip radius r_p + addendum, root radius r_p - dedendum.
struct Toothing {
  int z;
  double m, pressure_angle, addendum, dedendum;

  double pitch_radius() const { return m * z / 2.0; }
  double base_radius() const { return pitch_radius() * std::cos(pressure_angle); }
  double tip_radius() const { return pitch_radius() + addendum; }
  double root_radius() const { return pitch_radius() - dedendum; }
  // Half the polar angle a tooth covers at radius r (the tooth is pi m / 2 thick on the pitch
  // circle; its flank is radial below the base circle).
  double HalfAngle(double r) const {
    const double rb = base_radius();
    return kPi / (2.0 * z) + Inv(pressure_angle) - Inv(std::acos(rb / std::max(r, rb)));
  }

  // Exact area by integrating the angular extent of material over the radius:
  // A = pi r_root^2 + z * integral from r_root to r_tip of 2 theta(r) r dr.
  double Area() const {
    const double rb = base_radius(), r0 = root_radius(), r1 = tip_radius();
    const double r_involute = std::max(r0, rb);
    double area = kPi * r0 * r0;
    // Below the base circle the tooth's angular extent is constant.
    area += z * HalfAngle(rb) * (r_involute * r_involute - r0 * r0);
    area += z * Simpson([this](double r) { return 2.0 * HalfAngle(r) * r; }, r_involute, r1, 20000);
    return area;
  }

  // What the faceted outline can lose to its chords (every chord lies inside the material, so
  // the outline polygon's area is below Area() by at most this): circle arcs in facets of at
  // most 2 pi / segments lose at most pi r^2 (1 - sin(d)/d) per full circle; each of the 2z
  // flanks has 7 chords (8 points evenly spaced in the roll angle t, r = r_b sqrt(1 + t^2)),
  // each chord of the involute P(t) over a step h lies within h^2/8 max|P''| = h^2 r_tip / 8
  // of the curve and is at most h max|P'| = h r_b t_tip long.
  double ChordLossBound(int segments) const {
    const double d = 2.0 * kPi / segments;
    const double arcs =
        kPi * (std::pow(tip_radius(), 2) + std::pow(root_radius(), 2)) * (1.0 - std::sin(d) / d);
    const double rb = base_radius();
    auto roll = [rb](double r) { return std::sqrt(std::max(0.0, std::pow(r / rb, 2) - 1.0)); };
    const double t_tip = roll(tip_radius());
    const double h = (t_tip - roll(std::max(root_radius(), rb))) / 7.0;
    const double flanks = 2.0 * z * 7.0 * std::pow(h, 3) * rb * t_tip * tip_radius() / 8.0;
    return arcs + flanks;
  }
};

Toothing ExternalTeeth(int z, double m, double pressure_angle = kTwentyDegrees) {
  return {z, m, pressure_angle, m, 1.25 * m};
}

// Checks that every outline vertex between the base (or root) circle and the tip circle lies
// on an involute flank: at polar angle +-HalfAngle(r) from the nearest tooth centre 2 pi k / z.
// Vertices closer to the axis than `inner` (a bore) are skipped.
void ExpectInvoluteFlanks(const TriangleMesh& mesh, const Toothing& teeth, double inner,
                          double outer) {
  int flank_vertices = 0;
  double max_r = 0.0, min_r = std::numeric_limits<double>::infinity();
  const double lo = std::max(teeth.base_radius(), teeth.root_radius());
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const double r = v.head<2>().norm();
    if (r < inner || r > outer) continue;
    max_r = std::max(max_r, r);
    min_r = std::min(min_r, r);
    if (r <= lo + 1e-9 || r >= teeth.tip_radius() - 1e-9) continue;
    const double phi = std::atan2(v.y(), v.x());
    const double pitch_angle = 2.0 * kPi / teeth.z;
    const double from_centre = phi - pitch_angle * std::round(phi / pitch_angle);
    EXPECT_NEAR(std::abs(from_centre), teeth.HalfAngle(r), 1e-9) << "vertex " << v.transpose();
    ++flank_vertices;
  }
  // Six interior flank points per flank, both flanks of every tooth, on both end faces.
  EXPECT_EQ(flank_vertices, 2 * 2 * 6 * teeth.z);
  EXPECT_NEAR(max_r, teeth.tip_radius(), 1e-9);
  EXPECT_NEAR(min_r, teeth.root_radius(), 1e-9);
}

// ---------------------------------------------------------------------------------------------

TEST(PartLibrary, KindNames) {
  EXPECT_EQ(LibraryKindName(PlateSpec{}), "plate");
  EXPECT_EQ(LibraryKindName(LBracketSpec{}), "l_bracket");
  EXPECT_EQ(LibraryKindName(HexBoltSpec{}), "hex_bolt");
  EXPECT_EQ(LibraryKindName(HexNutSpec{}), "hex_nut");
  EXPECT_EQ(LibraryKindName(WasherSpec{}), "washer");
  EXPECT_EQ(LibraryKindName(SetscrewSpec{}), "setscrew");
  EXPECT_EQ(LibraryKindName(ShaftSpec{}), "shaft");
  EXPECT_EQ(LibraryKindName(SpurGearSpec{}), "spur_gear");
  EXPECT_EQ(LibraryKindName(RingGearSpec{}), "ring_gear");
  EXPECT_EQ(LibraryKindName(WormSpec{}), "worm");
  EXPECT_EQ(LibraryKindName(WormWheelSpec{}), "worm_wheel");
  EXPECT_EQ(LibraryKindName(RackSpec{}), "rack");
}

TEST(PartLibrary, PlateWithHoles) {
  PlateSpec spec;
  spec.length = 100;
  spec.width = 60;
  spec.thickness = 8;
  spec.holes = {{"", {-30, 0}, 10}, {"mount", {30, 10}, 12}, {"", {0, -15}, 6}};
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  EXPECT_EQ(EulerCharacteristic(part.mesh), 2 - 2 * 3);
  ExpectBox(part.mesh, {-50, -30, 0}, {50, 30, 8});

  double polygonal = 100.0 * 60.0, facet_loss = 0.0;
  for (const LibraryHole& h : spec.holes) {
    const double r = h.diameter / 2.0;
    const double area = InscribedArea(r, DefaultSegments(h.diameter));
    polygonal -= area;
    facet_loss += kPi * r * r - area;
  }
  const double volume = part.mesh.SignedVolume();
  EXPECT_NEAR(volume, polygonal * 8.0, 1e-9 * volume);
  double exact = 100.0 * 60.0 * 8.0;
  for (const LibraryHole& h : spec.holes) exact -= kPi * h.diameter * h.diameter / 4.0 * 8.0;
  EXPECT_GE(volume, exact);
  EXPECT_LE(volume - exact, facet_loss * 8.0 * (1 + 1e-9));

  ASSERT_EQ(part.features.size(), 5u);
  const char* ids[] = {"hole1", "mount", "hole3"};
  for (int i = 0; i < 3; ++i) {
    const Feature& hole = Find(part, ids[i]);
    const LibraryHole& h = spec.holes[i];
    ExpectAxial(hole, FeatureKind::kHole, {h.center.x(), h.center.y(), 8},
                -Eigen::Vector3d::UnitZ(), 8);
    EXPECT_TRUE(hole.through);
    EXPECT_EQ(hole.diameter, h.diameter);
  }
  ExpectAxial(Find(part, "top"), FeatureKind::kFace, {0, 0, 8}, Eigen::Vector3d::UnitZ(), 0);
  ExpectAxial(Find(part, "bottom"), FeatureKind::kFace, {0, 0, 0}, -Eigen::Vector3d::UnitZ(), 0);
  EXPECT_EQ(Find(part, "top").width, 100);
  EXPECT_EQ(Find(part, "top").height, 60);
}

TEST(PartLibrary, PlateWithoutHoles) {
  const LibraryPart part = MakeLibraryPart(PlateSpec{10, 20, 3, {}, 0});
  ExpectSolid(part.mesh);
  EXPECT_NEAR(part.mesh.SignedVolume(), 600.0, 1e-9);
  EXPECT_EQ(part.mesh.faces.size(), 12u);
}

TEST(PartLibrary, LBracket) {
  LBracketSpec spec;
  spec.length = 80;
  spec.height = 60;
  spec.width = 40;
  spec.thickness = 5;
  spec.base_holes = {{"", {50, 0}, 8}, {"", {70, 10}, 6}};
  spec.upright_holes = {{"", {0, 40}, 10}};
  spec.segments = 48;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  // Two shells (base leg with the corner; upright above it): 2 + 2, minus 2 per hole.
  EXPECT_EQ(EulerCharacteristic(part.mesh), 4 - 2 * 3);
  ExpectBox(part.mesh, {0, -20, 0}, {80, 20, 60});
  const double holes = InscribedArea(4, 48) + InscribedArea(3, 48) + InscribedArea(5, 48);
  const double expected = 40.0 * (80.0 * 5.0 + 5.0 * 55.0) - 5.0 * holes;
  EXPECT_NEAR(part.mesh.SignedVolume(), expected, 1e-9 * expected);

  ExpectAxial(Find(part, "base_hole1"), FeatureKind::kHole, {50, 0, 5}, -Eigen::Vector3d::UnitZ(),
              5);
  ExpectAxial(Find(part, "base_hole2"), FeatureKind::kHole, {70, 10, 5}, -Eigen::Vector3d::UnitZ(),
              5);
  ExpectAxial(Find(part, "upright_hole1"), FeatureKind::kHole, {5, 0, 40},
              -Eigen::Vector3d::UnitX(), 5);
  EXPECT_EQ(Find(part, "upright_hole1").diameter, 10);
  EXPECT_TRUE(Find(part, "upright_hole1").through);
  EXPECT_EQ(Find(part, "base_bottom").axis, -Eigen::Vector3d::UnitZ());
  EXPECT_EQ(Find(part, "base_top").axis, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(Find(part, "upright_outer").axis, -Eigen::Vector3d::UnitX());
  EXPECT_EQ(Find(part, "upright_inner").axis, Eigen::Vector3d::UnitX());
  EXPECT_NEAR(Find(part, "base_top").origin.z(), 5, 1e-12);
  EXPECT_NEAR(Find(part, "upright_inner").origin.x(), 5, 1e-12);
  for (const Feature& f : part.features) EXPECT_NEAR(f.axis.norm(), 1.0, 1e-12) << f.id;
}

TEST(PartLibrary, HexBoltIsoDefaults) {
  HexBoltSpec spec;
  spec.diameter = 8;
  spec.length = 40;
  spec.thread_length = 22;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  EXPECT_EQ(EulerCharacteristic(part.mesh), 2);  // one shell: head and shank joined
  // ISO 4017 M8: s = 13, k = 5.3; hexagon corners on the x axis.
  ExpectBox(part.mesh, {-13 / std::sqrt(3.0), -6.5, -5.3}, {13 / std::sqrt(3.0), 6.5, 40});
  const double expected = HexagonArea(13) * 5.3 + InscribedArea(4, 32) * 40;
  EXPECT_NEAR(part.mesh.SignedVolume(), expected, 1e-9 * expected);

  const Feature& thread = Find(part, "thread");
  ExpectAxial(thread, FeatureKind::kThread, {0, 0, 18}, Eigen::Vector3d::UnitZ(), 22);
  EXPECT_EQ(thread.diameter, 8);
  EXPECT_EQ(thread.pitch, 1.25);
  EXPECT_EQ(thread.hand, Hand::kRight);
  EXPECT_EQ(thread.fastening, Fastening::kTight);
  const Feature& shank = Find(part, "shank");
  ExpectAxial(shank, FeatureKind::kShaft, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 18);
  EXPECT_EQ(shank.diameter, 8);
  ExpectAxial(Find(part, "head"), FeatureKind::kFace, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 0);
}

TEST(PartLibrary, HexBoltFullyThreadedExplicitSizes) {
  HexBoltSpec spec;
  spec.diameter = 6;
  spec.pitch = 0.75;
  spec.length = 20;
  spec.across_flats = 11;
  spec.head_height = 4.5;
  spec.hand = Hand::kLeft;
  spec.fastening = Fastening::kLoose;
  spec.segments = 40;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  const double expected = HexagonArea(11) * 4.5 + InscribedArea(3, 40) * 20;
  EXPECT_NEAR(part.mesh.SignedVolume(), expected, 1e-9 * expected);
  EXPECT_EQ(part.features.size(), 2u);  // thread and head: no shank
  const Feature& thread = Find(part, "thread");
  ExpectAxial(thread, FeatureKind::kThread, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 20);
  EXPECT_EQ(thread.pitch, 0.75);
  EXPECT_EQ(thread.hand, Hand::kLeft);
  EXPECT_EQ(thread.fastening, Fastening::kLoose);
}

TEST(PartLibrary, HexBoltInterpolatesIsoHead) {
  HexBoltSpec spec;
  spec.diameter = 7;  // between M6 (s 10, k 4) and M8 (s 13, k 5.3)
  spec.length = 30;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  ExpectBox(part.mesh, {-11.5 / std::sqrt(3.0), -5.75, -4.65}, {11.5 / std::sqrt(3.0), 5.75, 30});
  EXPECT_EQ(Find(part, "thread").pitch, 1.0);  // ISO 261: M7 x 1
}

TEST(PartLibrary, HexNutIsoDefaults) {
  HexNutSpec spec;
  spec.diameter = 10;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  EXPECT_EQ(EulerCharacteristic(part.mesh), 0);  // one shell with a through hole
  // ISO 4032 M10: s = 16, m = 8.4.
  ExpectBox(part.mesh, {-16 / std::sqrt(3.0), -8, 0}, {16 / std::sqrt(3.0), 8, 8.4});
  const double expected = (HexagonArea(16) - InscribedArea(5, DefaultSegments(10))) * 8.4;
  EXPECT_NEAR(part.mesh.SignedVolume(), expected, 1e-9 * expected);
  const Feature& thread = Find(part, "thread");
  ExpectAxial(thread, FeatureKind::kTappedHole, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 8.4);
  EXPECT_TRUE(thread.through);
  EXPECT_EQ(thread.diameter, 10);
  EXPECT_EQ(thread.pitch, 1.5);
  ExpectAxial(Find(part, "bottom"), FeatureKind::kFace, {0, 0, 0}, -Eigen::Vector3d::UnitZ(), 0);
  ExpectAxial(Find(part, "top"), FeatureKind::kFace, {0, 0, 8.4}, Eigen::Vector3d::UnitZ(), 0);

  // Between M14 and M16 the ISO across flats is 1.5 d, which puts a 4-facet bore's corner
  // exactly on a chord between two hexagon corners.
  spec.diameter = 15;
  spec.segments = 4;
  const LibraryPart square_bore = MakeLibraryPart(spec);
  ExpectSolid(square_bore.mesh);
  EXPECT_NEAR(square_bore.mesh.SignedVolume(), (HexagonArea(22.5) - 2 * 7.5 * 7.5) * 13.8, 1e-9);
}

TEST(PartLibrary, Washer) {
  const LibraryPart part = MakeLibraryPart(WasherSpec{8.4, 16, 1.6, 0});
  ExpectSolid(part.mesh);
  const int n = DefaultSegments(16);
  EXPECT_EQ(n, 51);
  const double expected = (InscribedArea(8, n) - InscribedArea(4.2, n)) * 1.6;
  EXPECT_NEAR(part.mesh.SignedVolume(), expected, 1e-9 * expected);
  const double exact = kPi * (64 - 4.2 * 4.2) * 1.6;
  EXPECT_NEAR(part.mesh.SignedVolume(), exact,
              kPi * 64 * (1 - std::sin(2 * kPi / n) / (2 * kPi / n)) * 1.6);
  ExpectRoundBox(part.mesh, 8, n, 0, 1.6);
  const Feature& bore = Find(part, "bore");
  ExpectAxial(bore, FeatureKind::kHole, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 1.6);
  EXPECT_TRUE(bore.through);
  EXPECT_EQ(bore.diameter, 8.4);
  ExpectAxial(Find(part, "bottom"), FeatureKind::kFace, {0, 0, 0}, -Eigen::Vector3d::UnitZ(), 0);
  ExpectAxial(Find(part, "top"), FeatureKind::kFace, {0, 0, 1.6}, Eigen::Vector3d::UnitZ(), 0);
}

TEST(PartLibrary, SetscrewIsoCoarsePitch) {
  const std::pair<double, double> coarse[] = {{3, 0.5},  {4, 0.7},  {5, 0.8},   {6, 1.0},
                                              {8, 1.25}, {10, 1.5}, {12, 1.75}, {16, 2.0},
                                              {20, 2.5}, {24, 3.0}};
  for (const auto& [d, pitch] : coarse) {
    SetscrewSpec spec;
    spec.diameter = d;
    spec.length = 10;
    const LibraryPart part = MakeLibraryPart(spec);
    EXPECT_EQ(Find(part, "thread").pitch, pitch) << "M" << d;
  }
  SetscrewSpec spec;
  spec.diameter = 6;
  spec.length = 10;
  spec.hand = Hand::kLeft;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  EXPECT_NEAR(part.mesh.SignedVolume(), InscribedArea(3, 32) * 10, 1e-9);
  ExpectRoundBox(part.mesh, 3, 32, 0, 10);
  const Feature& thread = Find(part, "thread");
  ExpectAxial(thread, FeatureKind::kThread, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 10);
  EXPECT_EQ(thread.diameter, 6);
  EXPECT_EQ(thread.hand, Hand::kLeft);
}

TEST(PartLibrary, ShaftAndDefaultSegments) {
  const LibraryPart part = MakeLibraryPart(ShaftSpec{20, 100, true, 0});
  ExpectSolid(part.mesh);
  EXPECT_EQ(EulerCharacteristic(part.mesh), 2);
  EXPECT_NEAR(part.mesh.SignedVolume(), InscribedArea(10, 63) * 100, 1e-9 * 31400);
  const Feature& shaft = Find(part, "shaft");
  ExpectAxial(shaft, FeatureKind::kShaft, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 100);
  EXPECT_EQ(shaft.diameter, 20);
  EXPECT_TRUE(shaft.retained);
  // One ring of vertices per end: the facet count is max(32, ceil(pi d)), at most 128.
  EXPECT_EQ(part.mesh.vertices.size(), 2u * 63);
  EXPECT_EQ(MakeLibraryPart(ShaftSpec{5, 10, false, 0}).mesh.vertices.size(), 2u * 32);
  EXPECT_EQ(MakeLibraryPart(ShaftSpec{50, 10, false, 0}).mesh.vertices.size(), 2u * 128);
  EXPECT_EQ(MakeLibraryPart(ShaftSpec{50, 10, false, 7}).mesh.vertices.size(), 2u * 7);
}

TEST(PartLibrary, SpurGearInvoluteTeeth) {
  SpurGearSpec spec;
  spec.teeth = 20;
  spec.module = 1.5;
  spec.face_width = 5;
  spec.bore_diameter = 6;
  spec.segments = 96;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  EXPECT_EQ(EulerCharacteristic(part.mesh), 0);
  const Toothing teeth = ExternalTeeth(20, 1.5);
  ExpectInvoluteFlanks(part.mesh, teeth, 3.0 + 1e-6, 1e9);
  ExpectBox(part.mesh, {-16.5, -16.5, 0}, {16.5, 16.5, 5}, 16.5 * (1 - std::cos(kPi / 96)));

  // Volume: the exact outline area less at most the chords' loss, less the bore polygon.
  const double outline = part.mesh.SignedVolume() / 5.0 + InscribedArea(3.0, 96);
  EXPECT_LE(outline, teeth.Area() * (1 + 1e-9));
  EXPECT_GE(outline, teeth.Area() - teeth.ChordLossBound(96));

  const Feature& gear = Find(part, "teeth");
  ExpectAxial(gear, FeatureKind::kGear, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 5);
  EXPECT_EQ(gear.teeth, 20);
  EXPECT_EQ(gear.module, 1.5);
  EXPECT_FALSE(gear.internal);
  const Feature& bore = Find(part, "bore");
  ExpectAxial(bore, FeatureKind::kHole, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 5);
  EXPECT_TRUE(bore.through);
  EXPECT_EQ(bore.diameter, 6);
}

TEST(PartLibrary, SpurGearMatchesBosl2Meshes) {
  // External meshes made with BOSL2's spur_gear (../shared/data/gears/manifest.json: gears
  // without profile shift, bores with $fn=48, volumes as listed there). BOSL2 differs from
  // this model in the root only: its root is cut by the rounded tip of the generating rack (a
  // trochoid fillet) where this model has a sharp corner, and its clearance puts the root
  // circle a few micrometres lower. Both add material to BOSL2's gears, chiefly the fillets: a
  // rack tip radius of 0.38 m fills at most (1 - pi/4) (0.38 m)^2 of each of the 2z root
  // corners (a right angle).
  struct Reference {
    int teeth;
    double module, face_width, bore, volume;
  };
  for (const Reference& ref :
       {Reference{20, 1.5, 5, 6, 3315.0544}, Reference{20, 1.0, 6, 5, 1725.7373},
        Reference{31, 1.0, 6, 5, 4358.7566}}) {
    SpurGearSpec spec;
    spec.teeth = ref.teeth;
    spec.module = ref.module;
    spec.face_width = ref.face_width;
    spec.bore_diameter = ref.bore;
    spec.segments = 48;
    const LibraryPart part = MakeLibraryPart(spec);
    ExpectSolid(part.mesh);
    const double fillets =
        2 * ref.teeth * (1 - kPi / 4) * std::pow(0.38 * ref.module, 2) * ref.face_width;
    EXPECT_GT(ref.volume, part.mesh.SignedVolume()) << ref.teeth;
    EXPECT_LT(ref.volume - part.mesh.SignedVolume(), 1.2 * fillets) << ref.teeth;
  }
}

TEST(PartLibrary, SpurGearsOfManySizesAreSolid) {
  for (int z : {6, 7, 8, 9, 10, 11, 12, 13, 15, 17, 20, 25, 30, 41, 42, 43, 50, 80, 150}) {
    for (double m : {0.5, 1.0, 3.0}) {
      SpurGearSpec spec;
      spec.teeth = z;
      spec.module = m;
      spec.face_width = 4 * m;
      const LibraryPart plain = MakeLibraryPart(spec);
      ExpectSolid(plain.mesh);
      const Toothing teeth = ExternalTeeth(z, m);
      const int n = DefaultSegments(m * (z + 2));
      const double area = plain.mesh.SignedVolume() / spec.face_width;
      EXPECT_LE(area, teeth.Area() * (1 + 1e-9)) << z << " " << m;
      EXPECT_GE(area, teeth.Area() - teeth.ChordLossBound(n)) << z << " " << m;
      spec.bore_diameter = 0.5 * teeth.root_radius();
      ExpectSolid(MakeLibraryPart(spec).mesh);
    }
  }
  SpurGearSpec spec;
  spec.teeth = 24;
  spec.module = 2;
  spec.face_width = 10;
  spec.pressure_angle = 25.0 * kPi / 180.0;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  ExpectInvoluteFlanks(part.mesh, ExternalTeeth(24, 2, spec.pressure_angle), 0, 1e9);
}

TEST(PartLibrary, RingGearInternalTeeth) {
  RingGearSpec spec;
  spec.teeth = 60;
  spec.module = 1;
  spec.face_width = 8;
  spec.outer_diameter = 80;
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  EXPECT_EQ(EulerCharacteristic(part.mesh), 0);
  const int n = DefaultSegments(80);
  EXPECT_EQ(n, 128);
  ExpectRoundBox(part.mesh, 40, n, 0, 8);
  // The tooth spaces have the shape of external teeth 1.25 m high above the pitch circle;
  // the internal teeth's tips are 1 m inside it.
  const Toothing spaces{60, 1.0, kTwentyDegrees, 1.25, 1.0};
  ExpectInvoluteFlanks(part.mesh, spaces, 0, 39);
  const double material = part.mesh.SignedVolume() / 8.0;
  EXPECT_GE(material, InscribedArea(40, n) - spaces.Area() * (1 + 1e-9));
  EXPECT_LE(material, InscribedArea(40, n) - spaces.Area() + spaces.ChordLossBound(n));
  const Feature& teeth = Find(part, "teeth");
  ExpectAxial(teeth, FeatureKind::kGear, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 8);
  EXPECT_TRUE(teeth.internal);
  EXPECT_EQ(teeth.teeth, 60);
  EXPECT_EQ(teeth.module, 1);

  for (int z : {12, 20, 33, 34, 35, 100}) {
    spec.teeth = z;
    spec.outer_diameter = z + 10;
    ExpectSolid(MakeLibraryPart(spec).mesh);
  }
}

TEST(PartLibrary, WormWheel) {
  const LibraryPart part = MakeLibraryPart(WormWheelSpec{30, 2, 12, 10, 0});
  ExpectSolid(part.mesh);
  const Toothing teeth = ExternalTeeth(30, 2);
  ExpectInvoluteFlanks(part.mesh, teeth, 5 + 1e-6, 1e9);
  const int n = DefaultSegments(64);
  const double outline = part.mesh.SignedVolume() / 12.0 + InscribedArea(5, n);
  EXPECT_LE(outline, teeth.Area() * (1 + 1e-9));
  EXPECT_GE(outline, teeth.Area() - teeth.ChordLossBound(n));
  const Feature& wheel = Find(part, "teeth");
  ExpectAxial(wheel, FeatureKind::kWormWheel, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 12);
  EXPECT_EQ(wheel.teeth, 30);
  EXPECT_EQ(wheel.module, 2);
  ExpectAxial(Find(part, "bore"), FeatureKind::kHole, {0, 0, 0}, Eigen::Vector3d::UnitZ(), 12);
}

// The worm's axial profile as documented: a thread of axial pitch pi m centred on u = 0,
// thickness pi m / 2 on the pitch line, 20 degree flanks, addendum m, dedendum 1.25 m.
double WormProfile(double u, double m, double pitch_radius) {
  const double p = kPi * m;
  const double w = std::fmod(std::fmod(u, p) + p, p);
  const double from_centre = std::min(w, p - w);
  const double r = pitch_radius + (p / 4 - from_centre) / std::tan(kTwentyDegrees);
  return std::clamp(r, pitch_radius - 1.25 * m, pitch_radius + m);
}

void CheckWorm(const WormSpec& spec, int expected_segments) {
  SCOPED_TRACE("starts " + std::to_string(spec.starts));
  const LibraryPart part = MakeLibraryPart(spec);
  ExpectSolid(part.mesh);
  const double m = spec.module, rp = spec.pitch_diameter / 2, L = spec.length;
  const double lead = spec.starts * kPi * m;
  const double hand = spec.hand == Hand::kRight ? 1.0 : -1.0;
  const double rb = spec.bore_diameter / 2;
  ExpectBox(part.mesh, {-(rp + m), -(rp + m), 0}, {rp + m, rp + m, L}, 0.05 * m);

  // Every thread vertex lies on r = P(z - lead theta / 2 pi) (mirrored for a left hand).
  for (const Eigen::Vector3d& v : part.mesh.vertices) {
    const double r = v.head<2>().norm();
    if (rb > 0 && r < rb + 1e-9) continue;
    const double theta = std::atan2(v.y(), v.x());
    ASSERT_NEAR(r, WormProfile(v.z() - hand * lead * theta / (2 * kPi), m, rp), 1e-9)
        << v.transpose();
  }

  // Volume: every z-slice of the helical solid has the area of the polar region r(theta),
  // (1/2) integral of r^2 over theta = pi <P^2> (u runs over whole pitches as theta goes
  // round), the same as the solid of revolution of the axial profile.
  const double p = kPi * m;
  const int samples = 200000;
  double mean_square = 0.0;
  for (int i = 0; i < samples; ++i) {
    mean_square += std::pow(WormProfile((i + 0.5) * p / samples, m, rp), 2) / samples;
  }
  const double exact = L * (kPi * mean_square - kPi * rb * rb);
  // Discretisation: n angular facets of d = 2 pi / n lose at most a fraction 1 - sin(d)/d of
  // a slice's area to their chords; grid neighbours are at most du = lead / n apart in the
  // profile coordinate, so the linear interpolation across each of the 4 profile corners per
  // pitch (slope change 1/tan 20 deg) misses an area of at most (1/tan 20) (2 du)^2 / 8 in the
  // axial section, swept round at radius <= r_tip.
  const int n = expected_segments;
  const double d = 2 * kPi / n, du = lead / n;
  const double chords = L * kPi * (rp + m) * (rp + m) * (1 - std::sin(d) / d);
  const double corners =
      L / p * 4 * (2 * du) * (2 * du) / 8 / std::tan(kTwentyDegrees) * 2 * kPi * (rp + m);
  const double bore = L * (kPi * rb * rb - (rb > 0 ? InscribedArea(rb, n) : 0.0));
  EXPECT_NEAR(part.mesh.SignedVolume(), exact, chords + corners + bore);

  const Feature& worm = Find(part, "worm");
  ExpectAxial(worm, FeatureKind::kWorm, {0, 0, 0}, Eigen::Vector3d::UnitZ(), L);
  EXPECT_EQ(worm.starts, spec.starts);
  EXPECT_EQ(worm.module, m);
  EXPECT_EQ(worm.pitch_diameter, spec.pitch_diameter);
  EXPECT_EQ(worm.hand, spec.hand);
  if (rb > 0) {
    ExpectAxial(Find(part, "bore"), FeatureKind::kHole, {0, 0, 0}, Eigen::Vector3d::UnitZ(), L);
  }
}

TEST(PartLibrary, WormRightHandSingleStart) {
  WormSpec spec;
  spec.module = 2;
  spec.pitch_diameter = 20;
  spec.length = 30;
  CheckWorm(spec, DefaultSegments(24));
}

TEST(PartLibrary, WormLeftHandMultiStartWithBore) {
  WormSpec spec;
  spec.starts = 3;
  spec.module = 1;
  spec.pitch_diameter = 12;
  spec.length = 25;
  spec.bore_diameter = 4;
  spec.hand = Hand::kLeft;
  CheckWorm(spec, 48);  // at least 16 facets per start
  spec.starts = 2;
  spec.hand = Hand::kRight;
  spec.segments = 40;
  CheckWorm(spec, 40);
}

// The rack's tooth profile as documented: teeth centred on x = (k + 1/2) pi m, 20 degree
// flanks through the pitch line at a quarter pitch from the centre, tips at m, roots at
// -1.25 m.
double RackTop(double x, double m, double pressure_angle) {
  const double p = kPi * m;
  const double from_centre = std::abs(x - p * (std::floor(x / p) + 0.5));
  return std::clamp((p / 4 - from_centre) / std::tan(pressure_angle), -1.25 * m, m);
}

TEST(PartLibrary, Rack) {
  for (const double length : {50.0, 3.3 * kPi * 2, 2 * kPi * 2, 1.0}) {
    RackSpec spec;
    spec.module = 2;
    spec.length = length;
    spec.face_width = 10;
    const LibraryPart part = MakeLibraryPart(spec);
    ExpectSolid(part.mesh);
    const double depth = 4.25 * 2;  // default body depth below the pitch line
    double top = -depth;
    for (const Eigen::Vector3d& v : part.mesh.vertices) {
      top = std::max(top, v.y());
      if (v.y() > -depth) {
        EXPECT_NEAR(v.y(), RackTop(v.x(), 2, kTwentyDegrees), 1e-9);
      }
    }
    ExpectBox(part.mesh, {0, -depth, -5}, {length, top, 5});
    if (length >= 2 * kPi) {
      EXPECT_NEAR(top, 2.0, 1e-12);
    }
    const int samples = 1000000;
    double area = 0.0;
    for (int i = 0; i < samples; ++i) {
      area += (RackTop((i + 0.5) * length / samples, 2, kTwentyDegrees) + depth) * length / samples;
    }
    EXPECT_NEAR(part.mesh.SignedVolume(), 10 * area, 1e-6 * 10 * area) << length;
    const Feature& teeth = Find(part, "teeth");
    ExpectAxial(teeth, FeatureKind::kRack, {0, 0, 0}, Eigen::Vector3d::UnitX(), length);
    EXPECT_EQ(teeth.module, 2);
    EXPECT_EQ(teeth.normal, Eigen::Vector3d::UnitY());
  }
}

TEST(PartLibrary, BadParametersThrow) {
  PlateSpec plate{90, 60, 8, {{"", {0, 0}, 10}, {"", {40, 0}, 12}}, 0};
  EXPECT_EQ(Message([&] { MakeLibraryPart(plate); }),
            "plate: hole2 (diameter 12 at (40, 0)) does not fit inside the plate");
  plate.holes[1].center = {9, 0};
  EXPECT_EQ(Message([&] { MakeLibraryPart(plate); }),
            "plate: hole2 (diameter 12 at (9, 0)) overlaps hole1");
  plate.holes[1] = {"top", {30, 0}, 5};
  EXPECT_EQ(Message([&] { MakeLibraryPart(plate); }), "plate: duplicate feature id top");
  plate.holes.clear();
  plate.thickness = -1;
  EXPECT_EQ(Message([&] { MakeLibraryPart(plate); }), "plate: thickness -1 must be positive");
  plate.thickness = std::nan("");
  EXPECT_EQ(Message([&] { MakeLibraryPart(plate); }), "plate: thickness nan must be positive");

  LBracketSpec bracket{80, 60, 40, 5, {{"", {4, 0}, 6}}, {}, 0};
  EXPECT_EQ(Message([&] { MakeLibraryPart(bracket); }),
            "l_bracket: base_hole1 (diameter 6 at (4, 0)) does not fit inside the base leg "
            "beside the upright (x in [5, 80], y in [-20, 20])");
  bracket.base_holes.clear();
  bracket.upright_holes = {{"", {0, 6}, 6}};
  EXPECT_NE(Message([&] { MakeLibraryPart(bracket); }).find("upright_hole1"), std::string::npos);
  bracket.upright_holes.clear();
  bracket.height = 5;
  EXPECT_EQ(Message([&] { MakeLibraryPart(bracket); }),
            "l_bracket: height 5 must exceed the thickness 5");

  SpurGearSpec gear{30, 1, 10, 30, kTwentyDegrees, 0};
  EXPECT_EQ(Message([&] { MakeLibraryPart(gear); }),
            "spur_gear: bore_diameter 30 must be smaller than the root diameter 27.5");
  gear.teeth = 5;
  EXPECT_EQ(Message([&] { MakeLibraryPart(gear); }), "spur_gear: teeth 5 must be at least 6");
  gear.teeth = 30;
  gear.bore_diameter = 0;
  gear.pressure_angle = 0;
  EXPECT_NE(Message([&] { MakeLibraryPart(gear); }).find("spur_gear: pressure_angle 0"),
            std::string::npos);
  gear.pressure_angle = kTwentyDegrees;
  gear.segments = 2;
  EXPECT_EQ(Message([&] { MakeLibraryPart(gear); }),
            "spur_gear: segments 2 must be 0 or at least 3");
  EXPECT_EQ(Message([&] {
              MakeLibraryPart(WormWheelSpec{10, 0, 5, 0, 0});
            }),
            "worm_wheel: module 0 must be positive");

  EXPECT_EQ(Message([&] {
              MakeLibraryPart(RingGearSpec{40, 1, 5, 42, kTwentyDegrees, 0});
            }),
            "ring_gear: outer_diameter 42 must be larger than the root diameter 42.5");
  EXPECT_EQ(Message([&] {
              MakeLibraryPart(RingGearSpec{6, 1, 5, 20, kTwentyDegrees, 0});
            }),
            "ring_gear: the involute flanks meet below the tip radius 4.25 (pointed teeth)");

  HexBoltSpec bolt;
  bolt.diameter = 8;
  bolt.length = 20;
  bolt.thread_length = 25;
  EXPECT_EQ(Message([&] { MakeLibraryPart(bolt); }),
            "hex_bolt: thread_length 25 must not exceed the length 20");
  bolt.thread_length = 0;
  bolt.across_flats = 8;
  EXPECT_EQ(Message([&] { MakeLibraryPart(bolt); }),
            "hex_bolt: across_flats 8 must be larger than the diameter 8");
  bolt.across_flats = 0;
  bolt.pitch = -1;
  EXPECT_EQ(Message([&] { MakeLibraryPart(bolt); }), "hex_bolt: pitch -1 must not be negative");
  EXPECT_EQ(Message([&] {
              MakeLibraryPart(HexNutSpec{0, 0, 0, 0, Hand::kRight, 0});
            }),
            "hex_nut: diameter 0 must be positive");
  EXPECT_EQ(Message([&] {
              MakeLibraryPart(WasherSpec{10, 10, 1, 0});
            }),
            "washer: inner_diameter 10 must be smaller than the outer_diameter 10");
  EXPECT_EQ(Message([&] {
              MakeLibraryPart(ShaftSpec{5, -1, false, 0});
            }),
            "shaft: length -1 must be positive");
  EXPECT_EQ(Message([&] {
              MakeLibraryPart(SetscrewSpec{4, 0, 0, Hand::kRight, {}, 0});
            }),
            "setscrew: length 0 must be positive");

  WormSpec worm;
  worm.starts = 0;
  worm.module = 1;
  worm.pitch_diameter = 10;
  worm.length = 10;
  EXPECT_EQ(Message([&] { MakeLibraryPart(worm); }), "worm: starts 0 must be at least 1");
  worm.starts = 1;
  worm.pitch_diameter = 2;
  EXPECT_NE(Message([&] { MakeLibraryPart(worm); }).find("worm: pitch_diameter 2 must exceed"),
            std::string::npos);
  worm.pitch_diameter = 10;
  worm.bore_diameter = 8;
  EXPECT_EQ(Message([&] { MakeLibraryPart(worm); }),
            "worm: bore_diameter 8 must be smaller than the root diameter 7.5");

  RackSpec rack{1, 20, 5, 0, 0.7};
  EXPECT_EQ(Message([&] { MakeLibraryPart(rack); }),
            "rack: pressure_angle 0.7 gives pointed teeth");
  rack.pressure_angle = kTwentyDegrees;
  rack.height = 1;
  EXPECT_EQ(Message([&] { MakeLibraryPart(rack); }),
            "rack: height 1 must exceed the dedendum 1.25 modules (1.25)");
}

}  // namespace
}  // namespace mechanist
