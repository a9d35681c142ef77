#include "vsCoverageComposite.h"

#include "sampling/display_transform.h"
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
// (environment_display.glsl) and vtkEnvironmentMapBackground draws it.
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
      out[i] = vs::shared::vs_display_value(out[i], toneMapping);
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
    for (vtkIdType pixel = p0; pixel < p1; ++pixel)
    {
      const bool seesEnvironment = !environmentPixels.empty() && environmentPixels[pixel];
      const bool over = seesEnvironment && composite;
      const glm::vec3 background = over ? glm::make_vec3(this->BackgroundDisplay.data() + 3 * pixel) : glm::vec3(0.0f);
      const glm::vec4 c = vs::shared::vs_display_pixel(glm::make_vec4(mean.data() + 4 * pixel), seesEnvironment,
        composite, background, opaqueAlpha, exposure, toneMapping);
      std::copy(glm::value_ptr(c), glm::value_ptr(c) + 4, display.data() + 4 * pixel);
    }
  });
  return display;
}
}
