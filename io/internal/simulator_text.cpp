#include "io/internal/simulator_text.h"

#include <fmt/format.h>

#include <iterator>

#include "kernel/support/number_format.h"

namespace mechanist::internal {

std::string PairLabel(const Assembly& assembly, const Analysis& analysis, std::size_t pair) {
  const Pair& p = analysis.pairs[pair];
  std::string text = fmt::format("{} pair {} + {}", ToString(p.type), assembly.FeatureName(p.a),
                                 assembly.FeatureName(p.b));
  auto out = std::back_inserter(text);
  if (p.ratio) fmt::format_to(out, ", ratio {}", p.ratio->ToString());
  if (p.travel_per_revolution) {
    fmt::format_to(out, ", {} {} per revolution",
                   FormatNumber(*p.travel_per_revolution / assembly.units().mm_per_length, 9),
                   assembly.units().length);
  }
  return text;
}

std::string LinkLabel(const Assembly& assembly, const SimLink& link) {
  std::string text = link.parts.empty() ? "no part" : link.parts.size() > 1 ? "parts " : "part ";
  for (std::size_t k = 0; k < link.parts.size(); ++k) {
    text += (k ? ", " : "") + assembly.part(link.parts[k]).id;
  }
  if (link.ground) text += " (ground)";
  if (link.default_inertia) text += "; default inertia (no closed mesh)";
  return text;
}

std::string LimitLabel(const Assembly& assembly, const SimJoint& joint) {
  std::string text;
  auto add = [&](const char* end, const auto& contact) {
    if (!contact) return;
    if (!text.empty()) text += "; ";
    fmt::format_to(std::back_inserter(text), "{} stop: {} meets {}", end,
                   assembly.part(contact->first).id, assembly.part(contact->second).id);
  };
  add("lower", joint.lower_contact);
  add("upper", joint.upper_contact);
  return text;
}

std::string Provenance(const Assembly& assembly) {
  return fmt::format(
      "Written by mechanist from the assembly \"{}\": links are its rigid subassemblies, joints "
      "and couplings the pairs it inferred. Units: metres, kilograms, radians.",
      assembly.name());
}

}  // namespace mechanist::internal
