#pragma once

// A cycloidal disc's outline for tests.

#include <cmath>

#include "kernel/geometry/polygon_triangulation.h"

namespace mechanist::testing {

// A cycloidal disc's outline for `pins` pins of radius r_p on a circle of radius R and an
// eccentricity e, from the textbook parametric form (the pins' envelope), as a ring of points
// about the origin.
inline Ring2d CycloidOutline(int pins, double R, double r_p, double e, int samples) {
  Ring2d ring;
  for (int i = 0; i < samples; ++i) {
    const double t = 2 * 3.14159265358979323846 * i / samples;
    const double psi =
        std::atan2(std::sin((1 - pins) * t), R / (e * pins) - std::cos((1 - pins) * t));
    ring.emplace_back(R * std::cos(t) - r_p * std::cos(t + psi) - e * std::cos(pins * t),
                      -R * std::sin(t) + r_p * std::sin(t + psi) + e * std::sin(pins * t));
  }
  return ring;
}

}  // namespace mechanist::testing
