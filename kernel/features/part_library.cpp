#include "kernel/features/part_library.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "kernel/features/involute_gear.h"
#include "kernel/mesh/mesh_builder.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

constexpr double kPi = std::numbers::pi;
// Standard pressure angle of worms and worm wheels (their specs have no field for it).
constexpr double kTwentyDegrees = 20.0 * kPi / 180.0;
// Vertices per involute flank: enough for the flank's chord error to stay well below the
// tolerances assemblies are checked with (a few micrometres at module 1).
constexpr int kFlankPoints = 8;

std::invalid_argument Error(const std::string& message) { return std::invalid_argument(message); }

void RequirePositive(double value, std::string_view name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(fmt::format("{} {} must be positive", name, FormatNumber(value)));
  }
}

// Sizes where 0 selects a default.
void RequireNonNegative(double value, std::string_view name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(fmt::format("{} {} must not be negative", name, FormatNumber(value)));
  }
}

void RequireTeeth(int teeth) {
  if (teeth < 6) throw Error(fmt::format("teeth {} must be at least 6", teeth));
}

void RequirePressureAngle(double angle) {
  if (!(angle > 0.0 && angle < kPi / 2)) {
    throw Error(
        fmt::format("pressure_angle {} must be between 0 and pi/2 radians", FormatNumber(angle)));
  }
}

void RequireSegments(int segments) {
  if (segments < 0 || segments == 1 || segments == 2) {
    throw Error(fmt::format("segments {} must be 0 or at least 3", segments));
  }
}

// The facet count of a full circle of `diameter` mm: as requested, else about one facet per
// millimetre of circumference, at least 32 and at most 128.
int CircleSegments(int requested, double diameter) {
  if (requested > 0) return requested;
  return std::clamp(static_cast<int>(std::ceil(kPi * diameter)), 32, 128);
}

// A bore of `segments` facets (vertices on its circle) must stay inside the faceted root
// circle, whose chords come as close to the axis as root_radius cos(pi / segments).
void RequireBoreInsideRoot(double bore_diameter, double root_diameter, int segments) {
  if (!(bore_diameter < root_diameter)) {
    throw Error(fmt::format("bore_diameter {} must be smaller than the root diameter {}",
                            FormatNumber(bore_diameter), FormatNumber(root_diameter)));
  }
  const double faceted = root_diameter * std::cos(kPi / segments);
  if (!(bore_diameter < faceted)) {
    throw Error(fmt::format(
        "bore_diameter {} must be smaller than the faceted root diameter {} ({} segments)",
        FormatNumber(bore_diameter), FormatNumber(faceted), segments));
  }
}

// ISO 4014/4017 hex head (across flats s, head height k) and ISO 4032 nut thickness m, mm.
struct HexSize {
  double diameter, across_flats, head_height, nut_thickness;
};
constexpr std::array<HexSize, 20> kIsoHexSizes = {{
    {1.6, 3.2, 1.1, 1.3}, {2, 4, 1.4, 1.6},     {2.5, 5, 1.7, 2},    {3, 5.5, 2, 2.4},
    {4, 7, 2.8, 3.2},     {5, 8, 3.5, 4.7},     {6, 10, 4, 5.2},     {8, 13, 5.3, 6.8},
    {10, 16, 6.4, 8.4},   {12, 18, 7.5, 10.8},  {14, 21, 8.8, 12.8}, {16, 24, 10, 14.8},
    {18, 27, 11.5, 15.8}, {20, 30, 12.5, 18},   {22, 34, 14, 19.4},  {24, 36, 15, 21.5},
    {27, 41, 17, 23.8},   {30, 46, 18.7, 25.6}, {33, 50, 21, 28.7},  {36, 55, 22.5, 31},
}};

