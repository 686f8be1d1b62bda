#include "kernel/assembly_check.h"

#include <algorithm>
#include <map>
#include <string>

#include "kernel/mesh_check.h"
#include "kernel/number_format.h"

namespace mechanist {

namespace {

void AddMeshDiagnostics(const Part& part, const MeshCheck& check, std::vector<Diagnostic>& out) {
  auto add = [&](const char* code, const std::string& message) {
    out.push_back({Severity::kWarning, code, "part '" + part.id + "': " + message, {part.id}, {}});
  };
  if (check.non_finite_vertices > 0 || check.out_of_range_faces > 0 || check.face_count == 0) {
    add("mesh_invalid", "mesh has invalid elements: " + check.Problems().front());
  }
  if (!check.closed()) {
    add("mesh_not_closed", "mesh is not closed (" + std::to_string(check.boundary_edges) +
                               " boundary edges, " + std::to_string(check.non_manifold_edges) +
                               " edges shared by more than two faces)");
  }
  if (!check.consistently_oriented()) {
    add("mesh_misoriented", "mesh faces are not consistently oriented (" +
                                std::to_string(check.misoriented_edges) + " edges)");
  }
  if (check.closed() && check.consistently_oriented() && check.face_count > 0 &&
      !(check.signed_volume > 0)) {
    add("mesh_inward", "mesh faces point inward (negative volume)");
  }
  if (check.degenerate_faces > 0) {
    add("mesh_degenerate_faces",
        "mesh has " + std::to_string(check.degenerate_faces) + " degenerate faces");
  }
}

}  // namespace

std::vector<Diagnostic> CheckAssembly(const Assembly& assembly) {
  std::vector<Diagnostic> out = assembly.findings();
  std::map<const TriangleMesh*, MeshCheck> checked;  // instances share one mesh
  for (std::size_t i = 0; i < assembly.parts().size(); ++i) {
    const Part& part = assembly.part(i);
    if (part.HasGeometry()) {  // a features-only part has no mesh to check
      auto it = checked.find(part.mesh.get());
      if (it == checked.end()) it = checked.emplace(part.mesh.get(), CheckMesh(*part.mesh)).first;
      AddMeshDiagnostics(part, it->second, out);
    }

    const Aabb& box = assembly.MeshBox(i);
    const double margin = std::max(1.0, box.size().norm());
    // Origins from the compact table: the Features themselves are read only to name one.
    for (std::size_t k = 0; k < assembly.FeatureCount(i); ++k) {
      const Eigen::Vector3d& origin = assembly.FeatureOrigin({i, k});
      const Eigen::Vector3d outside = (box.min - origin).cwiseMax(origin - box.max).cwiseMax(0.0);
      if (!box.empty() && outside.norm() > margin) {
        const Feature& f = part.features[k];
        out.push_back({Severity::kWarning,
                       "feature_outside_part",
                       "feature '" + part.id + "/" + f.id + "' has its origin " +
                           FormatNumber(outside.norm()) +
                           " mm outside the part's mesh box (unit or frame mistake?)",
                       {part.id},
                       {part.id + "/" + f.id}});
      }
    }
  }
  return out;
}

std::vector<std::size_t> PartsWithoutGeometry(const Assembly& assembly) {
  std::vector<std::size_t> parts;
  for (std::size_t i = 0; i < assembly.parts().size(); ++i) {
    if (!assembly.part(i).HasGeometry()) parts.push_back(i);
  }
  std::sort(parts.begin(), parts.end(), [&](std::size_t a, std::size_t b) {
    return assembly.PartRank(a) < assembly.PartRank(b);
  });
  return parts;
}

}  // namespace mechanist
