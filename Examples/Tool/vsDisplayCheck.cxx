#include "vsDisplayCheck.h"

#include <X11/Xlib.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace vs
{
void RequireDisplay()
{
  const char* name = std::getenv("DISPLAY");
  const std::string hint = "VTK's render windows need an X display here (Debian's VTK has neither EGL nor OSMesa); "
                           "on a headless machine run under `xvfb-run -a vissweep ...`";
  if (!name || !*name)
  {
    throw std::runtime_error("DISPLAY is not set. " + hint);
  }
  Display* display = XOpenDisplay(name);
  if (!display)
  {
    throw std::runtime_error("cannot open the X display '" + std::string(name) + "'. " + hint);
  }
  XCloseDisplay(display);
}
}
