// The mechanist command line. Exit codes: 0 success, 1 the check or analysis found failures,
// 2 bad input or usage, 3 internal error.

#include <sys/time.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "io/adjusted_file_writer.h"
#include "io/adjustment_report.h"
#include "io/analysis_report.h"
#include "io/assembly_reader.h"
#include "io/assembly_report.h"
#include "io/atomic_file.h"
#include "io/feature_report.h"
#include "io/gap_report.h"
#include "io/gap_volume_writer.h"
#include "io/gltf_writer.h"
#include "io/info_report.h"
#include "io/input_error.h"
#include "io/mesh_reader.h"
#include "io/mjcf_writer.h"
#include "io/stl_writer.h"
#include "io/urdf_writer.h"
#include "io/vtp_series_writer.h"
#include "kernel/assembly_check.h"
#include "kernel/assembly_state.h"
#include "kernel/collision_model.h"
#include "kernel/number_format.h"
#include "reasoning/adjustment.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"
#include "reasoning/assembly_plan.h"
#include "reasoning/drag.h"
#include "reasoning/expectation_check.h"
#include "reasoning/gap_search.h"
#include "reasoning/motion_run.h"
#include "reasoning/operation_check.h"
#include "reasoning/simulation_model.h"
#include "viz/display.h"
#include "viz/motion_renderer.h"
#include "viz/png_encoder.h"
#include "viz/video_writer.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailures = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

// How long reading one input may take, seconds (--read-timeout); 0: no bound.
double g_read_timeout = 300;
// The message the alarm writes, prepared beforehand: a signal handler may only write and exit.
std::string g_timeout_message;

void OnReadTimeout(int) {
  // No exception can leave Open CASCADE at an arbitrary point safely (it may hold the heap's
  // lock): the process ends here, before any output file is written.
  [[maybe_unused]] const auto written =
      ::write(STDERR_FILENO, g_timeout_message.data(), g_timeout_message.size());
  ::_exit(kExitUsage);
}

// While alive, an alarm ends the process with exit code 2 and a message naming `file` when
// reading takes longer than g_read_timeout: a damaged file can send Open CASCADE's reader
// into an endless loop.
class ReadTimeout {
 public:
  explicit ReadTimeout(const std::string& file) {
    if (!(g_read_timeout > 0)) return;
    g_timeout_message = "mechanist: error: " + file + ": reading it took longer than " +
                        mechanist::FormatNumber(g_read_timeout) +
                        " s (--read-timeout); the file may be damaged\n";
    std::signal(SIGALRM, OnReadTimeout);
    itimerval timer{};
    timer.it_value.tv_sec = static_cast<time_t>(g_read_timeout);
    timer.it_value.tv_usec =
        static_cast<suseconds_t>(1e6 * (g_read_timeout - std::floor(g_read_timeout)));
    ::setitimer(ITIMER_REAL, &timer, nullptr);
    armed_ = true;
  }
  ~ReadTimeout() {
    if (!armed_) return;
    const itimerval off{};
    ::setitimer(ITIMER_REAL, &off, nullptr);
    std::signal(SIGALRM, SIG_DFL);
  }
  ReadTimeout(const ReadTimeout&) = delete;
  ReadTimeout& operator=(const ReadTimeout&) = delete;

 private:
  bool armed_ = false;
};

mechanist::Assembly ReadInput(const std::string& file) {
  const ReadTimeout timeout(file);
  return mechanist::ReadAssembly(file);
}

