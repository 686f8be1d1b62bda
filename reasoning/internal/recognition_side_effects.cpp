// What recognition does after the fits: the file's overrides, implied pins, compliant parts, tight
// threads, clamps, setscrews and unconnected parts.

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "kernel/support/union_find.h"
#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {

void Recognizer::ApplyOverrides() {
  for (const PairOverride& o : assembly_.overrides()) {
    std::erase_if(pairs_,
                  [&](const Pair& p) { return SameFeatures(p, o.features[0], o.features[1]); });
    std::erase_if(tight_, [&](const Screwed& t) {
      return (t.thread == Index(o.features[0]) && t.hole == o.features[1]) ||
             (t.thread == Index(o.features[1]) && t.hole == o.features[0]);
    });
    if (!o.type) continue;
    const WorldFeature* a = &At(o.features[0]);
    const WorldFeature* b = &At(o.features[1]);
    // The convex feature, the worm or the pinion first, as for recognised pairs.
    const auto kind_a = a->f.kind, kind_b = b->f.kind;
    if ((IsConcave(kind_a) && IsConvex(kind_b)) || kind_b == FeatureKind::kWorm ||
        kind_a == FeatureKind::kRack) {
      std::swap(a, b);
    }
    AddPair(*o.type, *a, *b);
    pairs_.back().source = o.implied_frame ? PairSource::kImpliedFrame : PairSource::kOverride;
    if (o.lead) pairs_.back().travel_per_revolution = *o.lead;
  }
}

void Recognizer::AddImpliedPins() {
  if (hole_candidates_.empty() || !assembly_.inference().implied_pins) return;
  std::vector<bool> filled(features_.size(), false);
  // Parts that rolling bearings join (rings, elements, cages and seats, by pairs of source
  // bearing) already move on each other as the bearings say (a thrust bearing's washers and
  // its cage have coaxial empty bores): no missing pin between them.
  UnionFind bearings(assembly_.parts().size());
  for (const Pair& p : pairs_) {
    const FeatureKind k = assembly_.kind(p.a);
    if (k == FeatureKind::kShaft || k == FeatureKind::kThread) filled[Index(p.b)] = true;
    if (p.source == PairSource::kBearing) {
      bearings.Join(static_cast<int>(p.a.part), static_cast<int>(p.b.part));
    }
  }
  // A hole on the axis of a shaft or thread that runs through it (a bolt in a bearing's bore,
  // whose seal recesses are holes too) holds no missing pin either.
  std::vector<const WorldFeature*> rods;
  for (const WorldFeature& w : features_) {
    if (w.f.kind == FeatureKind::kShaft || w.f.kind == FeatureKind::kThread) rods.push_back(&w);
  }
  auto on_a_rod = [&](const WorldFeature& h) {
    return std::any_of(rods.begin(), rods.end(), [&](const WorldFeature* r) {
      return r->ref.part != h.ref.part &&
             AngleBetweenLines(r->axis.direction, h.axis.direction) <= A_ &&
             DistanceToLine(h.axis.origin, r->axis.origin, r->axis.direction) <= L_ &&
             AxialOverlap(r->axis, h.axis) > L_;
    });
  };
  for (const auto& [x, y] : hole_candidates_) {
    if (filled[Index(x->ref)] || filled[Index(y->ref)] ||
        bearings.Find(static_cast<int>(x->ref.part)) ==
            bearings.Find(static_cast<int>(y->ref.part))) {
      continue;
    }
    const double d_max = std::max(x->f.diameter, y->f.diameter);
    if (std::abs(x->f.diameter - y->f.diameter) > kMaxImpliedPinDifference * d_max + L_) {
      continue;
    }
    const double angle = AngleBetweenLines(x->axis.direction, y->axis.direction);
    const double offset =
        std::max(DistanceToLine(x->axis.origin, y->axis.origin, y->axis.direction),
                 DistanceToLine(y->axis.origin, x->axis.origin, x->axis.direction));
    if (angle > A_ || offset > L_) continue;
    // The holes meet, or a pin bridges a gap of up to its diameter between them (knuckles
    // spaced apart on one hinge rod).
    const double gap = -AxialOverlap(x->axis, y->axis);
    if (gap > std::max(kMaxImpliedPinGap, d_max) + L_) continue;
    if (gap > kMaxImpliedPinGap + L_ && (on_a_rod(*x) || on_a_rod(*y))) continue;
    const bool x_first = NameLess(*x, *y);
    AddPair(PairType::kRevolute, x_first ? *x : *y, x_first ? *y : *x);
    pairs_.back().source = PairSource::kImpliedPin;
  }
}