// The ISO sizes for `diameter`: interpolated linearly between listed diameters, scaled in
// proportion to the nearest listed size outside the table (M1.6 .. M36).
HexSize IsoHexSize(double diameter) {
  auto scaled = [diameter](const HexSize& size) {
    const double f = diameter / size.diameter;
    return HexSize{diameter, f * size.across_flats, f * size.head_height, f * size.nut_thickness};
  };
  if (diameter <= kIsoHexSizes.front().diameter) return scaled(kIsoHexSizes.front());
  if (diameter >= kIsoHexSizes.back().diameter) return scaled(kIsoHexSizes.back());
  const auto upper =
      std::find_if(kIsoHexSizes.begin(), kIsoHexSizes.end(),
                   [diameter](const HexSize& size) { return size.diameter >= diameter; });
  const HexSize& hi = *upper;
  if (hi.diameter == diameter) return hi;
  const HexSize& lo = *(upper - 1);
  const double f = (diameter - lo.diameter) / (hi.diameter - lo.diameter);
  auto mix = [f](double a, double b) { return a + f * (b - a); };
  return {diameter, mix(lo.across_flats, hi.across_flats), mix(lo.head_height, hi.head_height),
          mix(lo.nut_thickness, hi.nut_thickness)};
}

// ISO 261 coarse pitches, mm, by nominal diameter (first, second and third choice sizes).
constexpr std::array<std::pair<double, double>, 38> kIsoCoarsePitches = {{
    {1, 0.25},   {1.2, 0.25}, {1.4, 0.3}, {1.6, 0.35}, {1.8, 0.35}, {2, 0.4},   {2.2, 0.45},
    {2.5, 0.45}, {3, 0.5},    {3.5, 0.6}, {4, 0.7},    {4.5, 0.75}, {5, 0.8},   {6, 1},
    {7, 1},      {8, 1.25},   {9, 1.25},  {10, 1.5},   {11, 1.5},   {12, 1.75}, {14, 2},
    {16, 2},     {18, 2.5},   {20, 2.5},  {22, 2.5},   {24, 3},     {27, 3},    {30, 3.5},
    {33, 3.5},   {36, 4},     {39, 4},    {42, 4.5},   {45, 4.5},   {48, 5},    {52, 5},
    {56, 5.5},   {60, 5.5},   {64, 6},
}};

// The coarse pitch of the largest listed nominal diameter not above `diameter` (so M7.5 gets
// M7's pitch); below M1 the M1 pitch scaled in proportion.
double IsoCoarsePitch(double diameter) {
  const auto& [d1, p1] = kIsoCoarsePitches.front();
  if (diameter < d1) return p1 * diameter / d1;
  double pitch = p1;
  for (const auto& [d, p] : kIsoCoarsePitches) {
    if (d <= diameter * (1.0 + 1e-9)) pitch = p;
  }
  return pitch;
}

Feature MakeFeature(std::string id, FeatureKind kind, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& axis, double length) {
  Feature f;
  f.id = std::move(id);
  f.kind = kind;
  f.origin = origin;
  f.axis = axis;
  f.length = length;
  return f;
}

// A flat face: `normal` is its outward normal, width and height its extents.
Feature FaceFeature(std::string id, const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                    double width, double height) {
  Feature f = MakeFeature(std::move(id), FeatureKind::kFace, centre, normal, 0.0);
  f.width = width;
  f.height = height;
  return f;
}

// A through hole of `diameter` whose mouth is at `mouth`, going along `axis` for `depth`.
Feature ThroughHole(std::string id, const Eigen::Vector3d& mouth, const Eigen::Vector3d& axis,
                    double depth, double diameter) {
  Feature f = MakeFeature(std::move(id), FeatureKind::kHole, mouth, axis, depth);
  f.diameter = diameter;
  f.through = true;
  return f;
}

// Counter-clockwise rectangle.
Ring2d Rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Counter-clockwise regular hexagon of `across_flats` about the origin, corners on the x axis.
Ring2d Hexagon(double across_flats) {
  return CircleRing({0.0, 0.0}, across_flats / std::sqrt(3.0), 6);
}

// Holes in a rectangular face [lo, hi] (in the face's own 2-D coordinates), named, checked to
// lie strictly inside the face and apart, with their facet counts.
struct PlacedHole {
  std::string id;
  Eigen::Vector2d center;
  double diameter;
  int segments;
};

