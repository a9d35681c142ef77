#include "vsCoverageComposite.h"

#include "vsDisplayTransform.h"
#include "sampling/interpolation.h"
#include "sampling/octahedral.h"

#include "vtkSMPTools.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace vs
{
// What an accumulator of n samples of alpha 1 (a pixel that sees the environment in the opaque
// image) averages to, as MonteCarloPass::Mean() computes it (the sum is n exactly), and its
// per-sample variance as MonteCarloPass::Variance() computes it: under the coverage alpha
// (VS_BACKGROUND_ENVIRONMENT_COVERAGE) GetRadiance() reports these, as the opaque image did.
float CoverageComposite::OpaqueMean(uint32_t n)
{
  if (n == 0)
  {
    return 0.0f;
  }
  const float inv = 1.0f / float(n);
  return float(n) * inv;
}

double CoverageComposite::OpaqueVariance(uint32_t n)
{
  if (n < 2)
  {
    return 0.0;
  }
  const double N = n, m = OpaqueMean(n);
  return std::max(0.0, (double(float(n)) / N - m * m) * N / (N - 1.0));
}

// The environment's radiance (times scale) through the centre of each pixel of a w x h image under
// invViewProj: bilinear between octahedral texels, as the kernel shows the environment
// (env_radiance_display) and vtkEnvironmentMapBackground draws it.
std::vector<float> CoverageComposite::EnvironmentRadiance(
  const vs::EnvironmentMap& map, const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale)
{
  std::vector<float> out(size_t(w) * h * 3);
  const glm::dmat4 inv(invViewProj);
  const uint32_t n = uint32_t(map.Size);
  // Rows in parallel (vtkSMPTools): at 512^2 the full-resolution preview's frame paid ~13 ms here.
  vtkSMPTools::For(0, vtkIdType(h), [&](vtkIdType y0, vtkIdType y1) {
  for (uint32_t y = uint32_t(y0); y < uint32_t(y1); ++y)
  {
    for (uint32_t x = 0; x < w; ++x)
    {
      const glm::dvec2 ndc((x + 0.5) / w * 2.0 - 1.0, (y + 0.5) / h * 2.0 - 1.0);
      const glm::dvec4 pn = inv * glm::dvec4(ndc, -1.0, 1.0), pf = inv * glm::dvec4(ndc, 1.0, 1.0);
      const glm::dvec3 d = glm::dvec3(pf) / pf.w - glm::dvec3(pn) / pn.w;
      glm::vec3 radiance(0.0f);
      if (glm::length(d) > 0.0)
      {
        const glm::vec2 uv = vs::shared::vs_dir_to_octa(glm::vec3(glm::normalize(d)));
        for (uint32_t c = 0; c < 4u; ++c)
        {
          float weight = 0.0f;
          const glm::uvec2 t = vs::shared::vs_octa_bilinear_texel(uv, n, c, weight);
          radiance += weight * map.Texel(int(t.x), int(t.y));
        }
      }
      float* o = out.data() + 3 * (size_t(y) * w + x);
      for (int k = 0; k < 3; ++k)
      {
        o[k] = scale * radiance[k];
      }
    }
  }
  });
  return out;
}

// The environment's display colour (rgb in [0, 1]) through the centre of each pixel: its radiance
// (EnvironmentRadiance) through the display transform.
std::vector<float> CoverageComposite::EnvironmentDisplay(
  const vs::EnvironmentMap& map, const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale, bool toneMapping)
{
  std::vector<float> out = EnvironmentRadiance(map, invViewProj, w, h, scale);
  vtkSMPTools::For(0, vtkIdType(out.size()), [&](vtkIdType i0, vtkIdType i1) {
    for (vtkIdType i = i0; i < i1; ++i)
    {
      out[i] = vs::DisplayValue(out[i], toneMapping);
    }
  });
  return out;
}

void CoverageComposite::UpdateBackground(const EnvironmentMap& map, const glm::mat4& invViewProj, uint32_t w,
  uint32_t h, float scale, bool toneMapping, int environmentUploads)
{
  if (this->BackgroundStale(invViewProj, w, h, scale, toneMapping, environmentUploads))
  {
    this->BackgroundDisplay = EnvironmentDisplay(map, invViewProj, w, h, scale, toneMapping);
  }
}

void CoverageComposite::UpdateBackground(const std::vector<float>& radiance, float exposure,
  const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale, bool toneMapping, int environmentUploads)
{
  if (this->BackgroundStale(invViewProj, w, h, scale, toneMapping, environmentUploads))
  {
    this->BackgroundDisplay.resize(radiance.size());
    vtkSMPTools::For(0, vtkIdType(radiance.size()), [&](vtkIdType i0, vtkIdType i1) {
      for (vtkIdType i = i0; i < i1; ++i)
      {
        this->BackgroundDisplay[i] = vs::DisplayValue(exposure * radiance[i], toneMapping);
      }
    });
  }
}

bool CoverageComposite::BackgroundStale(
  const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale, bool toneMapping, int environmentUploads)
{
  std::vector<double> key(glm::value_ptr(invViewProj), glm::value_ptr(invViewProj) + 16);
  key.insert(key.end(), { double(w), double(h), double(environmentUploads), double(scale), toneMapping ? 1.0 : 0.0 });
  if (key == this->BackgroundKey && this->BackgroundDisplay.size() == size_t(w) * h * 3)
  {
    return false;
  }
  this->BackgroundKey = key;
  return true;
}

std::vector<float> CoverageComposite::Display(const std::vector<float>& mean,
  const std::vector<uint8_t>& environmentPixels, float opaqueAlpha, bool composite, float exposure,
  bool toneMapping) const
{
  std::vector<float> display(mean.size());
  vtkSMPTools::For(0, vtkIdType(mean.size() / 4), [&](vtkIdType p0, vtkIdType p1) {
  for (size_t i = 4 * size_t(p0); i < 4 * size_t(p1); i += 4)
  {
    const size_t pixel = i / 4;
    const bool seesEnvironment = !environmentPixels.empty() && environmentPixels[pixel];
    if (seesEnvironment && composite)
    {
      // The tone-mapped full radiance F(L) (the environment seen through the volume included) over
      // what is behind: drawn with the coverage a as C = F(L) - (1 - a) B, B the environment's
      // display colour, so that over the skybox (which shows B) the pixel is F(L) as in the opaque
      // image, and what VTK drew in front of the skybox shows through with the transmittance 1 - a.
      // C is clamped at 0; it is rarely below: F(L) >= F(T L_env), and the display transform (sRGB
      // over the filmic curve) is nearly concave with F(0) = 0, so F(T L_env) >= T F(L_env) but for
      // noise. Where no sample met the volume (a = 0) the pixel is what is behind it.
      const float a = std::clamp(mean[i + 3], 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c)
      {
        const float full = vs::DisplayValue(exposure * mean[i + c], toneMapping);
        display[i + c] = a > 0.0f ? std::max(0.0f, full - (1.0f - a) * this->BackgroundDisplay[3 * pixel + c]) : 0.0f;
      }
      display[i + 3] = a;
      continue;
    }
    // The opaque image's alpha where this volume paints the environment; else the coverage.
    float a = std::clamp(seesEnvironment ? opaqueAlpha : mean[i + 3], 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c)
    {
      // Premultiplied: tone map the radiance of the covered part, then weigh by coverage.
      float l = a > 0.0f ? exposure * mean[i + c] / a : 0.0f;
      display[i + c] = a * vs::DisplayValue(l, toneMapping);
    }
    display[i + 3] = a;
  }
  });
  return display;
}
}