void Recognizer::AddLooseFits() {
  if (loose_candidates_.empty()) return;
  // Parts held by a pair other than a face contact: a face leaves a washer free to slide off
  // its shaft, so a part that only rests on faces is guided by nothing else.
  std::vector<bool> held(assembly_.parts().size(), false);
  for (const Pair& p : pairs_) {
    if (p.type != PairType::kPlanar) held[p.a.part] = held[p.b.part] = true;
  }
  std::vector<std::pair<const WorldFeature*, const WorldFeature*>> fits;
  for (const auto& [s, h] : loose_candidates_) {
    if (!(held[s->ref.part] && held[h->ref.part]) && Collinear(*s, *h)) fits.emplace_back(s, h);
  }
  // A hole that shafts of one part enter from both of its ends (a knuckle between two pin
  // stubs) cannot slide off them: retained.
  std::map<std::pair<std::size_t, std::size_t>, std::array<bool, 2>> ends;  // (hole, part)
  for (const auto& [s, h] : fits) {
    const double a = (s->axis.origin - h->axis.origin).dot(h->axis.direction);
    const double b = a + s->axis.length * s->axis.direction.dot(h->axis.direction);
    const bool at_start = std::min(a, b) <= L_, at_end = std::max(a, b) >= h->axis.length - L_;
    if (at_start == at_end) continue;  // through the whole hole, or inside it
    ends[{Index(h->ref), s->ref.part}][at_start ? 0 : 1] = true;
  }
  for (const auto& [s, h] : fits) {
    const std::array<bool, 2> at = ends[{Index(h->ref), s->ref.part}];
    const bool retained = s->f.retained || h->f.retained || (at[0] && at[1]);
    AddPair(retained ? PairType::kRevolute : PairType::kCylindrical, *s, *h);
    pairs_.back().source = PairSource::kLooseFit;
  }
}

void Recognizer::ReportLooseFits() {
  std::map<std::pair<std::string, std::string>, std::vector<const Pair*>> by_parts;
  for (const Pair& p : pairs_) {
    if (p.source != PairSource::kLooseFit) continue;
    by_parts[{std::string(assembly_.PartId(p.a.part)), std::string(assembly_.PartId(p.b.part))}]
        .push_back(&p);
  }
  std::set<std::size_t> on_faces;  // parts in face contacts
  for (const Pair& p : pairs_) {
    if (p.type == PairType::kPlanar) on_faces.insert({p.a.part, p.b.part});
  }
  for (const auto& [parts, pairs] : by_parts) {
    std::set<std::string> features;
    std::set<std::string_view> types;
    double clearance = std::numeric_limits<double>::infinity();
    for (const Pair* p : pairs) {
      features.insert(assembly_.FeatureName(p->a));
      features.insert(assembly_.FeatureName(p->b));
      types.insert(ToString(p->type));
      clearance = std::min(clearance, (At(p->b).f.diameter - At(p->a).f.diameter) / 2);
    }
    diagnostics_.push_back(
        {Severity::kInfo,
         "loose_fit",
         fmt::format("{} and {} are held by nothing but {} with at least {} of radial clearance"
                     "{} ({}; taken as their {} {}; an override of type none forbids one)",
                     parts.first, parts.second,
                     pairs.size() == 1 ? "a loose fit" : fmt::format("{} loose fits", pairs.size()),
                     Mm(clearance),
                     on_faces.count(pairs.front()->a.part) || on_faces.count(pairs.front()->b.part)
                         ? " and face contacts"
                         : "",
                     fmt::join(features, ", "), fmt::join(types, " and "),
                     pairs.size() == 1 ? "pair" : "pairs"),
         {parts.first, parts.second},
         {features.begin(), features.end()}});
  }
}

