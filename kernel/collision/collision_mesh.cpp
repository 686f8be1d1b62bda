#include "kernel/collision/collision_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "kernel/geometry/exact_predicates.h"
#include "kernel/geometry/triangle_geometry.h"
#include "kernel/mesh/winding_number.h"

namespace mechanist {
namespace {

constexpr std::int32_t kLeafSize = 4;

// Directions for the ray crossing test: no two parallel and none along a coordinate axis or a
// diagonal, so that rays rarely graze the edges of CAD meshes (mostly axis-aligned).
const std::array<Eigen::Vector3d, 6> kRayDirections = {
    Eigen::Vector3d(0.5773502691896258, 0.6180339887498949, 0.5331652197),
    Eigen::Vector3d(-0.3141592653589793, 0.8660254037844386, 0.2718281828),
    Eigen::Vector3d(0.7071067811865476, -0.1414213562373095, -0.6928203230),
    Eigen::Vector3d(-0.6324555320336759, -0.4472135954999579, 0.3162277660),
    Eigen::Vector3d(0.2236067977499790, 0.3605551275463989, -0.9055385138),
    Eigen::Vector3d(-0.8944271909999159, 0.1732050807568877, -0.4123105626)};

bool SegmentMayHitBox(const Eigen::Vector3d& p, const Eigen::Vector3d& d, const Aabb& box,
                      double margin) {
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double lo = box.min[k] - margin, hi = box.max[k] + margin;
    if (d[k] == 0.0) {
      if (p[k] < lo || p[k] > hi) return false;
      continue;
    }
    double a = (lo - p[k]) / d[k], b = (hi - p[k]) / d[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

double BoxDistanceSquared(const Eigen::Vector3d& p, const Aabb& box) {
  const Eigen::Vector3d d = (box.min - p).cwiseMax(Eigen::Vector3d::Zero()).cwiseMax(p - box.max);
  return d.squaredNorm();
}

}  // namespace

CollisionMesh::CollisionMesh(std::shared_ptr<const TriangleMesh> mesh) : mesh_(std::move(mesh)) {
  if (!mesh_) throw std::invalid_argument("CollisionMesh: null mesh");
  const auto& V = mesh_->vertices;
  const auto& F = mesh_->faces;
  const auto n = static_cast<std::int32_t>(F.size());

  normals_.resize(F.size());
  std::vector<Eigen::Vector3d> centroids(F.size());
  std::vector<Aabb>& boxes = face_boxes_;
  boxes.resize(F.size());
  for (std::int32_t f = 0; f < n; ++f) {
    const auto& [a, b, c] = Triangle(f);
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double len = cross.norm();
    normals_[f] =
        len > 0.0 && !Collinear(a, b, c) ? Eigen::Vector3d(cross / len) : Eigen::Vector3d::Zero();
    centroids[f] = (a + b + c) / 3.0;
    boxes[f].Extend(a);
    boxes[f].Extend(b);
    boxes[f].Extend(c);
  }

  order_.resize(F.size());
  for (std::int32_t f = 0; f < n; ++f) order_[f] = f;
  nodes_.reserve(2 * F.size() / kLeafSize + 1);
  // Iterative top-down build; the stack holds (node, first, count).
  nodes_.push_back({});
  std::vector<std::array<std::int32_t, 3>> stack = {{0, 0, n}};
  while (!stack.empty()) {
    const auto [node, first, count] = stack.back();
    stack.pop_back();
    Aabb box, centers;
    for (std::int32_t i = first; i < first + count; ++i) {
      box.Extend(boxes[order_[i]]);
      centers.Extend(centroids[order_[i]]);
    }
    nodes_[node].box_M = box;
    nodes_[node].center_M = box.center();
    nodes_[node].half_M = 0.5 * box.size();
    const Eigen::Vector3d extent = centers.size();
    int axis = 0;
    extent.maxCoeff(&axis);
    if (count <= kLeafSize || extent[axis] <= 0.0) {
      nodes_[node].first = first;
      nodes_[node].count = count;
      continue;
    }
    // Split by the surface-area heuristic over 16 bins along the longest axis of the
    // centroids (MacDonald and Booth 1990): fewer overlapping boxes than a median split.
    constexpr int kBins = 16;
    std::array<Aabb, kBins> bin_box;
    std::array<std::int32_t, kBins> bin_count{};
    auto bin_of = [&](std::int32_t t) {
      const double u = (centroids[t][axis] - centers.min[axis]) / extent[axis];
      return std::min(kBins - 1, static_cast<int>(u * kBins));
    };
    for (std::int32_t i = first; i < first + count; ++i) {
      const int k = bin_of(order_[i]);
      bin_box[k].Extend(boxes[order_[i]]);
      ++bin_count[k];
    }
    auto area = [](const Aabb& b) {
      if (b.empty()) return 0.0;
      const Eigen::Vector3d s = b.size();
      return s.x() * s.y() + s.y() * s.z() + s.z() * s.x();
    };
    std::array<double, kBins> right_cost{};
    Aabb right_box;
    std::int32_t right_n = 0;
    for (int k = kBins - 1; k > 0; --k) {
      right_box.Extend(bin_box[k]);
      right_n += bin_count[k];
      right_cost[k] = area(right_box) * right_n;
    }
    Aabb left_box;
    std::int32_t left_n = 0;
    int best_split = -1;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int k = 1; k < kBins; ++k) {
      left_box.Extend(bin_box[k - 1]);
      left_n += bin_count[k - 1];
      if (left_n == 0 || left_n == count) continue;
      const double cost = area(left_box) * left_n + right_cost[k];
      if (cost < best_cost) {
        best_cost = cost;
        best_split = k;
      }
    }
    std::int32_t half = count / 2;
    if (best_split > 0) {
      const auto middle =
          std::stable_partition(order_.begin() + first, order_.begin() + first + count,
                                [&](std::int32_t t) { return bin_of(t) < best_split; });
      half = static_cast<std::int32_t>(middle - (order_.begin() + first));
    } else {
      std::nth_element(order_.begin() + first, order_.begin() + first + half,
                       order_.begin() + first + count, [&](std::int32_t x, std::int32_t y) {
                         return centroids[x][axis] < centroids[y][axis] ||
                                (centroids[x][axis] == centroids[y][axis] && x < y);
                       });
    }
    const auto left = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[node].left = left;
    nodes_[node].right = left + 1;
    stack.push_back({left, first, half});
    stack.push_back({left + 1, first + half, count - half});
  }

  // Edge adjacency by vertex index; when that does not close the surface, by vertex position,
  // so that triangle soups (one vertex per corner, as in many STL and OBJ files) still have
  // neighbours.
  std::vector<std::int32_t> canonical(V.size());
  for (std::size_t i = 0; i < V.size(); ++i) canonical[i] = static_cast<std::int32_t>(i);
  BuildEdges(canonical);
  if (!closed_) {
    std::map<std::array<double, 3>, std::int32_t> canonical_of;
    for (std::size_t i = 0; i < V.size(); ++i) {
      canonical[i] =
          canonical_of.try_emplace({V[i].x(), V[i].y(), V[i].z()}, static_cast<std::int32_t>(i))
              .first->second;
    }
    BuildEdges(canonical);
  }
  if (closed_ && mesh_->SignedVolume() < 0.0) {
    for (Eigen::Vector3d& n : normals_) n = -n;
  }
  bool faces_out = true;
  solid_ = closed_ || WindingNumberIsIntegral(&faces_out);
  oriented_ = oriented_ && solid_ && faces_out;
  if (solid_ && !closed_) BuildClusters();
}

void CollisionMesh::BuildClusters() {
  clusters_.assign(nodes_.size(), Cluster());
  // Children come after their parent: backwards, every child is done before its parent.
  for (auto i = static_cast<std::int32_t>(nodes_.size()) - 1; i >= 0; --i) {
    const Node& node = nodes_[i];
    Cluster& cluster = clusters_[i];
    if (node.leaf()) {
      Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const auto [a, b, c] = Triangle(order_[k]);
        const Eigen::Vector3d area_vector = 0.5 * (b - a).cross(c - a);
        const double area = area_vector.norm();
        cluster.area_vector += area_vector;
        cluster.area += area;
        weighted += area * (a + b + c) / 3.0;
      }
      cluster.centre =
          cluster.area > 0.0 ? Eigen::Vector3d(weighted / cluster.area) : node.center_M;
      for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
        const auto [a, b, c] = Triangle(order_[k]);
        const Eigen::Vector3d area_vector = 0.5 * (b - a).cross(c - a);
        cluster.moment += ((a + b + c) / 3.0 - cluster.centre) * area_vector.transpose();
        for (const Eigen::Vector3d& corner : {a, b, c}) {
          cluster.radius = std::max(cluster.radius, (corner - cluster.centre).norm());
        }
      }
      continue;
    }
    const Cluster& l = clusters_[node.left];
    const Cluster& r = clusters_[node.right];
    cluster.area = l.area + r.area;
    cluster.area_vector = l.area_vector + r.area_vector;
    cluster.centre = cluster.area > 0.0
                         ? Eigen::Vector3d((l.area * l.centre + r.area * r.centre) / cluster.area)
                         : node.center_M;
    // Each child's moment moved from its centre to this one.
    cluster.moment = l.moment + (l.centre - cluster.centre) * l.area_vector.transpose() + r.moment +
                     (r.centre - cluster.centre) * r.area_vector.transpose();
    cluster.radius = std::max((l.centre - cluster.centre).norm() + l.radius,
                              (r.centre - cluster.centre).norm() + r.radius);
  }
}