// The file's assembly; when it declares adjustments and goals, with the adjustments solved and
// locked (the designer tightens the bolts), a line per adjustment on `out`.
mechanist::Assembly Load(const std::string& file, std::ostream& out) {
  const mechanist::Assembly assembly = ReadInput(file);
  mechanist::AdjustmentSummary summary;
  mechanist::Assembly adjusted = mechanist::Adjusted(assembly, &summary);
  for (std::size_t k = 0; k < summary.adjustments.size(); ++k) {
    const mechanist::Adjustment& a = assembly.adjustments()[k];
    if (!summary.adjustments[k].used) continue;
    const bool rotate = a.kind == mechanist::Adjustment::Kind::kRotate;
    const double value = summary.adjustments[k].value /
                         (rotate ? assembly.units().rad_per_angle : assembly.units().mm_per_length);
    out << "adjusted: " << a.id << " = "
        << mechanist::FormatNumber(std::round(value * 1e6) / 1e6 + 0.0, 9) << " "
        << (rotate ? assembly.units().angle : assembly.units().length);
    const auto& loosened = summary.adjustments[k].loosened;
    for (std::size_t f = 0; f < loosened.size(); ++f) {
      out << (f ? ", " : ", locked; tightened: ") << assembly.FeatureName(loosened[f]);
    }
    out << "\n";
  }
  if (!summary.all_met) out << "adjusted: some goals are not met (mechanist adjust tells)\n";
  return adjusted;
}

// A mesh file alone, or every mesh part of an assembly file.
int Features(const std::string& file, const std::string& json) {
  std::string extension = std::filesystem::path(file).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::vector<mechanist::FeatureReportEntry> entries;
  if (extension == ".json" || extension == ".step" || extension == ".stp") {
    const mechanist::Assembly assembly = ReadInput(file);
    entries = mechanist::RecogniseAssemblyFeatures(assembly);
    mechanist::WriteFeatureReport(entries, std::cout);
    mechanist::WriteDiagnostics(assembly.findings(), std::cout);
  } else {
    const mechanist::TriangleMesh mesh = [&] {
      const ReadTimeout timeout(file);
      return mechanist::ReadMesh(file);
    }();
    entries.push_back({std::filesystem::path(file).filename().string(), mechanist::RigidTransform(),
                       mechanist::RecognizeFeatures(mesh), true});
    mechanist::WriteFeatureReport(entries, std::cout);
  }
  if (!json.empty()) mechanist::WriteFileAtomically(json, mechanist::FeatureJson(entries), file);
  return kExitOk;
}

int Adjust(const std::string& file, const std::string& json, const std::string& write) {
  const mechanist::Assembly assembly = ReadInput(file);
  if (assembly.adjustments().empty()) {
    throw mechanist::InputError(file, "/adjustments", 0, 0,
                                "expected adjustments to solve, found none");
  }
  const mechanist::AdjustmentSummary summary =
      mechanist::SolveAdjustments(assembly, mechanist::Analyze(assembly).pairs);
  mechanist::WriteAdjustmentSummary(assembly, summary, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::AdjustmentJson(assembly, summary), file);
  }
  if (!write.empty()) {
    const mechanist::Assembly adjusted = mechanist::ApplyAdjustments(assembly, summary);
    mechanist::WriteFileAtomically(
        write, mechanist::AdjustedAssemblyText(assembly, adjusted, write), file);
  }
  return summary.all_met ? kExitOk : kExitFailures;
}

// The driver named by --driver, or nothing for an empty name.
std::optional<std::size_t> DriverIndex(const std::string& file, const mechanist::Assembly& assembly,
                                       const std::string& driver) {
  if (driver.empty()) return std::nullopt;
  for (std::size_t d = 0; d < assembly.drivers().size(); ++d) {
    if (assembly.drivers()[d].id == driver) return d;
  }
  throw mechanist::InputError(file, "", 0, 0,
                              "--driver: expected a driver id, found \"" + driver + "\"");
}

// Reports a fraction done on stderr when it is a terminal.
std::function<void(double)> Progress(const char* what) {
  if (!::isatty(STDERR_FILENO)) return {};
  return [what, last = -1](double fraction) mutable {
    const int percent = static_cast<int>(100 * fraction);
    if (percent == last) return;
    last = percent;
    std::fprintf(stderr, "\r%s: %3d%%%s", what, percent, percent == 100 ? "\n" : "");
  };
}

int Validate(const std::string& file) {
  const mechanist::Assembly assembly = ReadInput(file);
  const auto diagnostics = mechanist::CheckAssembly(assembly);
  mechanist::WriteDiagnostics(diagnostics, std::cout);
  std::size_t features = 0;
  for (const mechanist::Part& part : assembly.parts()) features += part.features.size();
  std::cout << file << ": valid (" << assembly.parts().size() << " parts, " << features
            << " features, " << diagnostics.size() << " diagnostics)\n";
  return kExitOk;
}