void Recognizer::SetCompliantPartsApart() {
  if (!assembly_.HasCompliantParts()) return;
  std::map<std::size_t, std::set<std::string>> touched;  // compliant part -> the others
  std::erase_if(pairs_, [&](const Pair& p) {
    const bool a = assembly_.IsCompliant(p.a.part), b = assembly_.IsCompliant(p.b.part);
    if (a) touched[p.a.part].insert(std::string(assembly_.PartId(p.b.part)));
    if (b) touched[p.b.part].insert(std::string(assembly_.PartId(p.a.part)));
    return a || b;
  });
  std::erase_if(tight_, [&](const Screwed& t) {
    return assembly_.IsCompliant(t.hole.part) ||
           assembly_.IsCompliant(features_[t.thread].ref.part);
  });
  for (std::size_t part = 0; part < assembly_.parts().size(); ++part) {
    if (!assembly_.IsCompliant(part)) continue;
    const std::set<std::string>& others = touched[part];
    std::string names;
    for (const std::string& o : others) names += (names.empty() ? "" : ", ") + o;
    std::vector<std::string> parts = {std::string(assembly_.PartId(part))};
    parts.insert(parts.end(), others.begin(), others.end());
    diagnostics_.push_back(
        {Severity::kInfo,
         "compliant_part",
         fmt::format("part '{}' is compliant (a spring, belt or hose): not a rigid link; {}",
                     parts.front(),
                     names.empty() ? "it touches no part by its features"
                                   : fmt::format("it connects {}", names)),
         parts,
         {}});
  }
}

void Recognizer::ReportOneParts() {
  std::map<std::string, std::set<std::string>> bodies;  // part instance -> its bodies in contact
  for (const Pair& p : pairs_) {
    if (p.source != PairSource::kOnePart) continue;
    auto& of = bodies[assembly_.part(p.a.part).body_of];
    of.insert(std::string(assembly_.PartId(p.a.part)));
    of.insert(std::string(assembly_.PartId(p.b.part)));
  }
  for (const auto& [instance, names] : bodies) {
    diagnostics_.push_back(
        {Severity::kInfo,
         "one_part",
         fmt::format("{} are bodies of one CAD part, '{}', touching face to face: held together "
                     "as one piece (an override of type none forbids it)",
                     fmt::join(names, ", "), instance),
         {names.begin(), names.end()},
         {}});
  }
}

