#include "vsSurfaceScattering.h"
#include "sampling/microfacet.h"
#include "vsError.h"

#include <cmath>
#include <string>

namespace vs
{
bool SurfaceScattering::Enabled(const shared::VsMonteCarloParams& params)
{
  return params.surface != 0u && params.surfaceBlending < 2.0f;
}

void SurfaceScattering::Check(const shared::VsMonteCarloParams& params)
{
  if (params.surface == 0u)
  {
    return;
  }
  auto fail = [](const std::string& what, float value, const std::string& range) {
    throw InputError("the surface scattering's " + what + " must be " + range + ", got " + std::to_string(value));
  };
  if (!(params.surfaceBlending >= 0.0f && params.surfaceBlending <= 2.0f))
  {
    fail("volumetric scattering blending", params.surfaceBlending, "in [0, 2]");
  }
  if (!(params.surfaceDiffuse >= 0.0f && std::isfinite(params.surfaceDiffuse)))
  {
    fail("diffuse weight", params.surfaceDiffuse, "finite and >= 0");
  }
  if (!(params.surfaceSpecular >= 0.0f && std::isfinite(params.surfaceSpecular)))
  {
    fail("specular weight", params.surfaceSpecular, "finite and >= 0");
  }
  if (!(params.surfaceDiffuse + params.surfaceSpecular <= 1.0f + 1e-6f))
  {
    fail("diffuse plus specular weight", params.surfaceDiffuse + params.surfaceSpecular, "at most 1");
  }
  if (!(params.surfaceRoughness > 0.0f && params.surfaceRoughness <= 1.0f))
  {
    fail("roughness", params.surfaceRoughness, "in (0, 1]");
  }
  if (!(params.gradientScale >= 0.0f && std::isfinite(params.gradientScale)))
  {
    fail("gradient scale", params.gradientScale, "finite and >= 0");
  }
  if (!(params.opacityDistance >= 0.0f && std::isfinite(params.opacityDistance)))
  {
    fail("opacity distance", params.opacityDistance, "finite and >= 0");
  }
}

double SurfaceScattering::ScalarRange(const shared::VsMonteCarloParams& params)
{
  const double perUnit = params.volume.tf.entriesPerUnit;
  const double range = perUnit > 0.0 ? (double(params.volume.tf.entries) - 1.0) / perUnit : 0.0;
  return std::isfinite(range) && range > 0.0 ? range : 0.0;
}

void SurfaceScattering::Set(shared::VsMonteCarloParams& params, const Settings& settings, double scalarRange,
  double meanSpacing, double unitDistance, double densityScale)
{
  params.surface = settings.Shade ? 1u : 0u;
  params.surfaceBlending = float(settings.Blending);
  const glm::vec2 w = shared::vs_surface_weights(float(settings.Diffuse), float(settings.Specular));
  params.surfaceDiffuse = w.x;
  params.surfaceSpecular = w.y;
  params.surfaceRoughness = shared::vs_roughness_from_specular_power(float(settings.SpecularPower));
  // A constant volume (range 0) has no gradient anywhere; its scale is then immaterial.
  const double scale = scalarRange > 0.0 && std::isfinite(scalarRange) ? meanSpacing / (0.25 * scalarRange) : 0.0;
  params.gradientScale = std::isfinite(scale) && scale < 3.0e38 ? float(scale) : 0.0f;
  const double distance = densityScale > 0.0 ? unitDistance / densityScale : 0.0;
  params.opacityDistance = std::isfinite(distance) && distance < 3.0e38 ? float(distance) : 0.0f;
}
}
