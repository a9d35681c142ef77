// Uniform sphere and phase-function sampling (sampling/sphere.h), exactly as the
// shaders compile it: chi-square against each sampler's own pdf, plus the
// chi-square helper itself.
#include "sampling/rng.h"
#include "sampling/sphere.h"
#include "vsChiSquare.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vs::shared;

namespace
{

vec3 RandomDirection(VsRng& rng)
{
  return vs_sample_uniform_sphere(vs_rng_vec2(rng));
}

} // namespace

TEST(SamplingSphere, ChiSquarePValueMatchesTables)
{
  // dof 2 has the closed form exp(-x/2); the rest are textbook quantiles.
  for (double x : { 0.1, 1.0, 5.0, 20.0 })
  {
    EXPECT_NEAR(vstest::ChiSquarePValue(x, 2), std::exp(-0.5 * x), 1e-12);
  }
  EXPECT_NEAR(vstest::ChiSquarePValue(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(vstest::ChiSquarePValue(18.307038, 10), 0.05, 1e-6);
  EXPECT_NEAR(vstest::ChiSquarePValue(149.449252, 100), 0.001, 1e-6);
  EXPECT_NEAR(vstest::ChiSquarePValue(1023.0, 1023), 0.494, 2e-3);
}

TEST(SamplingSphere, ChiSquareRejectsAWrongPdf)
{
  // The helper must have power: a sampler with a slightly tilted density
  // (1 + 0.1 z) / 4π checked against the uniform pdf fails.
  auto tilted = [](vec2 u, float& pdf)
  {
    // Invert the cdf of z for p(z) ∝ 1 + a z on [-1, 1].
    const float a = 0.1f;
    float c = 2.0f * u.x - 1.0f; // uniform in [-1,1)
    float z = (-1.0f + std::sqrt(std::max(0.0f, 1.0f - 2.0f * a * (-c - 0.5f * a)))) / a;
    z = glm::clamp(z, -1.0f, 1.0f);
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    pdf = VS_INV_4PI;
    return vec3(r * std::cos(2.0f * VS_PI * u.y), r * std::sin(2.0f * VS_PI * u.y), z);
  };
  auto uniformPdf = [](vec3) { return VS_INV_4PI; };
  vstest::SamplerReport r =
    vstest::RunSamplerTest(tilted, uniformPdf, vstest::SamplerTestOptions());
  EXPECT_LT(r.chi.pValue, 1e-10) << r.Summary();
}

TEST(SamplingSphere, UniformMatchesPdf)
{
  auto sample = [](vec2 u, float& pdf)
  {
    pdf = vs_uniform_sphere_pdf();
    return vs_sample_uniform_sphere(u);
  };
  auto pdf = [](vec3) { return vs_uniform_sphere_pdf(); };
  EXPECT_TRUE(vstest::SamplerMatchesPdf(sample, pdf));
  EXPECT_FLOAT_EQ(vs_isotropic_phase_pdf(), float(1.0 / (4.0 * M_PI)));
}

TEST(SamplingSphere, UniformEndpoints)
{
  EXPECT_NEAR(vs_sample_uniform_sphere(vec2(0.0f)).z, 1.0f, 1e-7f);
  EXPECT_NEAR(vs_sample_uniform_sphere(vec2(VS_ONE_MINUS_EPSILON)).z, -1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(vs_sample_uniform_sphere(vec2(VS_ONE_MINUS_EPSILON))), 1.0f, 1e-6f);
}

TEST(SamplingSphere, CoordinateFrameIsOrthonormal)
{
  VsRng rng = vs_rng_init(uvec2(1u, 2u), 0u, 3u);
  std::vector<vec3> normals = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 },
    glm::normalize(vec3(1e-8f, 0.0f, -1.0f)) };
  for (int i = 0; i < 1000; ++i)
  {
    normals.push_back(RandomDirection(rng));
  }
  for (vec3 n : normals)
  {
    vec3 t, b;
    vs_coordinate_frame(n, t, b);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(b), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, b), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(b, n), 0.0f, 1e-5f);
    EXPECT_GT(glm::dot(glm::cross(t, b), n), 0.99f); // right-handed
  }
}

class SamplingSphereHG : public testing::TestWithParam<float>
{
};

TEST_P(SamplingSphereHG, MatchesPdf)
{
  const float g = GetParam();
  VsRng rng = vs_rng_init(uvec2(5u, 6u), 7u, uint(std::abs(g) * 1000.0f));
  const vec3 axis = RandomDirection(rng);
  auto sample = [&](vec2 u, float& pdf) { return vs_sample_hg(axis, g, u, pdf); };
  auto pdf = [&](vec3 w) { return vs_hg_pdf(glm::dot(axis, w), g); };
  vstest::SamplerTestOptions o;
  o.sub = 16; // the pdf is smooth but peaked: integrate it finely
  o.integralTolerance = 2e-3;
  o.pdfTolerance = 2e-3; // cos θ recomputed from the direction
  EXPECT_TRUE(vstest::SamplerMatchesPdf(sample, pdf, o)) << "g = " << g;
}

