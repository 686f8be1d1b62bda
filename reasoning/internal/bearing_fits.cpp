// Rolling bearings modelled as they are sold: rings and balls or rollers (AddBearings), and
// bearings of one solid (AddSolidBearings); hubs fixed on their shafts by what the file leaves
// out (FixHubsOnFlats, FixHubsBySetscrewHoles, FixHubsOnBearingShafts).

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "kernel/geometry/circle_fit.h"
#include "kernel/support/union_find.h"
#include "reasoning/internal/recognizer.h"

namespace mechanist::internal {
namespace {

/// A circle in space through points: its centre, unit normal and radius, and the largest
/// distance of a point from it.
struct SpaceCircle {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
  double worst = 0.0;
};

/// The plane of the points (their centroid and the direction of least spread), then Kasa's
/// circle fit (FitCircle) in it. Nothing for fewer than three points or points on a line.
std::optional<SpaceCircle> FitSpaceCircle(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 3) return std::nullopt;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points) scatter += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  // Eigenvalues ascend: the plane's normal first, the in-plane directions after.
  if (!(eigen.eigenvalues()[1] > 1e-12 * eigen.eigenvalues()[2])) return std::nullopt;
  const Eigen::Vector3d n = eigen.eigenvectors().col(0);
  const Eigen::Vector3d u = eigen.eigenvectors().col(2), v = n.cross(u);
  std::vector<Eigen::Vector2d> in_plane;
  for (const Eigen::Vector3d& p : points)
    in_plane.emplace_back((p - centroid).dot(u), (p - centroid).dot(v));
  const FittedCircle fit = FitCircle(in_plane);
  if (!(fit.radius > 0)) return std::nullopt;
  SpaceCircle c;
  c.center = centroid + fit.center.x() * u + fit.center.y() * v;
  c.normal = n;
  c.radius = fit.radius;
  for (const Eigen::Vector3d& p : points) {
    const double off_plane = (p - c.center).dot(n);
    const double across = ((p - c.center) - off_plane * n).norm() - c.radius;
    c.worst = std::max(c.worst, std::hypot(off_plane, across));
  }
  return c;
}

/// A part that is one rolling element: a ball, a roller (one cylinder and flat ends), or a
/// tapered roller (two round flat ends of different sizes facing away from each other along
/// the line through their centres, and nothing else: its cone gives no feature).
struct RollingElement {
  const WorldFeature* w;   ///< the ball, the roller's cylinder, a tapered roller's large end
  Eigen::Vector3d center;  ///< world
  Eigen::Vector3d axis;    ///< world, unit; a ball's is its feature's (unused)
  double diameter = 0.0;   ///< mm; a tapered roller's mean (of its ends' outlines)
  double length = 0.0;     ///< mm along its axis; 0 for a ball
  bool tapered = false;
};

/// The tapered roller of a part whose only features are `x` and `y`, or nothing: they must be
/// faces, round (as wide as high) within `L` mm, of diameters more than `L` apart, facing away
/// from each other along the line through their centres within `L` and `A` rad.
std::optional<RollingElement> TaperedRoller(const WorldFeature& x, const WorldFeature& y, double L,
                                            double A) {
  if (x.f.kind != FeatureKind::kFace || y.f.kind != FeatureKind::kFace) return std::nullopt;
  const WorldFeature& small = x.f.width < y.f.width ? x : y;
  const WorldFeature& large = &small == &x ? y : x;
  const Eigen::Vector3d along = large.axis.origin - small.axis.origin;
  const double length = along.norm();
  auto round = [&](const WorldFeature& w) { return std::abs(w.f.width - w.f.height) <= L; };
  if (!round(small) || !round(large) || large.f.width - small.f.width <= L || length <= L ||
      AngleBetweenLines(small.axis.direction, large.axis.direction) > A ||
      small.axis.direction.dot(large.axis.direction) >= 0 ||
      DistanceToLine(large.axis.origin, small.axis.origin, small.axis.direction) > L ||
      along.dot(large.axis.direction) <= 0) {
    return std::nullopt;
  }
  // The axis is the large end's normal: an exact plane's, where the ends' centres are their
  // tessellated outlines'.
  return RollingElement{&large,
                        (small.axis.origin + large.axis.origin) / 2,
                        large.axis.direction,
                        (small.f.width + large.f.width) / 2,
                        length,
                        true};
}

}  // namespace

