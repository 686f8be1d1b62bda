#include "io/info_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iterator>
#include <string>
#include <utility>

#include "io/step_reader.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

constexpr double kDegPerRad = 57.29577951308232;

std::string Vec(const Eigen::Vector3d& v) {
  return fmt::format("({}, {}, {})", FormatNumber(v.x()), FormatNumber(v.y()), FormatNumber(v.z()));
}

// ", pose: position (x, y, z) mm, rotation A deg about (x, y, z)": a part's pose in the world,
// what its features are written against (nothing for the identity). A rotation that rounds to
// 0 degrees (a placement solved to rounding error) is left out: its axis would be noise.
std::string Pose(const RigidTransform& X_WP) {
  const Eigen::AngleAxisd rotation(X_WP.rotation());
  const bool turned = FormatNumber(rotation.angle() * kDegPerRad) != "0";
  if (!turned && X_WP.translation().isZero(0.0)) return "";
  return fmt::format(
      ", pose: position {} mm{}", Vec(X_WP.translation()),
      turned ? fmt::format(", rotation {} deg about {}",
                           FormatNumber(rotation.angle() * kDegPerRad), Vec(rotation.axis()))
             : "");
}

std::string Parameters(const Feature& f) {
  std::string s;
  // One parameter, after a space.
  auto add = [&s]<typename... T>(fmt::format_string<T...> format, T&&... args) {
    s += ' ';
    fmt::format_to(std::back_inserter(s), format, std::forward<T>(args)...);
  };
  switch (f.kind) {
    case FeatureKind::kShaft:
    case FeatureKind::kHole:
      add("diameter {} mm", FormatNumber(f.diameter));
      add("length {} mm", FormatNumber(f.length));
      if (f.through) add("through");
      if (f.retained) add("retained");
      break;
    case FeatureKind::kThread:
    case FeatureKind::kTappedHole:
      add("M{}x{}", FormatNumber(f.diameter), FormatNumber(f.pitch));
      add("length {} mm", FormatNumber(f.length));
      if (f.starts != 1) add("{} starts", f.starts);
      if (f.hand == Hand::kLeft) add("left-hand");
      if (f.through) add("through");
      if (f.kind == FeatureKind::kThread) {
        add("{}", f.fastening == Fastening::kTight ? "tight" : "loose");
      }
      break;
    case FeatureKind::kSlot:
    case FeatureKind::kKey:
      add("width {} mm", FormatNumber(f.width));
      add("length {} mm", FormatNumber(f.length));
      if (f.depth > 0) add("depth {} mm", FormatNumber(f.depth));
      add("normal {}", Vec(f.normal));
      break;
    case FeatureKind::kGear:
    case FeatureKind::kWormWheel:
      add("{} teeth", f.teeth);
      add("module {} mm", FormatNumber(f.module));
      add("face width {} mm", FormatNumber(f.length));
      if (f.internal) add("internal");
      if (f.helix_angle != 0.0) add("helix {} deg", FormatNumber(f.helix_angle * 180.0 / M_PI));
      break;
    case FeatureKind::kWorm:
      add("{} {}", f.starts, f.starts == 1 ? "start" : "starts");
      add("module {} mm", FormatNumber(f.module));
      add("pitch diameter {} mm", FormatNumber(f.pitch_diameter));
      add("length {} mm", FormatNumber(f.length));
      if (f.hand == Hand::kLeft) add("left-hand");
      break;
    case FeatureKind::kRack:
      add("module {} mm", FormatNumber(f.module));
      add("length {} mm", FormatNumber(f.length));
      add("normal {}", Vec(f.normal));
      break;
    case FeatureKind::kBall:
    case FeatureKind::kSocket:
      add("diameter {} mm", FormatNumber(f.diameter));
      break;
    case FeatureKind::kFace:
      if (f.width > 0) add("width {} mm", FormatNumber(f.width));
      if (f.height > 0) add("height {} mm", FormatNumber(f.height));
      break;
    case FeatureKind::kCycloidDisc:
      add("{} lobes", f.teeth);
      add("eccentricity {} mm", FormatNumber(f.eccentricity));
      add("length {} mm", FormatNumber(f.length));
      break;
    case FeatureKind::kBevelGear:
      add("{} teeth", f.teeth);
      add("module {} mm", FormatNumber(f.module));
      add("pitch angle {} deg", FormatNumber(f.pitch_angle * 180.0 / M_PI));
      add("face width {} mm", FormatNumber(f.length));
      if (f.spiral_angle != 0.0) add("spiral {} deg", FormatNumber(f.spiral_angle * 180.0 / M_PI));
      break;
    case FeatureKind::kPinRing:
      add("{} pins", f.teeth);
      add("pin circle {} mm", FormatNumber(f.diameter));
      add("pin diameter {} mm", FormatNumber(f.pin_diameter));
      add("length {} mm", FormatNumber(f.length));
      break;
  }
  return s;
}

}  // namespace

std::string DescribeFeature(const Feature& f, const RigidTransform& X_WP) {
  const AxisSegment axis_W = f.WorldAxis(X_WP);
  return fmt::format("{}: {} at {} axis {}{}", f.id, ToString(f.kind), Vec(axis_W.origin),
                     Vec(axis_W.direction), Parameters(f));
}

