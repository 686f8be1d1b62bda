#include "kernel/collision/mesh_contact.h"

#include <algorithm>
#include <cmath>

#include "kernel/geometry/exact_predicates.h"

namespace mechanist {
namespace {

// Margin that covers the rounding of boxes transformed in double precision, mm.
double PruneMargin(const CollisionMesh& a, const CollisionMesh& b, const RigidTransform& X_AB) {
  const double scale = a.bounds().size().norm() + b.bounds().size().norm() +
                       X_AB.translation().norm() + a.bounds().max.cwiseAbs().maxCoeff() +
                       b.bounds().max.cwiseAbs().maxCoeff();
  return 1e-12 * (1.0 + scale);
}

Aabb TriangleBox(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
  Aabb box;
  box.Extend(p);
  box.Extend(q);
  box.Extend(r);
  return box;
}

// Surface samples of face `f` of `mesh` (frame M): its corners and a barycentric grid.
void FaceSamples(const CollisionMesh& mesh, std::int32_t f, double spacing,
                 std::vector<Eigen::Vector3d>* out, double* bound) {
  const auto [a, b, c] = mesh.Triangle(f);
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const int k = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 8);
  *bound = std::max(*bound, longest / k);
  for (int i = 0; i <= k; ++i) {
    for (int j = 0; i + j <= k; ++j) {
      const double u = static_cast<double>(i) / k, v = static_cast<double>(j) / k;
      out->push_back(a + u * (b - a) + v * (c - a));
    }
  }
}

struct Deepest {
  double depth = 0.0;
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  bool found = false;
};

// Deepest of `samples_S` (points of the surface of S, frame S) inside `other` (frame O); all
// of them are known to be inside when `inside`.
void DeepestInside(const std::vector<Eigen::Vector3d>& samples_S, const RigidTransform& X_OS,
                   const RigidTransform& X_WS, const CollisionMesh& other, Deepest* deepest,
                   bool inside) {
  for (const Eigen::Vector3d& p_S : samples_S) {
    const Eigen::Vector3d p_O = X_OS * p_S;
    // The distance first: a point no deeper than the deepest yet needs no inside test (on an
    // open solid's surface that test is the slowest, its winding number there a half).
    const double d = other.ClosestPoint(p_O).distance;
    if (deepest->found && d <= deepest->depth) continue;
    if (!inside && !other.Contains(p_O)) continue;
    if (!deepest->found || d > deepest->depth) {
      deepest->depth = d;
      deepest->p_W = X_WS * p_S;
      deepest->found = true;
    }
  }
}

}  // namespace

std::vector<Eigen::Vector3d> ExpressVertices(const TriangleMesh& mesh, const RigidTransform& X_AM) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p_M : mesh.vertices) out.push_back(X_AM * p_M);
  return out;
}

