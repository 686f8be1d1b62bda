#include "kernel/features/involute_gear.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

Eigen::Vector2d Polar(double radius, double angle) {
  return radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
}

// Appends the interior vertices of the arc of `radius` from angle `from` to `to` (> from),
// in steps of at most `max_step`; the end points belong to the neighbouring flanks.
void AppendArcInterior(double radius, double from, double to, double max_step, Ring2d& ring) {
  const int steps = std::max(1, static_cast<int>(std::ceil((to - from) / max_step)));
  for (int s = 1; s < steps; ++s) ring.push_back(Polar(radius, from + (to - from) * s / steps));
}

}  // namespace

double Involute(double alpha) { return std::tan(alpha) - alpha; }

Ring2d InvoluteOutline(const InvoluteOutlineSpec& spec) {
  const double pi = std::numbers::pi;
  if (spec.teeth < 3 || !(spec.module > 0.0) || !std::isfinite(spec.module) ||
      !(spec.pressure_angle > 0.0 && spec.pressure_angle < pi / 2) || !(spec.addendum > 0.0) ||
      !(spec.dedendum > 0.0) || !(spec.max_arc_step > 0.0) || spec.flank_points < 2) {
    throw std::invalid_argument(
        "InvoluteOutline: need at least 3 teeth, positive module, addendum, dedendum and arc "
        "step, a pressure angle in (0, pi/2) and at least 2 flank points");
  }
  const double z = spec.teeth;
  const double r_pitch = spec.module * z / 2.0;
  const double r_base = r_pitch * std::cos(spec.pressure_angle);
  const double r_tip = r_pitch + spec.addendum;
  const double r_root = r_pitch - spec.dedendum;
  if (!(r_root > 0.0)) {
    throw std::invalid_argument(
        fmt::format("the dedendum {} leaves no root circle inside the pitch radius {}",
                    FormatNumber(spec.dedendum), FormatNumber(r_pitch)));
  }
  if (!(r_tip > r_base)) {
    throw std::invalid_argument(fmt::format("the tip radius {} does not exceed the base radius {}",
                                            FormatNumber(r_tip), FormatNumber(r_base)));
  }
  // theta(r) is base_half_angle - inv(acos(r_b / r)), and with the involute's roll angle t
  // (r = r_b sqrt(1 + t^2)) inv(acos(r_b / r)) = t - atan(t).
  const double base_half_angle = pi / (2.0 * z) + Involute(spec.pressure_angle);
  auto roll = [r_base](double r) {
    return std::sqrt(std::max(0.0, (r / r_base) * (r / r_base) - 1.0));
  };
  const double t_start = roll(std::max(r_root, r_base));
  const double t_tip = roll(r_tip);
  const double theta_root = base_half_angle - (t_start - std::atan(t_start));
  const double theta_tip = base_half_angle - (t_tip - std::atan(t_tip));
  if (!(theta_tip > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "the involute flanks meet below the tip radius {} (pointed teeth)", FormatNumber(r_tip)));
  }
  if (!(theta_root < pi / z)) {
    throw std::invalid_argument(
        fmt::format("neighbouring teeth overlap at the root radius {}", FormatNumber(r_root)));
  }

  struct FlankPoint {
    double radius, half_angle;
  };
  std::vector<FlankPoint> flank;
  for (int k = 0; k < spec.flank_points; ++k) {
    const double t = t_start + (t_tip - t_start) * k / (spec.flank_points - 1);
    flank.push_back({r_base * std::sqrt(1.0 + t * t), base_half_angle - (t - std::atan(t))});
  }
  // Exactly, so that flank ends lie on the same circles as the arcs they join.
  flank.front().radius = std::max(r_root, r_base);
  flank.back().radius = r_tip;

  const bool radial_root = r_root < r_base;
  Ring2d ring;
  for (int tooth = 0; tooth < spec.teeth; ++tooth) {
    const double centre = 2.0 * pi * tooth / z;
    if (radial_root) ring.push_back(Polar(r_root, centre - theta_root));
    for (const FlankPoint& p : flank) ring.push_back(Polar(p.radius, centre - p.half_angle));
    AppendArcInterior(r_tip, centre - theta_tip, centre + theta_tip, spec.max_arc_step, ring);
    for (auto p = flank.rbegin(); p != flank.rend(); ++p) {
      ring.push_back(Polar(p->radius, centre + p->half_angle));
    }
    if (radial_root) ring.push_back(Polar(r_root, centre + theta_root));
    AppendArcInterior(r_root, centre + theta_root, centre + 2.0 * pi / z - theta_root,
                      spec.max_arc_step, ring);
  }
  return ring;
}

}  // namespace mechanist