void Recognizer::SettleImpliedPins() {
  // Holes lie on one pin when their axes are parallel (within twice the angle tolerance: two
  // pairs through one knuckle may each lean its own way) and each one's middle lies nearer the
  // other's axis than the two pins' radii: holes a little out of line on one hinge rod, not
  // two pins side by side.
  const auto one_pin = [&](const WorldFeature& x, double dx, const WorldFeature& y, double dy) {
    const auto middle = [](const AxisSegment& s) {
      return s.origin + 0.5 * s.length * s.direction;
    };
    const double reach = 0.5 * (dx + dy);
    return AngleBetweenLines(x.axis.direction, y.axis.direction) <= 2 * A_ &&
           DistanceToLine(middle(y.axis), x.axis.origin, x.axis.direction) < reach &&
           DistanceToLine(middle(x.axis), y.axis.origin, y.axis.direction) < reach;
  };
  // The implied pins of each two parts, with each pair's pin diameter (its smaller hole's).
  struct Pins {
    std::vector<std::size_t> pairs;
    std::vector<double> diameters;
    std::set<std::string> holes;
  };
  std::map<std::pair<std::string, std::string>, Pins> by_parts;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const Pair& p = pairs_[i];
    if (p.source != PairSource::kImpliedPin) continue;
    std::string a(assembly_.PartId(p.a.part)), b(assembly_.PartId(p.b.part));
    if (b < a) std::swap(a, b);
    Pins& pins = by_parts[{a, b}];
    pins.pairs.push_back(i);
    pins.diameters.push_back(std::min(At(p.a).f.diameter, At(p.b).f.diameter));
    for (const FeatureRef f : {p.a, p.b}) pins.holes.insert(assembly_.FeatureName(f));
  }
  std::vector<bool> dropped(pairs_.size(), false);
  for (const auto& [parts, pins] : by_parts) {
    // Each pin (the pairs through it joined, whatever their order) and its diameter.
    const std::size_t n = pins.pairs.size();
    UnionFind same(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (one_pin(At(pairs_[pins.pairs[i]].a), pins.diameters[i], At(pairs_[pins.pairs[j]].a),
                    pins.diameters[j])) {
          same.Join(static_cast<int>(i), static_cast<int>(j));
        }
      }
    }
    std::map<int, double> diameter_of_pin;
    for (std::size_t k = 0; k < n; ++k) {
      const auto [it, added] =
          diameter_of_pin.try_emplace(same.Find(static_cast<int>(k)), pins.diameters[k]);
      if (!added) it->second = std::min(it->second, pins.diameters[k]);
    }
    std::string message;
    if (diameter_of_pin.size() == 1) {
      message = fmt::format(
          "{} and {} turn on a pin of about {} that the file does not model, in holes {} (a "
          "revolute pair; an override of type none forbids it, \"infer\": {{\"implied_pins\": "
          "false}} all of them)",
          parts.first, parts.second, Mm(diameter_of_pin.begin()->second),
          fmt::join(pins.holes, ", "));
    } else {
      // Two pins apart hold the parts as dowels do: one fixed pair, on the holes whose names
      // sort first (whatever the file's order), stands for them all.
      const auto ranks = [&](std::size_t pair) {
        return std::pair(assembly_.FeatureNameRank(pairs_[pair].a),
                         assembly_.FeatureNameRank(pairs_[pair].b));
      };
      const std::size_t held =
          *std::min_element(pins.pairs.begin(), pins.pairs.end(),
                            [&](std::size_t x, std::size_t y) { return ranks(x) < ranks(y); });
      pairs_[held].type = PairType::kFixed;
      pairs_[held].dof = DegreesOfFreedom(PairType::kFixed);
      for (const std::size_t pair : pins.pairs) dropped[pair] = pair != held;
      std::vector<double> diameters;
      for (const auto& [pin, d] : diameter_of_pin) diameters.push_back(d);
      std::sort(diameters.begin(), diameters.end());
      std::vector<std::string> sizes;
      for (const double d : diameters) sizes.push_back(Mm(d));
      sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
      message = fmt::format(
          "{} and {} are held together by pins that the file does not model, in holes {}: "
          "pins of about {} on {} axes let neither part turn (a fixed pair; overrides of type "
          "none on a pin's holes forbid that pin, \"infer\": {{\"implied_pins\": false}} all "
          "of them)",
          parts.first, parts.second, fmt::join(pins.holes, ", "), fmt::join(sizes, " and "),
          diameter_of_pin.size());
    }
    diagnostics_.push_back({Severity::kInfo,
                            "implied_pin",
                            message,
                            {parts.first, parts.second},
                            {pins.holes.begin(), pins.holes.end()}});
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    if (!dropped[i]) pairs_[kept++] = std::move(pairs_[i]);
  }
  pairs_.erase(pairs_.begin() + static_cast<std::ptrdiff_t>(kept), pairs_.end());
}

std::vector<Recognizer::Screwed> Recognizer::TightThreads() {
  RadixSort(tight_, BitWidth(features_.size()), [](const Screwed& t) { return t.thread; });
  std::vector<Screwed> screwed;
  for (const Screwed& t : tight_) {
    if (screwed.empty() || screwed.back().thread != t.thread) {
      screwed.push_back(t);
    } else if (assembly_.FeatureNameRank(t.hole) < assembly_.FeatureNameRank(screwed.back().hole)) {
      screwed.back().hole = t.hole;
    }
  }
  return screwed;
}

const FeatureRef* Recognizer::ScrewedInto(const std::vector<Screwed>& screwed, std::size_t thread) {
  const auto it =
      std::lower_bound(screwed.begin(), screwed.end(), thread,
                       [](const Screwed& s, std::size_t index) { return s.thread < index; });
  return it != screwed.end() && it->thread == thread ? &it->hole : nullptr;
}