std::vector<PlacedHole> PlaceHoles(const std::vector<LibraryHole>& holes, const std::string& prefix,
                                   const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                   const std::string& face, int segments) {
  std::vector<PlacedHole> placed;
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const LibraryHole& hole = holes[i];
    PlacedHole p{hole.id.empty() ? fmt::format("{}{}", prefix, i + 1) : hole.id, hole.center,
                 hole.diameter, 0};
    RequirePositive(p.diameter, fmt::format("{} diameter", p.id));
    const std::string what =
        fmt::format("{} (diameter {} at ({}, {}))", p.id, FormatNumber(p.diameter),
                    FormatNumber(p.center.x()), FormatNumber(p.center.y()));
    const double r = p.diameter / 2.0;
    // Strict inequalities: a polygon inscribed in the circle then stays off the face's edges.
    if (!p.center.allFinite() ||
        !((p.center.array() - r > lo.array()).all() && (p.center.array() + r < hi.array()).all())) {
      throw Error(fmt::format("{} does not fit inside {}", what, face));
    }
    for (const PlacedHole& other : placed) {
      if (!((p.center - other.center).norm() > r + other.diameter / 2.0)) {
        throw Error(fmt::format("{} overlaps {}", what, other.id));
      }
    }
    p.segments = CircleSegments(segments, p.diameter);
    placed.push_back(std::move(p));
  }
  return placed;
}

Region2d RegionWithHoles(Ring2d outer, const std::vector<PlacedHole>& holes) {
  Region2d region{std::move(outer), {}};
  for (const PlacedHole& h : holes) {
    region.holes.push_back(CircleRing(h.center, h.diameter / 2.0, h.segments));
  }
  return region;
}

// "[a, b]".
std::string Range(double a, double b) {
  return fmt::format("[{}, {}]", FormatNumber(a), FormatNumber(b));
}

LibraryPart Make(const PlateSpec& spec) {
  RequirePositive(spec.length, "length");
  RequirePositive(spec.width, "width");
  RequirePositive(spec.thickness, "thickness");
  RequireSegments(spec.segments);
  const double hl = spec.length / 2.0, hw = spec.width / 2.0, t = spec.thickness;
  const auto holes =
      PlaceHoles(spec.holes, "hole", {-hl, -hw}, {hl, hw}, "the plate", spec.segments);
  LibraryPart part;
  part.mesh = ExtrudeRegion(RegionWithHoles(Rectangle(-hl, -hw, hl, hw), holes), 0.0, t);
  for (const PlacedHole& h : holes) {
    part.features.push_back(ThroughHole(h.id, {h.center.x(), h.center.y(), t},
                                        -Eigen::Vector3d::UnitZ(), t, h.diameter));
  }
  part.features.push_back(
      FaceFeature("top", {0, 0, t}, Eigen::Vector3d::UnitZ(), spec.length, spec.width));
  part.features.push_back(
      FaceFeature("bottom", {0, 0, 0}, -Eigen::Vector3d::UnitZ(), spec.length, spec.width));
  return part;
}

LibraryPart Make(const LBracketSpec& spec) {
  RequirePositive(spec.length, "length");
  RequirePositive(spec.height, "height");
  RequirePositive(spec.width, "width");
  RequirePositive(spec.thickness, "thickness");
  RequireSegments(spec.segments);
  const double L = spec.length, H = spec.height, hw = spec.width / 2.0, t = spec.thickness;
  if (!(L > t)) {
    throw Error(
        fmt::format("length {} must exceed the thickness {}", FormatNumber(L), FormatNumber(t)));
  }
  if (!(H > t)) {
    throw Error(
        fmt::format("height {} must exceed the thickness {}", FormatNumber(H), FormatNumber(t)));
  }
  const auto base_holes =
      PlaceHoles(spec.base_holes, "base_hole", {t, -hw}, {L, hw},
                 fmt::format("the base leg beside the upright (x in {}, y in {})", Range(t, L),
                             Range(-hw, hw)),
                 spec.segments);
  const auto upright_holes = PlaceHoles(
      spec.upright_holes, "upright_hole", {-hw, t}, {hw, H},
      fmt::format("the upright leg above the base (y in {}, z in {})", Range(-hw, hw), Range(t, H)),
      spec.segments);

  // Two closed shells touching along z = t: the base leg with the corner, and the upright
  // above it, built in its (y, z) face coordinates and extruded along x.
  LibraryPart part;
  part.mesh = ExtrudeRegion(RegionWithHoles(Rectangle(0, -hw, L, hw), base_holes), 0.0, t);
  TriangleMesh upright =
      ExtrudeRegion(RegionWithHoles(Rectangle(-hw, t, hw, H), upright_holes), 0.0, t);
  // (u, v, w) -> (x, y, z) = (w, u, v) is a proper rotation, so orientation is kept.
  for (Eigen::Vector3d& v : upright.vertices) v = Eigen::Vector3d(v.z(), v.x(), v.y());
  part.mesh.Append(upright);

  for (const PlacedHole& h : base_holes) {
    part.features.push_back(ThroughHole(h.id, {h.center.x(), h.center.y(), t},
                                        -Eigen::Vector3d::UnitZ(), t, h.diameter));
  }
  for (const PlacedHole& h : upright_holes) {
    part.features.push_back(ThroughHole(h.id, {t, h.center.x(), h.center.y()},
                                        -Eigen::Vector3d::UnitX(), t, h.diameter));
  }
  const double w = spec.width;
  part.features.push_back(
      FaceFeature("base_bottom", {L / 2, 0, 0}, -Eigen::Vector3d::UnitZ(), L, w));
  part.features.push_back(
      FaceFeature("base_top", {(t + L) / 2, 0, t}, Eigen::Vector3d::UnitZ(), L - t, w));
  part.features.push_back(
      FaceFeature("upright_outer", {0, 0, H / 2}, -Eigen::Vector3d::UnitX(), w, H));
  part.features.push_back(
      FaceFeature("upright_inner", {t, 0, (t + H) / 2}, Eigen::Vector3d::UnitX(), w, H - t));
  return part;
}

