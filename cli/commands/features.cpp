#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "io/feature_report.h"
#include "io/info_report.h"
#include "io/mesh_reader.h"
#include "kernel/features/feature_recognition.h"

namespace mechanist::cli {

// A mesh file alone, or every mesh part of an assembly (or STEP) file.
Command FeaturesCommand() {
  auto json = std::make_shared<std::string>();
  Command c;
  c.name = "features";
  c.help = "Recognise the features of a mesh, or of an assembly's mesh parts";
  c.file_help = "a mesh (.stl, .obj, .ply, .off), an assembly (.json) or a STEP file";
  c.input = Input::kNone;
  c.options = {
      Option("--json", json.get(), "write the JSON report to this file"),
  };
  c.run = [json](Session& s) {
    std::string extension = std::filesystem::path(s.file).extension().string();
    for (char& ch : extension) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    std::vector<FeatureReportEntry> entries;
    if (extension == ".json" || extension == ".step" || extension == ".stp") {
      const Assembly assembly = ReadInput(s.file);
      entries = RecogniseAssemblyFeatures(assembly);
      WriteFeatureReport(entries, std::cout);
      WriteDiagnostics(assembly.findings(), std::cout);
    } else {
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
