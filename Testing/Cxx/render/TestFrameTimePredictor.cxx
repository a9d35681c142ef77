// The next frame's time for a loop with a deadline (issue 39): the longest of the last three frames
// per sample, the first frame only until the second, so that one frame slower than the one before
// does not run a budget over (ParaView's TimeBudget did, by a fraction of a millisecond); and a frame's
// part that does not grow with its samples kept apart, so that a last frame of few samples, sized to what
// is left of the budget, does not run it over by that part (the tool's --time-budget did, by up to 53 ms).
#include "vsFrameTimePredictor.h"

#include <gtest/gtest.h>

#include <limits>

TEST(FrameTimePredictor, NothingBeforeTheFirstFrame)
{
  vs::FrameTimePredictor p;
  EXPECT_EQ(p.SecondsPerSample(), 0.0);
  EXPECT_EQ(p.NextFrameSeconds(8), 0.0);
}

TEST(FrameTimePredictor, TheFirstFrameStandsOnlyUntilTheSecond)
{
  vs::FrameTimePredictor p;
  p.Add(0.4, 1); // pipelines, upload's page faults
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.4);
  p.Add(0.1, 10);
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.01);
  EXPECT_EQ(p.GetCount(), 1);
}

TEST(FrameTimePredictor, TheLongestOfTheLastThreeFramesPerSample)
{
  vs::FrameTimePredictor p;
  p.Add(1.0, 1);
  p.Add(0.010, 1);
  p.Add(0.024, 2); // 0.012 a sample: the slowest
  p.Add(0.009, 1);
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.012);
  EXPECT_DOUBLE_EQ(p.NextFrameSeconds(4), 0.048);
  p.Add(0.009, 1);
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.012);
  p.Add(0.008, 1); // the slow frame is now four frames back
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.009);
  EXPECT_EQ(p.GetCount(), 3);
}

TEST(FrameTimePredictor, FramesWithoutSamplesOrTimeAreNotCounted)
{
  vs::FrameTimePredictor p;
  p.Add(0.5, 0);
  p.Add(std::numeric_limits<double>::quiet_NaN(), 1);
  p.Add(std::numeric_limits<double>::infinity(), 1);
  p.Add(-1.0, 1);
  EXPECT_EQ(p.GetCount(), 0);
  EXPECT_EQ(p.SecondsPerSample(), 0.0);
  p.Add(0.2, 2);
  p.Add(0.03, 1);
  p.Reset();
  EXPECT_EQ(p.SecondsPerSample(), 0.0);
}

// Frames of t = a + b n (a = b = 1/16 s): the second frame had 2 samples, the others 6. A prediction per
// sample alone (7/96 s a sample) would give a frame of 2 samples 0.146 s where it takes 0.1875 s.
TEST(FrameTimePredictor, AFramesFixedPartApartFromItsSamples)
{
  vs::FrameTimePredictor p;
  const double a = 0.0625, b = 0.0625;
  p.Add(1.0, 1); // the first frame: dropped at the second
  p.Add(a + 2 * b, 2);
  EXPECT_NEAR(p.FixedSeconds(), 0.0, 1e-12) << "one frame counted: nothing to fit";
  for (int i = 0; i < 3; ++i)
    p.Add(a + 6 * b, 6);
  EXPECT_NEAR(p.FixedSeconds(), a, 1e-12);
  EXPECT_NEAR(p.SecondsPerSample(), b, 1e-12);
  EXPECT_GE(p.NextFrameSeconds(2) + 1e-12, a + 2 * b) << "the last, small frame must not be underestimated";
  EXPECT_NEAR(p.NextFrameSeconds(6), a + 6 * b, 1e-12);
  EXPECT_EQ(p.SamplesWithin(0.3), 3); // (0.3 - a) / b = 3.8
  EXPECT_EQ(p.SamplesWithin(0.1), 0); // (0.1 - a) / b = 0.6
  EXPECT_EQ(p.SamplesWithin(0.05), 0);
  // Frames of one number of samples keep the fixed part found before.
  for (int i = 0; i < vs::FrameTimePredictor::FitFrames + 2; ++i)
    p.Add(a + 6 * b, 6);
  EXPECT_NEAR(p.FixedSeconds(), a, 1e-12);
  EXPECT_NEAR(p.NextFrameSeconds(1), a + b, 1e-12);
}

TEST(FrameTimePredictor, TheFixedPartIsNeverNegativeNorLongerThanTheShortestFrame)
{
  vs::FrameTimePredictor p;
  p.Add(1.0, 1);
  p.Add(0.010, 1);
  p.Add(0.030, 2); // the line's intercept: -0.010
  EXPECT_EQ(p.FixedSeconds(), 0.0);
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.015);
  p.Reset();
  p.Add(1.0, 1);
  p.Add(0.5, 1);
  p.Add(0.1, 2); // the intercept: 0.9
  EXPECT_DOUBLE_EQ(p.FixedSeconds(), 0.1);
  EXPECT_DOUBLE_EQ(p.SecondsPerSample(), 0.4); // (0.5 - 0.1) / 1
  EXPECT_EQ(vs::FrameTimePredictor().SamplesWithin(1.0), 1 << 30) << "nothing known: no limit";
}