// The pitch of a thread: as given, else ISO coarse.
double ThreadPitch(double pitch, double diameter) {
  RequireNonNegative(pitch, "pitch");
  return pitch > 0.0 ? pitch : IsoCoarsePitch(diameter);
}

void RequireHexAroundBore(double across_flats, double diameter) {
  if (!(across_flats > diameter)) {
    throw Error(fmt::format("across_flats {} must be larger than the diameter {}",
                            FormatNumber(across_flats), FormatNumber(diameter)));
  }
}

LibraryPart Make(const HexBoltSpec& spec) {
  RequirePositive(spec.diameter, "diameter");
  RequirePositive(spec.length, "length");
  RequireNonNegative(spec.thread_length, "thread_length");
  RequireNonNegative(spec.across_flats, "across_flats");
  RequireNonNegative(spec.head_height, "head_height");
  RequireSegments(spec.segments);
  const double d = spec.diameter, L = spec.length;
  if (spec.thread_length > L) {
    throw Error(fmt::format("thread_length {} must not exceed the length {}",
                            FormatNumber(spec.thread_length), FormatNumber(L)));
  }
  const double pitch = ThreadPitch(spec.pitch, d);
  const HexSize iso = IsoHexSize(d);
  const double s = spec.across_flats > 0.0 ? spec.across_flats : iso.across_flats;
  const double k = spec.head_height > 0.0 ? spec.head_height : iso.head_height;
  RequireHexAroundBore(s, d);
  const int segments = CircleSegments(spec.segments, d);

  // One shell: the head's bearing face at z = 0 is the hexagon with the shank's circle as a
  // hole, and the shank's wall starts on that circle.
  MeshBuilder builder;
  const Ring2d hexagon = Hexagon(s);
  const Ring2d circle = CircleRing({0.0, 0.0}, d / 2.0, segments);
  const MeshBuilder::Indices head_bottom = builder.AddRing(hexagon, -k);
  const MeshBuilder::Indices head_top = builder.AddRing(hexagon, 0.0);
  const MeshBuilder::Indices shank_bottom = builder.AddRing(circle, 0.0);
  const MeshBuilder::Indices shank_top = builder.AddRing(circle, L);
  builder.AddWall(head_bottom, head_top);
  builder.AddWall(shank_bottom, shank_top);
  builder.AddCap(head_bottom, {}, /*facing_up=*/false);
  builder.AddCap(head_top, {shank_bottom}, /*facing_up=*/true);
  builder.AddCap(shank_top, {}, /*facing_up=*/true);

  LibraryPart part;
  part.mesh = builder.Release();
  const double thread_length = spec.thread_length > 0.0 ? spec.thread_length : L;
  Feature thread = MakeFeature("thread", FeatureKind::kThread, {0, 0, L - thread_length},
                               Eigen::Vector3d::UnitZ(), thread_length);
  thread.diameter = d;
  thread.pitch = pitch;
  thread.hand = spec.hand;
  thread.fastening = spec.fastening;
  part.features.push_back(thread);
  if (thread_length < L) {
    Feature shank = MakeFeature("shank", FeatureKind::kShaft, {0, 0, 0}, Eigen::Vector3d::UnitZ(),
                                L - thread_length);
    shank.diameter = d;
    part.features.push_back(shank);
  }
  part.features.push_back(
      FaceFeature("head", {0, 0, 0}, Eigen::Vector3d::UnitZ(), s, 2.0 * s / std::sqrt(3.0)));
  return part;
}

