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
#include <memory>
#include <optional>
#include <set>
#include <tuple>

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

/// Whether `w`'s axis is `pitch`'s: within `A` rad of its normal, its line within `L` mm of
/// its centre.
bool OnAxisOf(const WorldFeature& w, const SpaceCircle& pitch, double L, double A) {
  return AngleBetweenLines(w.axis.direction, pitch.normal) <= A &&
         DistanceToLine(pitch.center, w.axis.origin, w.axis.direction) <= L;
}

/// mm along `w`'s axis from its segment to `pitch`'s plane: 0 when the segment reaches it.
double FromPlaneOf(const WorldFeature& w, const SpaceCircle& pitch) {
  const double along = (pitch.center - w.axis.origin).dot(w.axis.direction);
  return std::max({0.0, -along, along - w.axis.length});
}

/// One rolling element: a part that is a ball, a roller (one cylinder and flat ends across
/// it), or a roller whose side gives no feature (a cone or a barrel's torus): two round flat
/// ends facing away from each other along the line through their centres, or one such end and
/// a domed other end (RollerByOneEnd), and nothing else; a tapered roller's ends differ in
/// size, a barrel roller's are equal. Or one ball of a ball set (several in one part).
struct RollingElement {
  enum class Shape { kBall, kRoller, kTaperedRoller, kBarrelRoller };
  Shape shape = Shape::kBall;
  /// The ball, the roller's cylinder, the larger of its two flat ends, or its one flat end.
  const WorldFeature* w;
  Eigen::Vector3d center;  ///< world
  Eigen::Vector3d axis;    ///< world, unit; a ball's means nothing
  double diameter = 0.0;   ///< mm; a tapered roller's mean of its ends, a barrel's ends'
  double length = 0.0;     ///< mm along its axis; 0 for a ball
};

/// The roller of a part whose only features are `x` and `y` (RollingElement), or nothing:
/// they must be faces, round (as wide as high) within `L` mm, facing away from each other
/// along the line through their centres within `L` and `A` rad. Ends whose diameters differ by
/// more than `L` are a tapered roller's, others a barrel roller's.
std::optional<RollingElement> RollerByItsEnds(const WorldFeature& x, const WorldFeature& y,
                                              double L, double A) {
  if (x.f.kind != FeatureKind::kFace || y.f.kind != FeatureKind::kFace) return std::nullopt;
  const WorldFeature& small = x.f.width < y.f.width ? x : y;
  const WorldFeature& large = &small == &x ? y : x;
  const Eigen::Vector3d along = large.axis.origin - small.axis.origin;
  const double length = along.norm();
  auto round = [&](const WorldFeature& w) { return std::abs(w.f.width - w.f.height) <= L; };
  if (!round(small) || !round(large) || !(small.f.width > L) || length <= L ||
      AngleBetweenLines(small.axis.direction, large.axis.direction) > A ||
      small.axis.direction.dot(large.axis.direction) >= 0 ||
      DistanceToLine(large.axis.origin, small.axis.origin, small.axis.direction) > L ||
      along.dot(large.axis.direction) <= 0) {
    return std::nullopt;
  }
  // The axis is the large end's normal: an exact plane's, where the ends' centres are their
  // tessellated outlines'.
  RollingElement roller;
  roller.shape = large.f.width - small.f.width > L ? RollingElement::Shape::kTaperedRoller
                                                   : RollingElement::Shape::kBarrelRoller;
  roller.w = &large;
  roller.center = (small.axis.origin + large.axis.origin) / 2;
  roller.axis = large.axis.direction;
  roller.diameter = (small.f.width + large.f.width) / 2;
  roller.length = length;
  return roller;
}

