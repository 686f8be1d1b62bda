#include "reasoning/movable_range.h"

namespace mechanist {

MovableRange FindMovableRange(const Assembly& assembly, const Analysis& analysis,
                              const CollisionModel& collision, const std::vector<ScrewPath>& paths,
                              double amount, bool periodic) {
  std::vector<bool> yields(assembly.parts().size(), false);
  for (const FreeMotion& f : analysis.motion.mobility.free_motions) {
    yields[f.part] = true;
    for (const std::size_t p : f.parts) yields[p] = true;
  }
  auto first_contact = [&](double sense) -> std::optional<OperationClash> {
    std::vector<ScrewPath> run = paths;
    for (ScrewPath& path : run) {
      for (ScrewMotion& m : path.screws) {
        m.turns_per_unit *= sense;
        m.travel_per_unit *= sense;
      }
    }
    // Parts that yield are not swept at all: their contacts are no stops.
    const std::vector<OperationClash> stops =
        SweepPaths(assembly, analysis, collision, run, amount, [&](std::size_t a, std::size_t b) {
          return !yields[a] && !yields[b];
        }).clashes;
    if (stops.empty()) return std::nullopt;
    return stops.front();
  };
  MovableRange range;
  range.ahead = first_contact(1.0);
  if (range.ahead || !periodic) range.behind = first_contact(-1.0);
  return range;
}

}  // namespace mechanist
