#pragma once

#include <string>

namespace mechanist {

/// True when an X display can be opened (VTK's OpenGL windows on Linux need one, even off
/// screen, and abort the process without it). Otherwise false, with in `reason` what was
/// tried and how to get one (xvfb-run).
bool DisplayAvailable(std::string* reason);

}  // namespace mechanist
