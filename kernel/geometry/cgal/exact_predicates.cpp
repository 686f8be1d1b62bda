// The only translation unit that includes CGAL's kernel: the exact predicates facade.
#include "kernel/geometry/exact_predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <Eigen/Geometry>
#include <cmath>

namespace mechanist {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 P(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

int Orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d) {
  return static_cast<int>(CGAL::orientation(P(a), P(b), P(c), P(d)));
}

bool Collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return CGAL::collinear(P(a), P(b), P(c));
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

namespace {

// +1 or -1 when all of p, q, r lie strictly on one side of the plane (a, b, c) beyond the
// error bound of the double computation, 0 otherwise.
int SurelyOneSide(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
  // The rounding error of n . w evaluated this way (three differences, a cross product, a dot
  // product) is below about 8 eps times the permanent sum |u_j v_k w_i|; the bound used is 64
  // times Shewchuk's orient3d bound A, (7 + 56 eps) eps, about 450 eps.
  constexpr double kBound = 64.0 * 1.1102230246251565e-16 * (7.0 + 56.0 * 1.1102230246251565e-16);
  const Eigen::Vector3d u = b - a, v = c - a;
  const Eigen::Vector3d n = u.cross(v);
  const Eigen::Vector3d n_abs(std::abs(u.y() * v.z()) + std::abs(u.z() * v.y()),
                              std::abs(u.z() * v.x()) + std::abs(u.x() * v.z()),
                              std::abs(u.x() * v.y()) + std::abs(u.y() * v.x()));
  int side = 0;
  for (const Eigen::Vector3d* x : {&p, &q, &r}) {
    const Eigen::Vector3d w = *x - a;
    const double d = n.dot(w);
    const double permanent = n_abs.dot(w.cwiseAbs());
    if (!(std::abs(d) > kBound * permanent)) return 0;  // also when d is not a number
    const int s = d > 0 ? 1 : -1;
    if (side != 0 && s != side) return 0;
    side = s;
  }
  return side;
}

}  // namespace

bool TrianglesSurelyApart(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                          const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                          const Eigen::Vector3d& b1, const Eigen::Vector3d& b2) {
  return SurelyOneSide(a0, a1, a2, b0, b1, b2) != 0 || SurelyOneSide(b0, b1, b2, a0, a1, a2) != 0;
}

bool SegmentIntersectsTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                               const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  // Most segments a sweep asks about end on one side of the triangle's plane: no need for CGAL.
  if (SurelyOneSide(a, b, c, p, q, q) != 0) return false;
  const K::Triangle_3 t(P(a), P(b), P(c));
  // A degenerate triangle is covered by its edges (TrianglesIntersect). Otherwise the segment
  // goes to CGAL as a segment: passed as the triangle (p, q, q), exactly degenerate, it would
  // make every call prove that degeneracy in exact arithmetic.
  if (t.is_degenerate()) return TrianglesIntersect(p, q, q, a, b, c);
  const K::Segment_3 s(P(p), P(q));
  return s.is_degenerate() ? t.has_on(s.source()) : CGAL::do_intersect(s, t);
}

}  // namespace mechanist
