#include "vtkVisSweepHeadlessWindow.h"

#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <algorithm>
#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkVisSweepHeadlessWindow);

namespace
{
// An 8-bit unsigned normalized channel as OpenGL (llvmpipe) stores a float: clamped to [0, 1], x 255
// in float, rounded half to even. A coverage of 1 of 6 samples is 42.5 x 255 exactly: rounded away from
// zero (std::lround) it was 1 off the OpenGL window (Render.TestHeadlessBlend).
unsigned char ToUnorm8(float v)
{
  v = std::min(std::max(v, 0.0f), 1.0f); // NaN: max(NaN, 0) is 0
  return static_cast<unsigned char>(std::nearbyint(v * 255.0f)); // the default rounding: half to even
}
}

vtkVisSweepHeadlessWindow::vtkVisSweepHeadlessWindow()
{
  this->SetOffScreenRendering(1);
  this->DoubleBuffer = 0;
  this->SetWindowName("VisSweep (headless)");
}

vtkVisSweepHeadlessWindow::~vtkVisSweepHeadlessWindow()
{
  // The renderers' props (the VisSweep mappers among them) let go of their device resources.
  vtkRenderer* ren;
  vtkCollectionSimpleIterator it;
  for (this->Renderers->InitTraversal(it); (ren = this->Renderers->GetNextRenderer(it));)
  {
    ren->SetRenderWindow(nullptr);
  }
}

void vtkVisSweepHeadlessWindow::Resize()
{
  const int* size = this->GetSize();
  const int w = std::max(0, size[0]), h = std::max(0, size[1]);
  if (w != this->PixelsSize[0] || h != this->PixelsSize[1])
  {
    this->Pixels.assign(size_t(w) * size_t(h) * 4, 0);
    this->PixelsSize[0] = w;
    this->PixelsSize[1] = h;
  }
}

void vtkVisSweepHeadlessWindow::Render()
{
  if (this->InRender)
  {
    return;
  }
  this->InRender = 1;
  this->InvokeEvent(vtkCommand::StartEvent);
  this->NeverRendered = 0;
  this->Resize();
  vtkRenderer* ren;
  vtkCollectionSimpleIterator it;
  for (this->Renderers->InitTraversal(it); (ren = this->Renderers->GetNextRenderer(it));)
  {
    if (!ren->GetDraw())
    {
      continue;
    }
    // As vtkRenderer::Render(): a renderer without a camera yet frames its props; the frame starts
    // with the StartEvent (VisSweep's mappers decide there which volume paints the environment).
    if (!ren->IsActiveCameraCreated())
    {
      ren->ResetCamera();
    }
    ren->InvokeEvent(vtkCommand::StartEvent);
    int w = 0, h = 0, x = 0, y = 0;
    ren->GetTiledSizeAndOrigin(&w, &h, &x, &y);
    int x2 = x + w - 1, y2 = y + h - 1;
    if (w > 0 && h > 0 && !ren->GetPreserveColorBuffer() && this->Clamp(x, y, x2, y2))
    {
      const double* bg = ren->GetBackground();
      const unsigned char clear[4] = { ToUnorm8(float(bg[0])), ToUnorm8(float(bg[1])), ToUnorm8(float(bg[2])),
        ToUnorm8(float(ren->GetBackgroundAlpha())) };
      for (int row = y; row <= y2; ++row)
      {
        for (int col = x; col <= x2; ++col)
        {
          std::memcpy(&this->Pixels[(size_t(row) * this->PixelsSize[0] + col) * 4], clear, 4);
        }
      }
    }
    // VisibleActorCount() counts the volumes too: look for the props that are not volumes.
    bool actors = false;
    vtkProp* prop;
    vtkCollectionSimpleIterator pit;
    for (ren->GetViewProps()->InitTraversal(pit); (prop = ren->GetViewProps()->GetNextProp(pit));)
    {
      actors = actors || (prop->GetVisibility() && !vtkVolume::SafeDownCast(prop));
    }
    if (actors && !this->WarnedActors)
    {
      this->WarnedActors = true;
      vtkWarningMacro(<< "draws volumes only: the renderer's actors are not drawn (they need an OpenGL window)");
    }
    vtkVolumeCollection* volumes = ren->GetVolumes();
    vtkVolume* volume;
    vtkCollectionSimpleIterator vit;
    for (volumes->InitTraversal(vit); (volume = volumes->GetNextVolume(vit));)
    {
      if (volume->GetVisibility())
      {
        volume->RenderVolumetricGeometry(ren);
      }
    }
    ren->InvokeEvent(vtkCommand::EndEvent);
  }
  this->InvokeEvent(vtkCommand::EndEvent);
  this->InRender = 0;
}

bool vtkVisSweepHeadlessWindow::Clamp(int& x, int& y, int& x2, int& y2) const
{
  if (x > x2)
  {
    std::swap(x, x2);
  }
  if (y > y2)
  {
    std::swap(y, y2);
  }
  x = std::max(x, 0);
  y = std::max(y, 0);
  x2 = std::min(x2, this->PixelsSize[0] - 1);
  y2 = std::min(y2, this->PixelsSize[1] - 1);
  return x <= x2 && y <= y2;
}