CollisionMesh::WindingEstimate CollisionMesh::WindingNumberAt(const Eigen::Vector3d& p_M) const {
  if (clusters_.empty()) return {WindingNumber(*mesh_, p_M), 0.0};
  // A node's expansion is taken when its error bound is at most 1e-4 of a whole turn (4 pi).
  constexpr double kBudget = 1e-4 * 4.0 * std::numbers::pi;
  double solid_angle = 0.0, bound = 0.0;
  std::vector<std::int32_t> stack = {0};
  while (!stack.empty()) {
    const std::int32_t i = stack.back();
    stack.pop_back();
    const Cluster& cluster = clusters_[i];
    const Eigen::Vector3d r = cluster.centre - p_M;
    const double d2 = r.squaredNorm();
    const double d = std::sqrt(d2);
    if (d > 2.0 * cluster.radius) {
      // The remainder of the first-order expansion: the kernel's second derivative, the third
      // of 1 / |x - p|, is at most 6 / rho^4 at distance rho >= d - radius, so each point of the
      // node's surface is off by at most 3 radius^2 / (d - radius)^4.
      const double gap = d - cluster.radius;
      const double error =
          3.0 * cluster.area * cluster.radius * cluster.radius / (gap * gap * gap * gap);
      if (error <= kBudget) {
        // The solid angle of the node's surface, integral of n . (x - p) / |x - p|^3 dA, with
        // the kernel expanded about the centre to first order: its gradient there is
        // I / |r|^3 - 3 r r^T / |r|^5.
        const double inv3 = 1.0 / (d2 * d);
        solid_angle += cluster.area_vector.dot(r) * inv3 + cluster.moment.trace() * inv3 -
                       3.0 * r.dot(cluster.moment * r) * inv3 / d2;
        bound += error;
        continue;
      }
    }
    const Node& node = nodes_[i];
    if (!node.leaf()) {
      stack.push_back(node.left);
      stack.push_back(node.right);
      continue;
    }
    for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
      const auto [a, b, c] = Triangle(order_[k]);
      solid_angle += TriangleSolidAngle(a - p_M, b - p_M, c - p_M);
    }
  }
  return {solid_angle / (4.0 * std::numbers::pi), bound / (4.0 * std::numbers::pi)};
}

