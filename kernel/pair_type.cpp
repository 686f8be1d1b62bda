#include "kernel/pair_type.h"

#include <array>
#include <utility>

namespace mechanist {
namespace {

constexpr std::array<std::pair<PairType, std::string_view>, 11> kNames = {{
    {PairType::kFixed, "fixed"},
    {PairType::kRevolute, "revolute"},
    {PairType::kCylindrical, "cylindrical"},
    {PairType::kScrew, "screw"},
    {PairType::kPrismatic, "prismatic"},
    {PairType::kPinSlot, "pin_slot"},
    {PairType::kSpherical, "spherical"},
    {PairType::kPlanar, "planar"},
    {PairType::kGear, "gear"},
    {PairType::kWormGear, "worm_gear"},
    {PairType::kRackPinion, "rack_pinion"},
}};

}  // namespace

std::string_view ToString(PairType type) {
  for (const auto& [t, name] : kNames) {
    if (t == type) return name;
  }
  return "?";
}

std::optional<PairType> ParsePairType(std::string_view name) {
  for (const auto& [t, n] : kNames) {
    if (n == name) return t;
  }
  return std::nullopt;
}

}  // namespace mechanist
