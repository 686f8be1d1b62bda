#include "kernel/assembly/pair_type.h"

#include "kernel/support/enum_names.h"

namespace mechanist {
namespace {

constexpr EnumNames<PairType, 14> kNames = {{
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
    {PairType::kCycloidal, "cycloidal"},
    {PairType::kBevelGear, "bevel_gear"},
    {PairType::kPinsInHoles, "pins_in_holes"},
}};

}  // namespace

std::string_view ToString(PairType type) { return NameOf(kNames, type); }

std::optional<PairType> ParsePairType(std::string_view name) { return ValueOf(kNames, name); }

std::string PairTypeNames() { return JoinNames(kNames); }

}  // namespace mechanist