LibraryPart Make(const HexNutSpec& spec) {
  RequirePositive(spec.diameter, "diameter");
  RequireNonNegative(spec.across_flats, "across_flats");
  RequireNonNegative(spec.thickness, "thickness");
  RequireSegments(spec.segments);
  const double d = spec.diameter;
  const double pitch = ThreadPitch(spec.pitch, d);
  const HexSize iso = IsoHexSize(d);
  const double s = spec.across_flats > 0.0 ? spec.across_flats : iso.across_flats;
  const double m = spec.thickness > 0.0 ? spec.thickness : iso.nut_thickness;
  RequireHexAroundBore(s, d);
  const int segments = CircleSegments(spec.segments, d);

  LibraryPart part;
  part.mesh = ExtrudeRegion({Hexagon(s), {CircleRing({0.0, 0.0}, d / 2.0, segments)}}, 0.0, m);
  Feature thread =
      MakeFeature("thread", FeatureKind::kTappedHole, {0, 0, 0}, Eigen::Vector3d::UnitZ(), m);
  thread.diameter = d;
  thread.pitch = pitch;
  thread.hand = spec.hand;
  thread.through = true;
  part.features.push_back(thread);
  const double e = 2.0 * s / std::sqrt(3.0);
  part.features.push_back(FaceFeature("bottom", {0, 0, 0}, -Eigen::Vector3d::UnitZ(), s, e));
  part.features.push_back(FaceFeature("top", {0, 0, m}, Eigen::Vector3d::UnitZ(), s, e));
  return part;
}

LibraryPart Make(const WasherSpec& spec) {
  RequirePositive(spec.inner_diameter, "inner_diameter");
  RequirePositive(spec.outer_diameter, "outer_diameter");
  RequirePositive(spec.thickness, "thickness");
  RequireSegments(spec.segments);
  const double di = spec.inner_diameter, dout = spec.outer_diameter, t = spec.thickness;
  if (!(di < dout)) {
    throw Error(fmt::format("inner_diameter {} must be smaller than the outer_diameter {}",
                            FormatNumber(di), FormatNumber(dout)));
  }
  // The same facet count on both circles keeps the inner polygon inside the outer one.
  const int segments = CircleSegments(spec.segments, dout);
  LibraryPart part;
  part.mesh = ExtrudeRegion(
      {CircleRing({0.0, 0.0}, dout / 2.0, segments), {CircleRing({0.0, 0.0}, di / 2.0, segments)}},
      0.0, t);
  part.features.push_back(ThroughHole("bore", {0, 0, 0}, Eigen::Vector3d::UnitZ(), t, di));
  part.features.push_back(FaceFeature("bottom", {0, 0, 0}, -Eigen::Vector3d::UnitZ(), dout, dout));
  part.features.push_back(FaceFeature("top", {0, 0, t}, Eigen::Vector3d::UnitZ(), dout, dout));
  return part;
}

TriangleMesh Cylinder(double diameter, double length, int segments) {
  return ExtrudeRegion({CircleRing({0.0, 0.0}, diameter / 2.0, segments), {}}, 0.0, length);
}

LibraryPart Make(const SetscrewSpec& spec) {
  RequirePositive(spec.diameter, "diameter");
  RequirePositive(spec.length, "length");
  RequireSegments(spec.segments);
  const double pitch = ThreadPitch(spec.pitch, spec.diameter);
  LibraryPart part;
  part.mesh = Cylinder(spec.diameter, spec.length, CircleSegments(spec.segments, spec.diameter));
  Feature thread =
      MakeFeature("thread", FeatureKind::kThread, {0, 0, 0}, Eigen::Vector3d::UnitZ(), spec.length);
  thread.diameter = spec.diameter;
  thread.pitch = pitch;
  thread.hand = spec.hand;
  thread.fastening = spec.fastening;
  part.features.push_back(thread);
  return part;
}

