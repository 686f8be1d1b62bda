#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/assembly_state.h"
#include "kernel/geometry/screw_path.h"
#include "reasoning/analysis.h"

namespace mechanist {

/// A run of the mechanism from its file poses: one driver turning or sliding in the sense of
/// its rate (the others held), or all drivers together at their rates, over a parameter s in
/// [0, amount]. The single source of the poses that the swept check, the animation and its
/// files use.
struct MotionRun {
  std::optional<std::size_t> driver;  ///< nothing: all drivers together, s counts time units
  /// How far it runs: driver revolutions or file length units (time units for all drivers).
  double amount = 0.0;
  bool possible = true;  ///< false when the drivers cannot run so (see `reason`)
  std::string reason;
  /// Per part: the pose after s is paths[p].At(s) * X_WP (the file pose), lengths in mm; the
  /// analysis' unit-rate paths, reversed for a driver whose rate is negative. All still when
  /// the run is not possible.
  std::vector<ScrewPath> paths;
};

/// The run of `driver` (with a single driver and none named, that driver; with several and
/// none named, all together) over `amount` (default: the driver's `amount`; for all drivers
/// the shortest time in which one of them completes its amount), with the motion of
/// `analysis`; a held driver (rate 0) named or alone does not run (`possible` false). Throws
/// std::invalid_argument for a driver index out of range or an amount that is negative or not
/// finite.
MotionRun PlanRun(const Assembly& assembly, const Analysis& analysis,
                  std::optional<std::size_t> driver, std::optional<double> amount);

/// The poses of every part at parameter s of `run` (world, mm).
AssemblyState StateAt(const Assembly& assembly, const MotionRun& run, double s);

/// The parameter of frame k of n frames spread evenly over the run, first at the file poses and
/// last at the end: amount k / (n - 1) (0 for a single frame).
double FrameParameter(const MotionRun& run, std::size_t k, std::size_t n);

/// How far the run has gone at s, for titles: "motor_shaft 90.0 deg", "lead_screw 2.50 mm",
/// "t = 0.500" for all drivers together (the file's length unit name; angles in degrees);
/// "still: " and the reason when the run is not possible.
std::string DescribeParameter(const Assembly& assembly, const MotionRun& run, double s);

}  // namespace mechanist