bool CollisionMesh::WindingNumberIsIntegral(bool* faces_out) const {
  // Points a little off both sides of up to 32 faces spread over the mesh: beside a solid's
  // face the winding number is an integer on either side, one more behind it than in front
  // when the face is wound outward (equal on both sides of a face inside the solid, as where
  // two of its faces lie on each other), one less when inward, and negative in front of a
  // shell wound inside out; beside an open sheet, near a half.
  const auto& F = mesh_->faces;
  const double offset = 1e-4 * std::max(bounds().size().norm(), 1e-9);
  const std::size_t step = std::max<std::size_t>(1, F.size() / 32);
  int near = 0, tested = 0;
  *faces_out = true;
  for (std::size_t f = 0; f < F.size(); f += step) {
    if (normals_[f].isZero()) continue;
    const auto [a, b, c] = Triangle(static_cast<std::int32_t>(f));
    const Eigen::Vector3d centroid = (a + b + c) / 3.0;
    double behind = 0.0, in_front = 0.0;
    for (const double side : {-1.0, 1.0}) {
      const double w = WindingNumber(*mesh_, centroid + side * offset * normals_[f]);
      near += std::abs(w - std::round(w)) <= 0.2;
      ++tested;
      (side < 0 ? behind : in_front) = w;
    }
    // A sliver's normal is rounding noise: it tells nothing of the winding.
    const bool sliver = 0.5 * (b - a).cross(c - a).norm() < offset * offset;
    if (!sliver && (behind - in_front < -0.5 || in_front < -0.5)) *faces_out = false;
  }
  return tested > 0 && 2 * near >= tested;
}

