#include "reasoning/drag.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/analysis_report.h"
#include "io/input_error.h"

namespace mechanist::cli {

Command DragCommand() {
  struct Options {
    std::string part, feature;
    bool rotate = false, translate = false;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "drag";
  c.help = "Turn or push one part: what moves with it, and which pair absorbs the motion";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = {
      Option("--part", &o->part, "the part to drag").Required(),
      Option("--feature", &o->feature,
             "the feature whose axis to use (default: its first in a pair)"),
      Option("--rotate", &o->rotate, "turn about the axis (default)"),
      Option("--translate", &o->translate, "push along the axis").Excludes("--rotate"),
  };
  c.run = [o](Session& s) {
    const Assembly& assembly = *s.assembly;
    const auto index = assembly.FindPart(o->part);
    if (!index) {
      throw InputError(s.file, "", 0, 0,
                       fmt::format("--part: expected a part id, found \"{}\"", o->part));
    }
    DragRequest request;
    request.part = *index;
    request.rotate = !o->translate;
    if (!o->feature.empty()) {
      const auto f = assembly.FindFeature(fmt::format("{}/{}", o->part, o->feature));
      if (!f) {
        throw InputError(s.file, "", 0, 0,
                         fmt::format("--feature: expected a feature of part {}, found \"{}\"",
                                     o->part, o->feature));
      }
      request.feature = f->feature;
    }
    const DragResult result = Drag(assembly, *s.analysis, request);
    WriteDragReport(assembly, *s.analysis, result, request.rotate, std::cout);
    return result.motion.possible ? kExitOk : kExitFailures;
  };
  return c;
}

}  // namespace mechanist::cli