void Recognizer::AddBearings() {
  // The rolling elements: parts that are one ball and nothing else, one shaft and faces
  // across its axis (its ends), or a tapered roller's two ends, sorted by kind and size.
  std::vector<RollingElement> elements;
  for (std::size_t part = 0; part < assembly_.parts().size(); ++part) {
    const std::size_t n = assembly_.FeatureCount(part);
    if (n == 1 && At({part, 0}).f.kind == FeatureKind::kBall) {
      const WorldFeature& ball = At({part, 0});
      elements.push_back({&ball, ball.axis.origin, ball.axis.direction, ball.f.diameter});
      continue;
    }
    if (n == 2) {
      if (const auto roller = TaperedRoller(At({part, 0}), At({part, 1}), L_, A_)) {
        elements.push_back(*roller);
        continue;
      }
    }
    const WorldFeature* cylinder = nullptr;
    bool only_ends = true;
    for (std::size_t f = 0; f < n; ++f) {
      const WorldFeature& w = At({part, f});
      if (w.f.kind == FeatureKind::kShaft && !cylinder)
        cylinder = &w;
      else if (w.f.kind != FeatureKind::kFace)
        only_ends = false;
    }
    if (!cylinder || !only_ends) continue;
    for (std::size_t f = 0; f < n; ++f) {
      const WorldFeature& w = At({part, f});
      only_ends =
          only_ends &&
          (&w == cylinder || AngleBetweenLines(w.axis.direction, cylinder->axis.direction) <= A_);
    }
    if (!only_ends) continue;
    elements.push_back(
        {cylinder, cylinder->axis.origin + cylinder->axis.length / 2 * cylinder->axis.direction,
         cylinder->axis.direction, cylinder->f.diameter, cylinder->axis.length});
  }
  if (elements.size() < 3) return;
  std::sort(elements.begin(), elements.end(),
            [&](const RollingElement& x, const RollingElement& y) {
              if (x.tapered != y.tapered) return y.tapered;
              if (x.length != y.length) return x.length < y.length;
              return x.diameter != y.diameter ? x.diameter < y.diameter : NameLess(*x.w, *y.w);
            });
  // Sets of elements of one size whose neighbours lie at most four diameters apart (single
  // linkage): the rolling elements of one bearing each. Elements of one size are consecutive
  // in that order; their neighbours are looked for in a grid of cells four diameters wide.
  std::vector<std::vector<const RollingElement*>> sets;
  for (std::size_t begin = 0, end = 0; begin < elements.size(); begin = end) {
    const RollingElement& size = elements[begin];
    double cell = 0.0;
    for (end = begin; end < elements.size() && elements[end].tapered == size.tapered &&
                      std::abs(elements[end].diameter - size.diameter) <= L_ &&
                      std::abs(elements[end].length - size.length) <= L_;
         ++end) {
      cell = std::max(cell, 4 * elements[end].diameter);
    }
    if (end - begin < 3 || !(cell > 0)) continue;
    using Cell = std::array<std::int64_t, 3>;
    auto cell_of = [&](const Eigen::Vector3d& p) {
      return Cell{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                  static_cast<std::int64_t>(std::floor(p.y() / cell)),
                  static_cast<std::int64_t>(std::floor(p.z() / cell))};
    };
    std::map<Cell, std::vector<std::size_t>> grid;
    for (std::size_t k = begin; k < end; ++k) grid[cell_of(elements[k].center)].push_back(k);
    std::vector<bool> taken(end - begin, false);
    for (std::size_t first = begin; first < end; ++first) {
      if (taken[first - begin]) continue;
      taken[first - begin] = true;
      std::vector<const RollingElement*> set{&elements[first]};
      for (std::size_t k = 0; k < set.size(); ++k) {
        const Cell c = cell_of(set[k]->center);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dz = -1; dz <= 1; ++dz) {
              const auto near = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
              if (near == grid.end()) continue;
              for (const std::size_t j : near->second) {
                const RollingElement& e = elements[j];
                if (taken[j - begin] || (e.center - set[k]->center).norm() > 4 * e.diameter) {
                  continue;
                }
                taken[j - begin] = true;
                set.push_back(&e);
              }
            }
          }
        }
      }
      if (set.size() >= 3) sets.push_back(std::move(set));
    }
  }
  for (std::vector<const RollingElement*>& set : sets) {
    std::vector<Eigen::Vector3d> centers;
    for (const RollingElement* e : set) centers.push_back(e->center);
    const std::optional<SpaceCircle> pitch = FitSpaceCircle(centers);
    if (!pitch || pitch->worst > L_) continue;
    // Rollers lie along the bearing's axis; tapered rollers' axes meet it, all at one
    // inclination of at most 45 deg (the apex their cones and the raceways' share). A ball's
    // axis means nothing.
    const RollingElement& first = *set.front();
    const bool tapered = first.tapered;
    const double tilt = AngleBetweenLines(first.axis, pitch->normal);
    if (first.length > 0 && (tapered ? tilt <= A_ || tilt > kPi / 4 : tilt > A_)) continue;
    if (first.length > 0 && std::any_of(set.begin(), set.end(), [&](const RollingElement* e) {
          return std::abs(AngleBetweenLines(e->axis, pitch->normal) - tilt) > A_ ||
                 (tapered &&
                  ClosestPointsOfLines(e->center, e->axis, pitch->center, pitch->normal).distance >
                      L_);
        })) {
      continue;
    }
    const double length = first.length;
    const double element_r = first.diameter / 2;
    const double reach = length > 0 ? length / 2 : element_r;  // from the elements' plane
    std::set<std::size_t> in_set;
    for (const RollingElement* e : set) in_set.insert(e->w->ref.part);
    // The rings' raceways or lands: coaxial with the pitch circle, between the elements'
    // inner (outer) side and the pitch circle, reaching the elements' plane within `reach`. A
    // needle bearing without an inner ring runs on the shaft itself. A tapered roller
    // bearing's raceways are cones, which give no feature: its rings are the nearest bore
    // inside the rollers and the nearest outside cylinder outside them.
    const WorldFeature* inner = nullptr;
    const WorldFeature* outer = nullptr;
    const FeatureKind inner_kind = tapered ? FeatureKind::kHole : FeatureKind::kShaft;
    const FeatureKind outer_kind = tapered ? FeatureKind::kShaft : FeatureKind::kHole;
    const double inner_from = tapered ? 0.0 : pitch->radius - element_r - L_;
    const double inner_to = tapered ? pitch->radius - element_r : pitch->radius;
    const double outer_from = tapered ? pitch->radius + element_r : pitch->radius;
    const double outer_to =
        tapered ? std::numeric_limits<double>::infinity() : pitch->radius + element_r + L_;
    for (const WorldFeature& w : features_) {
      const bool in = w.f.kind == inner_kind, out = w.f.kind == outer_kind;
      if ((!in && !out) || in_set.count(w.ref.part)) continue;
      if (AngleBetweenLines(w.axis.direction, pitch->normal) > A_ ||
          DistanceToLine(pitch->center, w.axis.origin, w.axis.direction) > L_) {
        continue;
      }
      const double r = w.f.diameter / 2;
      const double along = (pitch->center - w.axis.origin).dot(w.axis.direction);
      const double outside = std::max({0.0, -along, along - w.axis.length});
      if (outside > reach + L_) continue;
      if (in && r > inner_from && r < inner_to &&
          (!inner || r > inner->f.diameter / 2 ||
           (r == inner->f.diameter / 2 && NameLess(w, *inner)))) {
        inner = &w;
      }
      if (out && r < outer_to && r > outer_from &&
          (!outer || r < outer->f.diameter / 2 ||
           (r == outer->f.diameter / 2 && NameLess(w, *outer)))) {
        outer = &w;
      }
    }
    if (!inner || !outer || inner->ref.part == outer->ref.part) continue;
    // The rings' pairs go; the balls' too: a bearing's parts touch in many places.
    std::erase_if(pairs_, [&](const Pair& p) {
      const std::size_t a = p.a.part, b = p.b.part;
      return in_set.count(a) || in_set.count(b) ||
             (std::min(a, b) == std::min(inner->ref.part, outer->ref.part) &&
              std::max(a, b) == std::max(inner->ref.part, outer->ref.part));
    });
    // On the bearing's axis: the inner ring's bore, the outer ring's outside.
    auto on_axis = [&](const WorldFeature& w) {
      return AngleBetweenLines(w.axis.direction, pitch->normal) <= A_ &&
             DistanceToLine(pitch->center, w.axis.origin, w.axis.direction) <= L_;
    };
    // The inner ring's bore: its smallest hole on the axis, inside the raceway. A needle
    // bearing's shaft, which has none, is no ring: it runs on the shaft's own diameter.
    double bore = tapered ? inner->f.diameter : 0.0;
    for (std::size_t f = 0; f < assembly_.FeatureCount(inner->ref.part); ++f) {
      const WorldFeature& w = At({inner->ref.part, f});
      if (w.f.kind == FeatureKind::kHole && on_axis(w) && w.f.diameter < inner->f.diameter &&
          (bore == 0.0 || w.f.diameter < bore)) {
        bore = w.f.diameter;
      }
    }
    const bool inner_ring = bore > 0.0;
    if (!inner_ring) bore = inner->f.diameter;
    // The rings' seats: the outer ring's outside in a bore, the inner ring's bore on a shaft,
    // coaxial and of one size (within the length tolerance: no clearance to turn in) are
    // fitted, as bearings are; a ring that turns in its seat would make the bearing idle.
    std::set<std::string> seats;
    for (Pair& p : pairs_) {
      if (p.type != PairType::kCylindrical && p.type != PairType::kRevolute) continue;
      const WorldFeature& s = At(p.a);
      const WorldFeature& h = At(p.b);
      const bool ring =
          s.ref.part == outer->ref.part || (inner_ring && h.ref.part == inner->ref.part);
      if (!ring || s.f.kind != FeatureKind::kShaft || h.f.kind != FeatureKind::kHole ||
          AngleBetweenLines(s.axis.direction, pitch->normal) > A_ ||
          std::abs(s.f.diameter - h.f.diameter) > L_) {
        continue;
      }
      p.type = PairType::kFixed;
      p.dof = 0;
      p.source = PairSource::kBearing;
      seats.insert(
          std::string(assembly_.PartId(s.ref.part == outer->ref.part ? h.ref.part : s.ref.part)));
    }
    AddPair(PairType::kRevolute, *inner, *outer);
    pairs_.back().source = PairSource::kBearing;
    for (const RollingElement* e : set) {
      AddPair(PairType::kFixed, *e->w, *outer);
      pairs_.back().source = PairSource::kBearing;
    }
    // Its size as a catalogue gives it: the bore (above), the outer ring's outside diameter
    // and width (between its end faces, which chamfers do not shorten as they do its outside
    // cylinder); a tapered roller bearing's width is both rings' (its catalogue's T).
    double outside = 0.0, width = 0.0;
    for (std::size_t f = 0; f < assembly_.FeatureCount(outer->ref.part); ++f) {
      const WorldFeature& w = At({outer->ref.part, f});
      if (w.f.kind == FeatureKind::kShaft && on_axis(w) && w.f.diameter > outside) {
        outside = w.f.diameter, width = w.axis.length;
      }
    }
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::vector<std::size_t> rings{outer->ref.part};
    if (tapered) rings.push_back(inner->ref.part);
    for (const std::size_t ring : rings) {
      for (std::size_t f = 0; f < assembly_.FeatureCount(ring); ++f) {
        const WorldFeature& w = At({ring, f});
        if (w.f.kind != FeatureKind::kFace ||
            AngleBetweenLines(w.axis.direction, pitch->normal) > A_) {
          continue;
        }
        const double at = (w.axis.origin - pitch->center).dot(pitch->normal);
        lo = std::min(lo, at), hi = std::max(hi, at);
      }
    }
    if (hi > lo) width = hi - lo;
    const std::string size = bore > 0 && outside > 0
                                 ? fmt::format(", {} x {} x {} mm", FormatNumber(bore),
                                               FormatNumber(outside), FormatNumber(width))
                                 : "";
    std::vector<std::string> parts{std::string(assembly_.PartId(inner->ref.part)),
                                   std::string(assembly_.PartId(outer->ref.part))};
    for (const RollingElement* e : set) parts.emplace_back(assembly_.PartId(e->w->ref.part));
    // Needles: rollers at least 2.5 diameters long (ISO 3096's are 2.5 to 10).
    const bool needles = length >= 2.5 * 2 * element_r;
    const std::string kind = length == 0 ? "ball"
                             : tapered   ? "tapered roller"
                             : needles   ? "needle roller"
                                         : "cylindrical roller";
    const std::string named = length == 0 ? "balls" : needles && !tapered ? "needles" : "rollers";
    // A tapered roller's diameter is its ends' mean and its centre theirs, measured on their
    // tessellated outlines: the diameter is given to 0.1 mm, the pitch circle to 0.01 mm.
    const std::string each =
        length == 0 ? Mm(2 * element_r)
        : tapered
            ? fmt::format("{} x {} at {} to its axis",
                          FormatNumber(std::round(20 * element_r) / 10), Mm(length), Deg(tilt))
            : fmt::format("{} x {}", FormatNumber(2 * element_r), Mm(length));
    diagnostics_.push_back(
        {Severity::kInfo,
         "bearing",
         fmt::format("a {} bearing{}: {} turns in {} on {} {} of {} on a {} pitch circle "
                     "(a revolute pair; the {} are held with the outer ring, their spin and "
                     "orbit not modelled){}",
                     kind, size, assembly_.PartId(inner->ref.part),
                     assembly_.PartId(outer->ref.part), set.size(), named, each,
                     Mm(tapered ? std::round(200 * pitch->radius) / 100 : 2 * pitch->radius), named,
                     seats.empty() ? ""
                                   : fmt::format("; its rings are fitted (fixed) to {}",
                                                 fmt::join(seats, " and "))),
         parts,
         {Name(*inner), Name(*outer)}});
  }
}

