// vsDisplayCheck.h — the command-line tool renders through a VTK window, and Debian's
// VTK can only open one on an X display (it has neither EGL nor OSMesa). VTK aborts
// the process when the display is missing; this check turns that into an error that
// says what to do.
#ifndef vsDisplayCheck_h
#define vsDisplayCheck_h

namespace vs
{
/** Throws std::runtime_error naming the cause when no X display can be opened. */
void RequireDisplay();
}

#endif
