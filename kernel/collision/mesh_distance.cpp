#include "kernel/collision/mesh_distance.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernel/geometry/exact_predicates.h"
#include "kernel/geometry/triangle_geometry.h"

namespace mechanist {
namespace {

// Squared distance between segments [p1, q1] and [p2, q2] (Ericson 5.1.9); `mid` receives the
// midpoint of the closest points.
double SegmentSegmentSquared(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                             const Eigen::Vector3d& p2, const Eigen::Vector3d& q2,
                             Eigen::Vector3d* mid) {
  const Eigen::Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 1e-300 && e <= 1e-300) {
    *mid = 0.5 * (p1 + p2);
    return r.squaredNorm();
  }
  if (a <= 1e-300) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 1e-300) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  *mid = 0.5 * ((p1 + d1 * s) + (p2 + d2 * t));
  return ((p1 + d1 * s) - (p2 + d2 * t)).squaredNorm();
}

// Squared distance between two triangles: 0 when they share a point (exact test), else the
// closest pair is a vertex and a face or two edges. `mid` receives the midpoint of the closest
// such pair (for crossing triangles too: a point near the crossing).
double TriangleTriangleSquared(const std::array<Eigen::Vector3d, 3>& x,
                               const std::array<Eigen::Vector3d, 3>& y, Eigen::Vector3d* mid) {
  double best = std::numeric_limits<double>::infinity();
  auto offer = [&](double d, const Eigen::Vector3d& m) {
    if (d < best) {
      best = d;
      *mid = m;
    }
  };
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d on_y = ClosestPointOnTriangle(x[i], y[0], y[1], y[2]);
    offer((on_y - x[i]).squaredNorm(), 0.5 * (on_y + x[i]));
    const Eigen::Vector3d on_x = ClosestPointOnTriangle(y[i], x[0], x[1], x[2]);
    offer((on_x - y[i]).squaredNorm(), 0.5 * (on_x + y[i]));
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d m;
      const double d = SegmentSegmentSquared(x[i], x[(i + 1) % 3], y[j], y[(j + 1) % 3], &m);
      offer(d, m);
    }
  }
  if (!TrianglesSurelyApart(x[0], x[1], x[2], y[0], y[1], y[2]) &&
      TrianglesIntersect(x[0], x[1], x[2], y[0], y[1], y[2])) {
    return 0.0;
  }
  return best;
}

double BoxDistance(const Eigen::Vector3d& center_a, const Eigen::Vector3d& half_a,
                   const Eigen::Vector3d& center_b, const Eigen::Vector3d& half_b) {
  const Eigen::Vector3d gap =
      ((center_b - center_a).cwiseAbs() - half_a - half_b).cwiseMax(Eigen::Vector3d::Zero());
  return gap.norm();
}

}  // namespace

double SurfaceDistance(const CollisionMesh& a, const RigidTransform& X_WA, const CollisionMesh& b,
                       const RigidTransform& X_WB, double give_up, Eigen::Vector3d* p_W) {
  if (a.mesh().faces.empty() || b.mesh().faces.empty()) {
    return std::numeric_limits<double>::infinity();
  }
  const RigidTransform X_AB = X_WA.inverse() * X_WB;
  const Eigen::Matrix3d absR = X_AB.rotation().cwiseAbs();
  // B's nodes as axis-aligned boxes in A's frame (centre and half extents): larger than the
  // nodes, so their distances are lower bounds.
  auto node_b = [&](const CollisionMesh::Node& n) {
    return std::make_pair(Eigen::Vector3d(X_AB * n.center_M), Eigen::Vector3d(absR * n.half_M));
  };
  double best = give_up;
  double best_sq = give_up * give_up;
  // Depth first, nearer child pair first.
  struct Item {
    std::int32_t a, b;
    double bound;
  };
  std::vector<Item> stack;
  {
    const auto [cb, hb] = node_b(b.nodes()[0]);
    stack.push_back({0, 0, BoxDistance(a.nodes()[0].center_M, a.nodes()[0].half_M, cb, hb)});
  }
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.bound >= best) continue;
    const auto& na = a.nodes()[item.a];
    const auto& nb = b.nodes()[item.b];
    if (na.leaf() && nb.leaf()) {
      for (std::int32_t i = na.first; i < na.first + na.count; ++i) {
        const auto ta = a.Triangle(a.order()[i]);
        for (std::int32_t j = nb.first; j < nb.first + nb.count; ++j) {
          auto tb = b.Triangle(b.order()[j]);
          for (auto& v : tb) v = X_AB * v;
          Eigen::Vector3d mid_A = Eigen::Vector3d::Zero();
          const double d = TriangleTriangleSquared(ta, tb, &mid_A);
          if (d < best_sq) {
            best_sq = d;
            best = std::sqrt(d);
            if (p_W) *p_W = X_WA * mid_A;
          }
        }
      }
      continue;
    }
    const bool split_a =
        !na.leaf() && (nb.leaf() || na.half_M.squaredNorm() >= nb.half_M.squaredNorm());
    std::array<Item, 2> children;
    for (int k = 0; k < 2; ++k) {
      const std::int32_t ia = split_a ? (k == 0 ? na.left : na.right) : item.a;
      const std::int32_t ib = split_a ? item.b : (k == 0 ? nb.left : nb.right);
      const auto [cb, hb] = node_b(b.nodes()[ib]);
      children[k] = {ia, ib, BoxDistance(a.nodes()[ia].center_M, a.nodes()[ia].half_M, cb, hb)};
    }
    if (children[0].bound < children[1].bound) std::swap(children[0], children[1]);
    for (const Item& c : children) {
      if (c.bound < best) stack.push_back(c);
    }
  }
  return best;
}

}  // namespace mechanist
