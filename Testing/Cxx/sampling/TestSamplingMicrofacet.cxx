// The surface lobe of hybrid scattering (sampling/microfacet.h), exactly as the path kernel compiles it:
// its sampling against its own pdf (chi-square), reciprocity, directional albedo <= 1 (= kd without the
// specular part), VTK's settings' mappings and the surface event's probability.
#include "sampling/microfacet.h"
#include "sampling/rng.h"
#include "vsChiSquare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

using namespace vs::shared;

namespace
{
vec3 RandomDirection(VsRng& rng)
{
  return vs_sample_uniform_sphere(vs_rng_vec2(rng));
}

// (roughness, ks, kd) cases: diffuse only, specular only, both, rough and smooth.
struct Lobe
{
  float alpha, ks, kd;
};
const Lobe kLobes[] = { { 0.5f, 0.0f, 1.0f }, { 0.3f, 1.0f, 0.0f }, { 0.15f, 0.4f, 0.6f }, { 1.0f, 0.5f, 0.5f },
  { 0.05f, 0.8f, 0.2f } };
}

class SamplingMicrofacet : public testing::TestWithParam<std::tuple<int, float>>
{
};

// The sampler draws from vs_surface_pdf over the whole sphere (the pdf integrates to 1), for a normal on
// either side of wo and wo from head-on to grazing.
TEST_P(SamplingMicrofacet, MatchesPdf)
{
  const Lobe lobe = kLobes[std::get<0>(GetParam())];
  const float cosO = std::get<1>(GetParam());
  VsRng rng = vs_rng_init(uvec2(3u, uint(std::get<0>(GetParam()))), 11u, uint(cosO * 1000.0f));
  const vec3 n = RandomDirection(rng);
  vec3 t, b;
  vs_coordinate_frame(n, t, b);
  // wo at cos(n, wo) = cosO; a negative cosO puts the normal on the other side (two-sided).
  const vec3 wo = glm::normalize(cosO * n + std::sqrt(1.0f - cosO * cosO) * t);
  const vec3 kd(lobe.kd, 0.8f * lobe.kd, 0.5f * lobe.kd);
  auto sample = [&](vec2 u, float& pdf) { return vs_sample_surface(n, wo, kd, lobe.ks, lobe.alpha, u, pdf); };
  auto pdf = [&](vec3 w) { return vs_surface_pdf(n, wo, w, kd, lobe.ks, lobe.alpha); };
  vstest::SamplerTestOptions o;
  o.sub = lobe.alpha < 0.1f ? 32 : 16; // smooth but peaked: integrate finely
  o.integralTolerance = lobe.alpha < 0.1f ? 1e-2 : 3e-3;
  o.pdfTolerance = 2e-3; // the half vector recomputed from the direction
  EXPECT_TRUE(vstest::SamplerMatchesPdf(sample, pdf, o))
    << "alpha " << lobe.alpha << " ks " << lobe.ks << " kd " << lobe.kd << " cos " << cosO;
}

INSTANTIATE_TEST_SUITE_P(Sampling, SamplingMicrofacet,
  testing::Combine(testing::Values(0, 1, 2, 3, 4), testing::Values(0.95f, 0.4f, -0.7f, 0.08f)));

// The chi-square helper has power against this pdf: a sampler whose specular half vectors are drawn
// with a roughness 10% off fails.
TEST(SamplingMicrofacetHelper, RejectsAWrongRoughness)
{
  const vec3 n(0.0f, 0.0f, 1.0f), wo = glm::normalize(vec3(0.3f, 0.0f, 1.0f));
  auto sample = [&](vec2 u, float& pdf) {
    vec3 w = vs_sample_surface(n, wo, vec3(0.0f), 1.0f, 0.33f, u, pdf);
    pdf = vs_surface_pdf(n, wo, w, vec3(0.0f), 1.0f, 0.3f);
    return w;
  };
  auto pdf = [&](vec3 w) { return vs_surface_pdf(n, wo, w, vec3(0.0f), 1.0f, 0.3f); };
  vstest::SamplerTestOptions o;
  o.sub = 16;
  o.pdfTolerance = 1.0; // the sample's pdf is the claimed one; only the histogram may tell
  vstest::SamplerReport r = vstest::RunSamplerTest(sample, pdf, o);
  EXPECT_LT(r.chi.pValue, 1e-10) << r.Summary();
}

// f(wo, wi) = f(wi, wo) for random pairs on either side of the normal.
TEST(SamplingMicrofacetHelper, Reciprocal)
{
  VsRng rng = vs_rng_init(uvec2(1u, 2u), 3u, 4u);
  int nonZero = 0;
  for (int i = 0; i < 20000; ++i)
  {
    const vec3 n = RandomDirection(rng), a = RandomDirection(rng), b = RandomDirection(rng);
    const Lobe& lobe = kLobes[i % 5];
    const vec3 kd(lobe.kd, 0.5f, 0.25f);
    const vec3 fab = vs_surface_brdf(n, a, b, kd, lobe.ks, lobe.alpha);
    const vec3 fba = vs_surface_brdf(n, b, a, kd, lobe.ks, lobe.alpha);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_NEAR(fab[c], fba[c], 1e-4f * std::max(1.0f, fab[c])) << i;
      ASSERT_GE(fab[c], 0.0f);
    }
    nonZero += fab.x > 0.0f ? 1 : 0;
    // Two-sided: the normal's sign does not matter.
    const vec3 flipped = vs_surface_brdf(-n, a, b, kd, lobe.ks, lobe.alpha);
    ASSERT_NEAR(flipped.x, fab.x, 1e-5f * std::max(1.0f, fab.x));
  }
  EXPECT_GT(nonZero, 8000) << "half the pairs lie on one side of the surface";
  // Transmission is 0: the lobe reflects only.
  EXPECT_EQ(vs_surface_brdf(vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 0, -1), vec3(1.0f), 0.5f, 0.3f), vec3(0.0f));
}

