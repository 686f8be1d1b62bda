#include "reasoning/fastener_check.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "kernel/assembly_state.h"
#include "kernel/line_geometry.h"
#include "kernel/number_format.h"

namespace mechanist {
namespace {

std::string Mm(double x) { return FormatNumber(x) + " mm"; }

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
  const AssemblyState state = InitialState(assembly);
  auto world = [&](FeatureRef r) { return assembly.feature(r).WorldAxis(state.X_WP[r.part]); };
  auto too_short = [&](FeatureRef thread, FeatureRef nut, double shortfall,
                       const std::string& how) {
    out.push_back({Severity::kWarning,
                   "bolt_too_short",
                   "thread " + assembly.FeatureName(thread) + " " + how + " tapped hole " +
                       assembly.FeatureName(nut) + " (" + Mm(assembly.feature(nut).length) +
                       " long): it is " + Mm(shortfall) +
                       " too short for the parts it passes and its nut",
                   {assembly.part(thread.part).id, assembly.part(nut.part).id},
                   {assembly.FeatureName(thread), assembly.FeatureName(nut)}});
  };

  // The pairs of each part, and the thread pairs of each tapped hole: one pass over the pairs.
  std::vector<std::vector<const Pair*>> pairs_of(assembly.parts().size());
  std::map<FeatureRef, std::vector<const Pair*>> threads_in;
  for (const Pair& pair : pairs) {
    pairs_of[pair.a.part].push_back(&pair);
    pairs_of[pair.b.part].push_back(&pair);
    if (IsThreadPair(pair)) threads_in[pair.b].push_back(&pair);
  }
  std::vector<FeatureRef> threads;  // every thread feature, for nuts without one
  for (std::size_t q = 0; q < assembly.parts().size(); ++q) {
    for (std::size_t g = 0; g < assembly.part(q).features.size(); ++g) {
      if (assembly.part(q).features[g].kind == FeatureKind::kThread) threads.push_back({q, g});
    }
  }

  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    const Part& part = assembly.part(p);
    for (std::size_t f = 0; f < part.features.size(); ++f) {
      const Feature& h = part.features[f];
      if (h.kind != FeatureKind::kTappedHole || !h.through) continue;
      const FeatureRef nut{p, f};
      bool engaged = false;
      const auto in = threads_in.find(nut);
      for (const Pair* found : in == threads_in.end() ? std::vector<const Pair*>{} : in->second) {
        const Pair& pair = *found;
        engaged = true;
        const double overlap = AxialOverlap(world(pair.a), world(nut));
        if (overlap < h.length - L) {
          too_short(pair.a, nut, h.length - overlap, "engages " + Mm(overlap) + " of");
        }
      }
      if (engaged) continue;
      // A thread of the nut's size on the nut's axis that stops short of it (a scan of the
      // threads, for the rare nut that has none).
      bool reported = false;
      for (const FeatureRef& thread : threads) {
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
                       "nut " + part.id + " has no thread in its tapped hole " +
                           assembly.FeatureName(nut) + ": nothing holds it",
                       {part.id},
                       {assembly.FeatureName(nut)}});
      }
    }
  }

  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    std::vector<std::string> loose;
    bool firm = false;
    for (const Pair* found : pairs_of[p]) {
      const Pair& pair = *found;
      if (pair.fastening == PairFastening::kLoose) {
        loose.push_back(assembly.FeatureName(pair.a) + " in " + assembly.FeatureName(pair.b));
      } else if (pair.fastening != PairFastening::kNone) {
        firm = true;
      }
    }
    if (loose.empty() || firm) continue;
    std::string list;
    for (const std::string& l : loose) list += (list.empty() ? "" : ", ") + l;
    out.push_back({Severity::kWarning,
                   "loose_fastening_only",
                   "part " + assembly.part(p).id + " is held only by loose threads (" + list +
                       "): it can turn and travel on them",
                   {assembly.part(p).id},
                   {}});
  }
  return out;
}

}  // namespace mechanist