std::vector<std::pair<std::int32_t, std::int32_t>> IntersectingTriangles(const CollisionMesh& a,
                                                                         const RigidTransform& X_WA,
                                                                         const CollisionMesh& b,
                                                                         const RigidTransform& X_WB,
                                                                         std::size_t max_pairs) {
  std::vector<std::pair<std::int32_t, std::int32_t>> result;
  if (a.mesh().faces.empty() || b.mesh().faces.empty() || max_pairs == 0) return result;
  const RigidTransform X_AB = X_WA.inverse() * X_WB;
  const double margin = PruneMargin(a, b, X_AB);
  const Eigen::Matrix3d& R = X_AB.rotation();
  // A small epsilon keeps near-parallel edge axes from producing false separations.
  const Eigen::Matrix3d absR = R.cwiseAbs().array() + 1e-12;
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(margin);
  // B's node centres in A's frame, computed when first needed.
  std::vector<Eigen::Vector3d> center_b(b.nodes().size());
  std::vector<char> center_b_done(b.nodes().size(), 0);
  auto overlap = [&](std::int32_t ia, std::int32_t ib) {
    if (!center_b_done[ib]) {
      center_b[ib] = X_AB * b.nodes()[ib].center_M;
      center_b_done[ib] = 1;
    }
    const CollisionMesh::Node& na = a.nodes()[ia];
    return OrientedBoxesOverlap(center_b[ib] - na.center_M, na.half_M + grow,
                                b.nodes()[ib].half_M + grow, R, absR);
  };
  if (!overlap(0, 0)) return result;

  // B's vertices and face boxes in A's frame, computed when a leaf first needs them.
  const auto& vb_M = b.mesh().vertices;
  std::vector<Eigen::Vector3d> vb(vb_M.size());
  std::vector<char> vb_done(vb_M.size(), 0);
  std::vector<Aabb> box_b(b.mesh().faces.size());
  std::vector<char> box_b_done(b.mesh().faces.size(), 0);
  const auto& fa = a.mesh().faces;
  const auto& fb = b.mesh().faces;
  const auto& va = a.mesh().vertices;
  auto vertex_b = [&](std::int32_t v) -> const Eigen::Vector3d& {
    if (!vb_done[v]) {
      vb[v] = X_AB * vb_M[v];
      vb_done[v] = 1;
    }
    return vb[v];
  };
  auto face_box_b = [&](std::int32_t g) -> const Aabb& {
    if (!box_b_done[g]) {
      box_b[g] = TriangleBox(vertex_b(fb[g][0]), vertex_b(fb[g][1]), vertex_b(fb[g][2]));
      box_b_done[g] = 1;
    }
    return box_b[g];
  };

  std::vector<std::int32_t> near_b;
  std::vector<std::pair<std::int32_t, std::int32_t>> stack = {{0, 0}};
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const auto& na = a.nodes()[ia];
    const auto& nb = b.nodes()[ib];
    if ((ia != 0 || ib != 0) && !overlap(ia, ib)) continue;
    if (!na.leaf() || !nb.leaf()) {
      // Descend into the larger box (or the only inner node).
      const bool split_a =
          !na.leaf() && (nb.leaf() || na.half_M.squaredNorm() >= nb.half_M.squaredNorm());
      if (split_a) {
        stack.push_back({na.right, ib});
        stack.push_back({na.left, ib});
      } else {
        stack.push_back({ia, nb.right});
        stack.push_back({ia, nb.left});
      }
      continue;
    }
    // B's triangles that reach A's leaf box, and the box around them: most triangle pairs of
    // two overlapping leaves end at one of these two tests.
    near_b.clear();
    Aabb near_box;
    for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
      const std::int32_t g = b.order()[j];
      if (!face_box_b(g).Intersects(na.box_M)) continue;
      near_b.push_back(g);
      near_box.Extend(box_b[g]);
    }
    if (near_b.empty()) continue;
    for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
      const std::int32_t f = a.order()[i];
      const Aabb& box_a = a.face_boxes()[f];
      if (!box_a.Intersects(near_box)) continue;
      for (const std::int32_t g : near_b) {
        if (!box_a.Intersects(box_b[g])) continue;
        const Eigen::Vector3d &a0 = va[fa[f][0]], &a1 = va[fa[f][1]], &a2 = va[fa[f][2]];
        const Eigen::Vector3d &b0 = vb[fb[g][0]], &b1 = vb[fb[g][1]], &b2 = vb[fb[g][2]];
        if (TrianglesSurelyApart(a0, a1, a2, b0, b1, b2)) continue;
        if (TrianglesIntersect(a0, a1, a2, b0, b1, b2)) {
          result.push_back({f, g});
          if (result.size() >= max_pairs) return result;
        }
      }
    }
  }
  return result;
}

bool SurfacesIntersect(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                       const RigidTransform& X_WB) {
  return !IntersectingTriangles(a, X_WA, b, X_WB, 1).empty();
}