LibraryPart Make(const ShaftSpec& spec) {
  RequirePositive(spec.diameter, "diameter");
  RequirePositive(spec.length, "length");
  RequireSegments(spec.segments);
  LibraryPart part;
  part.mesh = Cylinder(spec.diameter, spec.length, CircleSegments(spec.segments, spec.diameter));
  Feature shaft =
      MakeFeature("shaft", FeatureKind::kShaft, {0, 0, 0}, Eigen::Vector3d::UnitZ(), spec.length);
  shaft.diameter = spec.diameter;
  shaft.retained = spec.retained;
  part.features.push_back(shaft);
  return part;
}

Feature GearTeeth(FeatureKind kind, int teeth, double module, double face_width) {
  Feature f = MakeFeature("teeth", kind, {0, 0, 0}, Eigen::Vector3d::UnitZ(), face_width);
  f.teeth = teeth;
  f.module = module;
  return f;
}

// An external involute gear (spur, helical, or worm wheel) with addendum 1 m, dedendum 1.25 m
// (normal module m; see SpurGearSpec for the helical one).
LibraryPart MakeExternalGear(int teeth, double module, double face_width, double bore_diameter,
                             double pressure_angle, int requested_segments, FeatureKind kind,
                             double helix_angle = 0.0) {
  RequireTeeth(teeth);
  RequirePositive(module, "module");
  RequirePositive(face_width, "face_width");
  RequireNonNegative(bore_diameter, "bore_diameter");
  RequirePressureAngle(pressure_angle);
  RequireSegments(requested_segments);
  if (!(std::abs(helix_angle) < kPi / 3)) {
    throw Error(fmt::format("helix_angle {} must be below pi/3 radians in size",
                            FormatNumber(helix_angle)));
  }
  const double cos_helix = std::cos(helix_angle);
  const double transverse = module / cos_helix;
  const int segments = CircleSegments(requested_segments, transverse * teeth + 2 * module);
  // A spur gear keeps its pressure angle bit for bit (atan(tan a) may differ in the last bit).
  const double transverse_pressure =
      helix_angle == 0.0 ? pressure_angle : std::atan(std::tan(pressure_angle) / cos_helix);
  Region2d region{InvoluteOutline({teeth, transverse, transverse_pressure, module, 1.25 * module,
                                   2.0 * kPi / segments, kFlankPoints}),
                  {}};
  if (bore_diameter > 0.0) {
    RequireBoreInsideRoot(bore_diameter, transverse * teeth - 2.5 * module, segments);
    region.holes.push_back(CircleRing({0.0, 0.0}, bore_diameter / 2.0, segments));
  }
  // At the pitch radius the helix rises face_width while turning by face_width tan(b) / r.
  const double twist = std::tan(helix_angle) / (transverse * teeth / 2.0);
  const int layers = std::max(
      1, static_cast<int>(std::ceil(std::abs(twist) * face_width / (2.0 * kPi / teeth / 16.0))));
  LibraryPart part;
  part.mesh = ExtrudeTwistedRegion(region, 0.0, face_width, twist, layers);
  part.features.push_back(GearTeeth(kind, teeth, module, face_width));
  part.features.back().helix_angle = helix_angle;
  if (bore_diameter > 0.0) {
    part.features.push_back(
        ThroughHole("bore", {0, 0, 0}, Eigen::Vector3d::UnitZ(), face_width, bore_diameter));
  }
  return part;
}

LibraryPart Make(const SpurGearSpec& spec) {
  return MakeExternalGear(spec.teeth, spec.module, spec.face_width, spec.bore_diameter,
                          spec.pressure_angle, spec.segments, FeatureKind::kGear, spec.helix_angle);
}

LibraryPart Make(const WormWheelSpec& spec) {
  return MakeExternalGear(spec.teeth, spec.module, spec.face_width, spec.bore_diameter,
                          kTwentyDegrees, spec.segments, FeatureKind::kWormWheel);
}

