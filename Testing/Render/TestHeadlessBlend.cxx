// vtkVisSweepHeadlessWindow::BlendPremultiplied against the OpenGL window's blend (issue 37): premultiplied
// float RGBA drawn as the mapper draws it (vtkOpenGLRenderWindow::DrawPixels under glBlendFuncSeparate
// ONE, ONE_MINUS_SRC_ALPHA) over a coloured background, and blended by the headless window over the same
// background: the same 8-bit pixels, bit for bit, for 16,384 random premultiplied colours, with values
// next to rounding ties (k + 1/2) / 255 and coverages j / n (where x 255 lands on a tie) among them.
#include "vsRenderTestUtilities.h"
#include "vtkVisSweepHeadlessWindow.h"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace
{
using vstest::Check;
constexpr int Size = 128;

std::vector<float> Colours()
{
  std::mt19937 rng(37);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> rgba(size_t(Size) * Size * 4);
  for (size_t p = 0; p < rgba.size() / 4; ++p)
  {
    float a = u(rng);
    if (p % 4 == 1)
    {
      a = (float(p % 255) + 0.5f) / 255.0f; // alpha next to a rounding tie
    }
    else if (p % 4 == 3)
    {
      // A coverage of j of n samples, as the Monte Carlo image's alpha: 1/6 x 255 is 42.5 exactly.
      const int n = 2 + int(p % 31);
      a = float(int(p / 4) % (n + 1)) / float(n);
    }
    rgba[p * 4 + 3] = a;
    for (int c = 0; c < 3; ++c)
    {
      // Premultiplied: colour <= alpha, a tone-mapped colour times the coverage; a quarter of them
      // next to a tie.
      rgba[p * 4 + c] = p % 4 == 2 ? std::min(a, (float((p * 7 + c) % 255) + 0.5f) / 255.0f) : a * u(rng);
    }
  }
  return rgba;
}

struct DrawData
{
  vtkRenderer* Renderer = nullptr;
  const std::vector<float>* Rgba = nullptr;
};

// The mapper's draw into an OpenGL window (vs::WindowCompositor::Draw), at the end of the renderer's frame.
void DrawInOpenGL(vtkObject*, unsigned long, void* client, void*)
{
  auto* d = static_cast<DrawData*>(client);
  auto* win = vtkOpenGLRenderWindow::SafeDownCast(d->Renderer->GetRenderWindow());
  vtkOpenGLState* state = win->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDisable(GL_DEPTH_TEST);
  win->DrawPixels(0, 0, Size - 1, Size - 1, 4, VTK_FLOAT, const_cast<float*>(d->Rgba->data()));
}
}

int TestHeadlessBlend(int, char*[])
{
  const std::vector<float> rgba = Colours();

  vtkNew<vtkRenderWindow> gl;
  gl->SetOffScreenRendering(1);
  gl->SetMultiSamples(0);
  gl->SetSize(Size, Size);
  vtkNew<vtkRenderer> glRenderer;
  glRenderer->SetBackground(0.2, 0.4, 0.6);
  gl->AddRenderer(glRenderer);
  DrawData data{ glRenderer, &rgba };
  vtkNew<vtkCallbackCommand> draw;
  draw->SetCallback(DrawInOpenGL);
  draw->SetClientData(&data);
  glRenderer->AddObserver(vtkCommand::EndEvent, draw);
  gl->Render();
  const std::vector<int> a = vstest::WindowPixels(gl);

  vtkNew<vtkVisSweepHeadlessWindow> headless;
  headless->SetSize(Size, Size);
  vtkNew<vtkRenderer> headlessRenderer;
  headlessRenderer->SetBackground(0.2, 0.4, 0.6);
  headless->AddRenderer(headlessRenderer);
  headless->Render(); // clears to the background
  headless->BlendPremultiplied(0, 0, Size - 1, Size - 1, rgba.data(), Size, Size);
  const std::vector<int> b = vstest::WindowPixels(headless);

  int differ = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    if (a[i] != b[i])
    {
      if (differ < 12)
      {
        const size_t p = i / 3, c = i % 3;
        std::printf("value %zu: source %.9g (x 255 = %.6f), alpha %.9g (x 255 = %.6f), background %d: OpenGL %d, "
                    "headless %d\n",
          i, double(rgba[p * 4 + c]), double(rgba[p * 4 + c]) * 255.0, double(rgba[p * 4 + 3]),
          double(rgba[p * 4 + 3]) * 255.0, int(c == 0 ? 51 : c == 1 ? 102 : 153), a[i], b[i]);
      }
      ++differ;
    }
  }
  std::printf("%zu values, %d differ, largest difference %d\n", a.size(), differ, vstest::MaxAbsoluteDifference(a, b));
  Check(a.size() == size_t(Size) * Size * 3 && a.size() == b.size(), "both windows read back");
  Check(differ == 0, "the headless blend is the OpenGL window's bit for bit (" + std::to_string(differ) + " values differ)");
  return vstest::ExitCode();
}