void Recognizer::AddSolidBearings() {
  std::vector<SolidBearing> found;
  for (std::size_t part = 0; part < assembly_.parts().size(); ++part) {
    const std::size_t n = assembly_.FeatureCount(part);
    const WorldFeature* outside = nullptr;
    const WorldFeature* bore = nullptr;
    for (std::size_t f = 0; f < n; ++f) {
      const WorldFeature& w = At({part, f});
      if (w.f.kind == FeatureKind::kShaft && (!outside || w.f.diameter > outside->f.diameter)) {
        outside = &w;
      }
    }
    if (!outside) continue;
    for (std::size_t f = 0; f < n; ++f) {
      const WorldFeature& w = At({part, f});
      if (w.f.kind != FeatureKind::kHole || w.f.diameter >= outside->f.diameter ||
          AngleBetweenLines(w.axis.direction, outside->axis.direction) > A_ ||
          DistanceToLine(w.axis.origin, outside->axis.origin, outside->axis.direction) > L_ ||
          std::abs(w.axis.length - outside->axis.length) > L_ ||
          AxialOverlap(w.axis, outside->axis) < w.axis.length - L_) {
        continue;
      }
      bore = &w;
    }
    if (!bore) continue;
    // Two flat faces or more at each end: the rings' ends, apart.
    const Eigen::Vector3d& u = outside->axis.direction;
    int at_start = 0, at_end = 0;
    for (std::size_t f = 0; f < n; ++f) {
      const WorldFeature& w = At({part, f});
      if (w.f.kind != FeatureKind::kFace || AngleBetweenLines(w.axis.direction, u) > A_) continue;
      const double along = (w.axis.origin - outside->axis.origin).dot(u);
      at_start += std::abs(along) <= L_ ? 1 : 0;
      at_end += std::abs(along - outside->axis.length) <= L_ ? 1 : 0;
    }
    if (at_start < 2 || at_end < 2) continue;
    found.push_back({outside->ref, bore->ref, {}, {}});
  }
  if (found.empty()) return;

  // One pass over the pairs: a candidate's outside and bore, by FeatureIndex.
  std::map<std::size_t, std::size_t> by_outside, by_bore;
  for (std::size_t i = 0; i < found.size(); ++i) {
    by_outside[Index(found[i].outside)] = i;
    by_bore[Index(found[i].bore)] = i;
  }
  for (Pair& p : pairs_) {
    if (p.type != PairType::kCylindrical && p.type != PairType::kRevolute) continue;
    const WorldFeature& s = At(p.a);
    const WorldFeature& h = At(p.b);
    if (const auto outside = by_outside.find(Index(p.a));
        outside != by_outside.end() && h.f.kind == FeatureKind::kHole &&
        std::abs(s.f.diameter - h.f.diameter) <= L_) {
      p.type = PairType::kFixed;
      p.dof = 0;
      p.source = PairSource::kBearing;
      found[outside->second].seats.insert(h.ref.part);
    } else if (const auto bore = by_bore.find(Index(p.b));
               bore != by_bore.end() && s.f.kind == FeatureKind::kShaft) {
      p.type = PairType::kRevolute;
      p.dof = 1;
      p.source = PairSource::kBearing;
      found[bore->second].turning.insert(s.ref.part);
    }
  }
  for (SolidBearing& b : found) {
    if (!b.seats.empty() || !b.turning.empty()) solid_bearings_.push_back(std::move(b));
  }
}

