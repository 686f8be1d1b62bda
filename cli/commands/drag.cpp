#include "reasoning/drag.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "io/analysis_report.h"
#include "io/input_error.h"
#include "kernel/support/ascii_lower.h"
#include "kernel/support/few_names.h"

namespace mechanist::cli {
namespace {

// What a user who typed `text` may have meant, for an error message: the `ids` that contain
// it (in any case), else all of them, shortened (FewNames).
std::string Candidates(const std::vector<std::string>& ids, const std::string& text,
                       const std::string& what) {
  std::vector<std::string> containing;
  for (const std::string& id : ids) {
    if (AsciiLower(id).find(AsciiLower(text)) != std::string::npos) containing.push_back(id);
  }
  if (!containing.empty()) {
    return fmt::format("; {} whose id contains it: {}", what, FewNames(containing));
  }
  return ids.empty() ? fmt::format("; there are no {}", what)
                     : fmt::format("; the {} are: {}", what, FewNames(ids));
}

}  // namespace

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
             "the feature whose axis to use (default: its first in a pair with another "
             "subassembly, else its subassembly's, the first that can move)"),
      Option("--rotate", &o->rotate, "turn about the axis (default)"),
      Option("--translate", &o->translate, "push along the axis").Excludes("--rotate"),
  };
  c.run = [o](Session& s) {
    const Assembly& assembly = *s.assembly;
    const auto index = assembly.FindPart(o->part);
    if (!index) {
      std::vector<std::string> ids;
      for (const Part& p : assembly.parts()) ids.push_back(p.id);
      throw InputError(s.file, "", 0, 0,
                       fmt::format("--part: expected a part id, found \"{}\"{}", o->part,
                                   Candidates(ids, o->part, "parts")));
    }
    DragRequest request;
    request.part = *index;
    request.rotate = !o->translate;
    if (!o->feature.empty()) {
      const auto f = assembly.FindFeature(fmt::format("{}/{}", o->part, o->feature));
      if (!f) {
        std::vector<std::string> ids;
        for (const Feature& feature : assembly.part(*index).features) ids.push_back(feature.id);
        throw InputError(s.file, "", 0, 0,
                         fmt::format("--feature: expected a feature of part {}, found \"{}\"{}",
                                     o->part, o->feature, Candidates(ids, o->feature, "features")));
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