std::set<std::pair<std::size_t, std::size_t>> Recognizer::UnclampedParts(
    const std::vector<Screwed>& screwed) const {
  std::set<std::pair<std::size_t, std::size_t>> unclamped;
  std::map<std::size_t, std::set<std::size_t>> passes;  // thread -> parts of its clearance holes
  for (const Pair& p : pairs_) {
    if (p.type == PairType::kCylindrical && assembly_.kind(p.a) == FeatureKind::kThread &&
        assembly_.kind(p.b) == FeatureKind::kHole && ScrewedInto(screwed, Index(p.a))) {
      passes[Index(p.a)].insert(p.b.part);
    }
  }
  std::map<std::size_t, std::set<std::size_t>> nuts;  // thread -> every part it is fixed in
  for (const Screwed& s : tight_) nuts[s.thread].insert(s.hole.part);
  // Each part's face contacts (planar pairs), so that a stack is walked without scanning
  // every pair for each thread.
  std::map<std::size_t, std::vector<const Pair*>> planar_of;
  if (!passes.empty()) {
    for (const Pair& p : pairs_) {
      if (p.type != PairType::kPlanar) continue;
      planar_of[p.a.part].push_back(&p);
      planar_of[p.b.part].push_back(&p);
    }
  }
  for (const auto& [thread, through] : passes) {
    const std::set<std::size_t>& parts = through;  // clang 14 cannot capture a binding
    const WorldFeature& t = features_[thread];
    // Where the stack is pressed from: the head, and every nut (a rod has one at each end).
    std::set<std::size_t> ends = nuts[thread];
    ends.insert(t.ref.part);
    auto in_stack = [&](std::size_t part) { return ends.count(part) > 0 || parts.count(part) > 0; };
    std::map<std::size_t, std::vector<std::size_t>> touching;  // face contacts across the axis
    std::set<const Pair*> seen;
    for (const std::set<std::size_t>* group :
         std::array<const std::set<std::size_t>*, 2>{&ends, &parts}) {
      for (const std::size_t part : *group) {
        const auto contacts = planar_of.find(part);
        if (contacts == planar_of.end()) continue;
        for (const Pair* p : contacts->second) {
          if (!in_stack(p->a.part) || !in_stack(p->b.part) || !seen.insert(p).second) continue;
          if (AngleBetweenLines(At(p->a).axis.direction, t.axis.direction) > A_) continue;
          touching[p->a.part].push_back(p->b.part);
          touching[p->b.part].push_back(p->a.part);
        }
      }
    }
    if (std::none_of(ends.begin(), ends.end(), [&](std::size_t e) { return touching.count(e); })) {
      continue;
    }
    std::set<std::size_t> reached = ends;
    std::vector<std::size_t> todo(ends.begin(), ends.end());
    while (!todo.empty()) {
      const std::size_t part = todo.back();
      todo.pop_back();
      for (const std::size_t next : touching[part]) {
        if (reached.insert(next).second) todo.push_back(next);
      }
    }
    for (const std::size_t part : parts) {
      if (!reached.count(part)) unclamped.insert({thread, part});
    }
  }
  return unclamped;
}

void Recognizer::ApplyClamp(Pair& p, const std::vector<Screwed>& screwed,
                            const std::set<std::pair<std::size_t, std::size_t>>& unclamped) const {
  if (p.type == PairType::kCylindrical && assembly_.kind(p.a) == FeatureKind::kThread &&
      assembly_.kind(p.b) == FeatureKind::kHole && ScrewedInto(screwed, Index(p.a)) &&
      !unclamped.count({Index(p.a), p.b.part})) {
    p.type = PairType::kFixed;
    p.dof = 0;
    p.source = PairSource::kClamp;
    p.fastening = PairFastening::kClamp;
    p.via = p.a;
  }
}

