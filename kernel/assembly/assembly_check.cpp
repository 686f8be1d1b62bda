#include "kernel/assembly/assembly_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "kernel/mesh/mesh_check.h"
#include "kernel/support/number_format.h"

namespace mechanist {

namespace {

// A mesh's problem as a finding, without the part.
struct MeshProblem {
  Severity severity = Severity::kWarning;
  const char* code = "";
  std::string message;
};

// `tessellated`: the mesh is Open CASCADE's tessellation of a STEP solid, not the designer's.
// Its zero-area faces and edges of more than two faces (a sphere's poles, faces meeting at a
// point) change no result and are not in the file: not said at all.
std::vector<MeshProblem> MeshProblems(const MeshCheck& check, bool tessellated) {
  std::vector<MeshProblem> problems;
  if (check.non_finite_vertices > 0 || check.out_of_range_faces > 0 || check.face_count == 0) {
    problems.push_back({Severity::kWarning, "mesh_invalid",
                        fmt::format("mesh has invalid elements: {}", check.Problems().front())});
  }
  if (!check.closed() && check.boundary_edges == 0) {
    // Watertight all the same: nothing for the designer to do. Tessellators leave such edges
    // at a sphere's poles, and shells exported as one mesh share them; interference decides
    // inside and outside by winding number.
    if (!tessellated) {
      problems.push_back(
          {Severity::kInfo, "mesh_non_manifold",
           fmt::format("mesh is watertight, but {} edges are shared by more than two faces "
                       "(inside and outside are decided by winding number)",
                       check.non_manifold_edges)});
    }
  } else if (!check.closed() && tessellated) {
    // Open CASCADE meshed a STEP solid's faces so that they do not meet along every edge:
    // nothing for the designer to do.
    problems.push_back({Severity::kInfo, "tessellation_open",
                        fmt::format("the tessellation of the STEP solid leaves {} boundary edges "
                                    "and {} edges shared by more than two faces (its faces' "
                                    "meshes do not meet along every edge; inside and outside are "
                                    "decided by winding number)",
                                    check.boundary_edges, check.non_manifold_edges)});
  } else if (!check.closed()) {
    problems.push_back({Severity::kWarning, "mesh_not_closed",
                        fmt::format("mesh is not closed ({} boundary edges, {} edges shared by "
                                    "more than two faces)",
                                    check.boundary_edges, check.non_manifold_edges)});
  }
  if (!check.consistently_oriented()) {
    problems.push_back({Severity::kWarning, "mesh_misoriented",
                        fmt::format("mesh faces are not consistently oriented ({} edges)",
                                    check.misoriented_edges)});
  }
  if (check.closed() && check.consistently_oriented() && check.face_count > 0 &&
      !(check.signed_volume > 0)) {
    problems.push_back(
        {Severity::kWarning, "mesh_inward", "mesh faces point inward (negative volume)"});
  }
  if (check.degenerate_faces > 0 && !tessellated) {
    // Zero-area faces (a tessellator's at a sphere's poles) bound nothing and touch nothing:
    // said, not warned.
    problems.push_back({Severity::kInfo, "mesh_degenerate_faces",
                        fmt::format("mesh has {} degenerate (zero-area) faces, which bound nothing",
                                    check.degenerate_faces)});
  }
  return problems;
}

// "part 'a'", or "parts 'a', 'b' and 'c'".
std::string PartNames(const std::vector<std::string>& parts) {
  std::string who = parts.size() == 1 ? "part '" : "parts '";
  for (std::size_t k = 0; k < parts.size(); ++k) {
    who += (k == 0 ? "" : k + 1 == parts.size() ? "' and '" : "', '") + parts[k];
  }
  return who + "'";
}

}  // namespace

std::vector<Diagnostic> CheckAssembly(const Assembly& assembly) {
  std::vector<Diagnostic> out = assembly.findings();
  // Each distinct mesh checked once (instances share one; a features-only part has none), and
  // each problem said once for all the parts that have it alike (the nine balls of a bearing).
  std::map<const TriangleMesh*, std::vector<MeshProblem>> problems;
  std::vector<MeshProblem> order;  // as first found, parts in order
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> parts_with;
  for (const Part& part : assembly.parts()) {
    if (!part.HasGeometry()) continue;
    auto [found, added] = problems.try_emplace(part.mesh.get());
    if (added) found->second = MeshProblems(CheckMesh(*part.mesh), part.tessellated);
    for (const MeshProblem& problem : found->second) {
      std::vector<std::string>& parts = parts_with[{problem.code, problem.message}];
      if (parts.empty()) order.push_back(problem);
      parts.push_back(part.id);
    }
  }
  for (const MeshProblem& problem : order) {
    std::vector<std::string>& parts = parts_with[{problem.code, problem.message}];
    std::sort(parts.begin(), parts.end());
    out.push_back({problem.severity,
                   problem.code,
                   fmt::format("{}: {}", PartNames(parts), problem.message),
                   parts,
                   {}});
  }
  for (std::size_t i = 0; i < assembly.parts().size(); ++i) {
    const Part& part = assembly.part(i);
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
                       fmt::format("feature '{}/{}' has its origin {} mm outside the part's mesh "
                                   "box (unit or frame mistake?)",
                                   part.id, f.id, FormatNumber(outside.norm())),
                       {part.id},
                       {fmt::format("{}/{}", part.id, f.id)}});
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