TEST_P(SamplingSphereHG, MeanCosineIsG)
{
  const float g = GetParam();
  const vec3 axis = glm::normalize(vec3(0.3f, -0.5f, 0.8f));
  VsRng rng = vs_rng_init(uvec2(8u, 9u), 1u, 2u);
  const int n = 200000;
  double sum = 0.0, sumSq = 0.0;
  for (int i = 0; i < n; ++i)
  {
    float pdf;
    double c = glm::dot(axis, vs_sample_hg(axis, g, vs_rng_vec2(rng), pdf));
    sum += c;
    sumSq += c * c;
  }
  double mean = sum / n, sigma = std::sqrt((sumSq / n - mean * mean) / n);
  EXPECT_NEAR(mean, std::abs(g) < VS_HG_ISOTROPIC_G ? 0.0 : g, 5.0 * sigma + 1e-4);
}

INSTANTIATE_TEST_SUITE_P(
  Sampling, SamplingSphereHG, testing::Values(-0.9f, -0.3f, 0.0f, 5e-4f, 2e-3f, 0.5f, 0.95f));

TEST(SamplingSphere, HenyeyGreensteinPdfIntegratesToOne)
{
  // ∫ p dω = 2π ∫_{-1}^{1} p(c) dc, by Simpson's rule in c.
  for (float g : { -0.99f, -0.5f, 0.0f, 1e-3f, 0.3f, 0.9f })
  {
    const int n = 2000000; // the g = -0.99 peak is 5e-5 wide in cos θ
    double s = 0.0;
    for (int i = 0; i <= n; ++i)
    {
      double c = -1.0 + 2.0 * i / n;
      double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      s += w * vs_hg_pdf(float(c), g);
    }
    EXPECT_NEAR(2.0 * M_PI * s * (2.0 / n) / 3.0, 1.0, 1e-4) << "g = " << g;
  }
}

TEST(SamplingSphere, HenyeyGreensteinIsotropicLimit)
{
  // Below |g| = 1e-3 sampler and pdf are exactly isotropic; just above, the pdf
  // differs from isotropic by O(g), so the switch is not a visible step.
  EXPECT_EQ(vs_hg_pdf(0.7f, 0.0f), VS_INV_4PI);
  EXPECT_EQ(vs_hg_pdf(-1.0f, -9e-4f), VS_INV_4PI);
  EXPECT_NEAR(vs_hg_pdf(1.0f, 1.01e-3f) / VS_INV_4PI, 1.0, 4e-3);
  EXPECT_NEAR(vs_hg_pdf(-1.0f, 1.01e-3f) / VS_INV_4PI, 1.0, 4e-3);
  EXPECT_EQ(vs_hg_sample_cos_theta(5e-4f, 0.25f), -0.5f);
}

TEST(SamplingSphere, HenyeyGreensteinCosThetaIsAccurate)
{
  // Against the textbook inverse cdf in double precision, for every g down to
  // the isotropic threshold and up to the strongest anisotropy.
  for (float g :
    { -0.9999f, -0.999f, -0.9f, -0.5f, -0.01f, -1.5e-3f, 1.5e-3f, 0.1f, 0.9f, 0.9999f })
  {
    double worst = 0.0;
    for (int i = 0; i <= 20000; ++i)
    {
      float u = std::min(i / 20000.0f, VS_ONE_MINUS_EPSILON);
      double gd = g, q = (1.0 - gd * gd) / (1.0 - gd + 2.0 * gd * u);
      double reference = (1.0 + gd * gd - q * q) / (2.0 * gd);
      worst = std::max(worst, std::abs(vs_hg_sample_cos_theta(g, u) - reference));
    }
    EXPECT_LT(worst, 2e-6) << "g = " << g;
  }
}

TEST(SamplingSphere, HenyeyGreensteinCosThetaIsMonotoneAndInRange)
{
  for (float g : { -0.999f, -0.5f, 2e-3f, 0.5f, 0.999f })
  {
    EXPECT_NEAR(vs_hg_sample_cos_theta(g, 0.0f), -1.0f, 1e-5f) << g;
    EXPECT_NEAR(vs_hg_sample_cos_theta(g, VS_ONE_MINUS_EPSILON), 1.0f, 2e-3f) << g;
    float previous = -1.0f;
    for (int i = 0; i <= 1000; ++i)
    {
      float c = vs_hg_sample_cos_theta(g, std::min(i / 1000.0f, VS_ONE_MINUS_EPSILON));
      ASSERT_TRUE(std::isfinite(c));
      ASSERT_GE(c, -1.0f);
      ASSERT_LE(c, 1.0f);
      EXPECT_GE(c, previous - 1e-5f) << "g " << g << " u " << i / 1000.0f;
      previous = c;
    }
  }
}
