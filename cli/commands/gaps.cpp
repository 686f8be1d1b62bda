#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "cli/commands.h"
#include "io/gap_report.h"
#include "io/input_error.h"
#include "reasoning/gap_search.h"
#include "viz/gap_volume_writer.h"

namespace mechanist::cli {

Command GapsCommand() {
  struct Options {
    double voxel = 0;
    std::string json, vtk;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "gaps";
  c.help = "Find the empty spaces enclosed between parts, with their volumes";
  c.options = {
      Option("--voxel", &o->voxel, "voxel edge, in the file's length units (mm for a STEP file)")
          .Required(),
      Option("--json", &o->json, "write the JSON report to this file").Output(),
      Option("--vtk", &o->vtk, "write the voxels as a VTK image (.vti) to this file").Output(),
  };
  c.run = [o](Session& s) {
    const Assembly& assembly = *s.assembly;
    if (!(o->voxel > 0) || !std::isfinite(o->voxel)) {
      throw InputError(s.file, "", 0, 0, "--voxel: expected a length > 0");
    }
    GapSearchOptions options;
    options.voxel = o->voxel * assembly.units().mm_per_length;
    options.progress = Progress("decomposing");
    GapSearch search;
    try {
      search = FindGaps(assembly, options);
    } catch (const std::invalid_argument& e) {
      throw InputError(s.file, "", 0, 0, fmt::format("--voxel: {}", e.what()));
    }
    WriteGapSummary(assembly, search, std::cout);
    // The volume may be too large to hold as text: it streams into its file here.
    if (!o->vtk.empty()) WriteGapVolume(o->vtk, search, s.file);
    if (!o->json.empty()) s.Report(o->json, GapJson(assembly, search));
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
