#include "reasoning/fastener_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>

#include "kernel/geometry/line_geometry.h"
#include "kernel/support/compressed_rows.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

std::string Mm(double x) { return fmt::format("{} mm", FormatNumber(x)); }

bool IsThreadPair(const Pair& p) {
  return p.source == PairSource::kRecognised &&
         (p.type == PairType::kScrew || p.type == PairType::kFixed) &&
         (p.fastening == PairFastening::kTight || p.fastening == PairFastening::kLoose);
}

}  // namespace

std::vector<Diagnostic> CheckFasteners(const Assembly& assembly, const std::vector<Pair>& pairs) {
  std::vector<Diagnostic> out;
  const double L = assembly.tolerance().length;
  const double A = assembly.tolerance().angle;
  auto world = [&](FeatureRef r) {
    return assembly.feature(r).WorldAxis(assembly.part(r.part).X_WP);
  };
  // A tapped hole the heuristics guessed is not measured: a collar or a block on a plain shaft
  // may be taken for a nut, and a screw in a housing's plain hole need not reach its end.
  std::set<std::string> guessed_nuts;
  for (const Diagnostic& d : assembly.findings()) {
    if (d.code == "nut_on_bolt" && !d.features.empty()) guessed_nuts.insert(d.features.front());
    // Per screw its thread, then every hole it tapped: the threads are no nuts and never
    // looked up.
    if (d.code == "screw_in_plain_hole") guessed_nuts.insert(d.features.begin(), d.features.end());
  }
  auto too_short = [&](FeatureRef thread, FeatureRef nut, double shortfall,
                       const std::string& how) {
    if (guessed_nuts.count(assembly.FeatureName(nut)) > 0) return;
    out.push_back(
        {Severity::kWarning,
         "bolt_too_short",
         fmt::format("thread {} {} tapped hole {} ({} long): it is {} too short for the parts it "
                     "passes and its nut",
                     assembly.FeatureName(thread), how, assembly.FeatureName(nut),
                     Mm(assembly.feature(nut).length), Mm(shortfall)),
         {std::string(assembly.PartId(thread.part)), std::string(assembly.PartId(nut.part))},
         {assembly.FeatureName(thread), assembly.FeatureName(nut)}});
  };

  // One read of the pairs (100,000 parts make 15 MB of them): the thread pairs of each tapped
  // hole, by the hole's index among all features (pairs in order); the parts with a firm
  // fastening; the loose pairs.
  std::vector<std::pair<std::size_t, const Pair*>> thread_pairs;
  std::vector<bool> firm(assembly.parts().size(), false);
  std::vector<const Pair*> loose_pairs;
  for (const Pair& pair : pairs) {
    if (IsThreadPair(pair)) thread_pairs.emplace_back(assembly.FeatureIndex(pair.b), &pair);
    if (pair.fastening == PairFastening::kLoose) {
      loose_pairs.push_back(&pair);
    } else if (pair.fastening != PairFastening::kNone) {
      firm[pair.a.part] = firm[pair.b.part] = true;
    }
  }
  const CompressedRows<const Pair*> threads_in(assembly.feature_count(), thread_pairs);
  for (const FeatureRef nut : assembly.FeaturesOfKind(FeatureKind::kTappedHole)) {
    const std::size_t p = nut.part;
    const Part& part = assembly.part(p);
    const Feature& h = assembly.feature(nut);
    if (!h.through) continue;
    bool engaged = false;
    for (const Pair* found : threads_in[assembly.FeatureIndex(nut)]) {
      const Pair& pair = *found;
      engaged = true;
      const double overlap = AxialOverlap(world(pair.a), world(nut));
      if (overlap < h.length - L) {
        too_short(pair.a, nut, h.length - overlap, fmt::format("engages {} of", Mm(overlap)));
      }
    }
    if (engaged) continue;
    // A thread of the nut's size on the nut's axis that stops short of it (a scan of the
    // threads, for the rare nut that has none).
    bool reported = false;
    for (const FeatureRef& thread : assembly.FeaturesOfKind(FeatureKind::kThread)) {
      const Feature& t = assembly.feature(thread);
      if (thread.part == p || std::abs(t.diameter - h.diameter) > L) continue;
      const AxisSegment ta = world(thread), ha = world(nut);
      if (AngleBetweenLines(ta.direction, ha.direction) > A ||
          DistanceToLine(ta.origin, ha.origin, ha.direction) > L) {
        continue;
      }
      const double overlap = AxialOverlap(ta, ha);
      if (overlap > L || -overlap > h.length + h.diameter) continue;
      too_short(thread, nut, h.length - overlap, "does not reach");
      reported = true;
      break;
    }
    const bool nut_like =
        std::count_if(part.features.begin(), part.features.end(),
                      [](const Feature& x) { return x.kind != FeatureKind::kFace; }) == 1;
    if (!reported && nut_like) {
      out.push_back({Severity::kWarning,
                     "nut_without_bolt",
                     fmt::format("nut {} has no thread in its tapped hole {}: nothing holds it",
                                 part.id, assembly.FeatureName(nut)),
                     {part.id},
                     {assembly.FeatureName(nut)}});
    }
  }

  // Parts held only by loose threads: the loose pairs of the parts with no firm fastening.
  std::map<std::size_t, std::string> loose;  // part -> its loose pairs, in pair order
  for (const Pair* found : loose_pairs) {
    const Pair& pair = *found;
    for (std::size_t part : {pair.a.part, pair.b.part}) {
      if (firm[part]) continue;
      std::string& list = loose[part];
      fmt::format_to(std::back_inserter(list), "{}{} in {}", list.empty() ? "" : ", ",
                     assembly.FeatureName(pair.a), assembly.FeatureName(pair.b));
    }
  }
  for (const auto& [p, list] : loose) {
    out.push_back({Severity::kWarning,
                   "loose_fastening_only",
                   fmt::format("part {} is held only by loose threads ({}): it can turn and travel "
                               "on them",
                               assembly.part(p).id, list),
                   {assembly.part(p).id},
                   {}});
  }
  return out;
}

}  // namespace mechanist
