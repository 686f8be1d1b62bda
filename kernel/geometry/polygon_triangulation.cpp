#include "kernel/geometry/polygon_triangulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mechanist {
namespace {

using Triangle = std::array<std::int32_t, 3>;

// A vertex of the circular doubly linked list the algorithm cuts ears from. Bridging a hole
// duplicates two vertices, so several nodes may carry the same vertex number.
struct Node {
  std::int32_t vertex;
  double x, y;
  std::int32_t prev = -1, next = -1;
};

// The earcut algorithm on a list of nodes. Orientation predicates use the usual cross product
// (positive for a left turn); earcut's `area` is its negation, so its signs are flipped here.
class EarClipper {
 public:
  // Links `ring` (vertex numbers from `first_vertex`) counter-clockwise or clockwise and
  // returns one of its nodes.
  std::int32_t LinkRing(const Ring2d& ring, std::int32_t first_vertex, bool counter_clockwise) {
    const bool reverse = (SignedArea(ring) > 0.0) != counter_clockwise;
    const auto n = static_cast<std::int32_t>(ring.size());
    const std::int32_t first = Size();
    for (std::int32_t k = 0; k < n; ++k) {
      const std::int32_t i = reverse ? n - 1 - k : k;
      nodes_.push_back({first_vertex + i, ring[i].x(), ring[i].y()});
    }
    for (std::int32_t k = 0; k < n; ++k) {
      nodes_[first + k].prev = first + (k + n - 1) % n;
      nodes_[first + k].next = first + (k + 1) % n;
    }
    return first;
  }

  // Joins the hole whose leftmost node is `leftmost` into the ring of `outer` through a
  // bridge from that node. Returns false when no outer edge is to the left of the hole.
  bool EliminateHole(std::int32_t leftmost, std::int32_t outer) {
    const std::int32_t bridge = FindHoleBridge(leftmost, outer);
    if (bridge < 0) return false;
    SplitPolygon(bridge, leftmost);
    return true;
  }

  // The leftmost node of the ring of `start` (lowest y among ties).
  std::int32_t Leftmost(std::int32_t start) const {
    std::int32_t p = start, leftmost = start;
    do {
      const Node& n = nodes_[p];
      const Node& l = nodes_[leftmost];
      if (n.x < l.x || (n.x == l.x && n.y < l.y)) leftmost = p;
      p = n.next;
    } while (p != start);
    return leftmost;
  }

  const Node& operator[](std::int32_t i) const { return nodes_[i]; }

  // Cuts ears off the ring of `ear` until none is left. Returns false when no ear can be
  // found, which does not happen for the simple polygons accepted here (earcut would go on by
  // dropping collinear vertices, which would leave cracks beside faces that share them).
  bool CutEars(std::int32_t ear, std::vector<Triangle>& triangles) {
    std::int32_t stop = ear;
    while (nodes_[ear].prev != nodes_[ear].next) {
      const std::int32_t prev = nodes_[ear].prev;
      const std::int32_t next = nodes_[ear].next;
      if (IsEar(ear)) {
        triangles.push_back({nodes_[prev].vertex, nodes_[ear].vertex, nodes_[next].vertex});
        Remove(ear);
        // Skipping the next vertex leads to fewer sliver triangles (as in earcut).
        ear = nodes_[next].next;
        stop = ear;
        continue;
      }
      ear = next;
      if (ear == stop) return false;
    }
    return true;
  }

 private:
  std::int32_t Size() const { return static_cast<std::int32_t>(nodes_.size()); }

  static double Cross(const Node& p, const Node& q, const Node& r) {
    return (q.x - p.x) * (r.y - q.y) - (q.y - p.y) * (r.x - q.x);
  }

  double Cross(std::int32_t p, std::int32_t q, std::int32_t r) const {
    return Cross(nodes_[p], nodes_[q], nodes_[r]);
  }

  // Whether the ring turns left at b by more than a hair. Corners within 1e-10 rad of straight
  // count as flat: rounding leaves vertices meant to be collinear (on a line through a circle's
  // vertex at angle pi, say) a few 1e-16 off it, and cutting such an ear would make a sliver.
  static bool IsConvex(const Node& a, const Node& b, const Node& c) {
    return Cross(a, b, c) >
           1e-10 * std::hypot(b.x - a.x, b.y - a.y) * std::hypot(c.x - b.x, c.y - b.y);
  }

