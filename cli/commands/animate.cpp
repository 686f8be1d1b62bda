#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <stdexcept>

#include "cli/commands.h"
#include "io/input_error.h"
#include "viz/animation_output.h"
#include "viz/display.h"
#include "viz/video_writer.h"

namespace mechanist::cli {

Command AnimateCommand() {
  struct Options {
    std::string out;
    std::size_t frames = 120;
    double amount = -1;  // -1: the driver's own amount
    std::string size = "800x600";
    std::vector<std::string> formats;
    std::string view = "iso";
    std::string driver;
    double fps = 30;
    double gaps = 0;  // voxel, file units; 0: no gaps
    bool no_clashes = false, no_axes = false;
    // Set by `check`:
    std::set<std::string> chosen;
    int width = 0, height = 0;
    View parsed_view = View::kIso;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "animate";
  c.help = "Run the mechanism and write PNG frames, videos, a ParaView series and glTF";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = {
      Option("--out", &o->out, "output folder (created)").Required(),
      Option("--frames", &o->frames, "number of frames (default 120)"),
      Option("--amount", &o->amount,
             "how far: driver revolutions or length units (default: the driver's amount)")
          .Bounded(Bound::kNonNegative),
      Option("--size", &o->size, "image size WIDTHxHEIGHT (default 800x600)"),
      Option("--format", &o->formats,
             "png,ogv,mp4,pvd,glb (default: all; mp4 only when ffmpeg is installed)")
          .Delimiter(','),
      Option("--view", &o->view, "iso, front, top or side (default iso)"),
      Option("--driver", &o->driver, "run only this driver (default: all at their rates)"),
      Option("--fps", &o->fps, "video and glTF frames per second (default 30)"),
      Option("--gaps", &o->gaps, "show the enclosed gaps found at this voxel size (file units)"),
      Option("--no-clashes", &o->no_clashes, "skip the clash checks (no red parts)"),
      Option("--no-axes", &o->no_axes, "do not draw feature axes"),
  };
  // The options are checked before the file is read and its adjustments solved.
  c.check = [o](const std::string& file) {
    auto usage = [&](const std::string& message) { return InputError(file, "", 0, 0, message); };
    const std::set<std::string> known = {"png", "ogv", "mp4", "pvd", "glb"};
    o->chosen = std::set<std::string>(o->formats.begin(), o->formats.end());
    for (const std::string& f : o->chosen) {
      if (!known.count(f)) {
        throw usage(fmt::format("--format: expected png, ogv, mp4, pvd or glb, found \"{}\"", f));
      }
    }
    if (o->chosen.empty()) {
      o->chosen = {"png", "ogv", "pvd", "glb"};
      if (FfmpegAvailable()) o->chosen.insert("mp4");
    } else if (o->chosen.count("mp4") && !FfmpegAvailable()) {
      throw usage("--format mp4: needs the ffmpeg program (Debian package ffmpeg), not found");
    }
    char tail = 0;
    if (std::sscanf(o->size.c_str(), "%dx%d%c", &o->width, &o->height, &tail) != 2 ||
        o->width < 16 || o->height < 16 || o->width > 8192 || o->height > 8192) {
      throw usage(fmt::format("--size: expected WIDTHxHEIGHT, 16 to 8192 pixels each, found \"{}\"",
                              o->size));
    }
    const auto view = ParseView(o->view);
    if (!view) {
      throw usage(fmt::format("--view: expected iso, front, top or side, found \"{}\"", o->view));
    }
    o->parsed_view = *view;
    if (o->frames < 1 || o->frames > 100000) throw usage("--frames: expected 1 to 100000");
    if (!(o->fps > 0) || o->fps > 240) throw usage("--fps: expected a rate in (0, 240]");
    if (o->gaps < 0 || !std::isfinite(o->gaps)) throw usage("--gaps: expected a voxel length > 0");
    if (o->amount < 0 && o->amount != -1) throw usage("--amount: expected a number >= 0");
    const bool render = o->chosen.count("png") || o->chosen.count("ogv") || o->chosen.count("mp4");
    std::string no_display;
    if (render && !DisplayAvailable(&no_display)) {
      throw usage(
          fmt::format("--format {}: {}", o->chosen.count("png") ? "png" : "ogv/mp4", no_display));
    }
  };
  c.run = [o](Session& s) {
    const Assembly& assembly = *s.assembly;
    AnimationRequest request;
    request.out = o->out;
    request.formats = o->chosen;
    request.frames = o->frames;
    request.driver = DriverIndex(s.file, assembly, o->driver);
    if (o->amount >= 0) request.amount = o->amount;
    request.render.width = o->width;
    request.render.height = o->height;
    request.render.view = o->parsed_view;
    request.render.feature_axes = !o->no_axes;
    if (assembly.name().empty())
      request.render.title = std::filesystem::path(s.file).stem().string();
    request.fps = o->fps;
    request.gap_voxel = o->gaps * assembly.units().mm_per_length;
    request.clashes = !o->no_clashes;
    request.protect = s.file;
    request.progress = [decomposing = Progress("decomposing"), rendering = Progress("rendering")](
                           const char* stage, double fraction) {
      const auto& report = std::string(stage) == "rendering" ? rendering : decomposing;
      if (report) report(fraction);
    };
    AnimationOutcome outcome;
    try {
      outcome = WriteAnimation(assembly, *s.analysis, request);
    } catch (const std::invalid_argument& e) {
      throw InputError(s.file, "", 0, 0, fmt::format("--gaps: {}", e.what()));
    }
    const MotionRun& run = outcome.run;
    if (!run.possible) std::cerr << "mechanist: note: nothing moves: " << run.reason << "\n";
    if (outcome.gaps) {
      std::cout << "gaps: " << *outcome.gaps << " at voxel " << o->gaps << " "
                << assembly.units().length << "\n";
    }
    if (outcome.render_seconds) {
      std::cout << "rendered " << outcome.frames << " frames at " << o->width << "x" << o->height
                << " in " << std::fixed << std::setprecision(1) << *outcome.render_seconds << " s\n"
                << std::defaultfloat;
    }
    std::cout << "animation: " << outcome.frames << " frames, "
              << (run.driver ? fmt::format("driver {}", assembly.drivers()[*run.driver].id)
                             : "all drivers")
              << " over " << run.amount << "\n";
    if (outcome.clashing_parts > 0) {
      std::cout << "parts in a clash (red): " << outcome.clashing_parts << "\n";
    }
    for (const std::string& w : outcome.written) std::cout << "wrote " << w << "\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
