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

// A mesh's problems as (code, message) findings, without the part.
std::vector<std::pair<const char*, std::string>> MeshProblems(const MeshCheck& check) {
  std::vector<std::pair<const char*, std::string>> problems;
  if (check.non_finite_vertices > 0 || check.out_of_range_faces > 0 || check.face_count == 0) {
    problems.emplace_back("mesh_invalid",
                          fmt::format("mesh has invalid elements: {}", check.Problems().front()));
  }
  if (!check.closed()) {
    problems.emplace_back("mesh_not_closed",
                          fmt::format("mesh is not closed ({} boundary edges, {} edges shared by "
                                      "more than two faces)",
                                      check.boundary_edges, check.non_manifold_edges));
  }
  if (!check.consistently_oriented()) {
    problems.emplace_back("mesh_misoriented",
                          fmt::format("mesh faces are not consistently oriented ({} edges)",
                                      check.misoriented_edges));
  }
  if (check.closed() && check.consistently_oriented() && check.face_count > 0 &&
      !(check.signed_volume > 0)) {
    problems.emplace_back("mesh_inward", "mesh faces point inward (negative volume)");
  }
  if (check.degenerate_faces > 0) {
    problems.emplace_back("mesh_degenerate_faces",
                          fmt::format("mesh has {} degenerate faces", check.degenerate_faces));
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
  std::map<const TriangleMesh*, std::vector<std::pair<const char*, std::string>>> problems;
  std::vector<std::pair<const char*, std::string>> order;  // as first found, parts in order
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> parts_with;
  for (const Part& part : assembly.parts()) {
    if (!part.HasGeometry()) continue;
    auto [found, added] = problems.try_emplace(part.mesh.get());
    if (added) found->second = MeshProblems(CheckMesh(*part.mesh));
    for (const auto& [code, message] : found->second) {
      std::vector<std::string>& parts = parts_with[{code, message}];
      if (parts.empty()) order.emplace_back(code, message);
      parts.push_back(part.id);
    }
  }
  for (const auto& [code, message] : order) {
    std::vector<std::string>& parts = parts_with[{code, message}];
    std::sort(parts.begin(), parts.end());
    out.push_back(
        {Severity::kWarning, code, fmt::format("{}: {}", PartNames(parts), message), parts, {}});
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