  // Whether p lies on the open segment from a to c, within the same tolerance. Clipping an ear
  // whose new edge a-c passes through a vertex would leave a zero-area corner behind.
  static bool OnOpenSegment(const Node& a, const Node& c, const Node& p) {
    if ((p.x == a.x && p.y == a.y) || (p.x == c.x && p.y == c.y)) return false;
    const double ux = c.x - a.x, uy = c.y - a.y, vx = p.x - a.x, vy = p.y - a.y;
    const double along = ux * vx + uy * vy;
    return std::abs(ux * vy - uy * vx) <= 1e-10 * std::hypot(ux, uy) * std::hypot(vx, vy) &&
           along > 0.0 && along < ux * ux + uy * uy;
  }

  // Inclusive test for a counter-clockwise triangle a, b, c.
  static bool PointInTriangle(double ax, double ay, double bx, double by, double cx, double cy,
                              double px, double py) {
    return (cx - px) * (ay - py) >= (ax - px) * (cy - py) &&
           (ax - px) * (by - py) >= (bx - px) * (ay - py) &&
           (bx - px) * (cy - py) >= (cx - px) * (by - py);
  }

  // A convex corner b whose triangle a, b, c holds no reflex or flat vertex of the remaining
  // ring and whose new edge a-c passes through no vertex. A vertex at a's position is a bridge
  // duplicate and ignored. Convex vertices need no test inside the triangle (none can be there
  // without a reflex one), but one can lie on the new edge.
  bool IsEar(std::int32_t ear) const {
    const Node& a = nodes_[nodes_[ear].prev];
    const Node& b = nodes_[ear];
    const Node& c = nodes_[b.next];
    if (!IsConvex(a, b, c)) return false;
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
    for (std::int32_t p = c.next; p != b.prev; p = nodes_[p].next) {
      const Node& n = nodes_[p];
      if (n.x < x0 || n.x > x1 || n.y < y0 || n.y > y1) continue;
      if (n.x == a.x && n.y == a.y) continue;
      if ((PointInTriangle(a.x, a.y, b.x, b.y, c.x, c.y, n.x, n.y) &&
           !IsConvex(nodes_[n.prev], n, nodes_[n.next])) ||
          OnOpenSegment(a, c, n)) {
        return false;
      }
    }
    return true;
  }

  // Whether the diagonal from a to b starts into the polygon's interior at a.
  bool LocallyInside(std::int32_t a, std::int32_t b) const {
    const std::int32_t prev = nodes_[a].prev, next = nodes_[a].next;
    return Cross(prev, a, next) > 0.0 ? Cross(a, b, next) <= 0.0 && Cross(a, prev, b) <= 0.0
                                      : Cross(a, b, prev) > 0.0 || Cross(a, next, b) > 0.0;
  }

  // Whether the sector at m contains the sector at p (both at the same position).
  bool SectorContainsSector(std::int32_t m, std::int32_t p) const {
    return Cross(nodes_[m].prev, m, nodes_[p].prev) > 0.0 &&
           Cross(nodes_[p].next, m, nodes_[m].next) > 0.0;
  }

  // Earcut's bridge search: the nearest outer edge hit by the ray from the hole's leftmost
  // vertex toward -x, then the vertex of least angle to the ray that the hole vertex sees.
  std::int32_t FindHoleBridge(std::int32_t hole, std::int32_t outer) const {
    const double hx = nodes_[hole].x, hy = nodes_[hole].y;
    double qx = -std::numeric_limits<double>::infinity();
    std::int32_t m = -1;
    std::int32_t p = outer;
    do {
      const Node& a = nodes_[p];
      const Node& b = nodes_[a.next];
      if (hy <= a.y && hy >= b.y && b.y != a.y) {
        const double x = a.x + (hy - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x <= hx && x > qx) {
          qx = x;
          m = a.x < b.x ? p : a.next;
          if (x == hx) return m;
        }
      }
      p = a.next;
    } while (p != outer);
    if (m < 0) return -1;

    const std::int32_t stop = m;
    const double mx = nodes_[m].x, my = nodes_[m].y;
    double tan_min = std::numeric_limits<double>::infinity();
    p = m;
    do {
      const Node& n = nodes_[p];
      if (hx >= n.x && n.x >= mx && hx != n.x &&
          PointInTriangle(hy < my ? hx : qx, hy, mx, my, hy < my ? qx : hx, hy, n.x, n.y)) {
        const double tan = std::abs(hy - n.y) / (hx - n.x);
        if (LocallyInside(p, hole) &&
            (tan < tan_min ||
             (tan == tan_min &&
              (n.x > nodes_[m].x || (n.x == nodes_[m].x && SectorContainsSector(m, p)))))) {
          m = p;
          tan_min = tan;
        }
      }
      p = n.next;
    } while (p != stop);
    return m;
  }

