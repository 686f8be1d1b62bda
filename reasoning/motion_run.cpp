#include "reasoning/motion_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mechanist {

MotionRun PlanRun(const Assembly& assembly, const Analysis& analysis,
                  std::optional<std::size_t> driver, std::optional<double> amount) {
  MotionRun run;
  const auto& drivers = assembly.drivers();
  const std::size_t n = assembly.parts().size();
  run.paths.assign(n, ScrewPath());
  if (!driver && drivers.size() == 1) driver = 0;  // one driver: its own units
  run.driver = driver;
  if (driver && *driver >= drivers.size()) {
    throw std::invalid_argument(fmt::format("PlanRun: no driver {}", *driver));
  }
  if (amount && !(*amount >= 0.0 && std::isfinite(*amount))) {
    throw std::invalid_argument("PlanRun: the amount must be finite and >= 0");
  }
  const auto& driven = analysis.motion.driven;
  if (drivers.empty() || driven.empty()) {
    run.possible = false;
    run.reason = "no driver: nothing runs";
    return run;
  }
  if (amount) {
    run.amount = *amount;
  } else if (driver) {
    // Amounts are kept in mm; the driver's parameter counts the file's length units.
    const Driver& d = drivers[*driver];
    run.amount = d.motion == Driver::Motion::kTranslation
                     ? d.amount / assembly.units().mm_per_length
                     : d.amount;
  } else {
    run.amount = std::numeric_limits<double>::infinity();
    for (const Driver& d : drivers) {
      if (d.rate != 0.0) run.amount = std::min(run.amount, d.amount / std::abs(d.rate));
    }
    if (!std::isfinite(run.amount)) run.amount = 0.0;
  }
  if (driver && drivers[*driver].rate == 0.0) {
    run.possible = false;
    run.reason = fmt::format("driver {} is held (rate 0): nothing runs", drivers[*driver].id);
    return run;
  }
  // driven: one entry per driver, then, with several, all together.
  const DrivenMotion& motion = driver ? driven[*driver] : driven.back();
  if (!motion.possible) {
    run.possible = false;
    run.reason = motion.reason;
    return run;
  }
  // A driver runs the way its rate says: the unit-rate motion reversed for a negative rate.
  const double sense = driver && drivers[*driver].rate < 0 ? -1.0 : 1.0;
  for (std::size_t p = 0; p < n; ++p) {
    run.paths[p] = motion.parts[p].path;
    for (ScrewMotion& m : run.paths[p].screws) {
      m.turns_per_unit *= sense;
      m.travel_per_unit *= sense;
    }
  }
  return run;
}

AssemblyState StateAt(const Assembly& assembly, const MotionRun& run, double s) {
  AssemblyState state = InitialState(assembly);
  for (std::size_t p = 0; p < state.X_WP.size(); ++p) {
    if (!run.paths[p].still()) state.X_WP[p] = run.paths[p].At(s) * state.X_WP[p];
  }
  return state;
}

double FrameParameter(const MotionRun& run, std::size_t k, std::size_t n) {
  if (n < 2) return 0.0;
  return run.amount * static_cast<double>(k) / static_cast<double>(n - 1);
}

std::string DescribeParameter(const Assembly& assembly, const MotionRun& run, double s) {
  char text[64];
  if (!run.possible) return fmt::format("still: {}", run.reason);
  if (!run.driver) {
    std::snprintf(text, sizeof text, "t = %.3f", s);
    return text;
  }
  const Driver& d = assembly.drivers()[*run.driver];
  const std::string& part = assembly.part(d.feature.part).id;
  if (d.motion == Driver::Motion::kRotation) {
    std::snprintf(text, sizeof text, "%.1f", 360.0 * s);
    return fmt::format("{} {} deg", part, text);
  }
  std::snprintf(text, sizeof text, "%.2f", s);
  return fmt::format("{} {} {}", part, text, assembly.units().length);
}

}  // namespace mechanist
