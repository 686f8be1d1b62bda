#pragma once

#include <Eigen/Core>

namespace mechanist {

/// The point of triangle (a, b, c) closest to p, by Voronoi regions of the vertices, edges
/// and face (Ericson, Real-Time Collision Detection, 5.1.5). Works for degenerate triangles.
Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace mechanist
