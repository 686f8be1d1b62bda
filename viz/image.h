#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mechanist {

/// An 8-bit RGB raster, rows from the top, three bytes per pixel.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes

  /// The first byte of pixel (column x, row y from the top).
  const std::uint8_t* At(int x, int y) const {
    return rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x);
  }
};

}  // namespace mechanist
