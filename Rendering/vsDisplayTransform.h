// vsDisplayTransform.h — the display transform of linear radiance shared by the mapper's window
// image and the environment background (vtkEnvironmentMapBackground): exposure, the filmic tone
// curve (Narkowicz's fit of ACES) or a clamp, then the sRGB transfer function.
#ifndef vsDisplayTransform_h
#define vsDisplayTransform_h

#include <algorithm>
#include <cmath>

namespace vs
{
inline float Filmic(float x)
{
  return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

inline float ToSRGB(float x)
{
  x = std::clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

/** The display value in [0, 1] of radiance `l` already multiplied by the exposure. */
inline float DisplayValue(float l, bool toneMapping)
{
  return ToSRGB(toneMapping ? Filmic(l) : std::min(l, 1.0f));
}
}

#endif