void Recognizer::ClampSandwichedParts() {
  // Thread (by FeatureIndex) -> the parts of its stack, and the parts it passes through.
  std::map<std::size_t, std::set<std::size_t>> stack, pierced;
  for (const Screwed& s : tight_) {
    stack[s.thread].insert(s.hole.part);
    stack[s.thread].insert(features_[s.thread].ref.part);
  }
  for (const Pair& p : pairs_) {
    if (assembly_.kind(p.a) != FeatureKind::kThread || assembly_.kind(p.b) != FeatureKind::kHole) {
      continue;
    }
    const auto thread = stack.find(Index(p.a));
    if (thread == stack.end()) continue;
    pierced[thread->first].insert(p.b.part);
    if (p.source == PairSource::kClamp) thread->second.insert(p.b.part);
  }
  // (bearing part, seat part) of the one-solid bearings whose bore is clamped.
  std::set<std::pair<std::size_t, std::size_t>> turning_seats;
  for (const SolidBearing& b : solid_bearings_) {
    if (!b.clamped) continue;
    for (const std::size_t seat : b.seats) turning_seats.insert({b.outside.part, seat});
  }
  // Each part's face contacts (planar pairs), so that a stack's neighbours are found without
  // scanning every pair for each thread.
  std::map<std::size_t, std::vector<Pair*>> planar_of;
  if (!stack.empty()) {
    for (Pair& p : pairs_) {
      if (p.type != PairType::kPlanar) continue;
      planar_of[p.a.part].push_back(&p);
      planar_of[p.b.part].push_back(&p);
    }
  }
  // The contact a clamp is recorded on: the first by feature names, whatever the file's order.
  auto by_names = [&](const Pair& p) {
    return std::pair(assembly_.FeatureNameRank(p.a), assembly_.FeatureNameRank(p.b));
  };
  for (auto& [thread, parts] : stack) {
    const WorldFeature& t = features_[thread];
    const std::set<std::size_t>& passed = pierced[thread];
    for (bool added = true; added;) {
      added = false;
      // Per part outside the stack: its first face contact with the stack on the side of +axis
      // and on the side of -axis (its face's normal along +axis or -axis).
      std::map<std::size_t, std::array<Pair*, 2>> sides;
      for (const std::size_t inner_part : parts) {
        const auto contacts = planar_of.find(inner_part);
        if (contacts == planar_of.end()) continue;
        for (Pair* p : contacts->second) {
          if (p->type != PairType::kPlanar) continue;  // clamped on an earlier pass
          const bool a_in = p->a.part == inner_part;
          const FeatureRef outer = a_in ? p->b : p->a;
          if (parts.count(outer.part) || passed.count(outer.part)) continue;  // see UnclampedParts
          if (turning_seats.count({inner_part, outer.part})) continue;
          const Eigen::Vector3d& n = At(outer).axis.direction;
          if (AngleBetweenLines(n, t.axis.direction) > A_) continue;
          Pair*& side = sides[outer.part][n.dot(t.axis.direction) > 0 ? 0 : 1];
          if (!side || by_names(*p) < by_names(*side)) side = p;
        }
      }
      for (const auto& [part, contacts] : sides) {
        if (!contacts[0] || !contacts[1]) continue;
        Pair& p = *contacts[0];
        p.type = PairType::kFixed;
        p.dof = 0;
        p.source = PairSource::kClamp;
        p.fastening = PairFastening::kClamp;
        p.via = t.ref;
        parts.insert(part);
        added = true;
      }
    }
  }
}

void Recognizer::ApplySetscrews(const std::vector<Screwed>& screwed) {
  for (const auto& [thread, s] : setscrew_candidates_) {
    const FeatureRef* hole = ScrewedInto(screwed, Index(thread->ref));
    if (!hole || s->ref.part == hole->part) continue;
    const Eigen::Vector3d tip = thread->axis.end();
    if (AngleBetweenLines(thread->axis.direction, s->axis.direction) < kPi / 2 - A_) continue;
    const double along = (tip - s->axis.origin).dot(s->axis.direction);
    if (along < -L_ || along > s->axis.length + L_) continue;
    const Eigen::Vector3d foot = s->axis.origin + along * s->axis.direction;
    if ((foot - tip).dot(thread->axis.direction) <= 0) continue;  // pointing away
    if (std::abs((foot - tip).norm() - s->f.diameter / 2) > L_) continue;
    Pair fixed;
    fixed.type = PairType::kFixed;
    fixed.a = s->ref;
    fixed.b = *hole;
    fixed.source = PairSource::kSetscrew;
    fixed.fastening = PairFastening::kSetscrew;
    fixed.dof = 0;
    fixed.via = thread->ref;
    pairs_.push_back(fixed);
  }
}

void Recognizer::ReportUnconnected() {
  if (std::optional<Diagnostic> unconnected = UnconnectedParts(assembly_, pairs_)) {
    diagnostics_.push_back(std::move(*unconnected));
  }
}

}  // namespace mechanist::internal