int Info(const std::string& file) {
  const mechanist::Assembly assembly = ReadInput(file);
  mechanist::WriteInfo(assembly, std::cout);
  const auto diagnostics = mechanist::CheckAssembly(assembly);
  if (!diagnostics.empty()) std::cout << "diagnostics: " << diagnostics.size() << "\n";
  mechanist::WriteDiagnostics(diagnostics, std::cout);
  return kExitOk;
}

/// Outputs are written only after the whole analysis succeeded, each atomically.
int Analyze(const std::string& file, const std::string& json, const std::string& dot) {
  const mechanist::Assembly assembly = Load(file, std::cout);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  mechanist::WriteAnalysisSummary(assembly, analysis, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::AnalysisJson(assembly, analysis), file);
  }
  if (!dot.empty()) {
    mechanist::WriteFileAtomically(dot, mechanist::AnalysisDot(assembly, analysis), file);
  }
  return kExitOk;
}

int Drag(const std::string& file, const std::string& part, const std::string& feature,
         bool translate) {
  const mechanist::Assembly assembly = Load(file, std::cout);
  const auto index = assembly.FindPart(part);
  if (!index) {
    throw mechanist::InputError(file, "", 0, 0,
                                "--part: expected a part id, found \"" + part + "\"");
  }
  mechanist::DragRequest request;
  request.part = *index;
  request.rotate = !translate;
  if (!feature.empty()) {
    const auto f = assembly.FindFeature(part + "/" + feature);
    if (!f) {
      throw mechanist::InputError(
          file, "", 0, 0,
          "--feature: expected a feature of part " + part + ", found \"" + feature + "\"");
    }
    request.feature = f->feature;
  }
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::DragResult result = mechanist::Drag(assembly, analysis, request);
  mechanist::WriteDragReport(assembly, analysis, result, request.rotate, std::cout);
  return result.motion.possible ? kExitOk : kExitFailures;
}

int Interference(const std::string& file, const std::string& json) {
  const mechanist::Assembly assembly = Load(file, std::cout);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::CollisionModel model(assembly);
  const auto contacts =
      mechanist::FindContacts(assembly, mechanist::InitialState(assembly), model, analysis.pairs);
  mechanist::WriteInterferenceSummary(assembly, analysis, contacts, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::InterferenceJson(assembly, analysis, contacts),
                                   file);
  }
  for (const auto& c : contacts) {
    if (c.verdict == mechanist::ContactVerdict::kClash) return kExitFailures;
  }
  return kExitOk;
}

int Assemble(const std::string& file, const std::string& json) {
  const mechanist::Assembly assembly = Load(file, std::cout);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::CollisionModel model(assembly);
  const mechanist::AssemblyPlan plan = mechanist::PlanAssembly(assembly, analysis, model);
  mechanist::WriteAssemblySummary(assembly, analysis, plan, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::AssemblyPlanJson(assembly, analysis, plan),
                                   file);
  }
  return plan.assemblable ? kExitOk : kExitFailures;
}

int Gaps(const std::string& file, double voxel, const std::string& json, const std::string& vtk) {
  const mechanist::Assembly assembly = ReadInput(file);
  if (!(voxel > 0) || !std::isfinite(voxel)) {
    throw mechanist::InputError(file, "", 0, 0, "--voxel: expected a length > 0");
  }
  mechanist::GapSearchOptions options;
  options.voxel = voxel * assembly.units().mm_per_length;
  options.progress = Progress("decomposing");
  mechanist::GapSearch search;
  try {
    search = mechanist::FindGaps(assembly, options);
  } catch (const std::invalid_argument& e) {
    throw mechanist::InputError(file, "", 0, 0, std::string("--voxel: ") + e.what());
  }
  mechanist::WriteGapSummary(assembly, search, std::cout);
  if (!vtk.empty()) mechanist::WriteGapVolume(vtk, search, file);
  if (!json.empty())
    mechanist::WriteFileAtomically(json, mechanist::GapJson(assembly, search), file);
  return kExitOk;
}

