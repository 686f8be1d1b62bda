#include "reasoning/fastener_inference.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
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
        if (AngleBetweenLines(s.direction, h.direction) > angle_tolerance ||
            DistanceToLine(h.origin, s.origin, s.direction) > length_tolerance ||
            std::abs(shaft.diameter - hole.diameter) > 0.02 * hole.diameter ||
            AxialOverlap(s, h) <= length_tolerance) {
          continue;
        }
        const double pitch = CoarsePitch(shaft.diameter);
        hole.kind = FeatureKind::kTappedHole;
        hole.fastening = Fastening::kTight;
        hole.pitch = pitch;
        shaft.kind = FeatureKind::kThread;
        shaft.fastening = Fastening::kTight;
        shaft.pitch = pitch;
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

}  // namespace mechanist
