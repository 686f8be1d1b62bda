#pragma once

#include <string>

namespace mechanist {

/// `value` with at most `significant` significant digits, no trailing zeros (printf's %.*g);
/// magnitudes below 1e-12 and "-0" print as "0": for messages and reports that must be
/// identical across runs and free of rotation round-off.
std::string FormatNumber(double value, int significant = 6);

/// `value` rounded as FormatNumber prints it (not-finite values unchanged): the numbers of
/// JSON reports, byte-identical across runs.
double RoundToSignificant(double value, int significant = 9);

}  // namespace mechanist
