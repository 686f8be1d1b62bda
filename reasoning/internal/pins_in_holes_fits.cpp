// Pins of one part in larger holes of another, all off-centre alike: a cycloidal reducer's
// output mechanism (Recognizer::AddPinsInHoles).

#include <fmt/format.h>

#include "kernel/geometry/circle_fit.h"
#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

void Recognizer::AddPinsInHoles() {
  if (pin_hole_candidates_.empty()) return;
  // Candidate pins by part; each pin's candidate holes (a larger parallel hole it stands in,
  // off its axis), by the hole's part.
  std::map<std::size_t, std::vector<const WorldFeature*>> shafts;
  std::map<const WorldFeature*, std::map<std::size_t, std::vector<const WorldFeature*>>> around;
  for (const WorldFeature& w : features_) {
    if (w.f.kind == FeatureKind::kShaft) shafts[w.ref.part].push_back(&w);
  }
  for (const auto& [pin, hole] : pin_hole_candidates_) around[pin][hole->ref.part].push_back(hole);
  std::set<std::pair<std::size_t, std::size_t>> joined;
  for (const auto& [pin_part, own] : shafts) {
    for (const WorldFeature* first : own) {
      // Every pin stands in a hole, the first too.
      const auto first_around = around.find(first);
      if (first_around == around.end()) continue;
      // The pins: this part's shafts of the first one's size, parallel to it.
      const Eigen::Vector3d u = first->axis.direction;
      std::vector<const WorldFeature*> pins;
      for (const WorldFeature* s : own) {
        if (std::abs(s->f.diameter - first->f.diameter) <= L_ &&
            AngleBetweenLines(s->axis.direction, u) <= A_) {
          pins.push_back(s);
        }
      }
      // In name order, so that the file's order changes nothing; each set once, from its first.
      std::sort(pins.begin(), pins.end(),
                [&](const WorldFeature* p, const WorldFeature* q) { return NameLess(*p, *q); });
      if (pins.size() < 3 || pins.front() != first) continue;
      // On a circle across the axis.
      const Eigen::Vector3d x = u.unitOrthogonal(), y = u.cross(x);
      std::vector<Eigen::Vector2d> centres;
      for (const WorldFeature* s : pins)
        centres.emplace_back(s->axis.origin.dot(x), s->axis.origin.dot(y));
      const FittedCircle circle = FitCircle(centres);
      if (!(circle.radius > first->f.diameter / 2)) continue;
      bool round = true;
      for (const Eigen::Vector2d& c : centres) {
        round = round && std::abs((c - circle.center).norm() - circle.radius) <= L_;
      }
      if (!round) continue;
      for (const auto& by_part : first_around->second) {
        const std::size_t hole_part = by_part.first;
        if (joined.count({pin_part, hole_part})) continue;
        // Each pin in a hole of one larger size, touching its wall: its axis off the hole's
        // by the radial clearance, the same offset for every pin.
        std::vector<const WorldFeature*> matched;
        std::optional<Eigen::Vector2d> offset;
        for (std::size_t k = 0; k < pins.size(); ++k) {
          const WorldFeature* pin = pins[k];
          const WorldFeature* found = nullptr;
          const auto pin_around = around.find(pin);
          if (pin_around == around.end() || !pin_around->second.count(hole_part)) break;
          for (const WorldFeature* h : pin_around->second.at(hole_part)) {
            const double clearance = (h->f.diameter - pin->f.diameter) / 2;
            if (clearance <= L_ || AngleBetweenLines(h->axis.direction, u) > A_ ||
                AxialOverlap(h->axis, pin->axis) <= L_ ||
                (!matched.empty() && std::abs(h->f.diameter - matched[0]->f.diameter) > L_)) {
              continue;
            }
            const Eigen::Vector2d off(h->axis.origin.dot(x) - centres[k].x(),
                                      h->axis.origin.dot(y) - centres[k].y());
            if (std::abs(off.norm() - clearance) > L_) continue;
            if (offset && (off - *offset).norm() > L_) continue;
            found = h;
            if (!offset) offset = off;  // the first pin's: the others are within L_ of it
            break;
          }
          if (!found) break;
          matched.push_back(found);
        }
        if (matched.size() != pins.size()) continue;
        joined.insert({pin_part, hole_part});
        AddPair(PairType::kPinsInHoles, *pins.front(), *matched.front());
        diagnostics_.push_back(
            {Severity::kInfo,
             "pins_in_holes",
             fmt::format("the {} pins of {} ({} on a {} circle) run in the {} holes of {} ({}), "
                         "{} off-centre alike: {} keeps the orientation of {} as it orbits (a "
                         "cycloidal reducer's output mechanism; a pins_in_holes coupling, 1:1)",
                         pins.size(), assembly_.PartId(pin_part), Mm(first->f.diameter),
                         Mm(2 * circle.radius), matched.size(), assembly_.PartId(hole_part),
                         Mm(matched.front()->f.diameter), Mm(offset->norm()),
                         assembly_.PartId(hole_part), assembly_.PartId(pin_part)),
             {std::string(assembly_.PartId(pin_part)), std::string(assembly_.PartId(hole_part))},
             {Name(*pins.front()), Name(*matched.front())}});
      }
    }
  }
}

}  // namespace mechanist::internal