/// The roller of a part whose only feature is `end`, one round flat end (as wide as high within
/// `L` mm), whose other end is domed (a tapered roller's large end bearing on its rib is a
/// sphere about the apex), or nothing. Its `mesh` (part frame, at pose `X_WP`) gives the rest:
/// every vertex lies behind the end's face within `L`; the roller's length, the mesh's extent
/// along the end's normal, is at least half the end's diameter; and its last quarter is at
/// least 0.8 times as wide as the flat end (a cone, a dome or a foot tapers off). A roller
/// whose widest section lies in the far half and is wider than the flat end by more than `L`
/// is tapered (its large end that section), any other a barrel roller of the flat end's
/// diameter.
std::optional<RollingElement> RollerByOneEnd(const WorldFeature& end, const TriangleMesh& mesh,
                                             const RigidTransform& X_WP, double L) {
  if (end.f.kind != FeatureKind::kFace || std::abs(end.f.width - end.f.height) > L ||
      !(end.f.width > L) || mesh.vertices.empty()) {
    return std::nullopt;
  }
  const Eigen::Vector3d& p_WO = end.axis.origin;
  const Eigen::Vector3d into = -end.axis.direction;  // the face's normal points out of the part
  struct Section {
    double h, r;  // mm along `into` from the end's face, and from its axis
  };
  std::vector<Section> sections;
  sections.reserve(mesh.vertices.size());
  double length = 0.0;
  for (const Eigen::Vector3d& p_P : mesh.vertices) {
    const Eigen::Vector3d d = X_WP * p_P - p_WO;
    const double h = d.dot(into);
    if (h < -L) return std::nullopt;
    sections.push_back({h, (d - h * into).norm()});
    length = std::max(length, h);
  }
  const double small = end.f.width / 2;
  if (length <= L || length < small) return std::nullopt;
  double widest = 0.0, widest_at = 0.0, far = 0.0;
  for (const Section& s : sections) {
    if (s.r > widest) widest = s.r, widest_at = s.h;
    if (s.h >= 0.75 * length) far = std::max(far, s.r);
  }
  if (far < 0.8 * small) return std::nullopt;
  const bool tapered = 2 * widest - end.f.width > L && widest_at > length / 2;
  RollingElement roller;
  roller.shape =
      tapered ? RollingElement::Shape::kTaperedRoller : RollingElement::Shape::kBarrelRoller;
  roller.w = &end;
  roller.center = p_WO + length / 2 * into;
  roller.axis = into;  // from the small end to the large, as RollerByItsEnds gives it
  roller.diameter = tapered ? small + widest : end.f.width;
  roller.length = length;
  return roller;
}

/// Rollers measured on their ends' tessellated outlines or their meshes (tapered and barrel
/// rollers): their diameters and lengths are given to 0.1 mm and their pitch circles to 0.01 mm.
bool ByTheirEnds(RollingElement::Shape shape) {
  return shape == RollingElement::Shape::kTaperedRoller ||
         shape == RollingElement::Shape::kBarrelRoller;
}

}  // namespace

/// One row of a bearing's rolling elements, on its pitch circle, and the rings' features.
struct Recognizer::BearingRow {
  std::vector<const RollingElement*> elements;
  SpaceCircle pitch;
  double tilt = 0.0;  ///< rad: the elements' axes from the pitch circle's
  /// The inner ring's feature that makes the revolute pair (a thrust bearing's shaft washer's
  /// bore), and the outer ring's (its housing washer's bore).
  const WorldFeature* inner = nullptr;
  const WorldFeature* outer = nullptr;
  bool thrust = false;  ///< the rings are washers on either side of the elements' plane
  /// The outer ring was found by its outside: a self-aligning ball bearing's, whose raceway
  /// is a sphere (no feature).
  bool self_aligning = false;
  /// The inner raceway is cut into a shaft (ShaftUnderRollers): no ring, hollow or not.
  bool raceway_on_shaft = false;
  /// mm: a thrust bearing's washers' raceway faces from the elements' plane, below and above.
  std::array<double, 2> washers{0.0, 0.0};
};

