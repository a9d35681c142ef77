// The sparse-table range query of a transfer function's extinction gives exactly what the linear
// scans of TransferFunctionSamples give (max and min are exact, so bit for bit), for every table
// size's power-of-two edge cases, plateaus and zeros, and ranges that are reversed, degenerate or
// beyond the table.
#include "vsExtinctionRangeQuery.h"
#include "vsTransferFunctionTable.h"

#include <gtest/gtest.h>

#include <random>

TEST(ExtinctionRangeQuery, EqualsTheScansOfTheTable)
{
  std::mt19937 rng(11);
  for (size_t count : { 2u, 3u, 4u, 5u, 17u, 255u, 256u, 257u, 4096u })
  {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // Piecewise: zeros, plateaus and noise, so that spans cross runs of equal and zero entries.
    auto opacity = [&](double s) {
      const double band = std::floor(s * 7.0);
      return std::fmod(band, 3.0) == 0.0 ? 0.0 : std::fmod(band, 3.0) == 1.0 ? 0.4 : u(rng);
    };
    const auto tf = vs::TransferFunctionSamples::FromFunctions(-2.0f, 3.0f, count,
      [&](double s) { return opacity((s + 2.0) / 5.0); }, [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; },
      0.5, 2.0);
    const vs::ExtinctionRangeQuery query(tf);
    std::uniform_real_distribution<float> s(-3.0f, 4.0f); // beyond the table on both sides
    for (int i = 0; i < 4000; ++i)
    {
      float a = s(rng), b = i % 5 == 0 ? a : s(rng); // every fifth range degenerate; half reversed
      ASSERT_EQ(query.Max(a, b), tf.MaxExtinction(a, b)) << count << " entries, [" << a << ", " << b << "]";
      ASSERT_EQ(query.Min(a, b), tf.MinExtinction(a, b)) << count << " entries, [" << a << ", " << b << "]";
    }
    EXPECT_EQ(query.Max(-2.0f, 3.0f), tf.MaxExtinction(-2.0f, 3.0f)) << "the whole table";
    EXPECT_EQ(query.Min(-2.0f, 3.0f), 0.0f);
  }
}
