#pragma once

#include <Eigen/Core>
#include <optional>

#include "kernel/features/feature.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// A helical spring: a round wire coiled about an axis (mesh frame, mm).
struct HelicalSpring {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< on the axis, at the coil's lower end
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   ///< unit
  double length = 0.0;                               ///< along the axis, end to end
  double mean_diameter = 0.0;                        ///< of the coil, at the wire's centre
  double wire_diameter = 0.0;
  double pitch = 0.0;  ///< axial advance per turn
  double turns = 0.0;
  Hand hand = Hand::kRight;
};

/// Recognises a helical spring, open or closely wound, from its mesh alone. For each principal
/// axis of the vertices, set through the centres of circles fitted to the lower and upper half
/// of them (Kasa; twice), the vertices must lie in an annulus about it (inner radius at least a
/// quarter of the outer; the wire's diameter d = outer - inner from 4% of the coil's mean
/// radius to all of it, a spring index of 2 to 50); the pitch p is searched (0.95 d to the
/// whole length, at most 200 turns, both hands) for the one that concentrates the phase
/// t / p - angle / 2 pi of the vertices on the annulus' rims, which lie on the wire's helix
/// (Fisher's mean resultant length at least 0.5); at least 2.5 turns; and the mesh's volume and
/// area within 30% of the wire's (pi d^2 / 4 and pi d times the helix' length, turns x
/// sqrt((pi D)^2 + p^2)), which a threaded rod, a tube (its vertices in an annulus too) or a
/// box is far from. Deterministic (vertices subsampled to at most 4096, evenly).
std::optional<HelicalSpring> RecognizeHelicalSpring(const TriangleMesh& mesh);

}  // namespace mechanist
