// Animation benchmark: the robot-hand worm drive run through one driver revolution in 120
// frames at 800x600, each stage of `mechanist animate` timed on its own: analysis, sampling
// with the clash checks, glTF, ParaView series, rendering, PNG encoding, Ogg Theora and MP4.
// Needs an X display: run under xvfb-run -a -s "-screen 0 1920x1080x24".
//
// Usage: animate_bench [frames = 120] [WIDTHxHEIGHT = 800x600]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

#include "io/load_assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/analysis.h"
#include "reasoning/animation.h"
#include "reasoning/interference.h"
#include "reasoning/motion_run.h"
#include "reasoning/operation_check.h"
#include "viz/gltf_writer.h"
#include "viz/motion_renderer.h"
#include "viz/png_encoder.h"
#include "viz/video_writer.h"
#include "viz/vtp_series_writer.h"

namespace {

double Seconds(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mechanist;
  const std::size_t frames = argc > 1 ? std::stoul(argv[1]) : 120;
  int width = 800, height = 600;
  if (argc > 2) std::sscanf(argv[2], "%dx%d", &width, &height);
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "mechanist_animate_bench";
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out);

  Assembly assembly = LoadAssembly(MECHANIST_SOURCE_DIR "/examples/robot_hand_worm/assembly.json");
  Analysis analysis;
  Animation animation;
  double total = 0;
  auto stage = [&](const char* name, const std::function<void()>& f) {
    const double s = Seconds(f);
    total += s;
    std::printf("%-34s %8.3f s\n", name, s);
  };
  std::printf("robot_hand_worm: %zu frames at %dx%d\n", frames, width, height);
  stage("analysis", [&] { analysis = Analyze(assembly); });
  stage("sampling + clash checks", [&] {
    const MotionRun run = PlanRun(assembly, analysis, std::nullopt, std::nullopt);
    animation = SampleRun(assembly, run, frames);
    const CollisionModel model(assembly);
    const auto contacts = FindContacts(assembly, InitialState(assembly), model, analysis.pairs);
    MarkClashes(contacts, CheckOperation(assembly, analysis, model, run.driver, run.amount),
                &animation);
  });
  stage("glTF (.glb)", [&] { GlbAnimation(assembly, analysis, animation, 30.0); });
  stage("ParaView series (.pvd + .vtp)",
        [&] { WriteVtpSeries(out / "motion.pvd", assembly, analysis, animation); });
  RenderOptions options;
  options.width = width;
  options.height = height;
  std::vector<Image> images;
  stage("rendering", [&] {
    MotionRenderer renderer(assembly, analysis, animation, options);
    for (std::size_t k = 0; k < frames; ++k) images.push_back(renderer.Render(k));
  });
  stage("PNG encoding", [&] {
    for (const Image& image : images) EncodePng(image);
  });
  stage("Ogg Theora", [&] {
    auto video = MakeOggTheoraWriter(out / "motion.ogv", 30.0);
    for (const Image& image : images) video->Add(image);
    video->Finish();
  });
  if (FfmpegAvailable()) {
    stage("MP4 (ffmpeg, libx264)", [&] {
      auto video = MakeMp4Writer(out / "motion.mp4", 30.0);
      for (const Image& image : images) video->Add(image);
      video->Finish();
    });
  }
  std::printf("%-34s %8.3f s\n", "total", total);
  std::filesystem::remove_all(out);
  return 0;
}
