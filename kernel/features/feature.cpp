#include "kernel/features/feature.h"

#include <cmath>

#include "kernel/support/enum_names.h"

namespace mechanist {
namespace {

constexpr EnumNames<FeatureKind, 16> kNames = {{
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
    {FeatureKind::kCycloidDisc, "cycloid_disc"},
    {FeatureKind::kPinRing, "pin_ring"},
    {FeatureKind::kBevelGear, "bevel_gear"},
}};

}  // namespace

std::string_view ToString(FeatureKind kind) { return NameOf(kNames, kind); }

std::optional<FeatureKind> ParseFeatureKind(std::string_view name) { return ValueOf(kNames, name); }

std::string FeatureKindNames() { return JoinNames(kNames); }

bool IsConvex(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::kShaft:
    case FeatureKind::kThread:
    case FeatureKind::kGear:
    case FeatureKind::kBevelGear:
    case FeatureKind::kWorm:
    case FeatureKind::kWormWheel:
    case FeatureKind::kKey:
    case FeatureKind::kBall:
      return true;
    default:
      return false;
  }
}

double MeshCentreDistance(const Feature& a, const Feature& b) {
  if (a.kind == FeatureKind::kWorm) return (a.pitch_diameter + a.module * b.teeth) / 2;
  if (b.kind == FeatureKind::kWorm) return (b.pitch_diameter + b.module * a.teeth) / 2;
  if (a.kind == FeatureKind::kRack) return b.PitchRadius();
  if (b.kind == FeatureKind::kRack) return a.PitchRadius();
  const double m = a.module / std::cos(a.helix_angle);  // helical: the transverse module
  if (a.internal || b.internal) return m * std::abs(a.teeth - b.teeth) / 2;
  return m * (a.teeth + b.teeth) / 2;
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