LibraryPart Make(const RingGearSpec& spec) {
  RequireTeeth(spec.teeth);
  RequirePositive(spec.module, "module");
  RequirePositive(spec.face_width, "face_width");
  RequirePositive(spec.outer_diameter, "outer_diameter");
  RequirePressureAngle(spec.pressure_angle);
  RequireSegments(spec.segments);
  const double m = spec.module, D = spec.outer_diameter;
  const int segments = CircleSegments(spec.segments, D);
  // The tooth spaces have the shape of external teeth reaching 1.25 m beyond the pitch circle
  // (the internal gear's root) and the internal teeth's tips lie 1 m inside it.
  const double root_diameter = m * (spec.teeth + 2.5);
  if (!(D > root_diameter)) {
    throw Error(fmt::format("outer_diameter {} must be larger than the root diameter {}",
                            FormatNumber(D), FormatNumber(root_diameter)));
  }
  if (!(D * std::cos(kPi / segments) > root_diameter)) {
    throw Error(fmt::format(
        "outer_diameter {} faceted with {} segments reaches in to {}, not clear of the root "
        "diameter {}",
        FormatNumber(D), segments, FormatNumber(D * std::cos(kPi / segments)),
        FormatNumber(root_diameter)));
  }
  const Ring2d spaces = InvoluteOutline(
      {spec.teeth, m, spec.pressure_angle, 1.25 * m, m, 2.0 * kPi / segments, kFlankPoints});
  LibraryPart part;
  part.mesh =
      ExtrudeRegion({CircleRing({0.0, 0.0}, D / 2.0, segments), {spaces}}, 0.0, spec.face_width);
  Feature teeth = GearTeeth(FeatureKind::kGear, spec.teeth, m, spec.face_width);
  teeth.internal = true;
  part.features.push_back(teeth);
  return part;
}

LibraryPart Make(const WormSpec& spec) {
  if (spec.starts < 1) throw Error(fmt::format("starts {} must be at least 1", spec.starts));
  RequirePositive(spec.module, "module");
  RequirePositive(spec.pitch_diameter, "pitch_diameter");
  RequirePositive(spec.length, "length");
  RequireNonNegative(spec.bore_diameter, "bore_diameter");
  RequireSegments(spec.segments);
  const double m = spec.module;
  const double r_pitch = spec.pitch_diameter / 2.0;
  const double r_root = r_pitch - 1.25 * m, r_tip = r_pitch + m;
  if (!(r_root > 0.0)) {
    throw Error(fmt::format(
        "pitch_diameter {} must exceed the thread depth below the pitch line, 2.5 modules ({})",
        FormatNumber(spec.pitch_diameter), FormatNumber(2.5 * m)));
  }
  // At least 16 facets per start, so that every thread turn gets 16 samples of its profile
  // per axial pitch (see below).
  const int segments = spec.segments > 0
                           ? spec.segments
                           : std::max(CircleSegments(0, 2.0 * r_tip), 16 * spec.starts);
  if (spec.bore_diameter > 0.0) RequireBoreInsideRoot(spec.bore_diameter, 2.0 * r_root, segments);

  // Axial section: a trapezoidal thread of axial pitch pi m per start, flanks at 20 degrees,
  // thread thickness pi m / 2 on the pitch line, centred on u = 0 (mod the pitch).
  const double pitch = kPi * m;
  const double lead = spec.starts * pitch;
  const double tan_flank = std::tan(kTwentyDegrees);
  auto profile = [=](double u) {
    const double w = u - pitch * std::floor(u / pitch);
    const double from_centre = std::min(w, pitch - w);
    return std::clamp(r_pitch + (pitch / 4.0 - from_centre) / tan_flank, r_root, r_tip);
  };
  const double hand = spec.hand == Hand::kRight ? 1.0 : -1.0;
  RadialGrid grid;
  grid.radius = [=](double theta, double z) {
    return profile(z - hand * lead * theta / (2.0 * kPi));
  };
  grid.angular_segments = segments;
  // The helix advances lead / segments per angular facet; the same axial step makes the grid
  // diagonals (nearly) follow the helix, so the thread's edges are not cut across.
  grid.axial_segments = std::max(1, static_cast<int>(std::ceil(spec.length * segments / lead)));
  grid.z0 = 0.0;
  grid.z1 = spec.length;
  grid.diagonal = spec.hand == Hand::kRight ? MeshBuilder::Diagonal::kForward
                                            : MeshBuilder::Diagonal::kBackward;
  grid.bore_radius = spec.bore_diameter / 2.0;
  grid.bore_segments = segments;

  LibraryPart part;
  part.mesh = MakeRadialGridSolid(grid);
  Feature worm =
      MakeFeature("worm", FeatureKind::kWorm, {0, 0, 0}, Eigen::Vector3d::UnitZ(), spec.length);
  worm.starts = spec.starts;
  worm.module = m;
  worm.pitch_diameter = spec.pitch_diameter;
  worm.hand = spec.hand;
  part.features.push_back(worm);
  if (spec.bore_diameter > 0.0) {
    part.features.push_back(
        ThroughHole("bore", {0, 0, 0}, Eigen::Vector3d::UnitZ(), spec.length, spec.bore_diameter));
  }
  return part;
}