bool Recognizer::FindBearingRings(BearingRow& row) const {
  // Rollers lie along the bearing's axis. Tapered and barrel rollers' axes lie in the plane
  // through it and their centres (a tapered roller's meets it at the apex its cone and the
  // raceways' share), all at one inclination of at most 45 deg; a tapered roller's leans.
  // Cylindrical rollers along radii are a thrust bearing's.
  const RollingElement& first = *row.elements.front();
  const SpaceCircle& pitch = row.pitch;
  const bool by_ends = ByTheirEnds(first.shape);
  row.tilt = AngleBetweenLines(first.axis, pitch.normal);
  const bool along_radii =
      first.shape == RollingElement::Shape::kRoller && std::abs(row.tilt - kPi / 2) <= A_;
  if (first.shape == RollingElement::Shape::kRoller && row.tilt > A_ && !along_radii) {
    return false;
  }
  if (by_ends && row.tilt > kPi / 4) return false;
  if (first.shape == RollingElement::Shape::kTaperedRoller && row.tilt <= A_) return false;
  if (first.shape != RollingElement::Shape::kBall &&
      std::any_of(row.elements.begin(), row.elements.end(), [&](const RollingElement* e) {
        const Eigen::Vector3d radial = (e->center - pitch.center).normalized();
        const Eigen::Vector3d across = pitch.normal.cross(radial).normalized();
        return std::abs(AngleBetweenLines(e->axis, pitch.normal) - row.tilt) > A_ ||
               ((by_ends || along_radii) && std::abs(e->axis.dot(across)) > std::sin(A_));
      })) {
    return false;
  }
  std::set<std::size_t> in_row;
  for (const RollingElement* e : row.elements) in_row.insert(e->w->ref.part);
  if (along_radii) return FindThrustWashers(row, in_row);
  // The elements' reach from the pitch circle: across it (a tilted roller's ends and sides)
  // and along its axis.
  const double element_r = first.diameter / 2;
  const double radial_reach =
      first.length / 2 * std::sin(row.tilt) + element_r * std::cos(row.tilt);
  const double reach = first.length > 0 ? first.length / 2 : element_r;
  // The rings' raceways or lands: coaxial with the pitch circle, between the elements'
  // inner (outer) side and the pitch circle, reaching the elements' plane within `reach`. A
  // needle bearing without an inner ring runs on the shaft itself. Tapered and barrel
  // rollers' raceways are cones and tori, which give no feature: their rings are the nearest
  // bore inside the rollers and the nearest outside cylinder outside them.
  const FeatureKind inner_kind = by_ends ? FeatureKind::kHole : FeatureKind::kShaft;
  const FeatureKind outer_kind = by_ends ? FeatureKind::kShaft : FeatureKind::kHole;
  const double inner_from = by_ends ? 0.0 : pitch.radius - element_r - L_;
  const double inner_to = by_ends ? pitch.radius - radial_reach : pitch.radius;
  const double outer_from = by_ends ? pitch.radius + radial_reach : pitch.radius;
  const double outer_to =
      by_ends ? std::numeric_limits<double>::infinity() : pitch.radius + element_r + L_;
  const WorldFeature* beyond = nullptr;  // balls: the nearest outside cylinder beyond them
  for (const WorldFeature& w : features_) {
    const bool in = w.f.kind == inner_kind, out = w.f.kind == outer_kind;
    if ((!in && !out) || in_row.count(w.ref.part)) continue;
    if (!OnAxisOf(w, pitch, L_, A_) || FromPlaneOf(w, pitch) > reach + L_) continue;
    const double r = w.f.diameter / 2;
    if (in && r > inner_from && r < inner_to &&
        (!row.inner || r > row.inner->f.diameter / 2 ||
         (r == row.inner->f.diameter / 2 && NameLess(w, *row.inner)))) {
      row.inner = &w;
    }
    if (out && r < outer_to && r > outer_from &&
        (!row.outer || r < row.outer->f.diameter / 2 ||
         (r == row.outer->f.diameter / 2 && NameLess(w, *row.outer)))) {
      row.outer = &w;
    }
    if (in && !by_ends && r > pitch.radius + element_r &&
        (!beyond || r < beyond->f.diameter / 2 ||
         (r == beyond->f.diameter / 2 && NameLess(w, *beyond)))) {
      beyond = &w;
    }
  }
  if (by_ends && !row.inner && row.outer) {
    row.inner = ShaftUnderRollers(row, in_row, inner_to);
    row.raceway_on_shaft = row.inner != nullptr;
  }
  if (row.inner && row.outer && row.inner->ref.part != row.outer->ref.part) return true;
  const WorldFeature* land = row.inner;
  row.inner = row.outer = nullptr;
  if (first.shape != RollingElement::Shape::kBall) return false;
  // Balls with no rings around them may run between washers.
  if (FindThrustWashers(row, in_row)) return true;
  // Balls on an inner ring's land or raceway, with no bore at their outer side: a
  // self-aligning ball bearing, whose outer raceway is a sphere about the bearing's centre,
  // which gives no feature. Its outer ring is the nearest outside cylinder beyond the balls,
  // on a part with no bore between the two (a housing's bore around the balls is no raceway).
  if (!land || !beyond || beyond->ref.part == land->ref.part) return false;
  for (std::size_t f = 0; f < assembly_.FeatureCount(beyond->ref.part); ++f) {
    const WorldFeature& w = At({beyond->ref.part, f});
    if (w.f.kind == FeatureKind::kHole && w.f.diameter / 2 > pitch.radius &&
        w.f.diameter < beyond->f.diameter && OnAxisOf(w, pitch, L_, A_) &&
        FromPlaneOf(w, pitch) <= reach + L_) {
      return false;
    }
  }
  row.inner = land;
  row.outer = beyond;
  row.self_aligning = true;
  return true;
}

