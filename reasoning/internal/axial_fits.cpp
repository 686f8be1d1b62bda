// Axial fits: a shaft, thread or pin seated in a hole, a clearance hole or a tapped hole.

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

bool Recognizer::Seated(const WorldFeature& c, const WorldFeature& h) {
  const double overlap = AxialOverlap(c.axis, h.axis);
  if (overlap <= L_) return false;
  const double angle = AngleBetweenLines(c.axis.direction, h.axis.direction);
  const double offset = std::max(DistanceToLine(c.axis.origin, h.axis.origin, h.axis.direction),
                                 DistanceToLine(h.axis.origin, c.axis.origin, c.axis.direction));
  if (angle > A_ || offset > L_) {
    if (angle <= near_A_ && offset <= near_L_) {
      Near("axes_not_collinear", c, h,
           fmt::format("axes are almost but not quite collinear: angle {}, offset {} (required "
                       "within {} and {})",
                       Deg(angle), Mm(offset), Deg(A_), Mm(L_)));
    }
    return false;
  }
  if (c.axis.direction.dot(h.axis.direction) < 0 && !h.f.through) {
    Near("feature_sense_reversed", c, h,
         fmt::format("collinear and overlapping, but the convex feature points out of the blind {} "
                     "(a convex axis points toward its free end, a concave one into the material)",
                     ToString(h.f.kind)));
    return false;
  }
  return true;
}

bool Recognizer::Collinear(const WorldFeature& c, const WorldFeature& h) const {
  return Engaged(c.axis, h.axis, h.f.through, L_, A_);
}

void Recognizer::ShaftHole(const WorldFeature& s, const WorldFeature& h) {
  // Far thinner or thicker than the hole, the shaft does not touch it (kMaxShaftClearance);
  // a little thinner, it may still guide a part nothing else holds (AddLooseFits).
  const double clearance = h.f.diameter - s.f.diameter;
  if (clearance > kMaxShaftClearance * h.f.diameter + L_) {
    if (clearance <= kMaxLooseClearance * h.f.diameter + L_) loose_candidates_.emplace_back(&s, &h);
    return;
  }
  if (-clearance > kMaxShaftClearance * h.f.diameter + L_) return;
  if (!Seated(s, h)) return;
  if (s.f.diameter <= h.f.diameter + L_) {
    AddPair(s.f.retained || h.f.retained ? PairType::kRevolute : PairType::kCylindrical, s, h);
  } else if (h.f.retained) {
    Near("shaft_larger_than_hole", s, h,
         fmt::format("shaft diameter {} is larger than the retained hole's {} (required at most "
                     "hole + {} for a part meant to turn)",
                     Mm(s.f.diameter), Mm(h.f.diameter), Mm(L_)));
  } else {
    AddPair(PairType::kFixed, s, h, PairFastening::kPressFit);
  }
}

void Recognizer::ThreadHole(const WorldFeature& t, const WorldFeature& h) {
  if (h.f.diameter > kMaxClearanceHoleRatio * t.f.diameter + L_) return;
  if (!Seated(t, h)) return;
  if (h.f.diameter + L_ >= t.f.diameter) {
    AddPair(PairType::kCylindrical, t, h);
  } else {
    Near("hole_smaller_than_thread", t, h,
         fmt::format("hole diameter {} is smaller than the thread's {} (required at least the "
                     "thread's major diameter)",
                     Mm(h.f.diameter), Mm(t.f.diameter)));
  }
}

void Recognizer::ThreadTapped(const WorldFeature& t, const WorldFeature& h) {
  // A thread far smaller than the tapped hole passes through it (a spindle through the
  // bonnet's seat): neither a pair nor a near miss.
  if (std::min(t.f.diameter, h.f.diameter) <
      kMinThreadDiameterRatio * std::max(t.f.diameter, h.f.diameter)) {
    return;
  }
  if (!Seated(t, h)) return;
  std::vector<std::string> mismatches;
  if (std::abs(t.f.diameter - h.f.diameter) > L_) {
    mismatches.push_back(fmt::format("diameter: thread M{}, tapped hole M{}",
                                     FormatNumber(t.f.diameter), FormatNumber(h.f.diameter)));
  }
  if (std::abs(t.f.pitch - h.f.pitch) > 1e-6 * std::max(t.f.pitch, h.f.pitch)) {
    mismatches.push_back(
        fmt::format("pitch: thread {}, tapped hole {}", Mm(t.f.pitch), Mm(h.f.pitch)));
  }
  if (t.f.starts != h.f.starts) {
    mismatches.push_back(fmt::format("starts: thread {}, tapped hole {}", t.f.starts, h.f.starts));
  }
  if (t.f.hand != h.f.hand) {
    mismatches.push_back(fmt::format("hand: thread {}, tapped hole {}",
                                     t.f.hand == Hand::kRight ? "right" : "left",
                                     h.f.hand == Hand::kRight ? "right" : "left"));
  }
  if (!mismatches.empty()) {
    Near("thread_mismatch", t, h,
         fmt::format("threads do not match (required equal); {}", fmt::join(mismatches, "; ")));
    return;
  }
  if (t.f.fastening == Fastening::kTight) {
    AddPair(PairType::kFixed, t, h, PairFastening::kTight);
  } else {
    AddPair(PairType::kScrew, t, h, PairFastening::kLoose);
  }
}

}  // namespace mechanist::internal
