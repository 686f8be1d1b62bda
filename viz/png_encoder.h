#pragma once

#include <string>

#include "viz/image.h"

namespace mechanist {

/// The PNG file (RGB, 8 bits per channel) of `image`, as bytes (VTK's PNG writer).
std::string EncodePng(const Image& image);

}  // namespace mechanist