const WorldFeature* Recognizer::ShaftUnderRollers(const BearingRow& row,
                                                  const std::set<std::size_t>& in_row,
                                                  double inside) const {
  // Rollers found by their ends and no bore inside them: they run on a raceway cut into a
  // shaft. Of the parts with a shaft coaxial with the pitch circle and thinner than `inside`
  // (anywhere along the axis: its cylinders lie beyond the raceway), the one whose mesh comes
  // nearest the rollers within their reach of their plane, inside the pitch circle, and at
  // least as near as their inner side; its such shaft nearest their plane, then the widest.
  const RollingElement& first = *row.elements.front();
  const SpaceCircle& pitch = row.pitch;
  const double reach = first.length / 2 * std::cos(row.tilt) + first.diameter / 2;
  std::map<std::size_t, double> raceway;  // per part: its mesh's radius nearest the rollers
  const WorldFeature* shaft = nullptr;
  double nearest = inside - L_;
  for (const WorldFeature& w : features_) {
    const std::size_t part = w.ref.part;
    if (w.f.kind != FeatureKind::kShaft || in_row.count(part) || part == row.outer->ref.part ||
        !(w.f.diameter / 2 < inside) || !OnAxisOf(w, pitch, L_, A_) || !assembly_.part(part).mesh) {
      continue;
    }
    auto [at, added] = raceway.emplace(part, 0.0);
    if (added) {
      for (const Eigen::Vector3d& p_P : assembly_.part(part).mesh->vertices) {
        const Eigen::Vector3d d = X_WP_[part] * p_P - pitch.center;
        const double h = d.dot(pitch.normal);
        const double r = (d - h * pitch.normal).norm();
        if (std::abs(h) <= reach && r < pitch.radius) at->second = std::max(at->second, r);
      }
    }
    // Of one part's shafts, the one nearest the rollers' plane (a journal beside the
    // raceway, not a collar further on), then the widest.
    const bool better_on_same_part = shaft && shaft->ref.part == part &&
                                     std::tuple(FromPlaneOf(w, pitch), -w.f.diameter) <
                                         std::tuple(FromPlaneOf(*shaft, pitch), -shaft->f.diameter);
    if (at->second > nearest || (at->second == nearest && better_on_same_part)) {
      nearest = at->second;
      shaft = &w;
    }
  }
  return shaft;
}

bool Recognizer::FindThrustWashers(BearingRow& row, const std::set<std::size_t>& in_row) const {
  // On each side of the elements' plane, the nearest flat face of another part square to the
  // axis, centred on it, reaching across the pitch circle and facing the elements within their
  // radius of the plane: the washers' raceway sides (beside a ball's groove, or a roller's
  // flat raceway).
  const SpaceCircle& pitch = row.pitch;
  const double element_r = row.elements.front()->diameter / 2;
  std::array<const WorldFeature*, 2> facing{nullptr, nullptr};  // below the plane, above it
  std::array<double, 2> distance{0.0, 0.0};
  for (const WorldFeature& w : features_) {
    if (w.f.kind != FeatureKind::kFace || in_row.count(w.ref.part)) continue;
    const double at = (w.axis.origin - pitch.center).dot(pitch.normal);
    if (AngleBetweenLines(w.axis.direction, pitch.normal) > A_ ||
        DistanceToLine(w.axis.origin, pitch.center, pitch.normal) > L_ ||
        !(w.f.width / 2 > pitch.radius) || std::abs(at) <= L_ || std::abs(at) > element_r + L_ ||
        w.axis.direction.dot(pitch.normal) * at >= 0) {
      continue;
    }
    const std::size_t side = at > 0;
    if (!facing[side] || std::abs(at) < distance[side] ||
        (std::abs(at) == distance[side] && NameLess(w, *facing[side]))) {
      facing[side] = &w, distance[side] = std::abs(at);
    }
  }
  if (!facing[0] || !facing[1] || facing[0]->ref.part == facing[1]->ref.part) return false;
  // Each washer's bore: its smallest hole on the axis. The shaft washer's is the smaller.
  std::array<const WorldFeature*, 2> bores{nullptr, nullptr};
  for (std::size_t side = 0; side < 2; ++side) {
    const std::size_t washer = facing[side]->ref.part;
    for (std::size_t f = 0; f < assembly_.FeatureCount(washer); ++f) {
      const WorldFeature& w = At({washer, f});
      if (w.f.kind == FeatureKind::kHole && OnAxisOf(w, pitch, L_, A_) &&
          (!bores[side] || w.f.diameter < bores[side]->f.diameter)) {
        bores[side] = &w;
      }
    }
    if (!bores[side]) return false;
  }
  const bool first_is_shaft_washer =
      bores[0]->f.diameter < bores[1]->f.diameter ||
      (bores[0]->f.diameter == bores[1]->f.diameter && NameLess(*bores[0], *bores[1]));
  row.inner = bores[first_is_shaft_washer ? 0 : 1];
  row.outer = bores[first_is_shaft_washer ? 1 : 0];
  row.thrust = true;
  row.washers = distance;
  return true;
}

