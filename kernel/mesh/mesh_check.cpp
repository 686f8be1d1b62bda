#include "kernel/mesh/mesh_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <tuple>

namespace mechanist {

MeshCheck CheckMesh(const TriangleMesh& mesh) {
  MeshCheck check;
  check.vertex_count = mesh.vertices.size();
  check.face_count = mesh.faces.size();
  for (const Eigen::Vector3d& v : mesh.vertices) {
    if (!v.allFinite()) ++check.non_finite_vertices;
  }
  const double extent = mesh.Bounds().empty() ? 0.0 : mesh.Bounds().size().norm();
  const auto n = static_cast<std::int64_t>(mesh.vertices.size());

  // Each face contributes three edges keyed by (low, high) with the traversal direction.
  struct Edge {
    std::int32_t low, high;
    bool forward;
    bool operator<(const Edge& o) const {
      return std::tie(low, high, forward) < std::tie(o.low, o.high, o.forward);
    }
  };
  std::vector<Edge> edges;
  edges.reserve(3 * mesh.faces.size());
  double six_volume = 0.0;
  for (const TriangleMesh::Face& f : mesh.faces) {
    if (std::any_of(f.begin(), f.end(), [n](std::int32_t i) { return i < 0 || i >= n; })) {
      ++check.out_of_range_faces;
      continue;
    }
    const Eigen::Vector3d& a = mesh.vertices[f[0]];
    const Eigen::Vector3d& b = mesh.vertices[f[1]];
    const Eigen::Vector3d& c = mesh.vertices[f[2]];
    const double twice_area = (b - a).cross(c - a).norm();
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] || !(twice_area > 1e-12 * extent * extent)) {
      ++check.degenerate_faces;
    }
    six_volume += a.dot(b.cross(c));
    for (int k = 0; k < 3; ++k) {
      const std::int32_t u = f[k], v = f[(k + 1) % 3];
      if (u == v) continue;
      edges.push_back({std::min(u, v), std::max(u, v), u < v});
    }
  }
  check.signed_volume = six_volume / 6.0;
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i, forward = 0;
    while (j < edges.size() && edges[j].low == edges[i].low && edges[j].high == edges[i].high) {
      if (edges[j].forward) ++forward;
      ++j;
    }
    const std::size_t uses = j - i;
    if (uses == 1) {
      ++check.boundary_edges;
    } else if (uses > 2) {
      ++check.non_manifold_edges;
    } else if (forward != 1) {
      ++check.misoriented_edges;
    }
    i = j;
  }
  return check;
}

std::vector<std::string> MeshCheck::Problems() const {
  std::vector<std::string> problems;
  auto add = [&problems](std::size_t count, const char* what) {
    if (count > 0) problems.push_back(fmt::format("{} {}", count, what));
  };
  add(non_finite_vertices, "vertices with non-finite coordinates");
  add(out_of_range_faces, "faces referring to missing vertices");
  add(degenerate_faces, "degenerate faces (repeated vertex or zero area)");
  add(boundary_edges, "boundary edges (the mesh is not closed)");
  add(non_manifold_edges, "edges shared by more than two faces");
  add(misoriented_edges, "edges whose faces are not consistently oriented");
  if (face_count == 0) problems.push_back("no faces");
  if (closed() && consistently_oriented() && face_count > 0 && !(signed_volume > 0.0)) {
    problems.push_back("faces point inward (negative volume)");
  }
  return problems;
}

}  // namespace mechanist
