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
    for (const OperationClash& c : SweepPaths(assembly, analysis, collision, run, amount).clashes) {
      if (!yields[c.part_a] && !yields[c.part_b]) return c;
    }
    return std::nullopt;
  };
  MovableRange range;
  range.ahead = first_contact(1.0);
  if (range.ahead || !periodic) range.behind = first_contact(-1.0);
  return range;
}

}  // namespace mechanist
