#include "viz/display.h"

#include <X11/Xlib.h>
#include <fmt/format.h>

#include <cstdlib>

namespace mechanist {

bool DisplayAvailable(std::string* reason) {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') {
    if (reason) {
      *reason =
          "no display: DISPLAY is not set; rendering needs an X server, run under "
          "xvfb-run -a -s \"-screen 0 1920x1080x24\" (Debian package xvfb), or write only "
          "--format pvd,glb";
    }
    return false;
  }
  Display* display = XOpenDisplay(name);
  if (display == nullptr) {
    if (reason) {
      *reason = fmt::format(
          "no display: cannot open DISPLAY={}; run under xvfb-run -a -s \"-screen 0 "
          "1920x1080x24\" (Debian package xvfb), or write only --format pvd,glb",
          name);
    }
    return false;
  }
  // Kept open for the life of the process: an X server started with xvfb-run resets when its
  // last client leaves, and a render window that connects during the reset fails (VTK then
  // aborts). One connection held here keeps the server up between render windows.
  static Display* kept = nullptr;
  if (kept == nullptr) {
    kept = display;
  } else {
    XCloseDisplay(display);
  }
  return true;
}

}  // namespace mechanist
