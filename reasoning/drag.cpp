#include "reasoning/drag.h"

#include <fmt/format.h>

#include <set>
#include <stdexcept>
#include <vector>

namespace mechanist {

DragResult Drag(const Assembly& assembly, const Analysis& analysis, const DragRequest& request) {
  const std::size_t body = analysis.subassembly_of[request.part];
  auto other_body = [&](const Pair& p) {
    const std::size_t a = analysis.subassembly_of[p.a.part];
    const std::size_t b = analysis.subassembly_of[p.b.part];
    return a != b && (a == body || b == body);
  };
  // The axes to try: the requested one; by default the part's sides of its pairs with other
  // subassemblies, then those of the other parts of its subassembly (a pendulum's rod, fixed
  // to the hub that turns in the bearing, moves on the hub's pairs), in pair order. The first
  // that moves is taken (a part's first pair may join it to a part that it carries, about an
  // axis on which it cannot turn itself); when none does, the first says what holds the part.
  std::vector<FeatureRef> axes;
  if (request.feature) {
    axes.push_back({request.part, *request.feature});
  } else {
    std::vector<FeatureRef> others;
    std::set<FeatureRef> seen;
    for (const Pair& p : analysis.pairs) {
      if (!other_body(p)) continue;
      const FeatureRef& side = analysis.subassembly_of[p.a.part] == body ? p.a : p.b;
      if (seen.insert(side).second) (side.part == request.part ? axes : others).push_back(side);
    }
    axes.insert(axes.end(), others.begin(), others.end());
    // The ground subassembly moves about no axis: its first says what holds the part.
    if (analysis.subassemblies[body].ground && axes.size() > 1) axes.resize(1);
    if (axes.empty()) {
      if (assembly.part(request.part).features.empty()) {
        throw std::invalid_argument(fmt::format("part {} has no feature to take an axis from",
                                                assembly.PartId(request.part)));
      }
      axes.push_back({request.part, 0});
    }
  }
  DragResult result;
  result.part = request.part;
  for (std::size_t k = 0; k < axes.size() && (k == 0 || !result.motion.possible); ++k) {
    ImposedMotion hand;
    hand.feature = axes[k];
    hand.rotation = request.rotate;
    hand.about_line = true;
    DrivenMotion motion = SolveImposed(analysis.motion, {hand});
    if (k == 0 || motion.possible) {
      result.axis = axes[k];
      result.motion = std::move(motion);
    }
  }
  result.part_freedoms = analysis.motion.mobility.part_freedoms[request.part];
  // A part of the ground subassembly is held by the fixed pairs that join it to the ground
  // (a motor's tight bolts), not by the pairs of the ground with moving parts.
  const bool grounded = analysis.subassemblies[body].ground;
  for (std::size_t i = 0; i < analysis.pairs.size(); ++i) {
    const Pair& p = analysis.pairs[i];
    if (!result.motion.possible) {
      const bool own = p.a.part == request.part || p.b.part == request.part;
      if (grounded ? own && p.type == PairType::kFixed : other_body(p)) {
        result.holding_pairs.push_back(i);
      }
      continue;
    }
    const bool a_moves = result.motion.parts[p.a.part].kind != MotionKind::kNone;
    const bool b_moves = result.motion.parts[p.b.part].kind != MotionKind::kNone;
    if (a_moves != b_moves) result.absorbing_pairs.push_back(i);
  }
  return result;
}

}  // namespace mechanist
