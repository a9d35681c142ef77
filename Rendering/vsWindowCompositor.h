// vsWindowCompositor.h — the mapper's meeting point with VTK's OpenGL window:
// reads the opaque depth of a renderer's viewport, and draws a premultiplied
// RGBA float image over it (blend ONE, ONE_MINUS_SRC_ALPHA), restoring the
// OpenGL state it touched.
#ifndef vsWindowCompositor_h
#define vsWindowCompositor_h

#include <vector>

class vtkRenderer;

namespace vs
{
struct Viewport
{
  int X = 0, Y = 0, Width = 0, Height = 0;
};

class WindowCompositor
{
public:
  static Viewport GetViewport(vtkRenderer* ren);
  /** Whether `ren`'s window draws the renderer's actors (a vtkSkybox background among them): false
   *  in a vtkVisSweepHeadlessWindow, where a volume paints the environment it shows itself. */
  static bool DrawsActors(vtkRenderer* ren);
  /** Window depth in [0,1] per pixel of the viewport, rows bottom-up. */
  static std::vector<float> ReadDepth(vtkRenderer* ren, const Viewport& vp);
  /** Draws `rgba` (premultiplied, vp.Width x vp.Height, rows bottom-up) over the viewport. */
  static bool Draw(vtkRenderer* ren, const Viewport& vp, const std::vector<float>& rgba);
  /** Draws a smaller `rgba` (width x height) stretched over the viewport (interactive frames). */
  static bool DrawScaled(
    vtkRenderer* ren, const Viewport& vp, const std::vector<float>& rgba, int width, int height);
  /** While one lives, Draw() and DrawScaled() draw nothing (a mapper with DrawImage off renders). */
  class Suppress
  {
  public:
    explicit Suppress(bool on);
    ~Suppress();
    Suppress(const Suppress&) = delete;
    Suppress& operator=(const Suppress&) = delete;

  private:
    bool On;
  };
};
}

#endif
