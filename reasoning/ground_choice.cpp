#include "reasoning/ground_choice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace mechanist {

std::vector<Diagnostic> ChooseGround(std::vector<Part>* parts) {
  if (std::any_of(parts->begin(), parts->end(), [](const Part& p) { return p.ground; })) {
    return {};
  }
  std::optional<std::size_t> chosen;
  double largest = -1.0;
  for (std::size_t i = 0; i < parts->size(); ++i) {
    const Part& part = (*parts)[i];
    if (part.compliant) continue;
    const double volume = part.HasGeometry() ? std::abs(part.mesh->SignedVolume()) : 0.0;
    if (volume > largest) {
      largest = volume;
      chosen = i;
    }
  }
  if (!chosen) return {};
  Part& ground = (*parts)[*chosen];
  ground.ground = true;
  return {
      {Severity::kInfo,
       "ground_chosen",
       fmt::format("no part is ground: '{}', the largest, is taken as fixed to the world "
                   "(mobility counts from it; set \"ground\": true on a part to choose another)",
                   ground.id),
       {ground.id},
       {}}};
}

}  // namespace mechanist
