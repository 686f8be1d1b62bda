#include "reasoning/drag.h"

#include <fmt/format.h>

#include <stdexcept>

namespace mechanist {

DragResult Drag(const Assembly& assembly, const Analysis& analysis, const DragRequest& request) {
  const Part& part = assembly.part(request.part);
  if (part.features.empty()) {
    throw std::invalid_argument(
        fmt::format("part {} has no feature to take an axis from", part.id));
  }
  const std::size_t body = analysis.subassembly_of[request.part];
  auto other_body = [&](const Pair& p) {
    const std::size_t a = analysis.subassembly_of[p.a.part];
    const std::size_t b = analysis.subassembly_of[p.b.part];
    return a != b && (a == body || b == body);
  };
  DragResult result;
  result.axis = {request.part, request.feature.value_or(0)};
  for (std::size_t i = 0; !request.feature && i < analysis.pairs.size(); ++i) {
    const Pair& p = analysis.pairs[i];
    if (!other_body(p) || (p.a.part != request.part && p.b.part != request.part)) continue;
    result.axis = p.a.part == request.part ? p.a : p.b;
    break;
  }
  result.motion = SolveImposed(analysis.motion, {{result.axis, request.rotate, 1.0, {}}});
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