void Recognizer::AddBearings() {
  // The rolling elements: parts that are one ball and nothing else, or a ball set; one shaft
  // and faces across its axis (its ends); two round ends; or one round end, measured on the
  // mesh. Sorted by shape and size.
  std::vector<RollingElement> elements;
  for (std::size_t part = 0; part < assembly_.parts().size(); ++part) {
    const std::size_t n = assembly_.FeatureCount(part);
    // A ball, or a ball set: three or more balls of one size in one part (fused with their
    // cage, as vendors' three-solid bearings have them), each ball an element.
    std::vector<const WorldFeature*> balls;
    for (std::size_t f = 0; f < n; ++f) {
      if (At({part, f}).f.kind == FeatureKind::kBall) balls.push_back(&At({part, f}));
    }
    const bool ball_set =
        balls.size() >= 3 && std::all_of(balls.begin(), balls.end(), [&](const WorldFeature* b) {
          return std::abs(b->f.diameter - balls.front()->f.diameter) <= L_;
        });
    if ((n == 1 && balls.size() == 1) || ball_set) {
      for (const WorldFeature* ball : balls) {
        elements.push_back({RollingElement::Shape::kBall, ball, ball->axis.origin,
                            ball->axis.direction, ball->f.diameter});
      }
      continue;
    }
    if (n == 2) {
      if (const auto roller = RollerByItsEnds(At({part, 0}), At({part, 1}), L_, A_)) {
        elements.push_back(*roller);
        continue;
      }
    }
    if (n == 1 && assembly_.part(part).mesh) {
      if (const auto roller =
              RollerByOneEnd(At({part, 0}), *assembly_.part(part).mesh, X_WP_[part], L_)) {
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
        {RollingElement::Shape::kRoller, cylinder,
         cylinder->axis.origin + cylinder->axis.length / 2 * cylinder->axis.direction,
         cylinder->axis.direction, cylinder->f.diameter, cylinder->axis.length});
  }
  if (elements.size() < 3) return;
  std::sort(elements.begin(), elements.end(),
            [&](const RollingElement& x, const RollingElement& y) {
              if (x.shape != y.shape) return x.shape < y.shape;
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
    for (end = begin; end < elements.size() && elements[end].shape == size.shape &&
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
  // Rows: a set's elements on one pitch circle. A set on circles side by side (a double-row
  // bearing's, whose rows are neighbours) is split where its centres' positions along the
  // direction of least spread (the circles' common axis) jump by more than the length
  // tolerance, and each part of three or more is fitted again.
  std::vector<BearingRow> rows;
  auto circle_of = [](const std::vector<const RollingElement*>& elements) {
    std::vector<Eigen::Vector3d> centers;
    for (const RollingElement* e : elements) centers.push_back(e->center);
    return FitSpaceCircle(centers);
  };
  auto add_row = [&](std::vector<const RollingElement*> elements, const SpaceCircle& pitch) {
    BearingRow row{std::move(elements), pitch};
    if (FindBearingRings(row)) rows.push_back(std::move(row));
  };
  for (std::vector<const RollingElement*>& set : sets) {
    const std::optional<SpaceCircle> spread = circle_of(set);
    if (!spread) continue;
    if (spread->worst <= L_) {
      add_row(set, *spread);
      continue;
    }
    auto height = [&](const RollingElement* e) {
      return (e->center - spread->center).dot(spread->normal);
    };
    std::stable_sort(set.begin(), set.end(), [&](const RollingElement* x, const RollingElement* y) {
      return height(x) < height(y);
    });
    for (std::size_t begin = 0, end = 0; begin < set.size(); begin = end) {
      for (end = begin + 1; end < set.size() && height(set[end]) - height(set[end - 1]) <= L_;
           ++end) {
      }
      if (end - begin < 3 || end - begin == set.size()) continue;
      std::vector<const RollingElement*> part(set.begin() + begin, set.begin() + end);
      std::sort(part.begin(), part.end(), [&](const RollingElement* x, const RollingElement* y) {
        return NameLess(*x->w, *y->w);
      });
      const std::optional<SpaceCircle> pitch = circle_of(part);
      if (pitch && pitch->worst <= L_) add_row(std::move(part), *pitch);
    }
  }
  // Rows between the same two rings are one bearing (in the order of their first row).
  std::vector<bool> done(rows.size(), false);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (done[r]) continue;
    std::vector<BearingRow> bearing;
    for (std::size_t s = r; s < rows.size(); ++s) {
      if (!done[s] && rows[s].inner->ref.part == rows[r].inner->ref.part &&
          rows[s].outer->ref.part == rows[r].outer->ref.part) {
        done[s] = true;
        bearing.push_back(rows[s]);
      }
    }
    AddBearing(bearing);
  }
}

void Recognizer::AddBearing(std::span<const BearingRow> rows) {
  const BearingRow& row = rows.front();
  const WorldFeature* inner = row.inner;
  const WorldFeature* outer = row.outer;
  const SpaceCircle& pitch = row.pitch;
  const RollingElement::Shape shape = row.elements.front()->shape;
  std::set<std::size_t> in_bearing;
  for (const BearingRow& each : rows) {
    for (const RollingElement* e : each.elements) in_bearing.insert(e->w->ref.part);
  }
  // The rings' pairs go; the elements' too: a bearing's parts touch in many places.
  std::erase_if(pairs_, [&](const Pair& p) {
    const std::size_t a = p.a.part, b = p.b.part;
    return in_bearing.count(a) || in_bearing.count(b) ||
           (std::min(a, b) == std::min(inner->ref.part, outer->ref.part) &&
            std::max(a, b) == std::max(inner->ref.part, outer->ref.part));
  });
  // The inner ring's bore: its smallest hole on the axis, inside the raceway. A needle
  // bearing's shaft, which has none, is no ring: it runs on the shaft's own diameter; nor is
  // a shaft with the raceway cut into it, hollow or not. The inner ring of rollers found by
  // their ends was found by its bore.
  double bore = inner->f.kind == FeatureKind::kHole ? inner->f.diameter : 0.0;
  for (std::size_t f = 0; !row.raceway_on_shaft && f < assembly_.FeatureCount(inner->ref.part);
       ++f) {
    const WorldFeature& w = At({inner->ref.part, f});
    if (w.f.kind == FeatureKind::kHole && OnAxisOf(w, pitch, L_, A_) &&
        w.f.diameter < inner->f.diameter && (bore == 0.0 || w.f.diameter < bore)) {
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
        AngleBetweenLines(s.axis.direction, pitch.normal) > A_ ||
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
  std::set<std::size_t> held;  // the elements' parts held with the outer ring
  for (const BearingRow& each : rows) {
    for (const RollingElement* e : each.elements) {
      if (!held.insert(e->w->ref.part).second) continue;  // a ball set's part, held already
      AddPair(PairType::kFixed, *e->w, *outer);
      pairs_.back().source = PairSource::kBearing;
    }
  }
  // Its size as a catalogue gives it: the bore (above), the outer ring's outside diameter
  // and width (between its end faces, which chamfers do not shorten as they do its outside
  // cylinder); a tapered roller bearing's width is both rings' (its catalogue's T; the cup's
  // alone on a shaft that carries the raceway), a thrust bearing's height both washers'.
  double outside = 0.0, width = 0.0;
  for (std::size_t f = 0; f < assembly_.FeatureCount(outer->ref.part); ++f) {
    const WorldFeature& w = At({outer->ref.part, f});
    if (w.f.kind == FeatureKind::kShaft && OnAxisOf(w, pitch, L_, A_) && w.f.diameter > outside) {
      outside = w.f.diameter, width = w.axis.length;
    }
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<std::size_t> rings{outer->ref.part};
  if ((shape == RollingElement::Shape::kTaperedRoller && inner_ring) || row.thrust) {
    rings.push_back(inner->ref.part);
  }
  for (const std::size_t ring : rings) {
    for (std::size_t f = 0; f < assembly_.FeatureCount(ring); ++f) {
      const WorldFeature& w = At({ring, f});
      if (w.f.kind != FeatureKind::kFace ||
          AngleBetweenLines(w.axis.direction, pitch.normal) > A_) {
        continue;
      }
      const double at = (w.axis.origin - pitch.center).dot(pitch.normal);
      lo = std::min(lo, at), hi = std::max(hi, at);
    }
  }
  if (hi > lo) width = hi - lo;
  // Cages, seals and shields: parts in no other role, with a feature, whose every vertex lies
  // between the rings, radially strictly between the features that make the revolute pair
  // (the lands or raceways beside the elements; the inner ring's bore and the outer ring's
  // outside where those were found by them: rollers found by their ends, a self-aligning
  // bearing) and axially within the rings' end faces; a thrust bearing's, axially strictly
  // between its washers' raceway faces and radially between the shaft washer's bore and the
  // housing washer's outside. They orbit with the elements or turn with a ring: held with
  // the outer ring, as the elements are.
  std::vector<std::size_t> cages;
  if (hi > lo) {
    const double r_in = inner->f.diameter / 2;
    const double r_out = row.thrust ? outside / 2 : outer->f.diameter / 2;
    const double h_lo = row.thrust ? -row.washers[0] : lo - L_;
    const double h_hi = row.thrust ? row.washers[1] : hi + L_;
    for (std::size_t part = 0; part < assembly_.parts().size(); ++part) {
      const std::shared_ptr<const TriangleMesh>& mesh = assembly_.part(part).mesh;
      if (part == inner->ref.part || part == outer->ref.part || in_bearing.count(part) ||
          assembly_.FeatureCount(part) == 0 || !mesh || mesh->vertices.empty()) {
        continue;
      }
      const bool between =
          std::all_of(mesh->vertices.begin(), mesh->vertices.end(), [&](const Eigen::Vector3d& v) {
            const Eigen::Vector3d d = X_WP_[part] * v - pitch.center;
            const double h = d.dot(pitch.normal);
            const double r = (d - h * pitch.normal).norm();
            return r > r_in && r < r_out && h > h_lo && h < h_hi;
          });
      if (between) cages.push_back(part);
    }
  }
  std::erase_if(pairs_, [&](const Pair& p) {
    return std::count(cages.begin(), cages.end(), p.a.part) ||
           std::count(cages.begin(), cages.end(), p.b.part);
  });
  std::vector<std::string> cage_ids;
  for (const std::size_t cage : cages) {
    AddPair(PairType::kFixed, At({cage, 0}), *outer);
    pairs_.back().source = PairSource::kBearing;
    cage_ids.emplace_back(assembly_.PartId(cage));
  }
  // A raceway cut into a shaft makes the shaft no part of the bearing.
  std::set<std::size_t> members(held.begin(), held.end());
  members.insert(outer->ref.part);
  if (inner_ring) members.insert(inner->ref.part);
  members.insert(cages.begin(), cages.end());
  bearings_.emplace_back(members.begin(), members.end());
  const std::string size = bore > 0 && outside > 0
                               ? fmt::format(", {} x {} x {} mm", FormatNumber(bore),
                                             FormatNumber(outside), FormatNumber(width))
                               : "";
  std::vector<std::string> parts{std::string(assembly_.PartId(inner->ref.part)),
                                 std::string(assembly_.PartId(outer->ref.part))};
  for (const BearingRow& each : rows) {
    for (const RollingElement* e : each.elements) {
      const std::string id(assembly_.PartId(e->w->ref.part));
      if (std::find(parts.begin(), parts.end(), id) == parts.end()) parts.push_back(id);
    }
  }
  parts.insert(parts.end(), cage_ids.begin(), cage_ids.end());
  // Needles: rollers at least 2.5 diameters long (ISO 3096's are 2.5 to 10). Barrel rollers
  // leaning towards the axis are a spherical roller bearing's.
  const double length = row.elements.front()->length;
  const double d = row.elements.front()->diameter;
  const bool needles = shape == RollingElement::Shape::kRoller && length >= 2.5 * d;
  std::string kind;
  switch (shape) {
    case RollingElement::Shape::kBall:
      kind = row.self_aligning ? "self-aligning ball" : "ball";
      break;
    case RollingElement::Shape::kRoller:
      kind = needles ? "needle roller" : "cylindrical roller";
      break;
    case RollingElement::Shape::kTaperedRoller:
      kind = "tapered roller";
      break;
    case RollingElement::Shape::kBarrelRoller:
      kind = row.tilt > A_ ? "spherical roller" : "barrel roller";
      break;
  }
  if (row.thrust) kind = "thrust " + kind;
  if (rows.size() > 1)
    kind = (rows.size() == 2 ? "double-row " : fmt::format("{}-row ", rows.size())) + kind;
  const std::string named = shape == RollingElement::Shape::kBall ? "balls"
                            : needles                             ? "needles"
                                                                  : "rollers";
  // Each row: its elements and pitch circle; rows alike are counted.
  std::vector<std::string> described;
  for (const BearingRow& each : rows) {
    const double tilt = each.tilt;
    const double across = ByTheirEnds(shape) ? std::round(10 * d) / 10 : d;
    const double shown_length = ByTheirEnds(shape) ? std::round(10 * length) / 10 : length;
    const std::string leaning =
        tilt > A_ && !each.thrust ? fmt::format(" at {} to its axis", Deg(tilt)) : "";
    const std::string ends =
        shape == RollingElement::Shape::kBarrelRoller ? " (at their ends)" : "";
    const std::string what =
        shape == RollingElement::Shape::kBall
            ? Mm(d)
            : fmt::format("{} x {}{}{}", FormatNumber(across), Mm(shown_length), ends, leaning);
    const double circle =
        ByTheirEnds(shape) ? std::round(200 * each.pitch.radius) / 100 : 2 * each.pitch.radius;
    described.push_back(fmt::format("{} {} of {} on a {} pitch circle", each.elements.size(), named,
                                    what, Mm(circle)));
  }
  const bool alike = std::all_of(described.begin(), described.end(),
                                 [&](const std::string& x) { return x == described.front(); });
  const std::string elements_text =
      rows.size() > 1 && alike ? fmt::format("{} rows of {}", rows.size(), described.front())
                               : fmt::format("{}", fmt::join(described, " and "));
  diagnostics_.push_back(
      {Severity::kInfo,
       "bearing",
       fmt::format(
           "a {} bearing{}: {} turns {} {} on {} (a revolute pair; the {} are held with "
           "the {}, their spin and orbit not modelled){}{}",
           kind, size, assembly_.PartId(inner->ref.part), row.thrust ? "against" : "in",
           assembly_.PartId(outer->ref.part), elements_text, named,
           row.thrust ? "housing washer" : "outer ring",
           cage_ids.empty()
               ? ""
               : fmt::format("; {} (between the rings: a cage, seal or shield) {} held "
                             "with the {} too",
                             fmt::join(cage_ids, " and "), cage_ids.size() == 1 ? "is" : "are",
                             row.thrust ? "housing washer" : "outer ring"),
           seats.empty()
               ? ""
               : fmt::format("; its rings are fitted (fixed) to {}", fmt::join(seats, " and "))),
       parts,
       {Name(*inner), Name(*outer)}});
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
  // Per hub's body: the bodies its pairs other than face contacts and teeth in mesh (which
  // couple turns and hold nothing) join it to. Per body: its bearings.
  std::map<int, std::set<int>> joined;
  for (const Pair* p : hubs) joined[body(p->b)];
  std::map<int, std::vector<const Pair*>> bearings;
  for (const Pair& p : pairs_) {
    const int a = body(p.a), b = body(p.b);
    const bool teeth = p.type == PairType::kGear || p.type == PairType::kBevelGear ||
                       p.type == PairType::kWormGear || p.type == PairType::kRackPinion;
    if (a == b || p.type == PairType::kPlanar || teeth) continue;
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
