#include "kernel/feature.h"

#include <array>
#include <utility>

namespace mechanist {
namespace {

constexpr std::array<std::pair<FeatureKind, std::string_view>, 13> kNames = {{
    {FeatureKind::kShaft, "shaft"},
    {FeatureKind::kHole, "hole"},
    {FeatureKind::kThread, "thread"},
    {FeatureKind::kTappedHole, "tapped_hole"},
    {FeatureKind::kSlot, "slot"},
    {FeatureKind::kKey, "key"},
    {FeatureKind::kGear, "gear"},
    {FeatureKind::kWorm, "worm"},
    {FeatureKind::kWormWheel, "worm_wheel"},
    {FeatureKind::kRack, "rack"},
    {FeatureKind::kBall, "ball"},
    {FeatureKind::kSocket, "socket"},
    {FeatureKind::kFace, "face"},
}};

}  // namespace

std::string_view ToString(FeatureKind kind) {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "?";
}

std::optional<FeatureKind> ParseFeatureKind(std::string_view name) {
  for (const auto& [k, n] : kNames) {
    if (n == name) return k;
  }
  return std::nullopt;
}

bool IsConvex(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::kShaft:
    case FeatureKind::kThread:
    case FeatureKind::kGear:
    case FeatureKind::kWorm:
    case FeatureKind::kWormWheel:
    case FeatureKind::kKey:
    case FeatureKind::kBall:
      return true;
    default:
      return false;
  }
}

bool IsConcave(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::kHole:
    case FeatureKind::kTappedHole:
    case FeatureKind::kSlot:
    case FeatureKind::kSocket:
      return true;
    default:
      return false;
  }
}

}  // namespace mechanist
