// Which directions each lazy update scheme re-sweeps after a data-only change
// (vsVisibilityUpdateScheduler), on the host: counts, the round-robin order, Static's
// interval, and environment-guided draws that follow the light and are distinct.
#include "vsVisibilityUpdateScheduler.h"
#include "vsError.h"

#include "sampling/update_order.h"

#include <gtest/gtest.h>

#include <set>

using vs::UpdateSchedule;
using vs::UpdateScheme;
using vs::VisibilityUpdateScheduler;

namespace
{
UpdateSchedule Make(UpdateScheme scheme, uint32_t k = 4, uint32_t interval = 16)
{
  UpdateSchedule s;
  s.Scheme = scheme;
  s.DirectionsPerFrame = k;
  s.StaticInterval = interval;
  return s;
}
}

TEST(VisibilityUpdateScheduler, FullSweepsEverythingEveryTime)
{
  VisibilityUpdateScheduler s;
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(s.OnDataChange(Make(UpdateScheme::Full), 8, {}).size(), 64u);
}

TEST(VisibilityUpdateScheduler, RoundRobinFollowsTheOrderAndCoversACycle)
{
  VisibilityUpdateScheduler s;
  std::multiset<uint32_t> seen;
  for (uint32_t change = 0; change < 16; ++change)
  {
    auto d = s.OnDataChange(Make(UpdateScheme::RoundRobin, 4), 8, {});
    ASSERT_EQ(d.size(), 4u);
    for (uint32_t i = 0; i < 4; ++i)
      EXPECT_EQ(d[i], vs::shared::vs_round_robin_direction(4 * change + i, 8));
    seen.insert(d.begin(), d.end());
  }
  EXPECT_EQ(seen.size(), 64u);
  EXPECT_EQ(std::set<uint32_t>(seen.begin(), seen.end()).size(), 64u); // each exactly once
  // A full update in between does not restart the order.
  s.OnFullUpdate();
  EXPECT_EQ(s.OnDataChange(Make(UpdateScheme::RoundRobin, 4), 8, {})[0], vs::shared::vs_round_robin_direction(64, 8));
}

// Only the directions the renderer needs (here: the upper half, as under a sky with a black
// ground) are handed out: Full and Static return exactly them, RoundRobin k of them per change,
// in the order, covering all of them in one cycle of the order; EnvironmentGuided never others.
TEST(VisibilityUpdateScheduler, OnlyEligibleDirectionsAreReturned)
{
  std::vector<uint8_t> eligible(64, 0);
  for (uint32_t n = 0; n < 32; ++n)
    eligible[n] = 1;
  VisibilityUpdateScheduler s;
  auto full = s.OnDataChange(Make(UpdateScheme::Full), 8, {}, eligible);
  EXPECT_EQ(full.size(), 32u);
  for (uint32_t n : full)
    EXPECT_TRUE(eligible[n]);
  auto stat = s.OnDataChange(Make(UpdateScheme::Static, 4, 1), 8, {}, eligible);
  EXPECT_EQ(stat, full);

  std::vector<uint32_t> expected; // the order with the ineligible directions left out
  for (uint32_t i = 0; i < 64; ++i)
  {
    const uint32_t n = vs::shared::vs_round_robin_direction(i, 8);
    if (eligible[n])
      expected.push_back(n);
  }
  std::vector<uint32_t> got;
  for (int change = 0; change < 8; ++change)
  {
    auto d = s.OnDataChange(Make(UpdateScheme::RoundRobin, 4), 8, {}, eligible);
    ASSERT_EQ(d.size(), 4u) << "k eligible directions per change";
    got.insert(got.end(), d.begin(), d.end());
  }
  EXPECT_EQ(got, expected); // each eligible direction exactly once in 8 changes of k = 4

  std::vector<float> importance(64, 1.0f);
  for (int draw = 0; draw < 20; ++draw)
    for (uint32_t n : s.OnDataChange(Make(UpdateScheme::EnvironmentGuided, 8), 8, importance, eligible))
      EXPECT_TRUE(eligible[n]) << n;

  const std::vector<uint8_t> none(64, 0);
  EXPECT_TRUE(s.OnDataChange(Make(UpdateScheme::RoundRobin, 4), 8, {}, none).empty());
  EXPECT_THROW(s.OnDataChange(Make(UpdateScheme::Full), 8, {}, std::vector<uint8_t>(10, 1)), vs::InputError);
}