void vtkVisSweepHeadlessWindow::BlendPremultiplied(
  int x, int y, int x2, int y2, const float* rgba, int width, int height)
{
  this->Resize();
  const int w = x2 - x + 1, h = y2 - y + 1;
  if (!rgba || w <= 0 || h <= 0 || width <= 0 || height <= 0)
  {
    return;
  }
  for (int row = std::max(y, 0); row <= std::min(y2, this->PixelsSize[1] - 1); ++row)
  {
    const int sy = std::min(height - 1, int(int64_t(row - y) * height / h));
    for (int col = std::max(x, 0); col <= std::min(x2, this->PixelsSize[0] - 1); ++col)
    {
      const int sx = std::min(width - 1, int(int64_t(col - x) * width / w));
      const float* s = rgba + (size_t(sy) * width + sx) * 4;
      unsigned char* d = &this->Pixels[(size_t(row) * this->PixelsSize[0] + col) * 4];
      // As an OpenGL blend into an 8-bit buffer computes it (llvmpipe's, bit for bit): the source in
      // 8 bits, the destination times (255 - source alpha) / 255 rounded, the sum saturated.
      const unsigned keep = 255u - ToUnorm8(s[3]);
      for (int c = 0; c < 4; ++c)
      {
        unsigned t = unsigned(d[c]) * keep + 128u;
        t = (t + (t >> 8)) >> 8;
        d[c] = static_cast<unsigned char>(std::min(255u, unsigned(ToUnorm8(s[c])) + t));
      }
    }
  }
}

unsigned char* vtkVisSweepHeadlessWindow::GetPixelData(int x, int y, int x2, int y2, int front, int right)
{
  vtkNew<vtkUnsignedCharArray> data;
  if (!this->GetPixelData(x, y, x2, y2, front, data, right))
  {
    return nullptr;
  }
  auto* out = new unsigned char[data->GetNumberOfValues()];
  std::copy(data->GetPointer(0), data->GetPointer(0) + data->GetNumberOfValues(), out);
  return out;
}

int vtkVisSweepHeadlessWindow::GetPixelData(
  int x, int y, int x2, int y2, int, vtkUnsignedCharArray* data, int)
{
  vtkNew<vtkUnsignedCharArray> rgba;
  if (!this->GetRGBACharPixelData(x, y, x2, y2, 0, rgba, 0))
  {
    return 0;
  }
  const vtkIdType n = rgba->GetNumberOfTuples();
  data->SetNumberOfComponents(3);
  data->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      data->SetValue(i * 3 + c, rgba->GetValue(i * 4 + c));
    }
  }
  return 1;
}

unsigned char* vtkVisSweepHeadlessWindow::GetRGBACharPixelData(int x, int y, int x2, int y2, int front, int right)
{
  vtkNew<vtkUnsignedCharArray> data;
  if (!this->GetRGBACharPixelData(x, y, x2, y2, front, data, right))
  {
    return nullptr;
  }
  auto* out = new unsigned char[data->GetNumberOfValues()];
  std::copy(data->GetPointer(0), data->GetPointer(0) + data->GetNumberOfValues(), out);
  return out;
}

int vtkVisSweepHeadlessWindow::GetRGBACharPixelData(
  int x, int y, int x2, int y2, int, vtkUnsignedCharArray* data, int)
{
  this->Resize();
  if (x > x2)
  {
    std::swap(x, x2);
  }
  if (y > y2)
  {
    std::swap(y, y2);
  }
  const int w = x2 - x + 1, h = y2 - y + 1;
  data->SetNumberOfComponents(4);
  data->SetNumberOfTuples(vtkIdType(w) * h);
  // Pixels outside the window read as 0, as a framebuffer read outside its bounds leaves them.
  std::fill(data->GetPointer(0), data->GetPointer(0) + data->GetNumberOfValues(), 0);
  for (int row = std::max(y, 0); row <= std::min(y2, this->PixelsSize[1] - 1); ++row)
  {
    for (int col = std::max(x, 0); col <= std::min(x2, this->PixelsSize[0] - 1); ++col)
    {
      std::memcpy(data->GetPointer((vtkIdType(row - y) * w + (col - x)) * 4),
        &this->Pixels[(size_t(row) * this->PixelsSize[0] + col) * 4], 4);
    }
  }
  return 1;
}

float* vtkVisSweepHeadlessWindow::GetRGBAPixelData(int x, int y, int x2, int y2, int front, int right)
{
  vtkNew<vtkFloatArray> data;
  if (!this->GetRGBAPixelData(x, y, x2, y2, front, data, right))
  {
    return nullptr;
  }
  auto* out = new float[data->GetNumberOfValues()];
  std::copy(data->GetPointer(0), data->GetPointer(0) + data->GetNumberOfValues(), out);
  return out;
}

int vtkVisSweepHeadlessWindow::GetRGBAPixelData(int x, int y, int x2, int y2, int, vtkFloatArray* data, int)
{
  vtkNew<vtkUnsignedCharArray> rgba;
  if (!this->GetRGBACharPixelData(x, y, x2, y2, 0, rgba, 0))
  {
    return 0;
  }
  data->SetNumberOfComponents(4);
  data->SetNumberOfTuples(rgba->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgba->GetNumberOfValues(); ++i)
  {
    data->SetValue(i, float(rgba->GetValue(i)) / 255.0f);
  }
  return 1;
}

void vtkVisSweepHeadlessWindow::ReleaseRGBAPixelData(float* data)
{
  delete[] data;
}

int vtkVisSweepHeadlessWindow::GetColorBufferSizes(int* rgba)
{
  if (rgba)
  {
    rgba[0] = rgba[1] = rgba[2] = rgba[3] = 8;
  }
  return 32;
}

void vtkVisSweepHeadlessWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Image: " << this->PixelsSize[0] << " x " << this->PixelsSize[1]
     << " RGBA, 8 bits per channel (VisSweep volumes only, no OpenGL)\n";
}