void CollisionMesh::BuildEdges(const std::vector<std::int32_t>& canonical) {
  const auto& F = mesh_->faces;
  const auto n = static_cast<std::int32_t>(F.size());
  edges_.clear();
  std::map<std::pair<std::int32_t, std::int32_t>, std::size_t> edge_of;
  std::vector<int> forward_uses;  // per edge: uses as (low -> high) minus uses as (high -> low)
  std::vector<int> uses;
  closed_ = n > 0;
  oriented_ = n > 0;
  face_edges_.assign(F.size(), {-1, -1, -1});
  for (std::int32_t f = 0; f < n; ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t u = canonical[F[f][k]], v = canonical[F[f][(k + 1) % 3]];
      if (u == v) continue;
      const auto key = std::minmax(u, v);
      const auto [it, inserted] = edge_of.try_emplace({key.first, key.second}, edges_.size());
      if (inserted) {
        edges_.push_back({{key.first, key.second}, {f, -1}, false});
        forward_uses.push_back(0);
        uses.push_back(0);
      } else if (edges_[it->second].faces[1] < 0) {
        edges_[it->second].faces[1] = f;
      } else {
        edges_[it->second].more_faces = true;
      }
      face_edges_[f][k] = static_cast<std::int32_t>(it->second);
      ++uses[it->second];
      forward_uses[it->second] += u < v ? 1 : -1;
    }
  }
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (uses[e] != 2 || forward_uses[e] != 0) closed_ = false;
    if (forward_uses[e] != 0) oriented_ = false;
  }
}

int CollisionMesh::EdgeConvexity(std::int32_t edge) const {
  const Edge& e = edges_[edge];
  if (e.faces[1] < 0 || e.more_faces) return 0;
  const Eigen::Vector3d& n0 = normals_[e.faces[0]];
  const Eigen::Vector3d& n1 = normals_[e.faces[1]];
  if (n0.isZero() || n1.isZero()) return 0;
  // The corner of the second face off the edge lies below the first face's plane for a convex
  // edge.
  const auto& V = mesh_->vertices;
  const Eigen::Vector3d& p = V[e.vertices[0]];
  double offset = 0.0;
  for (const std::int32_t v : mesh_->faces[e.faces[1]]) {
    const double h = n0.dot(V[v] - p);
    if (std::abs(h) > std::abs(offset)) offset = h;
  }
  const double scale = (V[e.vertices[1]] - p).norm();
  if (std::abs(offset) <= 1e-9 * scale || n0.cross(n1).norm() <= 1e-9) return 0;
  return offset < 0.0 ? 1 : -1;
}

std::array<Eigen::Vector3d, 3> CollisionMesh::Triangle(std::int32_t face) const {
  const auto& f = mesh_->faces[face];
  const auto& V = mesh_->vertices;
  return {V[f[0]], V[f[1]], V[f[2]]};
}

