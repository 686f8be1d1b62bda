#include "viz/animation_output.h"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/animation.h"
#include "reasoning/gap_search.h"
#include "reasoning/interference.h"
#include "reasoning/operation_check.h"
#include "viz/gltf_writer.h"
#include "viz/png_encoder.h"
#include "viz/video_writer.h"
#include "viz/vtp_series_writer.h"

namespace mechanist {

AnimationOutcome WriteAnimation(const Assembly& assembly, const Analysis& analysis,
                                const AnimationRequest& request) {
  namespace fs = std::filesystem;
  auto progress = [&](const char* stage) -> std::function<void(double)> {
    if (!request.progress) return {};
    return [&, stage](double fraction) { request.progress(stage, fraction); };
  };
  const auto& formats = request.formats;
  AnimationOutcome outcome;
  outcome.run = PlanRun(assembly, analysis, request.driver, request.amount);
  const MotionRun& run = outcome.run;
  Animation animation = SampleRun(assembly, run, request.frames);
  outcome.frames = animation.frame_count();
  if (request.clashes) {
    const CollisionModel model(assembly);
    const auto contacts = FindContacts(assembly, InitialState(assembly), model, analysis.pairs);
    const OperationCheck check = CheckOperation(assembly, analysis, model, run.driver, run.amount);
    MarkClashes(contacts, check, &animation);
  }
  for (const auto& c : animation.clash_from) outcome.clashing_parts += c.has_value();

  std::optional<TriangleMesh> gap_surface;
  std::vector<std::int32_t> gap_of_face;
  if (request.gap_voxel > 0) {
    GapSearchOptions options;
    options.voxel = request.gap_voxel;
    options.progress = progress("decomposing");
    const GapSearch search = FindGaps(assembly, options);
    gap_surface = GapSurface(search, &gap_of_face);
    outcome.gaps = search.gaps.size();
  }
  const TriangleMesh* gaps = gap_surface ? &*gap_surface : nullptr;

  const fs::path& out = request.out;
  std::error_code error;
  fs::create_directories(out, error);
  if (error) {
    throw InputError(out.string(), "", 0, 0, fmt::format("cannot create: {}", error.message()));
  }
  if (formats.count("glb")) {
    WriteFileAtomically(out / "motion.glb",
                        GlbAnimation(assembly, analysis, animation, request.fps, gaps),
                        request.protect);
    outcome.written.push_back((out / "motion.glb").string());
  }
  if (formats.count("pvd")) {
    WriteVtpSeries(out / "motion.pvd", assembly, analysis, animation, gaps, &gap_of_face,
                   request.protect);
    outcome.written.push_back((out / "motion.pvd").string());
  }
  if (!formats.count("png") && !formats.count("ogv") && !formats.count("mp4")) return outcome;

  const auto start = std::chrono::steady_clock::now();
  MotionRenderer renderer(assembly, analysis, animation, request.render, gaps);
  std::vector<std::unique_ptr<VideoWriter>> videos;
  if (formats.count("ogv")) {
    videos.push_back(MakeOggTheoraWriter(out / "motion.ogv", request.fps, request.protect));
    outcome.written.push_back((out / "motion.ogv").string());
  }
  if (formats.count("mp4")) {
    videos.push_back(MakeMp4Writer(out / "motion.mp4", request.fps, request.protect));
    outcome.written.push_back((out / "motion.mp4").string());
  }
  const auto rendering = progress("rendering");
  for (std::size_t k = 0; k < animation.frame_count(); ++k) {
    const Image image = renderer.Render(k);
    if (formats.count("png")) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04zu.png", k);
      WriteFileAtomically(out / name, EncodePng(image), request.protect);
    }
    for (auto& video : videos) video->Add(image);
    if (rendering) rendering(static_cast<double>(k + 1) / animation.frame_count());
  }
  for (auto& video : videos) video->Finish();
  if (formats.count("png")) outcome.written.push_back((out / "frame_*.png").string());
  outcome.render_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace mechanist
