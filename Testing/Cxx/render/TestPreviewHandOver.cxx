// The hand-over from the preview to the Monte Carlo estimate (vsPreviewHandOver.h): the preview's
// share is the blend of least expected squared error, measured from the two images alone.
#include "vsPreviewHandOver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace
{
// A synthetic hand-over: the truth per pixel, a preview off by `bias` in every channel, and the mean
// of `samples` samples of per-sample variance `variance` (Gaussian), rgba per pixel (alpha 1).
struct Images
{
  std::vector<float> Truth, Preview, Mean;
  std::vector<double> Variance;
};

Images MakeImages(size_t pixels, double bias, double variance, uint32_t samples, uint32_t seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, std::sqrt(variance / samples));
  Images im;
  for (size_t i = 0; i < pixels; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double t = c == 3 ? 1.0 : u(rng);
      im.Truth.push_back(float(t));
      im.Preview.push_back(float(c == 3 ? t : t + bias));
      im.Mean.push_back(float(c == 3 ? t : t + noise(rng)));
      im.Variance.push_back(c == 3 ? 0.0 : variance);
    }
  }
  return im;
}

double MeanSquaredError(const std::vector<float>& x, const std::vector<float>& truth)
{
  double sum = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    sum += (double(x[i]) - truth[i]) * (double(x[i]) - truth[i]);
  }
  return sum / double(x.size());
}
}

TEST(PreviewHandOver, ShareIsTheBlendOfLeastError)
{
  // V = 0.5 / 16, B = 0.1^2: s = V / (V + B) = 0.7576.
  const Images im = MakeImages(100000, 0.1, 0.5, 16, 7);
  const double share = vs::PreviewHandOver::PreviewShare(im.Preview, im.Mean, im.Variance, 16);
  EXPECT_NEAR(share, 0.03125 / (0.03125 + 0.01), 0.01);
  // The blend at that share errs less than either image, and as little as any share on a grid of 0.01.
  auto errorAt = [&](double s) {
    std::vector<float> blend = im.Mean;
    vs::PreviewHandOver::Blend(blend, im.Preview, s);
    return MeanSquaredError(blend, im.Truth);
  };
  const double best = errorAt(share);
  EXPECT_LT(best, errorAt(0.0));
  EXPECT_LT(best, errorAt(1.0));
  for (int k = 0; k <= 100; ++k)
  {
    EXPECT_LE(best, errorAt(0.01 * k) * 1.001) << "share " << 0.01 * k;
  }
}

TEST(PreviewHandOver, ShareFallsAsSamplesComeIn)
{
  double previous = 1.0;
  for (uint32_t n : { 2u, 8u, 32u, 128u, 512u, 2048u })
  {
    const Images im = MakeImages(20000, 0.1, 0.5, n, n);
    const double share = vs::PreviewHandOver::PreviewShare(im.Preview, im.Mean, im.Variance, n);
    const double expected = (0.5 / n) / (0.5 / n + 0.1 * 0.1);
    EXPECT_NEAR(share, expected, 0.03) << n << " samples";
    EXPECT_LT(share, previous) << n << " samples";
    previous = share;
  }
  EXPECT_LT(previous, vs::PreviewHandOver::EndShare); // 2048 samples: 0.024, the hand-over has ended
}

TEST(PreviewHandOver, EdgeCases)
{
  const Images im = MakeImages(100, 0.1, 0.5, 4, 3);
  // Fewer than 2 samples: no variance yet, the preview alone.
  EXPECT_EQ(vs::PreviewHandOver::PreviewShare(im.Preview, im.Mean, im.Variance, 0), 1.0);
  EXPECT_EQ(vs::PreviewHandOver::PreviewShare(im.Preview, im.Mean, im.Variance, 1), 1.0);
  // An exact preview of a noise-free estimate: the estimate.
  const std::vector<double> zero(im.Variance.size(), 0.0);
  EXPECT_EQ(vs::PreviewHandOver::PreviewShare(im.Truth, im.Truth, zero, 9), 0.0);
  // A preview that is exact: its bias is 0, so all of it while the estimate has variance.
  EXPECT_NEAR(vs::PreviewHandOver::PreviewShare(im.Truth, im.Truth, im.Variance, 9), 1.0, 1e-12);
  // Non-finite sums end the hand-over.
  std::vector<float> nan = im.Mean;
  nan[0] = std::nanf("");
  EXPECT_EQ(vs::PreviewHandOver::PreviewShare(im.Preview, nan, im.Variance, 9), 0.0);
  // Images of different sizes are a programming error.
  std::vector<float> shorter(im.Mean.begin(), im.Mean.end() - 4);
  EXPECT_THROW(vs::PreviewHandOver::PreviewShare(im.Preview, shorter, im.Variance, 9), std::logic_error);
  EXPECT_THROW(vs::PreviewHandOver::Blend(shorter, im.Preview, 0.5), std::logic_error);
}

// The share's cap in time (issue 39): 1 at the start, falling linearly to 0 at the hand-over's
// duration, so the estimate is shown alone from 0.95 of it (the cap is then below EndShare); a
// duration of 0 is no hand-over, a time not begun (negative, NaN) no cap yet.
TEST(PreviewHandOver, ShareCapEndsTheHandOverInTime)
{
  EXPECT_EQ(vs::PreviewHandOver::ShareCap(0.0, 5.0), 1.0);
  EXPECT_NEAR(vs::PreviewHandOver::ShareCap(2.5, 5.0), 0.5, 1e-12);
  EXPECT_LT(vs::PreviewHandOver::ShareCap(0.951 * 5.0, 5.0), vs::PreviewHandOver::EndShare);
  EXPECT_GT(vs::PreviewHandOver::ShareCap(0.949 * 5.0, 5.0), vs::PreviewHandOver::EndShare);
  EXPECT_EQ(vs::PreviewHandOver::ShareCap(7.0, 5.0), 0.0);
  EXPECT_EQ(vs::PreviewHandOver::ShareCap(1.0, 0.0), 0.0);
  EXPECT_EQ(vs::PreviewHandOver::ShareCap(-1.0, 5.0), 1.0);
  EXPECT_EQ(vs::PreviewHandOver::ShareCap(std::nan(""), 5.0), 1.0);
}