bool CollisionMesh::Contains(const Eigen::Vector3d& p_M) const {
  const Aabb& box = bounds();
  if (box.empty() || !box.Intersects(Aabb{p_M, p_M})) return false;
  if (solid_ && !closed_) {
    // The hierarchy's sum decides unless its error bound reaches the threshold (a point on the
    // surface or at a crack): the exact sum decides those, so the answer is always its.
    const WindingEstimate fast = WindingNumberAt(p_M);
    if (std::abs(std::abs(fast.value) - 0.5) > fast.error_bound + 1e-9) {
      return std::abs(fast.value) >= 0.5;
    }
    return std::abs(WindingNumber(*mesh_, p_M)) >= 0.5;
  }
  const double length = 2.0 * (box.size().norm() + (p_M - box.center()).norm()) + 1.0;
  const double margin = 1e-9 * (1.0 + box.size().norm());
  int winding = 0;
  for (const Eigen::Vector3d& direction : kRayDirections) {
    const Eigen::Vector3d d = direction.normalized() * length;
    const Eigen::Vector3d q = p_M + d;
    bool degenerate = false;
    winding = 0;
    std::vector<std::int32_t> stack = {0};
    while (!stack.empty() && !degenerate) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!SegmentMayHitBox(p_M, d, node.box_M, margin)) continue;
      if (!node.leaf()) {
        stack.push_back(node.left);
        stack.push_back(node.right);
        continue;
      }
      for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
        const std::int32_t f = order_[i];
        if (normals_[f].isZero()) continue;  // a zero-area face bounds nothing
        const auto& [a, b, c] = Triangle(f);
        const int sp = Orient3d(a, b, c, p_M), sq = Orient3d(a, b, c, q);
        if (sq == 0) {
          degenerate = true;
          break;
        }
        if (sp == sq) continue;
        const int e1 = Orient3d(p_M, q, a, b), e2 = Orient3d(p_M, q, b, c),
                  e3 = Orient3d(p_M, q, c, a);
        const bool outside = (e1 > 0 || e2 > 0 || e3 > 0) && (e1 < 0 || e2 < 0 || e3 < 0);
        if (sp == 0) {
          // p lies in the face's plane: the ray leaves the plane at p, so it crosses this face
          // only if p is on the face, that is on the surface.
          if (outside) continue;
          return false;
        }
        if (e1 == 0 || e2 == 0 || e3 == 0) {
          // On an edge or vertex, unless the other two signs already rule the crossing out.
          if (outside) continue;
          degenerate = true;
          break;
        }
        if (e1 == e2 && e2 == e3) winding += sp;
      }
    }
    if (!degenerate) return winding != 0;
  }
  // Every ray grazed an edge: the closest face's side decides.
  const Closest closest = ClosestPoint(p_M);
  return closest.face >= 0 && (p_M - closest.p_M).dot(normals_[closest.face]) < 0.0;
}

CollisionMesh::Closest CollisionMesh::ClosestPoint(const Eigen::Vector3d& p_M) const {
  Closest best;
  best.distance = std::numeric_limits<double>::infinity();
  double best_sq = best.distance;
  std::vector<std::int32_t> stack = {0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (BoxDistanceSquared(p_M, node.box_M) >= best_sq) continue;
    if (!node.leaf()) {
      // Visit the nearer child first.
      const double dl = BoxDistanceSquared(p_M, nodes_[node.left].box_M);
      const double dr = BoxDistanceSquared(p_M, nodes_[node.right].box_M);
      stack.push_back(dl < dr ? node.right : node.left);
      stack.push_back(dl < dr ? node.left : node.right);
      continue;
    }
    for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
      const std::int32_t f = order_[i];
      const auto& [a, b, c] = Triangle(f);
      const Eigen::Vector3d q = ClosestPointOnTriangle(p_M, a, b, c);
      const double sq = (q - p_M).squaredNorm();
      if (sq < best_sq) {
        best_sq = sq;
        best.p_M = q;
        best.face = f;
      }
    }
  }
  best.distance = std::sqrt(best_sq);
  return best;
}

}  // namespace mechanist