int Sweep(const std::string& file, const std::string& driver, double amount,
          const std::string& json) {
  const mechanist::Assembly assembly = Load(file, std::cout);
  const std::optional<std::size_t> index = DriverIndex(file, assembly, driver);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const mechanist::CollisionModel model(assembly);
  const mechanist::OperationCheck check = mechanist::CheckOperation(
      assembly, analysis, model, index, amount >= 0 ? std::optional<double>(amount) : std::nullopt);
  mechanist::WriteOperationSummary(assembly, check, std::cout);
  if (!json.empty()) {
    mechanist::WriteFileAtomically(json, mechanist::OperationJson(assembly, check), file);
  }
  bool jam = false;
  for (const auto& i : check.inferred) jam = jam || !i.carried;
  return check.clashes.empty() && check.undecided.empty() && !jam ? kExitOk : kExitFailures;
}

int Check(const std::string& file) {
  const mechanist::Assembly assembly = Load(file, std::cout);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  // The assembly plan sweeps every part; it runs only when an entry asks for it.
  std::optional<mechanist::AssemblyPlan> plan;
  for (const auto& e : assembly.expectations()) {
    if (e.kind == mechanist::Expectation::Kind::kAssemblable && !plan) {
      plan = mechanist::PlanAssembly(assembly, analysis, mechanist::CollisionModel(assembly));
    }
  }
  const auto results = mechanist::CheckExpectations(assembly, analysis, plan ? &*plan : nullptr);
  mechanist::WriteCheckResults(results, std::cout);
  for (const auto& r : results) {
    if (!r.passed) return kExitFailures;
  }
  return kExitOk;
}

struct AnimateRequest {
  std::string out;
  std::size_t frames = 120;
  double amount = -1;
  std::string size = "800x600";
  std::vector<std::string> formats;
  std::string view = "iso";
  std::string driver;
  double fps = 30;
  double gaps = 0;  // voxel, file units; 0: no gaps
  bool clashes = true;
  bool axes = true;
};