LibraryPart Make(const RackSpec& spec) {
  RequirePositive(spec.module, "module");
  RequirePositive(spec.length, "length");
  RequirePositive(spec.face_width, "face_width");
  RequireNonNegative(spec.height, "height");
  RequirePressureAngle(spec.pressure_angle);
  const double m = spec.module, L = spec.length;
  const double depth = spec.height > 0.0 ? spec.height : 4.25 * m;
  if (!(depth > 1.25 * m)) {
    throw Error(fmt::format("height {} must exceed the dedendum 1.25 modules ({})",
                            FormatNumber(depth), FormatNumber(1.25 * m)));
  }
  // Distances from a tooth's centre line to its tip corners and root corners.
  const double pitch = kPi * m;
  const double tan_flank = std::tan(spec.pressure_angle);
  const double tip_half = pitch / 4.0 - m * tan_flank;
  const double root_half = pitch / 4.0 + 1.25 * m * tan_flank;
  if (!(tip_half > 0.0)) {
    throw Error(
        fmt::format("pressure_angle {} gives pointed teeth", FormatNumber(spec.pressure_angle)));
  }
  if (!(root_half < pitch / 2.0)) {
    throw Error(fmt::format("pressure_angle {} leaves no root between the teeth",
                            FormatNumber(spec.pressure_angle)));
  }
  // Tooth k is centred on x = (k + 1/2) pitch; a tooth space is centred on x = 0. Heights
  // within a hair of the tip or root line are put exactly on it: the ear clipping must see
  // the root corners of different spaces as exactly collinear, or it may cut a sliver.
  const double hair = 1e-9 * pitch;
  auto top = [=](double x) {
    const double from_centre = std::abs(x - pitch * (std::floor(x / pitch) + 0.5));
    const double y = (pitch / 4.0 - from_centre) / tan_flank;
    if (y >= m - hair) return m;
    if (y <= -1.25 * m + hair) return -1.25 * m;
    return y;
  };
  Ring2d outline = {{0.0, -depth}, {L, -depth}, {L, top(L)}};
  // Profile corners strictly between the ends, right to left; one within a hair of an end
  // would make a sliver with the end's vertex.
  for (int k = static_cast<int>(std::ceil(L / pitch)); k >= 0; --k) {
    const double centre = (k + 0.5) * pitch;
    const std::pair<double, double> corners[] = {{centre + root_half, -1.25 * m},
                                                 {centre + tip_half, m},
                                                 {centre - tip_half, m},
                                                 {centre - root_half, -1.25 * m}};
    for (const auto& [x, y] : corners) {
      if (x > hair && x < L - hair) outline.push_back({x, y});
    }
  }
  outline.push_back({0.0, top(0.0)});

  LibraryPart part;
  part.mesh = ExtrudeRegion({outline, {}}, -spec.face_width / 2.0, spec.face_width / 2.0);
  Feature teeth = MakeFeature("teeth", FeatureKind::kRack, {0, 0, 0}, Eigen::Vector3d::UnitX(), L);
  teeth.module = m;
  teeth.normal = Eigen::Vector3d::UnitY();
  part.features.push_back(teeth);
  return part;
}

constexpr std::array<std::string_view, 12> kKindNames = {
    "plate", "l_bracket", "hex_bolt",  "hex_nut", "washer",     "setscrew",
    "shaft", "spur_gear", "ring_gear", "worm",    "worm_wheel", "rack",
};
static_assert(kKindNames.size() == std::variant_size_v<LibrarySpec>);

}  // namespace

LibraryPart MakeLibraryPart(const LibrarySpec& spec) {
  const std::string kind = LibraryKindName(spec);
  try {
    LibraryPart part = std::visit([](const auto& s) { return Make(s); }, spec);
    std::set<std::string> ids;
    for (const Feature& f : part.features) {
      if (!ids.insert(f.id).second) throw Error(fmt::format("duplicate feature id {}", f.id));
    }
    return part;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", kind, e.what()));
  }
}

std::string LibraryKindName(const LibrarySpec& spec) {
  return std::string(kKindNames[spec.index()]);
}

}  // namespace mechanist
