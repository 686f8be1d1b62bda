#include "kernel/collision/translational_sweep.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "kernel/collision/mesh_contact.h"
#include "kernel/geometry/exact_predicates.h"

namespace mechanist {
namespace {

// Whether testing along `axis` adds enough to the boxes' own test (along the frame's axes) to
// be worth its cost: an axis leaning off each of the frame's axes, two of its components at
// least a tenth of the largest. (A zero axis separates nothing.)
bool LeansOffTheFrame(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d m = axis.cwiseAbs();
  return (m.array() >= 0.1 * m.maxCoeff()).count() >= 2 && m.maxCoeff() > 0.0;
}

// The axes perpendicular to a direction of travel d, d x e_k for the frame's axes e_k, that
// lean off the frame (LeansOffTheFrame): separating axes of every band swept along d
// (SweptSegment).
struct AcrossTravel {
  explicit AcrossTravel(const Eigen::Vector3d& d) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d axis = d.cross(Eigen::Vector3d::Unit(k));
      if (LeansOffTheFrame(axis)) axes.push_back(axis);
    }
  }
  std::vector<Eigen::Vector3d> axes;
};

// The parallelogram that the segment from `a` to a + edge sweeps over travelling `length`
// along the unit d (a point's path when edge is zero), grown by `margin` on every side, for
// pruning a hierarchy of boxes: the box of a long oblique band holds much of an obstacle that
// the band itself passes by. Meets is the separating-axis test of a box and a convex polygon
// over the box's axes, the polygon's normal and the cross products of its two sides with the
// box's axes (Eberly, "Intersection of convex objects: the method of separating axes"), the
// last two kinds where they lean off the frame. The axes across d (`across`) serve every band
// of one sweep; a point's path needs no others.
class SweptSegment {
 public:
  SweptSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& edge, const Eigen::Vector3d& d,
               double length, const AcrossTravel& across, double margin)
      : a_(a), edge_(edge), sweep_(length * d), margin_(margin) {
    const Eigen::Vector3d low = edge_.cwiseMin(0.0) + sweep_.cwiseMin(0.0);
    const Eigen::Vector3d high = edge_.cwiseMax(0.0) + sweep_.cwiseMax(0.0);
    centre_ = a + 0.5 * (low + high);
    half_ = 0.5 * (high - low) + Eigen::Vector3d::Constant(margin);
    for (const Eigen::Vector3d& axis : across.axes) Add(axis);
    if (edge.isZero()) return;
    for (const Eigen::Vector3d& axis :
         {Eigen::Vector3d(edge.cross(d)), Eigen::Vector3d(edge.cross(Eigen::Vector3d::UnitX())),
          Eigen::Vector3d(edge.cross(Eigen::Vector3d::UnitY())),
          Eigen::Vector3d(edge.cross(Eigen::Vector3d::UnitZ()))}) {
      if (LeansOffTheFrame(axis)) Add(axis);
    }
  }

  // Whether the polygon meets the box of `centre` and `half` extents; only a pruning test (the
  // exact tests decide contacts), erring towards true.
  bool Meets(const Eigen::Vector3d& centre, const Eigen::Vector3d& half) const {
    if (((centre - centre_).cwiseAbs().array() > (half + half_).array()).any()) return false;
    const Eigen::Vector3d c = centre - a_;
    for (int k = 0; k < count_; ++k) {
      const Axis& axis = axes_[k];
      const double mid = axis.direction.dot(c), radius = axis.magnitudes.dot(half);
      if (mid - radius > axis.hi || mid + radius < axis.lo) return false;
    }
    return true;
  }

 private:
  struct Axis {
    Eigen::Vector3d direction, magnitudes;  // the axis, and its components' magnitudes
    double lo = 0.0, hi = 0.0;              // the grown polygon's extent along it, from a
  };

  // An axis to test, with the polygon's extent along it: its corners project to 0, its
  // sides' projections and their sum. Both sides are projected on every axis, even where one
  // is perpendicular to it in exact arithmetic: the normal of an edge that runs along d within
  // rounding is rounding noise, along which the edge may reach far.
  void Add(const Eigen::Vector3d& direction) {
    const Eigen::Vector3d magnitudes = direction.cwiseAbs();
    const double e = direction.dot(edge_), s = direction.dot(sweep_);
    const double grown = margin_ * magnitudes.sum();
    axes_[count_++] = {direction, magnitudes, std::min(0.0, e) + std::min(0.0, s) - grown,
                       std::max(0.0, e) + std::max(0.0, s) + grown};
  }

  Eigen::Vector3d a_, edge_, sweep_;
  Eigen::Vector3d centre_, half_;  // the grown polygon's box
  double margin_;
  // At most three axes across d and the edge's four (its normal and three cross products).
  std::array<Axis, 7> axes_;
  int count_ = 0;
};

