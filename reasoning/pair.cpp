#include "reasoning/pair.h"

#include "kernel/support/enum_names.h"

namespace mechanist {

// See the field order in pair.h.
static_assert(sizeof(Pair) <= 88, "Pair has grown: the analysis reads every pair several times");

namespace {

constexpr EnumNames<PairSource, 16> kSources = {{
    {PairSource::kRecognised, "recognised"},
    {PairSource::kOverride, "override"},
    {PairSource::kClamp, "clamp"},
    {PairSource::kSetscrew, "setscrew"},
    {PairSource::kImpliedPin, "implied_pin"},
    {PairSource::kInferred, "inferred_from_interference"},
    {PairSource::kBearing, "bearing"},
    {PairSource::kLooseFit, "loose_fit"},
    {PairSource::kOnePart, "one_part"},
    {PairSource::kShaftFlat, "shaft_flat"},
    {PairSource::kImpliedFrame, "implied_frame"},
    {PairSource::kSeated, "seated"},
    {PairSource::kSetscrewHole, "setscrew_hole"},
    {PairSource::kEmbedded, "embedded"},
    {PairSource::kBearingShaft, "bearing_shaft"},
    {PairSource::kCentred, "centred"},
}};

constexpr EnumNames<PairFastening, 6> kFastenings = {{
    {PairFastening::kNone, ""},
    {PairFastening::kPressFit, "press_fit"},
    {PairFastening::kTight, "tight"},
    {PairFastening::kLoose, "loose"},
    {PairFastening::kClamp, "clamp"},
    {PairFastening::kSetscrew, "setscrew"},
}};

}  // namespace

std::string_view ToString(PairSource source) { return NameOf(kSources, source); }

std::string_view ToString(PairFastening fastening) { return NameOf(kFastenings, fastening); }

std::optional<int> DegreesOfFreedom(PairType type) {
  switch (type) {
    case PairType::kFixed:
      return 0;
    case PairType::kRevolute:
    case PairType::kPrismatic:
    case PairType::kScrew:
      return 1;
    case PairType::kCylindrical:
    case PairType::kPinSlot:
      return 2;
    case PairType::kSpherical:
    case PairType::kPlanar:
      return 3;
    case PairType::kGear:
    case PairType::kWormGear:
    case PairType::kRackPinion:
    case PairType::kCycloidal:
    case PairType::kBevelGear:
    case PairType::kPinsInHoles:
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace mechanist
