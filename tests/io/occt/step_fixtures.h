#pragma once

#include <filesystem>

namespace mechanist::testing {

/// Writes a STEP file (AP214, no product names) of three solids built with Open CASCADE, whose
/// faces the tests know by construction:
/// - a 40 x 40 x 10 mm block (corner at the origin) with a 6 mm through hole along z at
///   (20, 20), countersunk 90 degrees to 12 mm at its top (the cone from z = 7 up);
/// - a 5 mm shaft along z at (60, 20) from z = 20 to 40 with a conical point of 5 mm below it
///   (included angle 2 atan(2.5 / 5));
/// - a 10 mm ball at (0, 60, 5).
/// Throws std::runtime_error when it cannot write the file.
void WriteConesAndBallStep(const std::filesystem::path& file);

}  // namespace mechanist::testing
