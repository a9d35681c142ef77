// vsDisplayCheck.h — the tool renders into a vtkVisSweepHeadlessWindow (no display); only what
// measures VTK's OpenGL window (bench frames) opens one, and Debian's VTK can only open one on an
// X display (it has neither EGL nor OSMesa). VTK aborts the process when the display is missing;
// this check turns that into an error that says what to do.
#ifndef vsDisplayCheck_h
#define vsDisplayCheck_h

namespace vs
{
/** Throws std::runtime_error naming the cause when no X display can be opened. */
void RequireDisplay();
}

#endif
