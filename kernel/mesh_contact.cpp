#include "kernel/mesh_contact.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "kernel/exact_predicates.h"

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

// Deepest of `samples_S` (points of the surface of S, frame S) inside `other` (frame O).
void DeepestInside(const std::vector<Eigen::Vector3d>& samples_S, const RigidTransform& X_OS,
                   const RigidTransform& X_WS, const CollisionMesh& other, Deepest* deepest) {
  for (const Eigen::Vector3d& p_S : samples_S) {
    const Eigen::Vector3d p_O = X_OS * p_S;
    if (!other.Contains(p_O)) continue;
    const double d = other.ClosestPoint(p_O).distance;
    if (!deepest->found || d > deepest->depth) {
      deepest->depth = d;
      deepest->p_W = X_WS * p_S;
      deepest->found = true;
    }
  }
}

}  // namespace

std::vector<Eigen::Vector3d> ExpressVertices(const TriangleMesh& mesh,
                                             const RigidTransform& X_AM) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& p_M : mesh.vertices) out.push_back(X_AM * p_M);
  return out;
}

std::vector<std::pair<std::int32_t, std::int32_t>> IntersectingTriangles(
    const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
    const RigidTransform& X_WB, std::size_t max_pairs) {
  std::vector<std::pair<std::int32_t, std::int32_t>> result;
  if (a.mesh().faces.empty() || b.mesh().faces.empty() || max_pairs == 0) return result;
  const RigidTransform X_AB = X_WA.inverse() * X_WB;
  const double margin = PruneMargin(a, b, X_AB);
  if (!BoxesOverlap(a.bounds(), b.bounds(), X_AB, margin)) return result;
  const std::vector<Eigen::Vector3d> vb_A = ExpressVertices(b.mesh(), X_AB);
  const auto& fa = a.mesh().faces;
  const auto& fb = b.mesh().faces;
  const auto& va = a.mesh().vertices;

  std::vector<std::pair<std::int32_t, std::int32_t>> stack = {{0, 0}};
  while (!stack.empty()) {
    const auto [ia, ib] = stack.back();
    stack.pop_back();
    const auto& na = a.nodes()[ia];
    const auto& nb = b.nodes()[ib];
    if (!BoxesOverlap(na.box_M, nb.box_M, X_AB, margin)) continue;
    if (!na.leaf() || !nb.leaf()) {
      // Descend into the larger box (or the only inner node).
      const bool split_a = !na.leaf() && (nb.leaf() || na.box_M.size().squaredNorm() >=
                                                           nb.box_M.size().squaredNorm());
      if (split_a) {
        stack.push_back({na.right, ib});
        stack.push_back({na.left, ib});
      } else {
        stack.push_back({ia, nb.right});
        stack.push_back({ia, nb.left});
      }
      continue;
    }
    for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
      const std::int32_t f = a.order()[i];
      const Eigen::Vector3d &a0 = va[fa[f][0]], &a1 = va[fa[f][1]], &a2 = va[fa[f][2]];
      const Aabb box_a = TriangleBox(a0, a1, a2);
      for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
        const std::int32_t g = b.order()[j];
        const Eigen::Vector3d &b0 = vb_A[fb[g][0]], &b1 = vb_A[fb[g][1]], &b2 = vb_A[fb[g][2]];
        if (!box_a.Intersects(TriangleBox(b0, b1, b2))) continue;
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
  if (pairs.empty()) {
    // No surfaces cross: either apart or one inside the other; one vertex decides.
    const auto& va = a.mesh().vertices;
    const auto& vb = b.mesh().vertices;
    if (b.closed() && !va.empty() && b.Contains(X_BA * va.front())) {
      result.contained = 1;
      DeepestInside(va, X_BA, X_WA, b, &deepest);
    } else if (a.closed() && !vb.empty() && a.Contains(X_AB * vb.front())) {
      result.contained = 2;
      DeepestInside(vb, X_AB, X_WB, a, &deepest);
    } else {
      return result;
    }
  } else {
    const auto [fa, fb] = pairs.front();
    const auto [p, q, r] = a.Triangle(fa);
    result.p_W = X_WA * ((p + q + r) / 3.0);
    if (!a.closed() || !b.closed()) {
      result.kind = ContactMeasure::Kind::kPenetrating;
      result.depth = std::numeric_limits<double>::infinity();
      return result;
    }
    const double spacing = std::max(tolerance, 1e-6);
    std::set<std::int32_t> faces_a, faces_b;
    for (const auto& [f, g] : pairs) {
      faces_a.insert(f);
      faces_b.insert(g);
    }
    std::vector<Eigen::Vector3d> samples;
    for (const std::int32_t f : faces_a) FaceSamples(a, f, spacing, &samples, &result.depth_bound);
    DeepestInside(samples, X_BA, X_WA, b, &deepest);
    samples.clear();
    for (const std::int32_t g : faces_b) FaceSamples(b, g, spacing, &samples, &result.depth_bound);
    DeepestInside(samples, X_AB, X_WB, a, &deepest);
    // Vertices away from the crossing can lie deeper still (a pin pushed far into a block).
    const Aabb box_b_in_a = TransformBox(X_AB, b.bounds());
    const Aabb box_a_in_b = TransformBox(X_BA, a.bounds());
    samples.clear();
    for (const auto& v : a.mesh().vertices) {
      if (box_b_in_a.Intersects(Aabb{v, v})) samples.push_back(v);
    }
    DeepestInside(samples, X_BA, X_WA, b, &deepest);
    samples.clear();
    for (const auto& v : b.mesh().vertices) {
      if (box_a_in_b.Intersects(Aabb{v, v})) samples.push_back(v);
    }
    DeepestInside(samples, X_AB, X_WB, a, &deepest);
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
