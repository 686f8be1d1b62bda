#include "reasoning/pair.h"

namespace mechanist {

std::string_view ToString(PairSource source) {
  switch (source) {
    case PairSource::kRecognised:
      return "recognised";
    case PairSource::kOverride:
      return "override";
    case PairSource::kClamp:
      return "clamp";
    case PairSource::kSetscrew:
      return "setscrew";
  }
  return "?";
}

std::string_view ToString(PairFastening fastening) {
  switch (fastening) {
    case PairFastening::kNone:
      return "";
    case PairFastening::kPressFit:
      return "press_fit";
    case PairFastening::kTight:
      return "tight";
    case PairFastening::kLoose:
      return "loose";
    case PairFastening::kClamp:
      return "clamp";
    case PairFastening::kSetscrew:
      return "setscrew";
  }
  return "?";
}

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
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace mechanist
