// The only translation unit that includes CGAL's kernel: the exact predicates facade.
#include "kernel/exact_predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

namespace mechanist {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 P(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

int Orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d) {
  return static_cast<int>(CGAL::orientation(P(a), P(b), P(c), P(d)));
}

bool TrianglesIntersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                        const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                        const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  const K::Triangle_3 a(P(a0), P(a1), P(a2));
  const K::Triangle_3 b(P(b0), P(b1), P(b2));
  if (a.is_degenerate() || b.is_degenerate()) {
    // CGAL's triangle-triangle test requires proper triangles; a degenerate one is covered by
    // its edges (a segment) or is a point.
    auto edges_hit = [](const K::Triangle_3& t, const K::Triangle_3& other) {
      for (int i = 0; i < 3; ++i) {
        const K::Segment_3 s(t.vertex(i), t.vertex((i + 1) % 3));
        if (s.is_degenerate() ? (other.is_degenerate() ? false : other.has_on(s.source()))
                              : (!other.is_degenerate() && CGAL::do_intersect(s, other))) {
          return true;
        }
      }
      return false;
    };
    if (!a.is_degenerate()) return edges_hit(b, a);
    if (!b.is_degenerate()) return edges_hit(a, b);
    for (int i = 0; i < 3; ++i) {
      const K::Segment_3 s(a.vertex(i), a.vertex((i + 1) % 3));
      for (int j = 0; j < 3; ++j) {
        const K::Segment_3 t(b.vertex(j), b.vertex((j + 1) % 3));
        if (s.is_degenerate() || t.is_degenerate()) {
          const K::Point_3& p = s.is_degenerate() ? s.source() : t.source();
          const K::Segment_3& other = s.is_degenerate() ? t : s;
          if (other.is_degenerate() ? p == other.source() : other.has_on(p)) return true;
        } else if (CGAL::do_intersect(s, t)) {
          return true;
        }
      }
    }
    return false;
  }
  return CGAL::do_intersect(a, b);
}

bool SegmentIntersectsTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                               const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  return TrianglesIntersect(p, q, q, a, b, c);
}

}  // namespace mechanist