ContactMeasure MeasureContact(const CollisionMesh& a, const RigidTransform& X_WA,
                              const CollisionMesh& b, const RigidTransform& X_WB,
                              double tolerance) {
  ContactMeasure result;
  const auto pairs = IntersectingTriangles(a, X_WA, b, X_WB);
  result.crossing_pairs = pairs.size();
  const RigidTransform X_AB = X_WA.inverse() * X_WB;
  const RigidTransform X_BA = X_AB.inverse();
  Deepest deepest;
  const double spacing = std::max(tolerance, 1e-6);
  const double rounding = 1e3 * PruneMargin(a, b, X_AB);
  // The faces of `mesh` (frame S) whose boxes meet `box_S` (the other solid's box in S) are
  // every face that can lie inside `other`; each is sampled. A face that does not cross the
  // other surface (`crossing` false) is wholly inside or outside: its centroid decides.
  auto measure = [&](const CollisionMesh& mesh, const RigidTransform& X_OS,
                     const RigidTransform& X_WS, const CollisionMesh& other, const Aabb& box_S,
                     const std::vector<char>& crossing) {
    std::vector<Eigen::Vector3d> samples;
    for (std::int32_t f = 0; f < static_cast<std::int32_t>(mesh.mesh().faces.size()); ++f) {
      if (!mesh.face_boxes()[f].Intersects(box_S)) continue;
      if (!crossing[f]) {
        // Clearly inside, not on the other surface within rounding: B's coordinates differ in
        // the two frames, so a face lying on the other's surface may test either way.
        const auto [p, q, r] = mesh.Triangle(f);
        const Eigen::Vector3d centroid_O = X_OS * ((p + q + r) / 3.0);
        if (other.ClosestPoint(centroid_O).distance <= rounding || !other.Contains(centroid_O)) {
          continue;
        }
      }
      samples.clear();
      FaceSamples(mesh, f, spacing, &samples, &result.depth_bound);
      DeepestInside(samples, X_OS, X_WS, other, &deepest, !crossing[f]);
    }
  };
  std::vector<char> crossing_a(a.mesh().faces.size(), 0), crossing_b(b.mesh().faces.size(), 0);
  for (const auto& [f, g] : pairs) {
    crossing_a[f] = 1;
    crossing_b[g] = 1;
  }
  const Aabb box_b_in_a = TransformBox(X_AB, b.bounds());
  const Aabb box_a_in_b = TransformBox(X_BA, a.bounds());
  if (pairs.empty()) {
    // No surfaces cross: either apart or one inside the other; one vertex of a face decides.
    const auto& va = a.mesh().vertices;
    const auto& vb = b.mesh().vertices;
    const auto& fa = a.mesh().faces;
    const auto& fb = b.mesh().faces;
    if (b.solid() && !fa.empty() && b.Contains(X_BA * va[fa.front()[0]])) {
      result.contained = 1;
      measure(a, X_BA, X_WA, b, box_b_in_a, crossing_a);
    } else if (a.solid() && !fb.empty() && a.Contains(X_AB * vb[fb.front()[0]])) {
      result.contained = 2;
      measure(b, X_AB, X_WB, a, box_a_in_b, crossing_b);
    } else {
      return result;
    }
  } else {
    const auto [fa, fb] = pairs.front();
    const auto [p, q, r] = a.Triangle(fa);
    result.p_W = X_WA * ((p + q + r) / 3.0);
    if (!a.solid() || !b.solid()) {
      result.open = {!a.solid(), !b.solid()};
      result.kind = ContactMeasure::Kind::kPenetrating;
      result.depth = std::numeric_limits<double>::infinity();
      return result;
    }
    // Every face of either mesh that can be inside the other, sampled: the crossing faces
    // and those wholly inside (a pin pushed far into a block).
    measure(a, X_BA, X_WA, b, box_b_in_a, crossing_a);
    measure(b, X_AB, X_WB, a, box_a_in_b, crossing_b);
  }
  if (deepest.found) {
    result.depth = deepest.depth;
    result.p_W = deepest.p_W;
  }
  result.kind = result.depth > tolerance ? ContactMeasure::Kind::kPenetrating
                                         : ContactMeasure::Kind::kTouching;
  return result;
}

}  // namespace mechanist