void Recognizer::ReportSolidBearings() {
  if (solid_bearings_.empty()) return;
  // The parts whose threads clamp each bore (by the bore's FeatureIndex).
  std::map<std::size_t, std::set<std::size_t>> bolts_on;
  for (const Pair& p : pairs_) {
    if (p.type == PairType::kFixed && p.source == PairSource::kClamp) {
      bolts_on[Index(p.b)].insert(p.a.part);
    }
  }
  std::set<std::size_t> clamped_outsides;  // by FeatureIndex
  for (SolidBearing& b : solid_bearings_) {
    b.clamped = bolts_on.count(Index(b.bore)) && !b.seats.empty();
    if (b.clamped) clamped_outsides.insert(Index(b.outside));
  }
  for (Pair& p : pairs_) {
    if (p.type == PairType::kFixed && p.source == PairSource::kBearing &&
        clamped_outsides.count(Index(p.a))) {
      p.type = PairType::kRevolute;
      p.dof = 1;
    }
  }
  // Part ids in the order of the ids, as the message lists them.
  auto ids = [&](const std::set<std::size_t>& parts) {
    std::set<std::string> named;
    for (const std::size_t part : parts) named.insert(std::string(assembly_.PartId(part)));
    return named;
  };
  for (const SolidBearing& b : solid_bearings_) {
    const std::set<std::string> seats = ids(b.seats);
    const std::set<std::string> turning = ids(b.turning);
    const std::set<std::string> bolts =
        b.clamped ? ids(bolts_on.at(Index(b.bore))) : std::set<std::string>{};
    const WorldFeature& outside = At(b.outside);
    const WorldFeature& bore = At(b.bore);
    const std::string_view part = assembly_.PartId(b.outside.part);
    std::string how;
    if (b.clamped) {
      how = fmt::format(" clamped through its bore by {}, {} turning on it (a revolute pair)",
                        fmt::join(bolts, " and "), fmt::join(seats, " and "));
    } else {
      how = seats.empty() ? "" : fmt::format(" fitted (fixed) in {}", fmt::join(seats, " and "));
      if (!turning.empty()) {
        how +=
            fmt::format(", {} turning in its bore (a revolute pair)", fmt::join(turning, " and "));
      }
    }
    std::vector<std::string> parts{std::string(part)};
    parts.insert(parts.end(), seats.begin(), seats.end());
    parts.insert(parts.end(), turning.begin(), turning.end());
    parts.insert(parts.end(), bolts.begin(), bolts.end());
    diagnostics_.push_back(
        {Severity::kInfo,
         "bearing",
         fmt::format("a bearing modelled as one solid, {} x {} x {} mm: {}{}",
                     FormatNumber(bore.f.diameter), FormatNumber(outside.f.diameter),
                     FormatNumber(outside.axis.length), part, how),
         std::move(parts),
         {Name(outside), Name(bore)}});
  }
}