// Calls visit(face) for every face of `mesh` in a leaf of its hierarchy whose box meets
// `region` (SweptSegment::Meets, in the mesh's own frame).
template <typename Visit>
void ForEachFaceNear(const CollisionMesh& mesh, const SweptSegment& region, Visit&& visit) {
  std::vector<std::int32_t> stack = {0};
  while (!stack.empty()) {
    const auto& node = mesh.nodes()[stack.back()];
    stack.pop_back();
    if (!region.Meets(node.center_M, node.half_M)) continue;
    if (!node.leaf()) {
      stack.push_back(node.right);
      stack.push_back(node.left);
      continue;
    }
    for (std::int32_t i = node.first; i < node.first + node.count; ++i) visit(mesh.order()[i]);
  }
}

// Sum of the unit normals of the faces beside `edge`, in the mesh's frame.
Eigen::Vector3d EdgeNormalSum(const CollisionMesh& mesh, std::int32_t edge) {
  const auto& e = mesh.edges()[edge];
  Eigen::Vector3d sum = mesh.face_normals()[e.faces[0]];
  if (e.faces[1] >= 0) sum += mesh.face_normals()[e.faces[1]];
  return sum;
}

// True when a point travelling through the boundary of `face` (the edges whose orientation
// with the travel segment [p, q] is zero; `corners`, p and q in one frame, the one in which the
// exact contact test ran) enters the solid there: across a convex edge it must also approach
// the neighbouring face, against that face's normal, by more than `min_approach`; `d_mesh` is
// the point's direction of travel in the mesh's own frame. Contacts that only graze a convex
// edge slide along the neighbour and do not block.
bool EntersAcrossBoundary(const CollisionMesh& mesh, std::int32_t face,
                          const std::array<Eigen::Vector3d, 3>& corners, const Eigen::Vector3d& p,
                          const Eigen::Vector3d& q, const Eigen::Vector3d& d_mesh,
                          double min_approach) {
  for (int k = 0; k < 3; ++k) {
    if (Orient3d(p, q, corners[k], corners[(k + 1) % 3]) != 0) continue;
    const std::int32_t e = mesh.face_edges()[face][k];
    if (e < 0) continue;
    const auto& edge = mesh.edges()[e];
    const std::int32_t other = edge.faces[0] == face ? edge.faces[1] : edge.faces[0];
    if (other < 0 || mesh.EdgeConvexity(e) != 1) continue;
    if (-mesh.face_normals()[other].dot(d_mesh) <= min_approach) return false;
  }
  return true;
}

struct Best {
  std::optional<SweepContact> contact;
  void Offer(SweepContact::Kind kind, double travel, const Eigen::Vector3d& p_W, double approach) {
    if (contact && travel >= contact->travel) return;
    contact = SweepContact{kind, travel, p_W, approach};
  }
  double limit(double max_travel) const { return contact ? contact->travel : max_travel; }
};

}  // namespace