// The directional albedo int f |n.wi| dwi, estimated by importance sampling (f |cos| / pdf): at most 1 for
// kd + ks = 1, exactly kd for ks = 0 (Lambert), and above 0.8 kd + ks for the smooth lobe at normal incidence.
TEST(SamplingMicrofacetHelper, DirectionalAlbedoAtMostOne)
{
  const vec3 n(0.0f, 0.0f, 1.0f);
  for (const Lobe& lobe : kLobes)
  {
    for (float cosO : { 1.0f, 0.7f, 0.3f, 0.05f })
    {
      const vec3 wo(std::sqrt(1.0f - cosO * cosO), 0.0f, cosO);
      const vec3 kd(lobe.kd);
      VsRng rng = vs_rng_init(uvec2(7u, 8u), 9u, uint(cosO * 100.0f));
      const int count = 200000;
      double sum = 0.0, sumSq = 0.0;
      for (int i = 0; i < count; ++i)
      {
        float pdf;
        const vec3 wi = vs_sample_surface(n, wo, kd, lobe.ks, lobe.alpha, vs_rng_vec2(rng), pdf);
        const double v = pdf > 0.0f ? vs_surface_brdf(n, wo, wi, kd, lobe.ks, lobe.alpha).x * std::abs(wi.z) / pdf : 0.0;
        sum += v;
        sumSq += v * v;
      }
      const double mean = sum / count, se = std::sqrt(std::max(0.0, sumSq / count - mean * mean) / count);
      EXPECT_LE(mean, 1.0 + 4.0 * se) << "alpha " << lobe.alpha << " cos " << cosO;
      if (lobe.ks == 0.0f)
        EXPECT_NEAR(mean, lobe.kd, 1e-5) << "Lambert alone: every sample is kd exactly";
      if (cosO == 1.0f && lobe.alpha <= 0.15f) // at 0.3, 8% of the normals reflect below the horizon
        EXPECT_GT(mean, 0.95 * (lobe.kd + lobe.ks)) << "a smooth lobe loses little at normal incidence, alpha " << lobe.alpha;
    }
  }
}

TEST(SamplingMicrofacetHelper, VtkSettings)
{
  // Walter et al.'s mapping: SpecularPower 10 (VTK's default) -> sqrt(1/6); 0 -> 1; 128 -> 0.124.
  EXPECT_NEAR(vs_roughness_from_specular_power(10.0f), std::sqrt(1.0f / 6.0f), 1e-6f);
  EXPECT_EQ(vs_roughness_from_specular_power(0.0f), 1.0f);
  EXPECT_NEAR(vs_roughness_from_specular_power(128.0f), 0.1240f, 1e-4f);
  EXPECT_EQ(vs_roughness_from_specular_power(1e30f), VS_MIN_ROUGHNESS);
  EXPECT_EQ(vs_roughness_from_specular_power(-5.0f), 1.0f);
  // Diffuse and specular sum to at most 1.
  EXPECT_EQ(vs_surface_weights(1.0f, 0.0f), vec2(1.0f, 0.0f));
  EXPECT_EQ(vs_surface_weights(0.7f, 0.2f), vec2(0.7f, 0.2f));
  EXPECT_EQ(vs_surface_weights(1.0f, 1.0f), vec2(0.5f, 0.5f));
  EXPECT_EQ(vs_surface_weights(-1.0f, 0.5f), vec2(0.0f, 0.5f));
}

TEST(SamplingMicrofacetHelper, SurfaceProbability)
{
  // Blending 2: never a surface; blending 0: wherever the gradient allows; 1: Exposure Render's
  // a (1 - exp(-25 g)); no gradient: never.
  for (float g : { 0.0f, 0.01f, 0.3f, 1.0f })
    for (float a : { 0.0f, 0.5f, 1.0f })
    {
      EXPECT_EQ(vs_surface_probability(2.0f, g, a), 0.0f);
      EXPECT_NEAR(vs_surface_probability(0.0f, g, a), 1.0f - std::exp(-25.0f * g), 1e-6f);
      EXPECT_NEAR(vs_surface_probability(1.0f, g, a), a * (1.0f - std::exp(-25.0f * g)), 1e-6f);
      EXPECT_EQ(vs_surface_probability(1.3f, 0.0f, a), 0.0f);
      // Continuous at 1.
      EXPECT_NEAR(vs_surface_probability(1.0f - 1e-4f, g, a), vs_surface_probability(1.0f + 1e-4f, g, a), 1e-3f);
    }
  // More blending, less surface; more gradient or opacity, more surface.
  float last = 2.0f;
  for (float b : { 0.0f, 0.25f, 0.5f, 0.75f, 1.0f, 1.25f, 1.5f, 2.0f })
  {
    const float p = vs_surface_probability(b, 0.6f, 0.8f);
    EXPECT_LE(p, last) << b;
    EXPECT_GE(p, 0.0f);
    EXPECT_LE(p, 1.0f);
    last = p;
  }
  EXPECT_LT(vs_surface_probability(1.0f, 0.2f, 0.5f), vs_surface_probability(1.0f, 0.8f, 0.5f));
  EXPECT_LT(vs_surface_probability(1.0f, 0.8f, 0.2f), vs_surface_probability(1.0f, 0.8f, 0.9f));
  EXPECT_GT(vs_surface_probability(1.0f, 1.0f, 1.0f), 0.99f);
}