int Animate(const std::string& file, const AnimateRequest& request) {
  namespace fs = std::filesystem;
  auto usage = [&](const std::string& message) {
    return mechanist::InputError(file, "", 0, 0, message);
  };
  const std::set<std::string> known = {"png", "ogv", "mp4", "pvd", "glb"};
  std::set<std::string> formats(request.formats.begin(), request.formats.end());
  for (const std::string& f : formats) {
    if (!known.count(f)) {
      throw usage("--format: expected png, ogv, mp4, pvd or glb, found \"" + f + "\"");
    }
  }
  if (formats.empty()) {
    formats = {"png", "ogv", "pvd", "glb"};
    if (mechanist::FfmpegAvailable()) formats.insert("mp4");
  } else if (formats.count("mp4") && !mechanist::FfmpegAvailable()) {
    throw usage("--format mp4: needs the ffmpeg program (Debian package ffmpeg), not found");
  }
  int width = 0, height = 0;
  char tail = 0;
  if (std::sscanf(request.size.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width < 16 ||
      height < 16 || width > 8192 || height > 8192) {
    throw usage("--size: expected WIDTHxHEIGHT, 16 to 8192 pixels each, found \"" + request.size +
                "\"");
  }
  const auto view = mechanist::ParseView(request.view);
  if (!view)
    throw usage("--view: expected iso, front, top or side, found \"" + request.view + "\"");
  if (request.frames < 1 || request.frames > 100000) {
    throw usage("--frames: expected 1 to 100000");
  }
  if (!(request.fps > 0) || request.fps > 240) throw usage("--fps: expected a rate in (0, 240]");
  if (request.gaps < 0 || !std::isfinite(request.gaps)) {
    throw usage("--gaps: expected a voxel length > 0");
  }
  if (request.amount < 0 && request.amount != -1) throw usage("--amount: expected a number >= 0");
  const bool render = formats.count("png") || formats.count("ogv") || formats.count("mp4");
  std::string no_display;
  if (render && !mechanist::DisplayAvailable(&no_display)) {
    throw usage("--format " + std::string(formats.count("png") ? "png" : "ogv/mp4") + ": " +
                no_display);
  }
  // The options are checked before the file is read and its adjustments solved.
  const mechanist::Assembly assembly = Load(file, std::cout);
  const std::optional<std::size_t> driver = DriverIndex(file, assembly, request.driver);

  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  const std::optional<double> amount =
      request.amount >= 0 ? std::optional<double>(request.amount) : std::nullopt;
  const mechanist::MotionRun run = mechanist::PlanRun(assembly, analysis, driver, amount);
  if (!run.possible) std::cerr << "mechanist: note: nothing moves: " << run.reason << "\n";
  mechanist::Animation animation = mechanist::SampleRun(assembly, run, request.frames);
  if (request.clashes) {
    const mechanist::CollisionModel model(assembly);
    const auto contacts =
        mechanist::FindContacts(assembly, mechanist::InitialState(assembly), model, analysis.pairs);
    const mechanist::OperationCheck check =
        mechanist::CheckOperation(assembly, analysis, model, run.driver, run.amount);
    mechanist::MarkClashes(contacts, check, &animation);
  }
  std::optional<mechanist::TriangleMesh> gap_surface;
  std::vector<std::int32_t> gap_of_face;
  if (request.gaps > 0) {
    mechanist::GapSearchOptions options;
    options.voxel = request.gaps * assembly.units().mm_per_length;
    options.progress = Progress("decomposing");
    try {
      const mechanist::GapSearch search = mechanist::FindGaps(assembly, options);
      gap_surface = mechanist::GapSurface(search, &gap_of_face);
      std::cout << "gaps: " << search.gaps.size() << " at voxel " << request.gaps << " "
                << assembly.units().length << "\n";
    } catch (const std::invalid_argument& e) {
      throw usage(std::string("--gaps: ") + e.what());
    }
  }
  const mechanist::TriangleMesh* gaps = gap_surface ? &*gap_surface : nullptr;

  const fs::path out(request.out);
  std::error_code error;
  fs::create_directories(out, error);
  if (error)
    throw mechanist::InputError(request.out, "", 0, 0, "cannot create: " + error.message());
  std::vector<std::string> written;
  if (formats.count("glb")) {
    mechanist::WriteFileAtomically(
        out / "motion.glb",
        mechanist::GlbAnimation(assembly, analysis, animation, request.fps, gaps), file);
    written.push_back((out / "motion.glb").string());
  }
  if (formats.count("pvd")) {
    mechanist::WriteVtpSeries(out / "motion.pvd", assembly, analysis, animation, gaps, &gap_of_face,
                              file);
    written.push_back((out / "motion.pvd").string());
  }
  if (render) {
    const auto start = std::chrono::steady_clock::now();
    mechanist::RenderOptions options;
    options.width = width;
    options.height = height;
    options.view = *view;
    options.feature_axes = request.axes;
    if (assembly.name().empty()) options.title = fs::path(file).stem().string();
    mechanist::MotionRenderer renderer(assembly, analysis, animation, options, gaps);
    std::vector<std::unique_ptr<mechanist::VideoWriter>> videos;
    if (formats.count("ogv")) {
      videos.push_back(mechanist::MakeOggTheoraWriter(out / "motion.ogv", request.fps, file));
      written.push_back((out / "motion.ogv").string());
    }
    if (formats.count("mp4")) {
      videos.push_back(mechanist::MakeMp4Writer(out / "motion.mp4", request.fps, file));
      written.push_back((out / "motion.mp4").string());
    }
    const auto progress = Progress("rendering");
    for (std::size_t k = 0; k < animation.frame_count(); ++k) {
      const mechanist::Image image = renderer.Render(k);
      if (formats.count("png")) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04zu.png", k);
        mechanist::WriteFileAtomically(out / name, mechanist::EncodePng(image), file);
      }
      for (auto& video : videos) video->Add(image);
      if (progress) progress(static_cast<double>(k + 1) / animation.frame_count());
    }
    for (auto& video : videos) video->Finish();
    if (formats.count("png")) written.push_back((out / "frame_*.png").string());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "rendered " << animation.frame_count() << " frames at " << width << "x" << height
              << " in " << std::fixed << std::setprecision(1) << seconds << " s\n"
              << std::defaultfloat;
  }
  std::cout << "animation: " << animation.frame_count() << " frames, "
            << (run.driver ? "driver " + assembly.drivers()[*run.driver].id : "all drivers")
            << " over " << run.amount << "\n";
  std::size_t clashing = 0;
  for (const auto& c : animation.clash_from) clashing += c.has_value();
  if (clashing > 0) std::cout << "parts in a clash (red): " << clashing << "\n";
  for (const std::string& w : written) std::cout << "wrote " << w << "\n";
  return kExitOk;
}