std::optional<SweepContact> FirstBlockingContact(
    const CollisionMesh& moving, const RigidTransform& X_WM, const CollisionMesh& obstacle,
    const RigidTransform& X_WO, const Eigen::Vector3d& d_W, const SweepOptions& options) {
  if (!(options.max_travel >= 0.0) || !std::isfinite(options.max_travel)) {
    throw std::invalid_argument("FirstBlockingContact: max_travel must be finite and >= 0");
  }
  if (!(options.min_approach >= 0.0)) {
    throw std::invalid_argument("FirstBlockingContact: min_approach must be >= 0");
  }
  if (std::abs(d_W.norm() - 1.0) > 1e-9) {
    throw std::invalid_argument("FirstBlockingContact: direction must be a unit vector");
  }
  Best best;
  const auto& mesh_m = moving.mesh();
  const auto& mesh_o = obstacle.mesh();
  if (mesh_m.faces.empty() || mesh_o.faces.empty()) return best.contact;

  const RigidTransform X_OW = X_WO.inverse();
  const RigidTransform X_OM = X_OW * X_WM;
  const RigidTransform X_MO = X_OM.inverse();
  const Eigen::Vector3d d = X_OW.RotateDirection(d_W);
  const Eigen::Vector3d d_M = X_MO.RotateDirection(d);
  const AcrossTravel across_o(d), across_m(d_M);  // in the obstacle's and the moving mesh's frames
  const double L = options.max_travel;
  const Eigen::Vector3d sweep = L * d;
  const std::vector<Eigen::Vector3d> vm = ExpressVertices(mesh_m, X_OM);
  const auto& vo = mesh_o.vertices;
  const double margin = 1e-9 * (1.0 + L + obstacle.bounds().size().norm() +
                                moving.bounds().size().norm() + X_OM.translation().norm());
  // Orientation tells entering from leaving only for solids (CollisionMesh::oriented: closed
  // meshes, and closed surfaces that meet themselves along an edge); any other mesh (a
  // surface, a soup, a cracked tessellation) is two-sided and every contact with it counts.
  const bool solids = moving.oriented() && obstacle.oriented();
  auto ignored = [&](const Eigen::Vector3d& p_O) {
    return options.ignore && options.ignore(X_WO * p_O);
  };

  // The moving mesh's swept box in O; nothing outside it can be reached.
  Aabb swept_O = TransformBox(X_OM, moving.bounds());
  Aabb shifted = swept_O;
  shifted.min += sweep;
  shifted.max += sweep;
  swept_O.Extend(shifted);
  {
    Aabb grown = obstacle.bounds();
    grown.min.array() -= margin;
    grown.max.array() += margin;
    if (!swept_O.Intersects(grown)) return best.contact;
  }

  // Vertices of the moving mesh reaching faces of the obstacle.
  // Surface points that lead a contact: the vertices, and the centroid of every face, which
  // is what meets the other solid first when faces meet face to face with their corners on
  // each other's corners (the common CAD mate), where every vertex only grazes an edge.
  std::vector<Eigen::Vector3d> leading_m = vm;
  for (const auto& f : mesh_m.faces) leading_m.push_back((vm[f[0]] + vm[f[1]] + vm[f[2]]) / 3.0);
  std::vector<Eigen::Vector3d> leading_o = vo;
  for (const auto& f : mesh_o.faces) leading_o.push_back((vo[f[0]] + vo[f[1]] + vo[f[2]]) / 3.0);
  // The points furthest ahead (moving) and nearest (obstacle) first: an early contact shrinks
  // every later query to the travel before it.
  std::sort(
      leading_m.begin(), leading_m.end(),
      [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return x.dot(d) > y.dot(d); });
  std::sort(
      leading_o.begin(), leading_o.end(),
      [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) { return x.dot(d) < y.dot(d); });

  for (const Eigen::Vector3d& v : leading_m) {
    // Only travels below the best contact so far matter.
    const double limit = best.limit(L);
    const Eigen::Vector3d end = v + limit * d;
    const SweptSegment path(v, Eigen::Vector3d::Zero(), d, limit, across_o, margin);
    ForEachFaceNear(obstacle, path, [&](std::int32_t f) {
      const Eigen::Vector3d& n = obstacle.face_normals()[f];
      const double approach = obstacle.oriented() ? -n.dot(d) : std::abs(n.dot(d));
      if (approach <= options.min_approach) return;
      const auto corners = obstacle.Triangle(f);
      const auto& [a, b, c] = corners;
      if (!SegmentIntersectsTriangle(v, end, a, b, c)) return;
      if (obstacle.oriented() &&
          !EntersAcrossBoundary(obstacle, f, corners, v, end, d, options.min_approach)) {
        return;
      }
      const double s = std::clamp(n.dot(a - v) / n.dot(d), 0.0, L);
      if (s >= best.limit(L) && best.contact) return;
      const Eigen::Vector3d p = v + s * d;
      if (ignored(p)) return;
      best.Offer(SweepContact::Kind::kVertexFace, s, X_WO * p, approach);
    });
  }

  // Vertices of the obstacle reached by faces of the moving mesh.
  Aabb swept_grown = swept_O;
  swept_grown.min.array() -= margin;
  swept_grown.max.array() += margin;
  for (const Eigen::Vector3d& w : leading_o) {
    if (!swept_grown.Intersects(Aabb{w, w})) continue;
    const Eigen::Vector3d w_M = X_MO * w;
    const SweptSegment path(w_M, Eigen::Vector3d::Zero(), -d_M, best.limit(L), across_m, margin);
    ForEachFaceNear(moving, path, [&](std::int32_t g) {
      const Eigen::Vector3d n = X_OM.RotateDirection(moving.face_normals()[g]);
      const double approach = moving.oriented() ? n.dot(d) : std::abs(n.dot(d));
      if (approach <= options.min_approach) return;
      const auto& face = mesh_m.faces[g];
      const Eigen::Vector3d &a = vm[face[0]], &b = vm[face[1]], &c = vm[face[2]];
      if (!SegmentIntersectsTriangle(w, w - sweep, a, b, c)) return;
      // Relative to the moving mesh the obstacle's vertex travels along -d.
      if (moving.oriented() &&
          !EntersAcrossBoundary(moving, g, {a, b, c}, w, w - sweep, -d_M, options.min_approach)) {
        return;
      }
      const double s = std::clamp(n.dot(w - a) / n.dot(d), 0.0, L);
      if (s >= best.limit(L) && best.contact) return;
      if (ignored(w)) return;
      best.Offer(SweepContact::Kind::kFaceVertex, s, X_WO * w, approach);
    });
  }

  // Convex edges of the moving mesh crossing convex edges of the obstacle (any edges when a
  // mesh is two-sided).
  std::vector<int> convex_o(obstacle.edges().size(), 2);  // 2: not computed yet
  for (std::size_t e = 0; e < moving.edges().size(); ++e) {
    const auto ei = static_cast<std::int32_t>(e);
    if (solids && moving.EdgeConvexity(ei) != 1) continue;
    const auto& edge = moving.edges()[e];
    const Eigen::Vector3d &a = vm[edge.vertices[0]], &b = vm[edge.vertices[1]];
    const Eigen::Vector3d moving_normals = X_OM.RotateDirection(EdgeNormalSum(moving, ei));
    const SweptSegment band(a, b - a, d, best.limit(L), across_o, margin);
    ForEachFaceNear(obstacle, band, [&](std::int32_t f) {
      for (const std::int32_t g : obstacle.face_edges()[f]) {
        if (g < 0) continue;
        // Each edge is visited from its first face only.
        if (obstacle.edges()[g].faces[0] != f) continue;
        if (convex_o[g] == 2) convex_o[g] = obstacle.EdgeConvexity(g);
        if (solids && convex_o[g] != 1) continue;
        const auto& other = obstacle.edges()[g];
        const Eigen::Vector3d &c = vo[other.vertices[0]], &e2 = vo[other.vertices[1]];
        Eigen::Vector3d m = (b - a).cross(e2 - c);
        const double m_norm = m.norm();
        if (m_norm <= 1e-12 * (b - a).norm() * (e2 - c).norm()) continue;  // parallel edges
        m /= m_norm;
        if (solids) {
          // Orient the common normal out of the obstacle, across its edge.
          if (m.dot(EdgeNormalSum(obstacle, g)) < 0.0) m = -m;
          if (m.dot(moving_normals) >= 0.0) continue;  // the solids would not meet here first
        } else if (m.dot(d) > 0.0) {
          m = -m;
        }
        const double approach = -m.dot(d);
        if (approach <= options.min_approach) continue;
        if (!SegmentIntersectsTriangle(c, e2, a, b, b + sweep) &&
            !SegmentIntersectsTriangle(c, e2, a, b + sweep, a + sweep)) {
          continue;
        }
        // A crossing at an end of either edge is a vertex touching an edge: the vertex-face
        // tests decide those (entering, or grazing along the neighbouring face).
        if (Orient3d(c, e2, a, a + sweep) == 0 || Orient3d(c, e2, b, b + sweep) == 0 ||
            Orient3d(a, b, a + sweep, c) == 0 || Orient3d(a, b, a + sweep, e2) == 0) {
          continue;
        }
        const double s = std::clamp(m.dot(c - a) / m.dot(d), 0.0, L);
        if (s >= best.limit(L) && best.contact) continue;
        // The crossing point on the obstacle's edge: where the moved edge's plane with m cuts it.
        const Eigen::Vector3d a_s = a + s * d;
        const Eigen::Vector3d plane_n = (b - a).cross(m);
        const double denom = plane_n.dot(e2 - c);
        const double u = denom != 0.0 ? std::clamp(plane_n.dot(a_s - c) / denom, 0.0, 1.0) : 0.5;
        const Eigen::Vector3d p = c + u * (e2 - c);
        if (ignored(p)) continue;
        best.Offer(SweepContact::Kind::kEdgeEdge, s, X_WO * p, approach);
      }
    });
  }
  return best.contact;
}

}  // namespace mechanist
