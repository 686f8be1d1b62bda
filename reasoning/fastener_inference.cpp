#include "reasoning/fastener_inference.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "kernel/features/feature_recognition.h"
#include "kernel/geometry/line_geometry.h"
#include "kernel/support/number_format.h"

namespace mechanist {

double CoarsePitch(double diameter) {
  static const std::array<std::pair<double, double>, 22> kTable = {
      {{1, 0.25}, {1.2, 0.25}, {1.6, 0.35}, {2, 0.4},  {2.5, 0.45}, {3, 0.5},
       {4, 0.7},  {5, 0.8},    {6, 1.0},    {8, 1.25}, {10, 1.5},   {12, 1.75},
       {14, 2.0}, {16, 2.0},   {20, 2.5},   {24, 3.0}, {30, 3.5},   {36, 4.0},
       {42, 4.5}, {48, 5.0},   {56, 5.5},   {64, 6.0}}};
  const auto* best = &kTable[0];
  for (const auto& row : kTable) {
    if (std::abs(row.first - diameter) < std::abs(best->first - diameter)) best = &row;
  }
  return best->second;
}

namespace {

// Makes `shaft` a tight thread screwed into `hole`, a tight tapped hole, both of the ISO coarse
// pitch for the shaft's diameter, which it returns.
double ScrewTight(Feature* shaft, Feature* hole) {
  const double pitch = CoarsePitch(shaft->diameter);
  hole->kind = FeatureKind::kTappedHole;
  hole->fastening = Fastening::kTight;
  hole->pitch = pitch;
  shaft->kind = FeatureKind::kThread;
  shaft->fastening = Fastening::kTight;
  shaft->pitch = pitch;
  return pitch;
}

// Whether the shaft's axis `s` runs along the hole's `h` (within the tolerances) and the two
// overlap along it.
bool Engaged(const AxisSegment& s, const AxisSegment& h, double length_tolerance,
             double angle_tolerance) {
  return AngleBetweenLines(s.direction, h.direction) <= angle_tolerance &&
         DistanceToLine(h.origin, s.origin, s.direction) <= length_tolerance &&
         AxialOverlap(s, h) > length_tolerance;
}

}  // namespace

std::vector<Diagnostic> InferNutsOnBolts(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred) {
  std::vector<Diagnostic> found;
  std::map<const TriangleMesh*, MeshFeatures> shapes;
  for (std::size_t n = 0; n < parts->size(); ++n) {
    Part& nut = (*parts)[n];
    std::vector<std::size_t> holes;
    bool all_inferred = true;
    for (std::size_t f = 0; f < nut.features.size(); ++f) {
      all_inferred = all_inferred && inferred(n, f);
      if (nut.features[f].kind == FeatureKind::kHole) holes.push_back(f);
    }
    if (!all_inferred || holes.size() != 1) continue;
    // Instances of one product share their mesh: recognised once.
    auto cached = shapes.find(nut.mesh.get());
    if (cached == shapes.end())
      cached = shapes.emplace(nut.mesh.get(), RecognizeFeatures(*nut.mesh)).first;
    const MeshFeatures& shape = cached->second;
    if (shape.polygon_sides == 0 || !shape.axis) continue;
    Feature& hole = nut.features[holes[0]];
    if (AngleBetweenLines(hole.axis, *shape.axis) > angle_tolerance) continue;
    const AxisSegment h = hole.WorldAxis(nut.X_WP);
    for (std::size_t b = 0; b < parts->size(); ++b) {
      if (b == n) continue;
      Part& bolt = (*parts)[b];
      for (std::size_t f = 0; f < bolt.features.size(); ++f) {
        Feature& shaft = bolt.features[f];
        // A shaft, or one a nut before this one made a thread (a rod with a nut at each end).
        if (shaft.kind != FeatureKind::kShaft && shaft.kind != FeatureKind::kThread) continue;
        if (!inferred(b, f)) continue;
        const AxisSegment s = shaft.WorldAxis(bolt.X_WP);
        if (std::abs(shaft.diameter - hole.diameter) > 0.02 * hole.diameter ||
            !Engaged(s, h, length_tolerance, angle_tolerance)) {
          continue;
        }
        const double pitch = ScrewTight(&shaft, &hole);
        found.push_back(
            {Severity::kInfo,
             "nut_on_bolt",
             fmt::format("part '{}' (a {}-sided prism with a bore) sits on '{}/{}' ({} "
                         "mm): taken as a nut on a bolt, a tight thread of pitch {} mm "
                         "(heuristic)",
                         nut.id, shape.polygon_sides, bolt.id, shaft.id,
                         FormatNumber(shaft.diameter), FormatNumber(pitch)),
             {nut.id, bolt.id},
             {fmt::format("{}/{}", nut.id, hole.id), fmt::format("{}/{}", bolt.id, shaft.id)}});
        break;
      }
      if (hole.kind == FeatureKind::kTappedHole) break;
    }
  }
  return found;
}

std::vector<Diagnostic> InferScrewsInPlainHoles(
    std::vector<Part>* parts, double length_tolerance, double angle_tolerance,
    const std::function<bool(std::size_t part, std::size_t feature)>& inferred) {
  std::vector<Diagnostic> found;
  for (std::size_t s = 0; s < parts->size(); ++s) {
    Part& screw = (*parts)[s];
    if (!screw.HasGeometry()) continue;
    bool all_inferred = true;
    std::optional<std::size_t> shank;
    for (std::size_t f = 0; f < screw.features.size(); ++f) {
      all_inferred = all_inferred && inferred(s, f);
      const Feature& x = screw.features[f];
      if (x.kind == FeatureKind::kShaft && (!shank || x.length > screw.features[*shank].length)) {
        shank = f;
      }
    }
    if (!all_inferred || !shank) continue;
    Feature& thread = screw.features[*shank];
    if (thread.length < 1.5 * thread.diameter) continue;
    // The head: a shorter, wider coaxial shaft at one end of the shank.
    const AxisSegment a = thread.LocalAxis();
    std::optional<Eigen::Vector3d> head_side;  // from the shank's middle toward the head
    double head_diameter = 0.0;
    for (const Feature& x : screw.features) {
      if (x.kind != FeatureKind::kShaft || &x == &thread) continue;
      if (x.diameter < 1.3 * thread.diameter || x.diameter > 2.5 * thread.diameter ||
          x.length > x.diameter || AngleBetweenLines(x.axis, a.direction) > angle_tolerance ||
          DistanceToLine(x.origin, a.origin, a.direction) > length_tolerance) {
        continue;
      }
      const double t0 = (x.origin - a.origin).dot(a.direction);
      const double t1 = t0 + x.length * x.axis.dot(a.direction);
      // Beside the shank, up to a quarter of its diameter away (a fillet under the head).
      const double near = std::min(t0, t1), far = std::max(t0, t1);
      const double gap = 0.25 * thread.diameter + length_tolerance;
      if (far <= length_tolerance && far >= -gap) {
        head_side = -a.direction;
      } else if (near >= a.length - length_tolerance && near <= a.length + gap) {
        head_side = a.direction;
      } else {
        continue;
      }
      head_diameter = x.diameter;
      break;
    }
    if (!head_side) continue;
    // A screw is no wider than its head (a motor with a shaft is).
    bool slender = true;
    for (const Eigen::Vector3d& v : screw.mesh->vertices) {
      const Eigen::Vector3d d = v - a.origin;
      slender =
          slender && (d - d.dot(a.direction) * a.direction).norm() <= 0.5 * head_diameter * 1.05;
    }
    if (!slender) continue;
    const Eigen::Vector3d tip_P = head_side->dot(a.direction) > 0
                                      ? a.origin
                                      : Eigen::Vector3d(a.origin + a.length * a.direction);
    const AxisSegment t = thread.WorldAxis(screw.X_WP);
    const Eigen::Vector3d tip = screw.X_WP * tip_P;
    const Eigen::Vector3d inward = screw.X_WP.RotateDirection(-*head_side);  // toward the tip
    for (std::size_t p = 0; p < parts->size(); ++p) {
      if (p == s) continue;
      Part& part = (*parts)[p];
      bool screwed = false;
      for (std::size_t f = 0; f < part.features.size() && !screwed; ++f) {
        Feature& hole = part.features[f];
        if (hole.kind != FeatureKind::kHole || !inferred(p, f)) continue;
        const AxisSegment h = hole.WorldAxis(part.X_WP);
        if (std::abs(hole.diameter - thread.diameter) > 0.1 * thread.diameter ||
            !Engaged(t, h, length_tolerance, angle_tolerance)) {
          continue;
        }
        // The tip inside the hole: not before its start nor past its end.
        const double s0 = (h.origin - tip).dot(inward);
        const double s1 = (h.origin + h.length * h.direction - tip).dot(inward);
        if (std::min(s0, s1) > length_tolerance || std::max(s0, s1) < -length_tolerance) continue;
        const double drilled = hole.diameter;
        hole.diameter = thread.diameter;
        const double pitch = ScrewTight(&thread, &hole);
        found.push_back(
            {Severity::kInfo,
             "screw_in_plain_hole",
             fmt::format("part '{}' (a head and a {} mm shank) ends in '{}/{}' ({} mm): taken "
                         "as screwed into it, a tight thread of pitch {} mm (heuristic: the "
                         "file models no thread)",
                         screw.id, FormatNumber(thread.diameter), part.id, hole.id,
                         FormatNumber(drilled), FormatNumber(pitch)),
             {screw.id, part.id},
             {fmt::format("{}/{}", screw.id, thread.id), fmt::format("{}/{}", part.id, hole.id)}});
        screwed = true;
      }
      if (screwed) break;
    }
  }
  return found;
}

}  // namespace mechanist
