#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "viz/viewer_page.h"

namespace mechanist::cli {

// One self-contained HTML page to look at and work the mechanism in a browser.
Command ViewCommand() {
  auto out = std::make_shared<std::string>();
  Command c;
  c.name = "view";
  c.help = "Write an interactive 3D viewer of the mechanism: one HTML file, opens offline";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = [out](CLI::App& app) {
    app.add_option("--out", *out, "the HTML file (default: FILE's name with .html, here)");
  };
  c.run = [out](Session& s) {
    const std::string path =
        out->empty() ? std::filesystem::path(s.file).stem().string() + ".html" : *out;
    s.Report(path, ViewerHtml(*s.assembly, *s.analysis));
    std::cout << "viewer: " << std::filesystem::absolute(path).string()
              << " (open it in a browser)\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
