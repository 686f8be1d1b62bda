#include "io/internal/simulator_text.h"

#include "kernel/support/number_format.h"

namespace mechanist::internal {

std::string PairLabel(const Assembly& assembly, const Analysis& analysis, std::size_t pair) {
  const Pair& p = analysis.pairs[pair];
  std::string text = std::string(ToString(p.type)) + " pair " + assembly.FeatureName(p.a) + " + " +
                     assembly.FeatureName(p.b);
  if (p.ratio) text += ", ratio " + p.ratio->ToString();
  if (p.travel_per_revolution) {
    text += ", " + FormatNumber(*p.travel_per_revolution / assembly.units().mm_per_length, 9) +
            " " + assembly.units().length + " per revolution";
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
    text += std::string(end) + " stop: " + assembly.part(contact->first).id + " meets " +
            assembly.part(contact->second).id;
  };
  add("lower", joint.lower_contact);
  add("upper", joint.upper_contact);
  return text;
}

std::string Provenance(const Assembly& assembly) {
  return "Written by mechanist from the assembly \"" + assembly.name() +
         "\": links are its rigid subassemblies, joints and couplings the pairs it inferred. "
         "Units: metres, kilograms, radians.";
}

}  // namespace mechanist::internal