// Writes the simulator model as URDF and/or MJCF, each with its meshes in a folder beside it
// (FILE_meshes/, one binary STL in metres per mesh source).
int Export(const std::string& file, const std::string& urdf, const std::string& mjcf,
           double density, bool drive, bool limits) {
  if (urdf.empty() && mjcf.empty()) {
    throw mechanist::InputError(file, "", 0, 0, "export: expected --urdf or --mjcf, found neither");
  }
  if (!(density > 0) || !std::isfinite(density)) {
    throw mechanist::InputError(file, "", 0, 0, "--density: expected kg/m^3 > 0");
  }
  const mechanist::Assembly assembly = Load(file, std::cout);
  const mechanist::Analysis analysis = mechanist::Analyze(assembly);
  mechanist::SimulationOptions options;
  options.density = density;
  std::optional<mechanist::CollisionModel> collision;
  if (limits) options.collision = &collision.emplace(assembly);
  options.progress = Progress("movable ranges");
  const mechanist::SimulationModel model =
      mechanist::BuildSimulationModel(assembly, analysis, options);
  std::vector<std::string> written;
  std::set<std::filesystem::path> mesh_folders;  // written already (URDF and MJCF side by side)
  auto write_meshes = [&](const std::filesystem::path& out) {
    const std::string folder = out.stem().string() + "_meshes";
    if (!mesh_folders.insert(out.parent_path() / folder).second) return folder;
    std::error_code error;
    std::filesystem::create_directories(out.parent_path() / folder, error);
    if (error) {
      throw mechanist::InputError((out.parent_path() / folder).string(), "", 0, 0,
                                  "cannot create the mesh folder: " + error.message());
    }
    for (const mechanist::SimMesh& m : model.meshes) {
      mechanist::WriteFileAtomically(out.parent_path() / folder / (m.name + ".stl"),
                                     mechanist::BinaryStl(*m.mesh, 1e-3), file);
    }
    written.push_back((out.parent_path() / folder).string() + "/ (" +
                      std::to_string(model.meshes.size()) + " meshes)");
    return folder;
  };
  if (!urdf.empty()) {
    const std::string folder = write_meshes(urdf);
    mechanist::WriteFileAtomically(urdf, mechanist::UrdfText(assembly, analysis, model, folder),
                                   file);
    written.push_back(urdf);
  }
  if (!mjcf.empty()) {
    mechanist::MjcfOptions mjcf_options;
    mjcf_options.mesh_dir = write_meshes(mjcf);
    mjcf_options.drive = drive;
    mechanist::WriteFileAtomically(
        mjcf, mechanist::MjcfText(assembly, analysis, model, mjcf_options), file);
    written.push_back(mjcf);
  }
  std::size_t limited = 0;
  for (const auto& j : model.joints) limited += j.lower || j.upper;
  std::size_t actuated = 0;
  for (const auto& a : model.actuators) actuated += a.joint.has_value();
  std::size_t closed = 0;
  for (const auto& l : model.loops) closed += !l.anchors_W.empty();
  std::cout << "links: " << model.links.size() << " (root " << model.links.front().name << ")\n"
            << "joints: " << model.joints.size() << " ("
            << (limits ? std::to_string(limited) + " stopped by a contact in the swept check"
                       : std::string("movable ranges not searched: --no-limits"))
            << ")\n"
            << "couplings: " << model.couplings.size() << "\n"
            << "loops cut (URDF cannot close them): " << model.loops.size() << " (" << closed
            << " closed by MJCF equalities)\n"
            << "actuators: " << actuated << " of " << model.actuators.size() << " drivers\n";
  for (const mechanist::SimLoop& loop : model.loops) {
    const mechanist::Pair& p = analysis.pairs[loop.pair];
    std::cout << "  loop cut at the " << mechanist::ToString(p.type) << " pair "
              << assembly.FeatureName(p.a) << " + " << assembly.FeatureName(p.b)
              << (loop.anchors_W.empty() ? ": open in MJCF too (no equality for it)"
                                         : ": closed in MJCF by <connect>")
              << "\n";
  }
  for (const std::string& note : model.notes) std::cout << "note: " << note << "\n";
  for (const std::string& w : written) std::cout << "wrote " << w << "\n";
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "mechanist: reads a mechanical assembly and tells whether it can be assembled "
      "and how it moves"};
  app.set_version_flag("--version", std::string("mechanist ") + MECHANIST_VERSION);
  app.require_subcommand(1);
  app.add_option("--read-timeout", g_read_timeout,
                 "seconds reading one input file may take before mechanist gives up with exit "
                 "code 2 (default 300; 0: no bound); before the command")
      ->check(CLI::NonNegativeNumber);

  std::string file;
  CLI::App* validate =
      app.add_subcommand("validate", "Read everything, print diagnostics; exit 0 if valid");
  validate->add_option("FILE", file, "assembly file (.json)")->required();
  CLI::App* info = app.add_subcommand(
      "info", "Parts, triangle counts, features, bounding boxes, units, drivers");
  info->add_option("FILE", file, "assembly file (.json)")->required();

  std::string json, dot;
  CLI::App* analyze = app.add_subcommand(
      "analyze", "Recognise pairs and subassemblies; print a summary, optionally write reports");
  analyze->add_option("FILE", file, "assembly file (.json)")->required();
  analyze->add_option("--json", json, "write the JSON report to this file");
  analyze->add_option("--dot", dot, "write the pair graph as Graphviz DOT to this file");
  CLI::App* check =
      app.add_subcommand("check", "Evaluate the file's expect entries; exit 1 if any fails");
  check->add_option("FILE", file, "assembly file (.json)")->required();

  CLI::App* interference = app.add_subcommand(
      "interference", "Parts that penetrate in the assembled state; exit 1 if any clash");
  interference->add_option("FILE", file, "assembly file (.json)")->required();
  interference->add_option("--json", json, "write the JSON report to this file");
  CLI::App* assemble = app.add_subcommand(
      "assemble",
      "Check the file's steps, or find an assembly sequence; exit 1 if it cannot be assembled");
  assemble->add_option("FILE", file, "assembly file (.json)")->required();
  assemble->add_option("--json", json, "write the JSON report to this file");

  std::string driver;
  double amount = -1;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run the mechanism and report parts that collide while it moves; exit 1 if any");
  sweep->add_option("FILE", file, "assembly file (.json)")->required();
  sweep->add_option("--driver", driver, "run only this driver (default: all at their rates)");
  sweep
      ->add_option("--amount", amount,
                   "how far: driver revolutions or length units (default: the driver's amount)")
      ->check(CLI::NonNegativeNumber);
  sweep->add_option("--json", json, "write the JSON report to this file");

  double voxel = 0;
  std::string vtk;
  CLI::App* gaps = app.add_subcommand(
      "gaps", "Find the empty spaces enclosed between parts, with their volumes");
  gaps->add_option("FILE", file, "assembly file (.json)")->required();
  gaps->add_option("--voxel", voxel, "voxel edge, in the file's length units")->required();
  gaps->add_option("--json", json, "write the JSON report to this file");
  gaps->add_option("--vtk", vtk, "write the voxels as a VTK image (.vti) to this file");

  std::string part, feature;
  CLI::App* drag = app.add_subcommand(
      "drag", "Turn or push one part: what moves with it, and which pair absorbs the motion");
  drag->add_option("FILE", file, "assembly file (.json)")->required();
  drag->add_option("--part", part, "the part to drag")->required();
  drag->add_option("--feature", feature,
                   "the feature whose axis to use (default: its first in a pair)");
  bool rotate = false, translate = false;
  CLI::Option* rotate_flag = drag->add_flag("--rotate", rotate, "turn about the axis (default)");
  drag->add_flag("--translate", translate, "push along the axis")->excludes(rotate_flag);

  CLI::App* features = app.add_subcommand(
      "features", "Recognise the features of a mesh, or of an assembly's mesh parts");
  features
      ->add_option("FILE", file,
                   "a mesh (.stl, .obj, .ply, .off), an assembly (.json) or a STEP file")
      ->required();
  features->add_option("--json", json, "write the JSON report to this file");

  std::string write;
  CLI::App* adjust = app.add_subcommand(
      "adjust", "Solve the adjustments for the goals; exit 1 if a goal cannot be met");
  adjust->add_option("FILE", file, "assembly file (.json)")->required();
  adjust->add_option("--json", json, "write the JSON report to this file");
  adjust->add_option("--write", write, "write the adjusted assembly to this new file");

  AnimateRequest animate_request;
  CLI::App* animate = app.add_subcommand(
      "animate", "Run the mechanism and write PNG frames, videos, a ParaView series and glTF");
  animate->add_option("FILE", file, "assembly file (.json)")->required();
  animate->add_option("--out", animate_request.out, "output folder (created)")->required();
  animate->add_option("--frames", animate_request.frames, "number of frames (default 120)");
  animate
      ->add_option("--amount", animate_request.amount,
                   "how far: driver revolutions or length units (default: the driver's amount)")
      ->check(CLI::NonNegativeNumber);
  animate->add_option("--size", animate_request.size, "image size WIDTHxHEIGHT (default 800x600)");
  animate
      ->add_option("--format", animate_request.formats,
                   "png,ogv,mp4,pvd,glb (default: all; mp4 only when ffmpeg is installed)")
      ->delimiter(',');
  animate->add_option("--view", animate_request.view, "iso, front, top or side (default iso)");
  animate->add_option("--driver", animate_request.driver,
                      "run only this driver (default: all at their rates)");
  animate->add_option("--fps", animate_request.fps,
                      "video and glTF frames per second (default 30)");
  animate->add_option("--gaps", animate_request.gaps,
                      "show the enclosed gaps found at this voxel size (file units)");
  bool no_clashes = false, no_axes = false;
  animate->add_flag("--no-clashes", no_clashes, "skip the clash checks (no red parts)");
  animate->add_flag("--no-axes", no_axes, "do not draw feature axes");

  std::string urdf, mjcf;
  double density = 7850;
  bool drive = false;
  CLI::App* export_command = app.add_subcommand(
      "export", "Write the mechanism for simulators: URDF and MJCF with joints and couplings");
  export_command->add_option("FILE", file, "assembly file (.json)")->required();
  export_command->add_option("--urdf", urdf, "write URDF to this file (meshes beside it)");
  export_command->add_option("--mjcf", mjcf, "write MuJoCo MJCF to this file (meshes beside it)");
  export_command->add_option("--density", density, "kg/m^3 of every part (default 7850, steel)");
  export_command->add_flag("--drive", drive,
                           "MJCF: a keyframe at the file pose with the drivers running");
  bool no_limits = false;
  export_command->add_flag("--no-limits", no_limits,
                           "skip the swept check for joint ranges (faster on large files)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }

  try {
    if (*validate) return Validate(file);
    if (*info) return Info(file);
    if (*analyze) return Analyze(file, json, dot);
    if (*check) return Check(file);
    if (*interference) return Interference(file, json);
    if (*assemble) return Assemble(file, json);
    if (*sweep) return Sweep(file, driver, amount, json);
    if (*gaps) return Gaps(file, voxel, json, vtk);
    if (*drag) return Drag(file, part, feature, translate);
    if (*adjust) return Adjust(file, json, write);
    if (*features) return Features(file, json);
    if (*export_command) return Export(file, urdf, mjcf, density, drive, !no_limits);
    if (*animate) {
      animate_request.clashes = !no_clashes;
      animate_request.axes = !no_axes;
      return Animate(file, animate_request);
    }
  } catch (const mechanist::InputError& e) {
    std::cerr << "mechanist: error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "mechanist: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitUsage;
}
