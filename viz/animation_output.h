#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"
#include "reasoning/motion_run.h"
#include "viz/motion_renderer.h"

namespace mechanist {

/// What to write of a run of the mechanism (`mechanist animate`).
struct AnimationRequest {
  std::filesystem::path out;  ///< folder, created when missing
  /// "png" (frame_NNNN.png), "ogv", "mp4" (motion.*), "pvd" (ParaView series), "glb" (glTF).
  std::set<std::string> formats;
  std::size_t frames = 120;
  std::optional<std::size_t> driver;  ///< nothing: all drivers at their rates
  std::optional<double> amount;       ///< default: the driver's amount
  RenderOptions render;               ///< size, view, feature axes, title
  double fps = 30;
  double gap_voxel = 0;           ///< mm; 0: no gaps drawn
  bool clashes = true;            ///< mark the parts in a clash (static and swept checks)
  std::filesystem::path protect;  ///< never written over (the input)
  /// Called as stages progress ("decomposing", "rendering"), with the fraction done.
  std::function<void(const char* stage, double fraction)> progress;
};

/// What WriteAnimation wrote.
struct AnimationOutcome {
  MotionRun run;
  std::size_t frames = 0;
  std::size_t clashing_parts = 0;        ///< parts drawn red from their first contact
  std::optional<std::size_t> gaps;       ///< gaps found, when asked for
  std::optional<double> render_seconds;  ///< when frames or videos were rendered
  std::vector<std::string> written;      ///< the files (frames as "frame_*.png")
};

/// Runs the mechanism as PlanRun says, samples `frames` poses (StateAt), marks clashes, finds
/// the gaps when asked, and writes the requested files into `out`, each atomically. Rendering
/// (png, ogv, mp4) needs an X display. Throws std::invalid_argument for a gap voxel the search
/// refuses, InputError for a file or folder that cannot be written.
AnimationOutcome WriteAnimation(const Assembly& assembly, const Analysis& analysis,
                                const AnimationRequest& request);

}  // namespace mechanist
