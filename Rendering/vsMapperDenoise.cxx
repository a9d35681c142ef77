// vsMapperDenoise.cxx — vtkVisibilitySweepVolumeMapper's display filter (DisplayDenoise, issue 39): the
// guide it reads (the still preview of the view, or the hand-over's) and the filter of the image the
// window shows (vs::DenoisePass, a guided filter on the device). GetRadiance() is never filtered. Members
// of the mapper, in a file of their own.
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsMapperInternals.h"
#include "vsDenoisePass.h"

#include "vtkImageData.h"

#include <algorithm>
#include <cmath>

namespace
{
// The still preview's frames averaged into the guide, their offsets rotated (dither.h): the fixed
// pattern's moire (which the filter would copy from its guide) averages out.
const uint32_t GuideFrames = 4;

bool Finite(const std::vector<float>& v)
{
  for (float x : v)
  {
    if (!std::isfinite(x))
    {
      return false;
    }
  }
  return true;
}
}

void vtkVisibilitySweepVolumeMapper::UpdateDenoiseGuide(vtkRenderer* ren, vtkVolume* vol, uint32_t w, uint32_t h)
{
  Internals& I = *this->Impl;
  if (!this->DisplayDenoise || I.HandOver.Active) // the hand-over's preview guides while it lasts
  {
    return;
  }
  Internals::DenoiseGuide& g = I.Guide;
  if (g.Width != w || g.Height != h)
  {
    g = Internals::DenoiseGuide();
  }
  if (g.Frames >= GuideFrames)
  {
    return;
  }
  std::vector<float> frame;
  this->RenderLit(ren, vol, true, false, g.Frames, &frame);
  if (frame.size() != size_t(w) * h * 4)
  {
    return; // nothing to guide with (the estimate is shown as it is)
  }
  if (g.Frames == 0)
  {
    g.Rgba = std::move(frame);
    g.Width = w;
    g.Height = h;
  }
  else
  {
    const float k = float(g.Frames);
    for (size_t i = 0; i < frame.size(); ++i)
    {
      g.Rgba[i] += (frame[i] - g.Rgba[i]) / (k + 1.0f);
    }
  }
  ++g.Frames;
}

void vtkVisibilitySweepVolumeMapper::DenoiseDisplay(std::vector<float>& shown, const std::vector<double>& variance,
  uint32_t samples, double previewShare, uint32_t w, uint32_t h)
{
  Internals& I = *this->Impl;
  this->LastDisplayDenoised = false;
  if (!this->DisplayDenoise || samples < 2 || variance.size() != shown.size())
  {
    return; // one sample has no variance to weigh the fit with
  }
  const std::vector<float>* guide = nullptr;
  if (I.HandOver.Active && I.HandOver.Rgba.size() == shown.size())
  {
    guide = &I.HandOver.Rgba;
  }
  else if (I.Guide.Width == w && I.Guide.Height == h && I.Guide.Rgba.size() == shown.size())
  {
    guide = &I.Guide.Rgba;
  }
  if (!guide || !Finite(shown) || !Finite(*guide))
  {
    return;
  }
  // The variance of each pixel of the image shown: (1 - s)^2 times the estimate's, during the hand-over.
  // A pixel whose samples all agree (their per-sample variance below 1e-4 of its square in every channel:
  // the float sums' rounding, where the environment is seen past the volume) is exact: variance 0, shown
  // as it is and left out of the fits (denoise_params.h).
  const double factor = (1.0 - previewShare) * (1.0 - previewShare) / double(samples);
  std::vector<float> noise(variance.size(), 0.0f);
  for (size_t i = 0; i + 3 < variance.size(); i += 4)
  {
    bool exact = true;
    for (size_t c = 0; c < 3; ++c)
    {
      const double m = shown[i + c];
      exact = exact && !(variance[i + c] > 1e-4 * m * m);
    }
    for (size_t c = 0; c < 3 && !exact; ++c)
    {
      const double v = variance[i + c] * factor;
      noise[i + c] = std::isfinite(v) ? float(v) : 0.0f;
    }
  }
  if (!I.Denoise)
  {
    I.Denoise = std::make_unique<vs::DenoisePass>(I.Context);
  }
  std::vector<float> filtered = I.Denoise->Filter(shown, *guide, noise, w, h, uint32_t(this->DisplayDenoiseRadius));
  this->LastDenoiseSeconds = I.Denoise->LastSeconds();
  // The filter's bias (what the preview lacks at finer scale than the window) does not fall with samples;
  // the estimate's variance does. As the hand-over does with the preview, the image shown is the blend of
  // least expected error, (1 - f) x shown + f x filtered with f = V / (V + B): V the mean variance of the
  // pixels shown, B the filtered image's squared bias, its mean squared difference from them less V
  // (the filtered image's own noise neglected). Early f ~ 1; once the estimate's noise falls below the
  // filter's bias the estimate takes over (measured: docs/benchmarks.md, "A clean image early").
  double V = 0.0, D = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < shown.size(); ++i)
  {
    if (i % 4 == 3)
    {
      continue;
    }
    const double d = double(filtered[i]) - double(shown[i]);
    V += double(noise[i]);
    D += d * d;
    ++n;
  }
  V /= double(std::max<size_t>(n, 1));
  D /= double(std::max<size_t>(n, 1));
  const double B = std::max(0.0, D - V);
  const double f = V + B > 0.0 && std::isfinite(V + B) ? V / (V + B) : 0.0;
  for (size_t i = 0; i < shown.size(); ++i)
  {
    if (i % 4 != 3)
    {
      shown[i] = float((1.0 - f) * double(shown[i]) + f * double(filtered[i]));
    }
  }
  this->LastDisplayDenoised = f > 0.0;
}

vtkImageData* vtkVisibilitySweepVolumeMapper::GetDisplayedRadiance()
{
  return this->Impl->Displayed;
}
