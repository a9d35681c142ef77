// The display's guided filter of the estimate (vsDenoisePass.h, denoise_params.h; issue 39): it keeps a
// constant image, keeps an edge of its guide sharp, removes most of the noise of a synthetic estimate,
// and is deterministic. (That GetRadiance() is never filtered: Render.TestMapperDisplayDenoise.)
#include "vsContext.h"
#include "vsDenoisePass.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

namespace
{
const uint32_t W = 64, H = 48;

std::vector<float> Image(float r, float g, float b)
{
  std::vector<float> v;
  for (uint32_t i = 0; i < W * H; ++i)
    v.insert(v.end(), { r, g, b, 1.0f });
  return v;
}

// A scene with edges: discs and a step on a gradient, rgb of different levels.
float Truth(uint32_t x, uint32_t y, int c)
{
  const float base = 0.2f + 0.3f * float(x) / W + (x >= W / 2 ? 0.5f : 0.0f);
  const float dx = float(x) - 16.0f, dy = float(y) - 20.0f;
  const float disc = dx * dx + dy * dy < 64.0f ? 0.8f : 0.0f;
  return (base + disc) * (0.6f + 0.2f * float(c));
}

double MeanSquaredError(const std::vector<float>& x, const std::vector<float>& truth)
{
  double e = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    if (i % 4 == 3)
      continue;
    e += (double(x[i]) - truth[i]) * (double(x[i]) - truth[i]);
    ++n;
  }
  return e / double(n);
}
}

TEST(Denoise, KeepsAConstantImage)
{
  vs::DenoisePass pass(vs::Context::Default());
  const std::vector<float> constant = Image(0.3f, 0.5f, 0.7f);
  // A constant guide, whatever the variance: a g + b is the estimate's level.
  const std::vector<float> out = pass.Filter(constant, Image(2.0f, 1.0f, 0.1f), Image(0.01f, 0.01f, 0.01f), W, H, 4);
  ASSERT_EQ(out.size(), constant.size());
  for (size_t i = 0; i < out.size(); ++i)
    EXPECT_NEAR(out[i], constant[i], 1e-5f) << "pixel " << i / 4 << " channel " << i % 4;
  // A guide with edges and an exact estimate (no variance): the estimate, not the guide's edges.
  std::vector<float> guide(constant.size());
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x)
      for (int c = 0; c < 4; ++c)
        guide[4 * (y * W + x) + c] = c == 3 ? 1.0f : Truth(x, y, c);
  const std::vector<float> exact = pass.Filter(constant, guide, Image(0.0f, 0.0f, 0.0f), W, H, 4);
  for (size_t i = 0; i < exact.size(); ++i)
    EXPECT_NEAR(exact[i], constant[i], 1e-3f) << "pixel " << i / 4 << " channel " << i % 4;
  EXPECT_GT(pass.LastSeconds(), 0.0);
}

// The guide has a step at x = W/2 (0.2 to 1, every channel); the estimate is 0.8 x the guide plus noise
// of standard deviation 0.15 (its variance given). A box filter of the window's size would spread the
// step over 2r + 1 pixels; the guided filter keeps the columns next to the step at their levels.
TEST(Denoise, KeepsAnEdgeOfTheGuideSharp)
{
  vs::DenoisePass pass(vs::Context::Default());
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.0f, 0.15f);
  std::vector<float> guide, estimate;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x)
    {
      const float g = x < W / 2 ? 0.2f : 1.0f;
      guide.insert(guide.end(), { g, g, g, 1.0f });
      estimate.insert(estimate.end(), { 0.8f * g + noise(rng), 0.8f * g + noise(rng), 0.8f * g + noise(rng), 1.0f });
    }
  const uint32_t r = 6;
  const std::vector<float> out = pass.Filter(estimate, guide, Image(0.0225f, 0.0225f, 0.0225f), W, H, r);
  // The column means (over rows and channels) on either side of the step and r pixels away.
  auto column = [&](const std::vector<float>& im, uint32_t x) {
    double s = 0.0;
    for (uint32_t y = 0; y < H; ++y)
      for (int c = 0; c < 3; ++c)
        s += im[4 * (y * W + x) + c];
    return s / (3.0 * H);
  };
  for (uint32_t x : { W / 2 - r, W / 2 - 1, W / 2, W / 2 + r })
  {
    const double expected = x < W / 2 ? 0.16 : 0.8;
    EXPECT_NEAR(column(out, x), expected, 0.02) << "column " << x;
  }
  // And the noise is gone on either side: each pixel within 0.15 of its level (the noise's sd is 0.15).
  double worst = 0.0;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(out[4 * (y * W + x) + c]) - (x < W / 2 ? 0.16 : 0.8)));
  EXPECT_LT(worst, 0.15);
}

// A noisy estimate of a scene with edges and a guide that errs (a smooth multiplicative bias and an
// offset, as the preview's light volume does): the filtered image is several times closer to the truth
// than the estimate, and the estimate's own level wins over the guide's.
TEST(Denoise, ReducesTheErrorOfANoisyEstimate)
{
  vs::DenoisePass pass(vs::Context::Default());
  std::mt19937 rng(11);
  const float sd = 0.2f;
  std::normal_distribution<float> noise(0.0f, sd);
  std::vector<float> truth, guide, estimate;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x)
      for (int c = 0; c < 4; ++c)
      {
        const float t = c == 3 ? 1.0f : Truth(x, y, c);
        const float bias = 0.7f + 0.3f * float(y) / H;
        truth.push_back(t);
        guide.push_back(c == 3 ? 1.0f : t * bias + 0.05f);
        estimate.push_back(c == 3 ? 1.0f : t + noise(rng));
      }
  const std::vector<float> out = pass.Filter(estimate, guide, Image(sd * sd, sd * sd, sd * sd), W, H, 5);
  const double before = MeanSquaredError(estimate, truth), after = MeanSquaredError(out, truth),
               guideError = MeanSquaredError(guide, truth);
  std::printf("MSE: estimate %.3e, guide %.3e, filtered %.3e\n", before, guideError, after);
  EXPECT_LT(after, before / 5.0);
  EXPECT_LT(after, guideError / 5.0);
  // Deterministic: the same inputs give the same bits.
  const std::vector<float> again = pass.Filter(estimate, guide, Image(sd * sd, sd * sd, sd * sd), W, H, 5);
  EXPECT_EQ(0, std::memcmp(out.data(), again.data(), out.size() * sizeof(float)));
}

TEST(Denoise, RefusesImagesOfOtherSizes)
{
  vs::DenoisePass pass(vs::Context::Default());
  const std::vector<float> im = Image(1.0f, 1.0f, 1.0f);
  EXPECT_THROW(pass.Filter(im, std::vector<float>(im.size() - 4), im, W, H, 3), std::invalid_argument);
  EXPECT_THROW(pass.Filter(im, im, im, W, H + 1, 3), std::invalid_argument);
  EXPECT_TRUE(pass.Filter({}, {}, {}, 0, 0, 3).empty());
}
