#pragma once

#include <Eigen/Core>

#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// The volume integrals of a solid bounded by a closed, outward-oriented triangle mesh, per unit
/// density, in the mesh's own frame and units (mm for part meshes).
struct MassProperties {
  double volume = 0.0;                                ///< mm^3
  Eigen::Vector3d center = Eigen::Vector3d::Zero();   ///< centroid, mm
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the centroid, mm^5
};

/// Volume, centroid and inertia tensor (per unit density) of the solid `mesh` bounds, by the
/// divergence theorem over its faces (D. Eberly, "Polyhedral Mass Properties (Revisited)",
/// 2002). Exact for a closed, consistently oriented mesh; a mesh wound inside out gives the
/// same centroid and a negative volume and inertia. Zero for a mesh without volume.
MassProperties ComputeMassProperties(const TriangleMesh& mesh);

}  // namespace mechanist
