#include "vsWindowCompositor.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkVisSweepHeadlessWindow.h"
#include "vtk_glew.h"

namespace vs
{
namespace
{
int suppressed = 0; // Suppress scopes alive (rendering is single threaded, as VTK's is)
}

WindowCompositor::Suppress::Suppress(bool on)
  : On(on)
{
  suppressed += on ? 1 : 0;
}

WindowCompositor::Suppress::~Suppress()
{
  suppressed -= this->On ? 1 : 0;
}

Viewport WindowCompositor::GetViewport(vtkRenderer* ren)
{
  Viewport vp;
  ren->GetTiledSizeAndOrigin(&vp.Width, &vp.Height, &vp.X, &vp.Y);
  return vp;
}

bool WindowCompositor::DrawsActors(vtkRenderer* ren)
{
  return !vtkVisSweepHeadlessWindow::SafeDownCast(ren->GetRenderWindow());
}

std::vector<float> WindowCompositor::ReadDepth(vtkRenderer* ren, const Viewport& vp)
{
  std::vector<float> depth(size_t(vp.Width) * vp.Height, 1.0f);
  if (vp.Width > 0 && vp.Height > 0)
  {
    ren->GetRenderWindow()->GetZbufferData(vp.X, vp.Y, vp.X + vp.Width - 1, vp.Y + vp.Height - 1, depth.data());
  }
  return depth;
}

bool WindowCompositor::Draw(vtkRenderer* ren, const Viewport& vp, const std::vector<float>& rgba)
{
  return DrawScaled(ren, vp, rgba, vp.Width, vp.Height);
}

bool WindowCompositor::DrawScaled(
  vtkRenderer* ren, const Viewport& vp, const std::vector<float>& rgba, int width, int height)
{
  if (vp.Width <= 0 || vp.Height <= 0 || suppressed > 0)
  {
    return false;
  }
  if (auto* headless = vtkVisSweepHeadlessWindow::SafeDownCast(ren->GetRenderWindow()))
  {
    // No OpenGL: the same blend into the window's 8-bit image.
    headless->BlendPremultiplied(vp.X, vp.Y, vp.X + vp.Width - 1, vp.Y + vp.Height - 1, rgba.data(), width, height);
    return true;
  }
  auto* win = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!win)
  {
    return false;
  }
  vtkOpenGLState* state = win->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  if (width == vp.Width && height == vp.Height)
  {
    win->DrawPixels(vp.X, vp.Y, vp.X + vp.Width - 1, vp.Y + vp.Height - 1, 4, VTK_FLOAT,
      const_cast<float*>(rgba.data()));
  }
  else
  {
    win->DrawPixels(vp.X, vp.Y, vp.X + vp.Width - 1, vp.Y + vp.Height - 1, 0, 0, width - 1, height - 1, width,
      height, 4, VTK_FLOAT, const_cast<float*>(rgba.data()));
  }
  return true;
}
}
