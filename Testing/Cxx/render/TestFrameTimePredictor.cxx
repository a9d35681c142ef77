// The next frame's time for a loop with a deadline (issue 39): the longest of the last three frames
// per sample, the first frame only until the second, so that one frame slower than the one before
// does not run a budget over (ParaView's TimeBudget did, by a fraction of a millisecond).
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
