#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/assembly_report.h"
#include "io/feature_report.h"
#include "io/info_report.h"
#include "io/input_error.h"
#include "io/mesh_reader.h"
#include "io/step_reader.h"
#include "kernel/features/feature_recognition.h"
#include "kernel/support/ascii_lower.h"

namespace mechanist::cli {

// A mesh file alone, or every mesh part of an assembly (or STEP) file.
Command FeaturesCommand() {
  static constexpr const char* kInputs =
      "a mesh (.stl, .obj, .ply, .off), an assembly (.json) or a STEP file (.step, .stp)";
  auto json = std::make_shared<std::string>();
  Command c;
  c.name = "features";
  c.help = "Recognise the features of a mesh, or of an assembly's mesh parts";
  c.file_help = kInputs;
  c.input = Input::kNone;
  c.options = {
      Option("--json", json.get(), "write the JSON report to this file").Output(),
  };
  c.run = [json](Session& s) {
    const std::string extension = AsciiLower(std::filesystem::path(s.file).extension().string());
    std::vector<FeatureReportEntry> entries;
    if (extension == ".json" || IsStepFile(s.file)) {
      const Assembly assembly = ReadInput(s.file);
      entries = RecogniseAssemblyFeatures(assembly);
      WriteFeatureReport(entries, std::cout);
      WriteSkippedParts(assembly, std::cout);
      // What the reading found; the ground it chose is the analysis' business.
      std::vector<Diagnostic> findings = assembly.findings();
      std::erase_if(findings, [](const Diagnostic& d) { return d.code == "ground_chosen"; });
      WriteDiagnostics(findings, std::cout);
    } else {
      if (extension != ".stl" && extension != ".obj" && extension != ".ply" &&
          extension != ".off") {
        throw InputError(
            s.file, "", 0, 0,
            fmt::format("expected {}; found {}", kInputs,
                        extension.empty() ? "no extension" : "the extension '" + extension + "'"));
      }
      TriangleMesh mesh;
      WithinReadTimeout(s.file, [&] { mesh = ReadMesh(s.file); });
      entries.push_back({std::filesystem::path(s.file).filename().string(), RigidTransform(),
                         RecognizeFeatures(mesh), true});
      WriteFeatureReport(entries, std::cout);
    }
    if (!json->empty()) s.Report(*json, FeatureJson(entries));
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
