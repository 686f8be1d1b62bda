#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "viz/viewer_page.h"

namespace mechanist::cli {

// One self-contained HTML page to look at and work the mechanism in a browser.
Command ViewCommand() {
  struct Options {
    std::string out;
    bool no_ranges = false;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "view";
  c.help = "Write an interactive 3D viewer of the mechanism: one HTML file, opens offline";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = [o](CLI::App& app) {
    app.add_option("--out", o->out, "the HTML file (default: FILE's name with .html, here)");
    app.add_flag("--no-ranges", o->no_ranges,
                 "skip the swept check for where each drag stops (faster on large files)");
  };
  c.run = [o](Session& s) {
    const std::string path =
        o->out.empty() ? std::filesystem::path(s.file).stem().string() + ".html" : o->out;
    ViewerOptions options;
    options.ranges = !o->no_ranges;
    s.Report(path, ViewerHtml(*s.assembly, *s.analysis, options));
    std::cout << "viewer: " << std::filesystem::absolute(path).string()
              << " (open it in a browser)\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
