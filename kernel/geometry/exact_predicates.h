#pragma once

#include <Eigen/Core>

namespace mechanist {

/// Exact geometric predicates on double coordinates (CGAL's filtered exact predicates behind
/// this facade): the answers are those of exact arithmetic on the given doubles, never
/// affected by rounding. Points are in any one frame; lengths in mm.

/// Sign of det[b-a, c-a, d-a]: +1 when d lies on the side of the plane through a, b, c from
/// which a, b, c appear counter-clockwise, -1 on the other side, 0 when the four points are
/// coplanar. This is CGAL's orientation(a, b, c, d).
int Orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d);

/// True when a, b and c lie on one line (or coincide), exactly: a triangle without area.
bool Collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// True when the closed triangles (a0, a1, a2) and (b0, b1, b2) share at least one point
/// (touching counts). Degenerate triangles are treated as segments or points.
bool TrianglesIntersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                        const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                        const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

/// True when the double-precision test proves the triangles apart: all three corners of one
/// triangle lie strictly on one side of the other's plane by more than a forward error bound
/// of the double computation (64 times Shewchuk's orient3d bound, far above this evaluation's
/// error of about 8 eps times the permanent). False means "maybe": ask
/// TrianglesIntersect. A cheap filter in front of the exact test (Moller 1997's plane test).
bool TrianglesSurelyApart(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                          const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                          const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

/// True when the closed segment [p, q] and the closed triangle (a, b, c) share a point.
bool SegmentIntersectsTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                               const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);

}  // namespace mechanist
