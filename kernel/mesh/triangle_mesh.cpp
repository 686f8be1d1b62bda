#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

Aabb TriangleMesh::Bounds() const {
  Aabb box;
  for (const Eigen::Vector3d& v : vertices) box.Extend(v);
  return box;
}

double TriangleMesh::SignedVolume() const {
  double six_volume = 0.0;
  for (const Face& f : faces) {
    six_volume += vertices[f[0]].dot(vertices[f[1]].cross(vertices[f[2]]));
  }
  return six_volume / 6.0;
}

double TriangleMesh::Area() const {
  double twice_area = 0.0;
  for (const Face& f : faces) {
    twice_area += (vertices[f[1]] - vertices[f[0]]).cross(vertices[f[2]] - vertices[f[0]]).norm();
  }
  return twice_area / 2.0;
}

void TriangleMesh::Append(const TriangleMesh& other) {
  const auto offset = static_cast<std::int32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  faces.reserve(faces.size() + other.faces.size());
  for (const Face& f : other.faces) faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
}

void TriangleMesh::Scale(double factor) {
  for (Eigen::Vector3d& v : vertices) v *= factor;
}

}  // namespace mechanist
