#include "kernel/support/number_format.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mechanist {

std::string FormatNumber(double value, int significant) {
  // Below 1e-12 (mm, radians, ratios) a value is rounding noise of a rotation, not data.
  if (std::abs(value) < 1e-12) value = 0.0;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  std::string text(buffer);
  // A value that rounds to zero may print as "-0"; a sign on zero means nothing to a reader.
  if (text == "-0") text = "0";
  return text;
}

double RoundToSignificant(double value, int significant) {
  if (!std::isfinite(value)) return value;
  return std::strtod(FormatNumber(value, significant).c_str(), nullptr);
}

}  // namespace mechanist
