#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "kernel/geometry/aabb.h"

namespace mechanist {

/// An indexed triangle mesh in its part's frame, lengths in millimetres. Faces list vertex
/// indices counter-clockwise seen from outside (outward normals by the right-hand rule).
struct TriangleMesh {
  using Face = std::array<std::int32_t, 3>;

  std::vector<Eigen::Vector3d> vertices;
  std::vector<Face> faces;

  /// Bounding box of the vertices referenced or not (in the mesh's own frame).
  Aabb Bounds() const;
  /// Signed volume by the divergence theorem, sum over faces of (a . (b x c)) / 6; positive
  /// for a closed outward-oriented mesh. mm^3.
  double SignedVolume() const;
  /// Total face area, mm^2.
  double Area() const;
  /// Appends another mesh's vertices and faces (indices shifted).
  void Append(const TriangleMesh& other);
  /// Scales every vertex by `factor` (unit conversion).
  void Scale(double factor);
};

}  // namespace mechanist