void WriteInfo(const Assembly& assembly, std::ostream& out) {
  const AssemblyState state = InitialState(assembly);
  out << "assembly: " << (assembly.name().empty() ? "(unnamed)" : assembly.name()) << "\n";
  if (!assembly.source().empty()) out << "file: " << assembly.source() << "\n";
  // A STEP file's own units say what its values were (read in mm whatever they are): what a
  // designer compares with the CAD system's. Read alone, the file's units are the STEP file's.
  const std::vector<StepFileUnits>& steps = assembly.step_units();
  const bool step_alone = IsStepFile(assembly.source()) && steps.size() == 1;
  if (step_alone && !steps.front().length.empty()) {
    out << "units in file: length " << fmt::format("{}", fmt::join(steps.front().length, ", "))
        << " (read in mm; reported: mm, degrees)\n";
  } else {
    out << "units in file: length " << assembly.units().length << ", angle "
        << assembly.units().angle << " (reported: mm, degrees)\n";
    for (const StepFileUnits& step : steps) {
      if (step.length.empty()) continue;
      out << "  STEP file " << step.file << ": length "
          << fmt::format("{}", fmt::join(step.length, ", ")) << " (read in mm)\n";
    }
  }
  out << "tolerance: " << FormatNumber(assembly.tolerance().length) << " mm, "
      << FormatNumber(assembly.tolerance().angle * kDegPerRad) << " deg; friction "
      << FormatNumber(assembly.friction()) << "\n";
  std::size_t grounded = 0, triangles = 0, features = 0;
  for (const Part& part : assembly.parts()) {
    grounded += part.ground ? 1 : 0;
    triangles += part.mesh->faces.size();
    features += part.features.size();
  }
  out << "parts: " << assembly.parts().size() << " (" << grounded << " ground), " << triangles
      << " triangles, " << features << " features\n";
  for (std::size_t i = 0; i < assembly.parts().size(); ++i) {
    const Part& part = assembly.part(i);
    out << "  " << part.id << (part.ground ? " [ground]" : "")
        << (part.placement.empty() ? "" : " [placed by features]") << ": ";
    if (part.HasGeometry()) {
      // The mesh's own extent in the world, not its part-frame box turned (larger when the
      // part is turned: a gear's box at 45 degrees reached 1.4 times its radius).
      Aabb box_W;
      for (const Eigen::Vector3d& p_P : part.mesh->vertices) box_W.Extend(state.X_WP[i] * p_P);
      out << part.mesh_source << ", " << part.mesh->faces.size() << " triangles, box "
          << Vec(box_W.min) << " .. " << Vec(box_W.max) << " mm";
    } else {
      out << "no mesh (features only)";
    }
    if (!part.group.empty()) out << ", group " << part.group;
    out << Pose(state.X_WP[i]) << "\n";
    for (const Feature& f : part.features)
      out << "    " << DescribeFeature(f, state.X_WP[i]) << "\n";
  }
  if (!assembly.drivers().empty()) out << "drivers: " << assembly.drivers().size() << "\n";
  for (const Driver& d : assembly.drivers()) {
    const bool rotation = d.motion == Driver::Motion::kRotation;
    out << "  " << d.id << ": " << (rotation ? "rotation" : "translation") << " of "
        << assembly.FeatureName(d.feature) << " relative to "
        << (d.relative_to ? assembly.part(*d.relative_to).id : std::string("the ground")) << ", "
        << FormatNumber(d.rate) << (rotation ? " rev/s" : " mm/s") << ", amount "
        << FormatNumber(d.amount) << (rotation ? " rev" : " mm") << "\n";
  }
  if (!assembly.adjustments().empty()) {
    out << "adjustments: " << assembly.adjustments().size() << "\n";
  }
  for (const Adjustment& a : assembly.adjustments()) {
    const bool rotate = a.kind == Adjustment::Kind::kRotate;
    const double scale = rotate ? kDegPerRad : 1.0;
    out << "  " << a.id << ": " << (rotate ? "rotate " : "translate ") << assembly.part(a.moves).id
        << (rotate ? " about " : " along ") << assembly.FeatureName(a.axis) << " in ["
        << FormatNumber(a.lower * scale) << ", " << FormatNumber(a.upper * scale) << "]"
        << (rotate ? " deg" : " mm") << "\n";
  }
  if (!assembly.goals().empty()) out << "goals: " << assembly.goals().size() << "\n";
  for (const Goal& g : assembly.goals()) {
    out << "  " << (g.kind == Goal::Kind::kMesh ? "mesh " : "coaxial ")
        << assembly.FeatureName(g.features[0]) << " with " << assembly.FeatureName(g.features[1])
        << "\n";
  }
  if (!assembly.steps().empty()) out << "steps: " << assembly.steps().size() << "\n";
  for (const AssemblyStep& s : assembly.steps()) {
    out << "  insert " << assembly.FeatureName(s.insert) << " into " << assembly.FeatureName(s.into)
        << "\n";
  }
  if (!assembly.overrides().empty()) out << "overrides: " << assembly.overrides().size() << "\n";
  for (const PairOverride& o : assembly.overrides()) {
    out << "  " << assembly.FeatureName(o.features[0]) << " + "
        << assembly.FeatureName(o.features[1]) << ": "
        << (o.type ? std::string(ToString(*o.type)) : std::string("none"));
    if (o.lead) out << ", lead " << FormatNumber(*o.lead) << " mm";
    out << "\n";
  }
  if (!assembly.expectations().empty()) {
    out << "expectations: " << assembly.expectations().size() << "\n";
  }
}

void WriteDiagnostics(const std::vector<Diagnostic>& diagnostics, std::ostream& out) {
  for (const Diagnostic& d : diagnostics) {
    out << ToString(d.severity) << " " << d.code << ": " << d.message << "\n";
  }
}

}  // namespace mechanist