std::optional<Recognizer::HubOnShaft> Recognizer::AsHubOnShaft(const Pair& p) const {
  if (p.type != PairType::kCylindrical || p.source != PairSource::kRecognised) return {};
  const WorldFeature& s = At(p.a);
  const WorldFeature& h = At(p.b);
  if (s.f.kind != FeatureKind::kShaft || h.f.kind != FeatureKind::kHole) return {};
  const Eigen::Vector3d& u = s.axis.direction;
  const double h0 = (h.axis.origin - s.axis.origin).dot(u);
  const double h1 = h0 + h.axis.length * h.axis.direction.dot(u);
  return HubOnShaft{s, h, std::min(h0, h1), std::max(h0, h1)};
}

void Recognizer::FixHubsOnFlats() {
  for (Pair& p : pairs_) {
    const std::optional<HubOnShaft> hub = AsHubOnShaft(p);
    if (!hub) continue;
    const WorldFeature& s = hub->s;
    const WorldFeature& h = hub->h;
    const Eigen::Vector3d& u = s.axis.direction;
    const double r = s.f.diameter / 2;
    const double lo = hub->lo, hi = hub->hi;
    const WorldFeature* flat = nullptr;
    for (std::size_t f = 0; f < assembly_.FeatureCount(s.ref.part) && !flat; ++f) {
      const WorldFeature& w = At({s.ref.part, f});
      if (w.f.kind != FeatureKind::kFace || std::abs(w.axis.direction.dot(u)) > std::sin(A_))
        continue;
      const Eigen::Vector3d d = w.axis.origin - s.axis.origin;
      const double along = d.dot(u);
      const double depth = r - (d - along * u).dot(w.axis.direction);  // cut below the surface
      if (depth <= L_ || depth >= r) continue;
      // Its extent along the axis: at most its larger extent (a face keeps no in-plane
      // direction), taken whole.
      const double half = w.f.width > 0 ? std::max(w.f.width, w.f.height) / 2 : 0.0;
      if (along + half > lo + L_ && along - half < hi - L_) flat = &w;
    }
    if (!flat) continue;
    p.type = PairType::kFixed;
    p.dof = 0;
    p.source = PairSource::kShaftFlat;
    diagnostics_.push_back(
        {Severity::kInfo,
         "shaft_flat",
         fmt::format("{} sits on the flat {} of {}: fixed to it (the flat turns it: a setscrew "
                     "or a D-shaped bore the file does not model; an override of type none "
                     "forbids it)",
                     assembly_.PartId(h.ref.part), Name(*flat), Name(s)),
         {std::string(assembly_.PartId(h.ref.part)), std::string(assembly_.PartId(s.ref.part))},
         {Name(s), Name(h), Name(*flat)}});
  }
}

