#pragma once

#include <Eigen/Core>

#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// The generalized winding number of `mesh` at p_M (in the mesh's frame): the sum of the
/// signed solid angles its triangles subtend at p_M, divided by 4 pi (Jacobson, Kavan and
/// Sorkine-Hornung, "Robust inside-outside segmentation using generalized winding numbers",
/// 2013), each solid angle by Van Oosterom and Strackee's formula (1983). It is an integer
/// (1 inside, 0 outside; -1 inside a mesh wound inside out) for a closed mesh and degrades
/// gracefully for a mesh with cracks or missing faces, whose inside stays near 1. Undefined on
/// the surface itself. O(faces).
double WindingNumber(const TriangleMesh& mesh, const Eigen::Vector3d& p_M);

/// The signed solid angle (steradians) that the triangle with corners a, b, c (relative to the
/// point that sees it) subtends (Van Oosterom and Strackee 1983): positive when the point lies
/// on the side its normal (b - a) x (c - a) points away from, as points inside a closed mesh
/// wound outward do.
double TriangleSolidAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c);

}  // namespace mechanist
