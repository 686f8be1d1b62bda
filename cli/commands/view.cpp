#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "cli/commands.h"
#include "io/input_error.h"
#include "viz/viewer_page.h"

namespace mechanist::cli {

// One self-contained HTML page to look at and work the mechanism in a browser.
Command ViewCommand() {
  struct Options {
    std::string out;
    bool ranges = false, no_ranges = false;
    bool plan = false, no_plan = false;
    double gaps = 0;  // voxel, file units; 0: none
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "view";
  c.help = "Write an interactive 3D viewer of the mechanism: one HTML file, opens offline";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = {
      Option("--out", &o->out, "the HTML file (default: FILE's name with .html, here)").Output(),
      Option("--ranges", &o->ranges,
             "search where each drag stops even above 100,000 triangles (slow)"),
      Option("--no-ranges", &o->no_ranges, "do not search where each drag stops")
          .Excludes("--ranges"),
      Option("--plan", &o->plan, "plan the assembly sequence even above 100,000 triangles (slow)"),
      Option("--no-plan", &o->no_plan, "do not plan the assembly sequence").Excludes("--plan"),
      Option("--gaps", &o->gaps, "show the enclosed gaps found at this voxel size (file units)")
          .Bounded(Bound::kPositive),
  };
  c.run = [o](Session& s) {
    const std::string path =
        o->out.empty() ? fmt::format("{}.html", std::filesystem::path(s.file).stem().string())
                       : o->out;
    // The swept checks of every drag and of every insertion take long on a large real file
    // (the Onshape robot hand, 279,525 triangles: its drags' ranges 22 s): above
    // kMaxSweptTriangles they run only when asked.
    constexpr std::size_t kMaxSweptTriangles = 100000;
    std::size_t triangles = 0;
    for (const Part& part : s.assembly->parts()) {
      if (part.HasGeometry()) triangles += part.mesh->faces.size();
    }
    ViewerOptions options;
    options.ranges = o->ranges || (!o->no_ranges && triangles <= kMaxSweptTriangles);
    options.plan = o->plan || (!o->no_plan && triangles <= kMaxSweptTriangles);
    options.gap_voxel = o->gaps * s.assembly->units().mm_per_length;
    options.plan_progress = Progress("assembly sequence");
    options.range_progress = Progress("movable ranges");
    if (!options.ranges && !o->no_ranges) {
      std::cout << "movable ranges not searched: " << triangles
                << " triangles, more than 100,000 (--ranges searches them)\n";
    }
    if (!options.plan && !o->no_plan) {
      std::cout << "assembly sequence not planned: " << triangles
                << " triangles, more than 100,000 (--plan plans it)\n";
    }
    try {
      s.Report(path, ViewerHtml(*s.assembly, *s.analysis, options));
    } catch (const std::invalid_argument& e) {  // the gap search refuses the voxel
      throw InputError(s.file, "", 0, 0, fmt::format("--gaps: {}", e.what()));
    }
    std::cout << "viewer: " << std::filesystem::absolute(path).string()
              << " (open it in a browser)\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