void Recognizer::FixHubsBySetscrewHoles() {
  for (Pair& p : pairs_) {
    const std::optional<HubOnShaft> hub = AsHubOnShaft(p);
    if (!hub) continue;
    const WorldFeature& s = hub->s;
    const WorldFeature& h = hub->h;
    const Eigen::Vector3d& u = s.axis.direction;
    const double bore = h.f.diameter / 2;
    // Where the hub and the shaft overlap along the shaft's axis.
    const double lo = std::max(hub->lo, 0.0), hi = std::min(hub->hi, s.axis.length);
    const auto radial = [&](const Eigen::Vector3d& p_W) {
      return DistanceToLine(p_W, s.axis.origin, u);
    };
    const WorldFeature* found = nullptr;
    for (std::size_t f = 0; f < assembly_.FeatureCount(h.ref.part) && !found; ++f) {
      const WorldFeature& t = At({h.ref.part, f});
      if (t.f.kind != FeatureKind::kHole || t.ref == h.ref || t.f.diameter >= h.f.diameter) {
        continue;
      }
      if (std::abs(t.axis.direction.dot(u)) > std::sin(A_)) continue;  // not across the shaft
      // Through the shaft's axis, within the overlap.
      const LineLineClosest c =
          ClosestPointsOfLines(s.axis.origin, u, t.axis.origin, t.axis.direction);
      if (c.distance > L_ || c.s < lo - L_ || c.s > hi + L_) continue;
      const double r0 = radial(t.axis.origin), r1 = radial(t.axis.end());
      if (std::min(r0, r1) > bore + L_ || std::max(r0, r1) <= bore + L_) continue;
      found = &t;
    }
    if (!found) continue;
    const WorldFeature& t = *found;
    const std::size_t hub_part = h.ref.part, shaft_part = s.ref.part;
    // Nothing in the hole, and nothing but the shaft's part and face contacts on the hub.
    const bool free_hub = std::none_of(pairs_.begin(), pairs_.end(), [&](const Pair& q) {
      if (q.a == t.ref || q.b == t.ref) return true;
      if (q.a.part != hub_part && q.b.part != hub_part) return false;
      const std::size_t other = q.a.part == hub_part ? q.b.part : q.a.part;
      return other != shaft_part && q.type != PairType::kPlanar;
    });
    if (!free_hub) continue;
    p.type = PairType::kFixed;
    p.dof = 0;
    p.source = PairSource::kSetscrewHole;
    diagnostics_.push_back(
        {Severity::kInfo,
         "setscrew_hole",
         fmt::format("{} sits on {} with an empty radial hole {} ({}) into its bore: fixed to it "
                     "by a setscrew the file does not model (an override of type none forbids "
                     "it)",
                     assembly_.PartId(hub_part), Name(s), Name(t), Mm(t.f.diameter)),
         {std::string(assembly_.PartId(hub_part)), std::string(assembly_.PartId(shaft_part))},
         {Name(s), Name(h), Name(t)}});
  }
}

