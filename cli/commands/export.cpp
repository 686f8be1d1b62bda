#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

#include "cli/commands.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/mjcf_writer.h"
#include "io/stl_writer.h"
#include "io/urdf_writer.h"
#include "reasoning/simulation_model.h"

namespace mechanist::cli {

// Writes the simulator model as URDF and/or MJCF, each with its meshes in a folder beside it
// (FILE_meshes/, one binary STL in metres per mesh source).
Command ExportCommand() {
  struct Options {
    std::string urdf, mjcf;
    double density = 7850;
    bool drive = false, no_limits = false;
  };
  auto o = std::make_shared<Options>();
  Command c;
  c.name = "export";
  c.help = "Write the mechanism for simulators: URDF and MJCF with joints and couplings";
  c.input = Input::kAdjusted;
  c.analysis = true;
  c.options = {
      Option("--urdf", &o->urdf, "write URDF to this file (meshes beside it)"),
      Option("--mjcf", &o->mjcf, "write MuJoCo MJCF to this file (meshes beside it)"),
      Option("--density", &o->density, "kg/m^3 of every part (default 7850, steel)"),
      Option("--drive", &o->drive, "MJCF: a keyframe at the file pose with the drivers running"),
      Option("--no-limits", &o->no_limits,
             "skip the swept check for joint ranges (faster on large files)"),
  };
  c.check = [o](const std::string& file) {
    if (o->urdf.empty() && o->mjcf.empty()) {
      throw InputError(file, "", 0, 0, "export: expected --urdf or --mjcf, found neither");
    }
    if (!(o->density > 0) || !std::isfinite(o->density)) {
      throw InputError(file, "", 0, 0, "--density: expected kg/m^3 > 0");
    }
  };
  c.run = [o](Session& s) {
    const Assembly& assembly = *s.assembly;
    const Analysis& analysis = *s.analysis;
    const bool limits = !o->no_limits;
    SimulationOptions options;
    options.density = o->density;
    std::optional<CollisionModel> collision;
    if (limits) options.collision = &collision.emplace(assembly);
    options.progress = Progress("movable ranges");
    const SimulationModel model = BuildSimulationModel(assembly, analysis, options);
    std::vector<std::string> written;
    std::set<std::filesystem::path> mesh_folders;  // written already (URDF and MJCF side by side)
    auto write_meshes = [&](const std::filesystem::path& out) {
      const std::string folder = fmt::format("{}_meshes", out.stem().string());
      const std::filesystem::path path = out.parent_path() / folder;
      if (!mesh_folders.insert(path).second) return folder;
      std::error_code error;
      std::filesystem::create_directories(path, error);
      if (error) {
        throw InputError(path.string(), "", 0, 0,
                         fmt::format("cannot create the mesh folder: {}", error.message()));
      }
      for (const SimMesh& m : model.meshes) {
        WriteFileAtomically(path / fmt::format("{}.stl", m.name), BinaryStl(*m.mesh, 1e-3), s.file);
      }
      written.push_back(fmt::format("{}/ ({} meshes)", path.string(), model.meshes.size()));
      return folder;
    };
    if (!o->urdf.empty()) {
      const std::string folder = write_meshes(o->urdf);
      WriteFileAtomically(o->urdf, UrdfText(assembly, analysis, model, folder), s.file);
      written.push_back(o->urdf);
    }
    if (!o->mjcf.empty()) {
      MjcfOptions mjcf_options;
      mjcf_options.mesh_dir = write_meshes(o->mjcf);
      mjcf_options.drive = o->drive;
      WriteFileAtomically(o->mjcf, MjcfText(assembly, analysis, model, mjcf_options), s.file);
      written.push_back(o->mjcf);
    }
    std::size_t limited = 0;
    for (const auto& j : model.joints) limited += j.lower || j.upper;
    std::size_t actuated = 0;
    for (const auto& a : model.actuators) actuated += !a.terms.empty();
    std::size_t closed = 0;
    for (const auto& l : model.loops) closed += !l.anchors_W.empty();
    std::cout << "links: " << model.links.size() << " (root " << model.links.front().name << ")\n"
              << "joints: " << model.joints.size() << " ("
              << (limits ? fmt::format("{} stopped by a contact in the swept check", limited)
                         : std::string("movable ranges not searched: --no-limits"))
              << ")\n"
              << "couplings: " << model.couplings.size() << "\n"
              << "loops cut (URDF cannot close them): " << model.loops.size() << " (" << closed
              << " closed by MJCF equalities)\n"
              << "actuators: " << actuated << " of " << model.actuators.size() << " drivers\n";
    for (const SimLoop& loop : model.loops) {
      const Pair& p = analysis.pairs[loop.pair];
      std::cout << "  loop cut at the " << ToString(p.type) << " pair " << assembly.FeatureName(p.a)
                << " + " << assembly.FeatureName(p.b)
                << (loop.anchors_W.empty() ? ": open in MJCF too (no equality for it)"
                                           : ": closed in MJCF by <connect>")
                << "\n";
    }
    for (const std::string& note : model.notes) std::cout << "note: " << note << "\n";
    for (const std::string& w : written) std::cout << "wrote " << w << "\n";
    return kExitOk;
  };
  return c;
}

}  // namespace mechanist::cli