  // Links a to b by two coincident edges, duplicating both nodes, so that the two rings they
  // belong to become one.
  void SplitPolygon(std::int32_t a, std::int32_t b) {
    const std::int32_t a2 = Size();
    nodes_.push_back({nodes_[a].vertex, nodes_[a].x, nodes_[a].y});
    const std::int32_t b2 = Size();
    nodes_.push_back({nodes_[b].vertex, nodes_[b].x, nodes_[b].y});
    const std::int32_t an = nodes_[a].next, bp = nodes_[b].prev;
    nodes_[a].next = b;
    nodes_[b].prev = a;
    nodes_[a2].next = an;
    nodes_[an].prev = a2;
    nodes_[b2].next = a2;
    nodes_[a2].prev = b2;
    nodes_[bp].next = b2;
    nodes_[b2].prev = bp;
  }

  void Remove(std::int32_t p) {
    nodes_[nodes_[p].prev].next = nodes_[p].next;
    nodes_[nodes_[p].next].prev = nodes_[p].prev;
  }

  std::vector<Node> nodes_;
};

void CheckRing(const Ring2d& ring, const std::string& name) {
  if (ring.size() < 3) {
    throw std::invalid_argument(
        fmt::format("TriangulatePolygon: {} has {} vertices, fewer than 3", name, ring.size()));
  }
  if (!(std::abs(SignedArea(ring)) > 0.0)) {
    throw std::invalid_argument(fmt::format("TriangulatePolygon: {} has no area", name));
  }
}

}  // namespace

double SignedArea(const Ring2d& ring) {
  double twice_area = 0.0;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    twice_area += ring[j].x() * ring[i].y() - ring[i].x() * ring[j].y();
  }
  return twice_area / 2.0;
}

std::vector<std::array<std::int32_t, 3>> TriangulatePolygon(const Ring2d& outer,
                                                            const std::vector<Ring2d>& holes) {
  CheckRing(outer, "the outer ring");
  EarClipper clipper;
  const std::int32_t outer_node = clipper.LinkRing(outer, 0, /*counter_clockwise=*/true);
  auto vertex_count = static_cast<std::int32_t>(outer.size());

  // Holes go in from left to right, so that each bridge only crosses rings already joined.
  struct Hole {
    std::int32_t leftmost;
    std::size_t number;
  };
  std::vector<Hole> queue;
  for (std::size_t h = 0; h < holes.size(); ++h) {
    CheckRing(holes[h], fmt::format("hole {}", h + 1));
    const std::int32_t node = clipper.LinkRing(holes[h], vertex_count, /*counter_clockwise=*/false);
    vertex_count += static_cast<std::int32_t>(holes[h].size());
    queue.push_back({clipper.Leftmost(node), h});
  }
  std::sort(queue.begin(), queue.end(), [&clipper](const Hole& a, const Hole& b) {
    const Node& p = clipper[a.leftmost];
    const Node& q = clipper[b.leftmost];
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  for (const Hole& hole : queue) {
    if (!clipper.EliminateHole(hole.leftmost, outer_node)) {
      throw std::invalid_argument(
          fmt::format("TriangulatePolygon: hole {} is not inside the outer ring", hole.number + 1));
    }
  }

  std::vector<Triangle> triangles;
  triangles.reserve(static_cast<std::size_t>(vertex_count) + 2 * holes.size());
  if (!clipper.CutEars(outer_node, triangles)) {
    throw std::invalid_argument(
        "TriangulatePolygon: no ear left to cut; the rings cross or touch each other");
  }
  return triangles;
}

}  // namespace mechanist
