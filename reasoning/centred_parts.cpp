#include "reasoning/centred_parts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

#include "kernel/collision/grid_broad_phase.h"
#include "kernel/geometry/aabb.h"
#include "kernel/geometry/line_geometry.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

std::string Mm(double x) { return FormatNumber(x) + " mm"; }

// A shaft of one body standing in a wider hole of another, on its axis.
struct Candidate {
  FeatureRef shaft, hole;
  std::size_t shaft_body = 0, hole_body = 0;
};

}  // namespace

Centring CentreFloatingParts(const Assembly& assembly,
                             const std::vector<Subassembly>& subassemblies,
                             const std::vector<std::size_t>& subassembly_of,
                             std::vector<Pair>* pairs) {
  Centring centring;
  if (!assembly.inference().centred_parts) return centring;
  std::vector<bool> held(subassemblies.size(), false);
  for (std::size_t b = 0; b < subassemblies.size(); ++b) held[b] = subassemblies[b].ground;
  std::vector<bool> in_face_contact(subassemblies.size(), false);
  for (const Pair& p : *pairs) {
    const std::size_t a = subassembly_of[p.a.part], b = subassembly_of[p.b.part];
    if (a == b) continue;
    if (p.type == PairType::kPlanar) {
      in_face_contact[a] = in_face_contact[b] = true;
    } else {
      held[a] = held[b] = true;
    }
  }
  if (std::all_of(held.begin(), held.end(), [](bool h) { return h; })) return centring;

  const double L = assembly.tolerance().length, A = assembly.tolerance().angle;
  auto world_axis = [&](FeatureRef ref) {
    return assembly.feature(ref).WorldAxis(assembly.part(ref.part).X_WP);
  };
  // Shafts and holes, with their axes' boxes grown by the length tolerance: collinear and
  // engaged axes have overlapping boxes (a broad phase, for assemblies of many parts).
  std::vector<FeatureRef> round;
  std::vector<Aabb> boxes_W;
  std::vector<std::uint32_t> bodies;
  for (std::size_t i = 0; i < assembly.parts().size(); ++i) {
    if (assembly.IsCompliant(i)) continue;
    const std::vector<Feature>& features = assembly.part(i).features;
    for (std::size_t k = 0; k < features.size(); ++k) {
      if (features[k].kind != FeatureKind::kShaft && features[k].kind != FeatureKind::kHole) {
        continue;
      }
      const AxisSegment axis = world_axis({i, k});
      Aabb box;
      box.Extend(axis.origin);
      box.Extend(axis.end());
      box.min.array() -= L;
      box.max.array() += L;
      round.push_back({i, k});
      boxes_W.push_back(box);
      bodies.push_back(static_cast<std::uint32_t>(subassembly_of[i]));
    }
  }
  std::vector<Candidate> candidates;
  for (const auto& [i, j] : OverlappingBoxPairs(boxes_W, bodies)) {
    FeatureRef s = round[i], h = round[j];
    if (assembly.feature(s).kind == assembly.feature(h).kind) continue;
    if (assembly.feature(s).kind == FeatureKind::kHole) std::swap(s, h);
    const std::size_t bs = subassembly_of[s.part], bh = subassembly_of[h.part];
    if (held[bs] && held[bh]) continue;
    const Feature &shaft = assembly.feature(s), &hole = assembly.feature(h);
    if (shaft.diameter + L >= hole.diameter) continue;  // a fit: recognition's business
    if (!Engaged(world_axis(s), world_axis(h), hole.through, L, A)) continue;
    candidates.push_back({s, h, bs, bh});
  }
  // By part and feature order, whatever order the broad phase found them in.
  auto order = [](const Candidate& c) {
    return std::tuple(c.shaft.part, c.shaft.feature, c.hole.part, c.hole.feature);
  };
  std::sort(candidates.begin(), candidates.end(),
            [&](const Candidate& x, const Candidate& y) { return order(x) < order(y); });

  for (bool added = true; added;) {
    added = false;
    for (const Candidate& c : candidates) {
      if (held[c.shaft_body] == held[c.hole_body]) continue;
      const bool shaft_floats = !held[c.shaft_body];
      Pair fixed;
      fixed.type = PairType::kFixed;
      fixed.dof = 0;
      fixed.source = PairSource::kCentred;
      fixed.a = c.shaft;
      fixed.b = c.hole;
      pairs->push_back(fixed);
      const std::size_t floating = shaft_floats ? c.shaft_body : c.hole_body;
      held[floating] = added = centring.changed = true;

      const FeatureRef mine = shaft_floats ? c.shaft : c.hole;
      const FeatureRef host = shaft_floats ? c.hole : c.shaft;
      const double d_shaft = assembly.feature(c.shaft).diameter;
      const double d_hole = assembly.feature(c.hole).diameter;
      const std::string part(assembly.PartId(mine.part));
      centring.diagnostics.push_back(
          {Severity::kInfo,
           "centred",
           fmt::format("part '{}' is held to the rest by {}, but {} ({}) stands centred {} {} "
                       "({}), {} of radial clearance: taken as fixed there (a thread, an adapter "
                       "or glue the file leaves out; \"infer\": {{\"centred_parts\": false}} "
                       "turns this off)",
                       part, in_face_contact[floating] ? "nothing but face contacts" : "no pair",
                       assembly.FeatureName(mine), Mm(shaft_floats ? d_shaft : d_hole),
                       shaft_floats ? "in" : "on", assembly.FeatureName(host),
                       Mm(shaft_floats ? d_hole : d_shaft), Mm((d_hole - d_shaft) / 2)),
           {part, std::string(assembly.PartId(host.part))},
           {assembly.FeatureName(c.shaft), assembly.FeatureName(c.hole)}});
    }
  }
  return centring;
}

}  // namespace mechanist
