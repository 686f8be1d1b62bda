#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "kernel/assembly/assembly.h"
#include "reasoning/analysis.h"

namespace mechanist {

/// Where ViewerHtml finds three.js (Debian's libjs-three, r111: the global build and its
/// OrbitControls), inlined into every page.
struct ViewerOptions {
  std::filesystem::path three_dir = "/usr/share/javascript/three";
  /// Search every drag's movable range with the swept check (FindMovableRange): the page
  /// stops a drag at the first contact each way and shows it; and sweep every driver's run
  /// (CheckOperation): the page shows its clashes and jams as the run reaches them. Slow on large
  /// real files.
  bool ranges = true;
  /// Plan the assembly sequence (PlanAssembly, a swept check of every part) for the page's
  /// stepper. Slow on large real files.
  bool plan = true;
  /// Find the enclosed gaps at this voxel edge (mm) and show them as translucent volumes with
  /// their volumes; 0: no gaps.
  double gap_voxel = 0.0;
  /// Receives the fraction of the assembly sequence planned (PlanAssembly's progress);
  /// optional.
  std::function<void(double)> plan_progress;
  /// Receives the fraction of the drags' range searches done (each distinct motion searched
  /// once, on every core): 0 first, then one call at a time; optional.
  std::function<void(double)> range_progress;
};

/// One self-contained HTML page (no server, no network) to look at and work the analysed
/// mechanism in a browser: the parts in 3D at their file poses (three.js, inlined), coloured by
/// subassembly with the ground muted, orbit/pan/zoom, a section plane, the feature axes on a
/// toggle; beside it the subassemblies, the pairs (hover or click highlights their parts), the
/// mobility and the diagnostics (click highlights the parts); a slider and a play button per
/// driver, moving the parts along the same paths as `animate` and `sweep` (PlanRun: the pose
/// after s is path.At(s) * X_WP); and a drag for every part: it turns about (or slides along)
/// the axis Drag gives it, everything coupled follows, up to the first contact each way (the
/// movable range, shown with the parts that meet), or the page says which pairs hold it.
/// Parts in a clash at rest (interference) are drawn red with a dot at the contact point, and
/// with `gap_voxel` the enclosed gaps show. With `plan`, a stepper shows the assembly sequence
/// (PlanAssembly): each insertion moving along its direction into place, a blocked one up to
/// its first contact with the obstacle shown. Meshes are stored once per shared mesh,
/// quantised to 16 bits per coordinate across their box. The page's state is `window.mechanist`
/// (for tests and scripts). Throws std::runtime_error when three.js is not found under
/// `options.three_dir`.
std::string ViewerHtml(const Assembly& assembly, const Analysis& analysis,
                       const ViewerOptions& options = {});

}  // namespace mechanist
