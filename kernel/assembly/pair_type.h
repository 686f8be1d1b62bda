#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mechanist {

/// The kinds of pair (kinematic relation) between two parts (spec, "Recognition"). One byte:
/// it is stored in every pair.
enum class PairType : std::uint8_t {
  kFixed,
  kRevolute,
  kCylindrical,
  kScrew,
  kPrismatic,
  kPinSlot,
  kSpherical,
  kPlanar,
  kGear,
  kWormGear,
  kRackPinion,
  kCycloidal,  ///< a cycloid disc rolling in its pin ring: couples like an internal gear pair
  kBevelGear,  ///< two bevel gears whose pitch cones share their apex
  /// Pins of one part in larger holes of another, all off-centre alike (a cycloidal reducer's
  /// output mechanism): the two parts keep the same orientation about the pins' axes while
  /// one orbits the other.
  kPinsInHoles,
};

/// A coupling of two turning or sliding axes (gear, bevel gear, worm gear, rack and pinion,
/// cycloidal, pins in holes): it relates the rates of its parts' joints instead of guiding a
/// part.
constexpr bool IsCoupling(PairType type) {
  return type == PairType::kGear || type == PairType::kWormGear || type == PairType::kRackPinion ||
         type == PairType::kCycloidal || type == PairType::kBevelGear ||
         type == PairType::kPinsInHoles;
}

/// The format's spelling ("worm_gear").
std::string_view ToString(PairType type);
/// The type spelled `name`, or nothing.
std::optional<PairType> ParsePairType(std::string_view name);
/// Every type's spelling, comma-separated ("fixed, revolute, ..."), for messages.
std::string PairTypeNames();

}  // namespace mechanist