TEST(VisibilityUpdateScheduler, StaticRefreshesAtTheIntervalOnly)
{
  VisibilityUpdateScheduler s;
  for (int cycle = 0; cycle < 2; ++cycle)
  {
    for (int i = 1; i < 5; ++i)
      EXPECT_TRUE(s.OnDataChange(Make(UpdateScheme::Static, 4, 5), 8, {}).empty()) << "change " << i;
    EXPECT_EQ(s.OnDataChange(Make(UpdateScheme::Static, 4, 5), 8, {}).size(), 64u);
  }
  // A full update (e.g. a new transfer function) restarts the interval.
  EXPECT_TRUE(s.OnDataChange(Make(UpdateScheme::Static, 4, 5), 8, {}).empty());
  s.OnFullUpdate();
  for (int i = 1; i < 5; ++i)
    EXPECT_TRUE(s.OnDataChange(Make(UpdateScheme::Static, 4, 5), 8, {}).empty());
  EXPECT_EQ(s.OnDataChange(Make(UpdateScheme::Static, 4, 5), 8, {}).size(), 64u);
}

TEST(VisibilityUpdateScheduler, EnvironmentGuidedDrawsDistinctLitDirectionsByImportance)
{
  // Light in 6 of 64 directions: 2 strong (weight 100) and 4 weak (weight 1).
  std::vector<float> importance(64, 0.0f);
  importance[9] = importance[50] = 100.0f;
  importance[1] = importance[2] = importance[3] = importance[4] = 1.0f;
  VisibilityUpdateScheduler s;
  std::vector<int> drawn(64, 0);
  const int changes = 2000;
  for (int c = 0; c < changes; ++c)
  {
    auto d = s.OnDataChange(Make(UpdateScheme::EnvironmentGuided, 4), 8, importance);
    ASSERT_EQ(d.size(), 4u);
    ASSERT_EQ(std::set<uint32_t>(d.begin(), d.end()).size(), 4u) << "directions must be distinct";
    for (uint32_t n : d)
    {
      ASSERT_GT(importance[n], 0.0f) << "unlit direction " << n << " drawn";
      ++drawn[n];
    }
  }
  // Without replacement, the two strong directions are (almost) always among the 4, and the
  // 2 remaining draws fall on the weak ones uniformly: 2000 * 2 / 4 = 1000 each.
  EXPECT_GT(drawn[9], 0.99 * changes);
  EXPECT_GT(drawn[50], 0.99 * changes);
  for (int n : { 1, 2, 3, 4 })
    EXPECT_NEAR(drawn[n], 1000, 120) << n; // binomial sd ~ 19; the strong ones skip a few draws
  // Asking for more directions than are lit gives the lit ones only; a black sky gives none.
  EXPECT_EQ(s.OnDataChange(Make(UpdateScheme::EnvironmentGuided, 10), 8, importance).size(), 6u);
  EXPECT_TRUE(s.OnDataChange(Make(UpdateScheme::EnvironmentGuided, 4), 8, std::vector<float>(64, 0.0f)).empty());
}

TEST(VisibilityUpdateScheduler, BadInputIsAnError)
{
  VisibilityUpdateScheduler s;
  EXPECT_THROW(s.OnDataChange(Make(UpdateScheme::RoundRobin), 6, {}), vs::InputError);
  EXPECT_THROW(s.OnDataChange(Make(UpdateScheme::EnvironmentGuided), 8, std::vector<float>(16, 1.0f)), vs::InputError);
}
