// Slot fits: a pin in a slot, a key in a keyway.

#include <fmt/format.h>

#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

void Recognizer::PinSlot(const WorldFeature& s, const WorldFeature& sl) {
  const Eigen::Vector3d& n = sl.normal_W;
  if (AngleBetweenLines(s.axis.direction, n) > A_ || s.axis.direction.dot(n) <= 0) return;
  const LineLineClosest c =
      ClosestPointsOfLines(s.axis.origin, s.axis.direction, sl.axis.origin, sl.axis.direction);
  if (c.distance > L_ || c.t < -L_ || c.t > sl.axis.length + L_) return;
  if (c.s < -L_ - sl.f.depth || c.s > s.axis.length - L_) return;
  if (s.f.diameter <= sl.f.width + L_) {
    AddPair(PairType::kPinSlot, s, sl);
  } else {
    Near("pin_wider_than_slot", s, sl,
         fmt::format("pin diameter {} is wider than the slot's {} (required at most the slot "
                     "width)",
                     Mm(s.f.diameter), Mm(sl.f.width)));
  }
}

void Recognizer::KeySlot(const WorldFeature& k, const WorldFeature& sl) {
  if (AngleBetweenLines(k.axis.direction, sl.axis.direction) > A_) return;
  if (AngleBetweenLines(k.normal_W, sl.normal_W) > A_ || k.normal_W.dot(sl.normal_W) <= 0) {
    return;
  }
  const Eigen::Vector3d d = k.axis.origin - sl.axis.origin;
  const Eigen::Vector3d side = sl.axis.direction.cross(sl.normal_W);
  if (std::abs(d.dot(side)) > L_ || std::abs(d.dot(sl.normal_W)) > sl.f.depth + L_) return;
  if (AxialOverlap(k.axis, sl.axis) <= L_) return;
  if (k.f.width <= sl.f.width + L_) {
    AddPair(PairType::kPrismatic, k, sl);
  } else {
    Near("key_wider_than_slot", k, sl,
         fmt::format("key width {} is wider than the slot's {} (required at most the slot width)",
                     Mm(k.f.width), Mm(sl.f.width)));
  }
}

}  // namespace mechanist::internal