void Recognizer::FixHubsOnBearingShafts() {
  std::vector<Pair*> hubs;
  bool any_bearing = false;
  for (Pair& p : pairs_) {
    if (AsHubOnShaft(p)) hubs.push_back(&p);
    any_bearing =
        any_bearing || (p.type == PairType::kRevolute && p.source == PairSource::kBearing);
  }
  if (hubs.empty() || !any_bearing) return;
  // The rigid bodies so far: parts joined by fixed pairs (roots: their smallest part).
  UnionFind bodies(assembly_.parts().size());
  for (const Pair& p : pairs_) {
    if (p.type == PairType::kFixed) {
      bodies.Join(static_cast<int>(p.a.part), static_cast<int>(p.b.part));
    }
  }
  auto body = [&](FeatureRef ref) { return bodies.Find(static_cast<int>(ref.part)); };
  // Per hub's body: the bodies its pairs other than face contacts join it to. Per body: its
  // bearings.
  std::map<int, std::set<int>> joined;
  for (const Pair* p : hubs) joined[body(p->b)];
  std::map<int, std::vector<const Pair*>> bearings;
  for (const Pair& p : pairs_) {
    const int a = body(p.a), b = body(p.b);
    if (a == b || p.type == PairType::kPlanar) continue;
    if (const auto hub = joined.find(a); hub != joined.end()) hub->second.insert(b);
    if (const auto hub = joined.find(b); hub != joined.end()) hub->second.insert(a);
    if (p.type == PairType::kRevolute && p.source == PairSource::kBearing) {
      bearings[a].push_back(&p);
      bearings[b].push_back(&p);
    }
  }
  for (Pair* p : hubs) {
    const HubOnShaft hub = *AsHubOnShaft(*p);
    const WorldFeature& s = hub.s;
    const WorldFeature& h = hub.h;
    const int hub_body = body(h.ref), shaft_body = body(s.ref);
    // More than the shaft holds it, or the shaft's body has no bearing.
    const auto on_shaft = bearings.find(shaft_body);
    if (joined.at(hub_body) != std::set<int>{shaft_body} || on_shaft == bearings.end()) continue;
    // A bearing on the shaft's axis between the shaft's body and a third one.
    const Pair* bearing = nullptr;
    for (const Pair* q : on_shaft->second) {
      const int other = body(q->a) == shaft_body ? body(q->b) : body(q->a);
      const WorldFeature& axis = At(q->a);
      if (other != hub_body && AngleBetweenLines(axis.axis.direction, s.axis.direction) <= A_ &&
          DistanceToLine(axis.axis.origin, s.axis.origin, s.axis.direction) <= L_) {
        bearing = q;
        break;
      }
    }
    if (!bearing) continue;
    p->type = PairType::kFixed;
    p->dof = 0;
    p->source = PairSource::kBearingShaft;
    const std::size_t own = body(bearing->a) == shaft_body ? bearing->a.part : bearing->b.part;
    const std::size_t across = own == bearing->a.part ? bearing->b.part : bearing->a.part;
    diagnostics_.push_back(
        {Severity::kInfo,
         "bearing_shaft",
         fmt::format("{} is held by nothing but {}, on the axis of a bearing between {} and {}: "
                     "taken as fixed to it (a part on a bearing's shaft or housing turns with "
                     "it: its key, setscrew, screws, glue or press fit is not in the file; an "
                     "override of type none forbids it)",
                     assembly_.PartId(h.ref.part), Name(s), assembly_.PartId(own),
                     assembly_.PartId(across)),
         {std::string(assembly_.PartId(h.ref.part)), std::string(assembly_.PartId(s.ref.part))},
         {Name(s), Name(h)}});
  }
}

}  // namespace mechanist::internal
