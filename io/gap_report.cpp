#include "io/gap_report.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "io/assembly_report.h"
#include "kernel/assembly/assembly_check.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

using Json = nlohmann::ordered_json;

// 9 significant digits, as in the other reports: no rounding noise, byte-identical output.
double Num(double x) { return RoundToSignificant(x); }

Json Point(const Eigen::Vector3d& p) { return Json::array({Num(p.x()), Num(p.y()), Num(p.z())}); }

std::string Text(const Eigen::Vector3d& p) {
  return fmt::format("({}, {}, {})", FormatNumber(p.x()), FormatNumber(p.y()), FormatNumber(p.z()));
}

std::string PartList(const Assembly& assembly, const std::vector<std::size_t>& parts) {
  std::string s;
  for (const std::size_t p : parts) s += (s.empty() ? "" : ", ") + assembly.part(p).id;
  return s.empty() ? "none" : s;
}

}  // namespace

void WriteGapSummary(const Assembly& assembly, const GapSearch& search, std::ostream& out) {
  const OccupancyOctree& tree = *search.octree;
  const auto& n = tree.extent();
  out << "gaps: " << search.gaps.size() << " enclosed gap" << (search.gaps.size() == 1 ? "" : "s")
      << " at voxel " << FormatNumber(search.voxel) << " mm (grid " << n[0] << " x " << n[1]
      << " x " << n[2] << ", " << tree.leaf_count() << " octree cells)\n";
  WriteSkippedParts(assembly, out);
  // Thin gaps (free octants only) enclosed by the same parts are often one narrow space that
  // the grid cuts where it is thinner than a voxel: a finer voxel tells.
  std::map<std::vector<std::size_t>, int> thin;
  for (const Gap& gap : search.gaps) {
    if (gap.voxels == 0) ++thin[gap.parts];
  }
  for (const auto& [parts, count] : thin) {
    if (count < 2) continue;
    out << "  note: " << count << " gaps 1 to 2 voxels thick enclosed by "
        << PartList(assembly, parts)
        << ": one narrow space may be cut into pieces where it is thinner than a voxel; --voxel "
        << FormatNumber(search.voxel / 2) << " tells\n";
  }
  for (std::size_t g = 0; g < search.gaps.size(); ++g) {
    const Gap& gap = search.gaps[g];
    out << "  gap " << g + 1 << ": " << FormatNumber(gap.volume) << " +/- "
        << FormatNumber(gap.volume_error) << " mm^3 in " << Text(gap.box_W.min) << " - "
        << Text(gap.box_W.max) << ", enclosed by " << PartList(assembly, gap.parts)
        << "; closest to the outside at " << Text(gap.p_gap_W) << ", " << FormatNumber(gap.wall)
        << " mm from " << Text(gap.p_outside_W) << "\n";
  }
}

std::string GapJson(const Assembly& assembly, const GapSearch& search) {
  const OccupancyOctree& tree = *search.octree;
  Json report;
  report["assembly"] = assembly.name();
  Json skipped = Json::array();
  for (const std::size_t p : PartsWithoutGeometry(assembly)) skipped.push_back(assembly.PartId(p));
  report["skipped"] = skipped;
  report["voxel"] = Num(search.voxel);
  report["grid"] = Json::array({tree.extent()[0], tree.extent()[1], tree.extent()[2]});
  report["cells"] = tree.leaf_count();
  report["memory_bytes"] = tree.MemoryBytes();
  Json gaps = Json::array();
  for (std::size_t g = 0; g < search.gaps.size(); ++g) {
    const Gap& gap = search.gaps[g];
    Json parts = Json::array();
    for (const std::size_t p : gap.parts) parts.push_back(assembly.part(p).id);
    gaps.push_back({{"id", g + 1},
                    {"volume", Num(gap.volume)},
                    {"volume_error", Num(gap.volume_error)},
                    {"voxels", gap.voxels},
                    {"boundary_voxels", gap.boundary_voxels},
                    {"box", {{"min", Point(gap.box_W.min)}, {"max", Point(gap.box_W.max)}}},
                    {"parts", parts},
                    {"closest_to_outside",
                     {{"gap_point", Point(gap.p_gap_W)},
                      {"outside_point", Point(gap.p_outside_W)},
                      {"distance", Num(gap.wall)}}}});
  }
  report["gaps"] = gaps;
  return report.dump(2) + "\n";
}

}  // namespace mechanist
