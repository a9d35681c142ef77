// Hierarchical sample warping (sampling/warp.h), exactly as the shaders compile
// it: the tabulated n x n warp, and the descent of the environment
// importance quadtree. Chi-square tests of the warped sample against the
// probabilities the warp reports, plus the numerical edge cases.
#include "sampling/rng.h"
#include "sampling/warp.h"
#include "vsChiSquare.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

using namespace vs::shared;

namespace
{

// A map of n x n values in the compact layout of vs_warp (index y*n + x).
using Map = std::array<float, 256>;

struct WarpResult
{
  uvec2 texel;
  float prob;
  vec2 uRemapped;
};

using WarpFn = std::function<WarpResult(const Map&, vec2)>;

// The default direction resolution, from a copy in a plain float[64].
WarpResult Warp8x8(const Map& m, vec2 u)
{
  float values[64];
  std::copy(m.begin(), m.begin() + 64, values);
  WarpResult r;
  vs_warp(values, 8u, u, r.texel, r.prob, r.uRemapped);
  return r;
}

WarpFn WarpN(uint n)
{
  return [n](const Map& m, vec2 u)
  {
    Map copy = m;
    WarpResult r;
    vs_warp(copy.data(), n, u, r.texel, r.prob, r.uRemapped);
    return r;
  };
}

// The map with its sum pyramid behind it (warp.h), built as the render kernel builds it.
std::vector<float> WithPyramid(const Map& m, uint n)
{
  std::vector<float> v((4 * n * n - 1) / 3, 0.0f);
  std::copy(m.begin(), m.begin() + n * n, v.begin());
  for (uint size = n / 2; size > 0; size /= 2)
  {
    const uint base = vs_pyramid_offset(n, size);
    for (uint i = 0; i < size * size; ++i)
    {
      v[base + i] = vs_pyramid_parent(v.data(), n, 2 * size, uvec2(i % size, i / size));
    }
  }
  return v;
}

WarpFn WarpPyramidN(uint n)
{
  return [n](const Map& m, vec2 u)
  {
    std::vector<float> v = WithPyramid(m, n);
    WarpResult r;
    vs_warp_pyramid(v.data(), n, u, r.texel, r.prob, r.uRemapped);
    return r;
  };
}

double Total(const Map& m, uint n)
{
  double t = 0.0;
  for (uint i = 0; i < n * n; ++i)
  {
    t += m[i];
  }
  return t;
}

// Maps used throughout, all n x n.
Map RandomMap(uint n, uint seed)
{
  Map m{};
  VsRng rng = vs_rng_init(uvec2(n, seed), 11u, seed);
  for (uint i = 0; i < n * n; ++i)
  {
    m[i] = vs_rng_float(rng);
  }
  return m;
}

Map OneHotMap(uint n, uvec2 hot)
{
  Map m{};
  m[hot.y * n + hot.x] = 1.0f;
  return m;
}

// Visibility after adding ε = 0.01: mostly blocked, a few open directions.
Map EpsilonFloorMap(uint n)
{
  Map m{};
  for (uint i = 0; i < n * n; ++i)
  {
    m[i] = 0.01f + (i % 7u == 3u ? 1.0f : 0.0f);
  }
  return m;
}

// Entries of 1e-30 next to ordinary ones, and zeros.
Map NearZeroMap(uint n)
{
  Map m = RandomMap(n, 5u);
  for (uint i = 0; i < n * n; ++i)
  {
    m[i] = i % 3u == 0u ? 1e-30f : (i % 3u == 1u ? 0.0f : m[i]);
  }
  return m;
}

// Checks one warp against the map: every result valid, prob = value / total,
// and the remapped position (texel + uRemapped) / n distributed with density
// prob * n² over [0,1)^2 (chi-square on a grid 8 times finer than the map, so
// uniformity within the texel is tested too).
void ExpectWarpMatchesMap(const WarpFn& warp, const Map& m, uint n, const char* name)
{
  SCOPED_TRACE(name);
  const int samples = 100000, sub = 8, res = int(n) * sub;
  const double total = Total(m, n);
  std::vector<double> observed(size_t(res) * res, 0.0), expected(size_t(res) * res, 0.0);
  for (int y = 0; y < res; ++y)
  {
    for (int x = 0; x < res; ++x)
    {
      expected[size_t(y) * res + x] = samples * m[(y / sub) * n + x / sub] / total / (sub * sub);
    }
  }
  VsRng rng = vs_rng_init(uvec2(3u, n), 1u, 99u);
  int invalid = 0;
  for (int i = 0; i < samples; ++i)
  {
    WarpResult r = warp(m, vs_rng_vec2(rng));
    float value = m[r.texel.y * n + r.texel.x];
    bool valid = r.texel.x < n && r.texel.y < n && value > 0.0f && r.uRemapped.x >= 0.0f &&
                 r.uRemapped.x < 1.0f && r.uRemapped.y >= 0.0f && r.uRemapped.y < 1.0f &&
                 std::abs(r.prob - value / total) <= 1e-5 * value / total;
    if (!valid)
    {
      ++invalid;
      continue;
    }
    vec2 uv = (vec2(r.texel) + r.uRemapped) * float(sub);
    observed[size_t(uv.y) * res + size_t(uv.x)] += 1.0;
  }
  EXPECT_EQ(invalid, 0);
  vstest::ChiSquareResult chi = vstest::ChiSquare(observed, expected);
  EXPECT_TRUE(chi.failure.empty()) << chi.failure;
  EXPECT_GE(chi.pValue, vstest::kChiSquareSignificance)
    << "chi2 " << chi.chi2 << " dof " << chi.dof;
}

} // namespace

// ------------------------------------------------------------ tabulated warps

TEST(SamplingWarp, Warp8x8MatchesMaps)
{
  ExpectWarpMatchesMap(Warp8x8, RandomMap(8, 1), 8, "random");
  ExpectWarpMatchesMap(Warp8x8, OneHotMap(8, uvec2(5, 2)), 8, "one-hot");
  ExpectWarpMatchesMap(Warp8x8, EpsilonFloorMap(8), 8, "epsilon floor");
  ExpectWarpMatchesMap(Warp8x8, NearZeroMap(8), 8, "near zero");
}

TEST(SamplingWarp, WarpAnySizeMatchesMaps)
{
  for (uint n : { 2u, 4u, 8u, 16u })
  {
    SCOPED_TRACE(n);
    ExpectWarpMatchesMap(WarpN(n), RandomMap(n, 2), n, "random");
    ExpectWarpMatchesMap(WarpN(n), NearZeroMap(n), n, "near zero");
  }
  ExpectWarpMatchesMap(WarpN(16), OneHotMap(16, uvec2(15, 0)), 16, "one-hot");
}

// The pyramid warp (the render kernel's: log2 n steps instead of block sums) samples the map.
TEST(SamplingWarp, PyramidWarpMatchesMaps)
{
  for (uint n : { 2u, 4u, 8u, 16u })
  {
    SCOPED_TRACE(n);
    ExpectWarpMatchesMap(WarpPyramidN(n), RandomMap(n, 2), n, "random");
    ExpectWarpMatchesMap(WarpPyramidN(n), NearZeroMap(n), n, "near zero");
    ExpectWarpMatchesMap(WarpPyramidN(n), EpsilonFloorMap(n), n, "epsilon floor");
  }
  ExpectWarpMatchesMap(WarpPyramidN(8), OneHotMap(8, uvec2(5, 2)), 8, "one-hot");
  ExpectWarpMatchesMap(WarpPyramidN(16), OneHotMap(16, uvec2(15, 0)), 16, "one-hot");
}

// Its probability function returns exactly what the descent reports, sums to one, and an all-zero
// map gives probability 0.
TEST(SamplingWarp, PyramidProbAgreesWithItsWarp)
{
  for (uint n : { 2u, 8u, 16u })
  {
    std::vector<float> v = WithPyramid(NearZeroMap(n), n);
    VsRng rng = vs_rng_init(uvec2(6u, n), 0u, 1u);
    for (int i = 0; i < 1000; ++i)
    {
      WarpResult r;
      vs_warp_pyramid(v.data(), n, vs_rng_vec2(rng), r.texel, r.prob, r.uRemapped);
      EXPECT_EQ(r.prob, vs_warp_pyramid_prob(v.data(), n, r.texel));
    }
    double sum = 0.0;
    for (uint y = 0; y < n; ++y)
      for (uint x = 0; x < n; ++x)
        sum += vs_warp_pyramid_prob(v.data(), n, uvec2(x, y));
    EXPECT_NEAR(sum, 1.0, 1e-5) << n;
  }
  Map zero{};
  std::vector<float> v = WithPyramid(zero, 8);
  WarpResult r;
  vs_warp_pyramid(v.data(), 8, vec2(0.3f, 0.7f), r.texel, r.prob, r.uRemapped);
  EXPECT_EQ(r.prob, 0.0f);
  EXPECT_LT(r.texel.x, 8u);
  EXPECT_LT(r.texel.y, 8u);
}

TEST(SamplingWarp, ProbFunctionsAgreeWithWarp)
{
  Map m = NearZeroMap(8);
  float values[64];
  std::copy(m.begin(), m.begin() + 64, values);
  VsRng rng = vs_rng_init(uvec2(6u, 6u), 0u, 1u);
  for (int i = 0; i < 1000; ++i)
  {
    WarpResult r = Warp8x8(m, vs_rng_vec2(rng));
    EXPECT_EQ(r.prob, vs_warp_prob(values, 8u, r.texel));
    EXPECT_EQ(r.prob, vs_warp_prob(m.data(), 8u, r.texel));
  }
  double sum = 0.0;
  for (uint y = 0; y < 8; ++y)
  {
    for (uint x = 0; x < 8; ++x)
    {
      sum += vs_warp_prob(values, 8u, uvec2(x, y));
    }
  }
  EXPECT_NEAR(sum, 1.0, 1e-6);
}

// Extreme samples must stay inside the map and inside [0,1) after rescaling.
TEST(SamplingWarp, ExtremeSamples)
{
  const float one = VS_ONE_MINUS_EPSILON;
  const vec2 corners[] = { { 0.0f, 0.0f }, { one, one }, { 0.0f, one }, { one, 0.0f },
    { 0.5f, 0.5f } };
  for (const Map& m : { RandomMap(8, 4), OneHotMap(8, uvec2(0, 7)), OneHotMap(8, uvec2(7, 0)),
         EpsilonFloorMap(8), NearZeroMap(8) })
  {
    for (vec2 u : corners)
    {
      WarpResult r = Warp8x8(m, u);
      ASSERT_LT(r.texel.x, 8u);
      ASSERT_LT(r.texel.y, 8u);
      EXPECT_GT(m[r.texel.y * 8 + r.texel.x], 0.0f) << u.x << " " << u.y;
      EXPECT_GT(r.prob, 0.0f);
      EXPECT_GE(r.uRemapped.x, 0.0f);
      EXPECT_GE(r.uRemapped.y, 0.0f);
      EXPECT_LT(r.uRemapped.x, 1.0f);
      EXPECT_LT(r.uRemapped.y, 1.0f);
    }
  }
  // With every texel positive, u = 0 picks the first texel and u -> 1 the last,
  // and the remapped sample keeps the extreme.
  Map positive = RandomMap(8, 6);
  WarpResult first = Warp8x8(positive, vec2(0.0f));
  EXPECT_EQ(first.texel, uvec2(0u));
  EXPECT_EQ(first.uRemapped, vec2(0.0f));
  WarpResult last = Warp8x8(positive, vec2(one));
  EXPECT_EQ(last.texel, uvec2(7u));
  EXPECT_GT(last.uRemapped.x, 0.9999f);
  EXPECT_GT(last.uRemapped.y, 0.9999f);
}

TEST(SamplingWarp, AllZeroMapGivesProbZero)
{
  Map zero{};
  float values[64] = {};
  for (vec2 u : { vec2(0.0f), vec2(0.3f, 0.7f), vec2(VS_ONE_MINUS_EPSILON) })
  {
    WarpResult r = Warp8x8(zero, u);
    EXPECT_EQ(r.prob, 0.0f);
    EXPECT_LT(r.texel.x, 8u);
    EXPECT_LT(r.texel.y, 8u);
    EXPECT_TRUE(std::isfinite(r.uRemapped.x) && std::isfinite(r.uRemapped.y));
    for (uint n : { 4u, 16u })
    {
      WarpResult g = WarpN(n)(zero, u);
      EXPECT_EQ(g.prob, 0.0f);
      EXPECT_LT(g.texel.x, n);
      EXPECT_TRUE(std::isfinite(g.uRemapped.x) && std::isfinite(g.uRemapped.y));
    }
  }
  EXPECT_EQ(vs_warp_total(values, 8u), 0.0f);
  EXPECT_EQ(vs_warp_prob(values, 8u, uvec2(3u)), 0.0f);
}

// Probabilities of 1e-30 (and a lone 1e-30 among zeros) must not produce NaN or
// Inf anywhere in [0,1)^2, including the samples that land on tiny texels.
TEST(SamplingWarp, TinyValuesStayFinite)
{
  Map allTiny{}, loneTiny{}, mixed = NearZeroMap(8);
  std::fill(allTiny.begin(), allTiny.begin() + 64, 1e-30f);
  loneTiny[42] = 1e-30f;
  mixed[9] = 1e30f;
  const float one = VS_ONE_MINUS_EPSILON;
  for (const Map& m : { allTiny, loneTiny, mixed })
  {
    const double total = Total(m, 8);
    for (int j = 0; j <= 256; ++j)
    {
      for (int i = 0; i <= 256; ++i)
      {
        vec2 u(std::min(i / 256.0f, one), std::min(j / 256.0f, one));
        WarpResult r = Warp8x8(m, u);
        float value = m[r.texel.y * 8 + r.texel.x];
        ASSERT_GT(value, 0.0f);
        // 1e-30 / 1e30 underflows to prob 0 (the sample is then skipped): only
        // u = 0 exactly reaches such a texel.
        double expected = value / total;
        ASSERT_TRUE(std::isfinite(r.prob) && r.prob >= 0.0f);
        ASSERT_NEAR(r.prob, expected, 1e-5 * expected + 1e-37);
        ASSERT_TRUE(r.uRemapped.x >= 0.0f && r.uRemapped.x < 1.0f);
        ASSERT_TRUE(r.uRemapped.y >= 0.0f && r.uRemapped.y < 1.0f);
      }
    }
  }
  EXPECT_EQ(Warp8x8(loneTiny, vec2(0.7f, 0.2f)).prob, 1.0f);
  EXPECT_FLOAT_EQ(Warp8x8(allTiny, vec2(0.7f, 0.2f)).prob, 1.0f / 64.0f);
}

// The warp is monotone in each coordinate of u (with the other fixed): it keeps
// the stratification of u, which is why one sample drives the whole descent.
TEST(SamplingWarp, MonotoneInEachCoordinate)
{
  Map m = NearZeroMap(8);
  for (float fixed : { 0.1f, 0.5f, 0.93f })
  {
    vec2 previousX(-1.0f), previousY(-1.0f);
    for (int i = 0; i < 4096; ++i)
    {
      float t = i / 4096.0f;
      WarpResult a = Warp8x8(m, vec2(t, fixed));
      WarpResult b = Warp8x8(m, vec2(fixed, t));
      vec2 uvA = (vec2(a.texel) + a.uRemapped) / 8.0f;
      vec2 uvB = (vec2(b.texel) + b.uRemapped) / 8.0f;
      ASSERT_GE(uvA.x, previousX.x - 1e-6f) << t;
      ASSERT_GE(uvB.y, previousY.y - 1e-6f) << t;
      previousX = uvA;
      previousY = uvB;
    }
  }
}

TEST(SamplingWarp, SplitNeverChoosesAnEmptySide)
{
  const float one = VS_ONE_MINUS_EPSILON;
  for (float u : { 0.0f, 0.5f, one })
  {
    float v = u;
    EXPECT_EQ(vs_warp_split(1.0f, 0.0f, v), 0u);
    EXPECT_LT(v, 1.0f);
    v = u;
    EXPECT_EQ(vs_warp_split(0.0f, 1e-30f, v), 1u);
    EXPECT_LT(v, 1.0f);
    v = u;
    EXPECT_EQ(vs_warp_split(0.0f, 0.0f, v), 0u);
    EXPECT_EQ(v, u);
    // Lopsided weights: the rescaled sample stays in [0,1).
    v = u;
    vs_warp_split(1e-30f, 1e30f, v);
    EXPECT_GE(v, 0.0f);
    EXPECT_LT(v, 1.0f);
  }
}

// Splitting [0,1) in proportion a : b maps each part linearly onto [0,1).
TEST(SamplingWarp, SplitRescalesLinearly)
{
  for (vec2 ab : { vec2(1.0f, 3.0f), vec2(5.0f, 0.01f), vec2(1e-30f, 2e-30f) })
  {
    const double p = double(ab.x) / (double(ab.x) + ab.y);
    for (int i = 0; i < 10000; ++i)
    {
      float u = std::min(i / 10000.0f, VS_ONE_MINUS_EPSILON), v = u;
      uint side = vs_warp_split(ab.x, ab.y, v);
      double expected = side == 0u ? u / p : (u - p) / (1.0 - p);
      ASSERT_EQ(side, u < p ? 0u : 1u) << u;
      ASSERT_NEAR(v, expected, 2e-6 / std::min(p, 1.0 - p)) << u;
    }
  }
}

// -------------------------------------------------------- environment quadtree

namespace
{

const uint kLevels = 5; // 32 x 32 leaves

// Random leaves, one quadrant (a whole level-1 subtree) and one level-3 node zero.
std::vector<float> TestEnvLeaves()
{
  const uint n = 1u << kLevels;
  std::vector<float> leaves(n * n);
  VsRng rng = vs_rng_init(uvec2(1u, 1u), 0u, 5u);
  for (uint y = 0; y < n; ++y)
  {
    for (uint x = 0; x < n; ++x)
    {
      bool zeroQuadrant = x < n / 2 && y >= n / 2;
      bool zeroNode = (x >> 2) == 5u && (y >> 2) == 1u;
      float v = vs_rng_float(rng);
      leaves[y * n + x] =
        zeroQuadrant || zeroNode ? 0.0f : (x == 20 && y == 3 ? 1e-30f : v * v * 10.0f);
    }
  }
  return leaves;
}

// Chi-square of the descent from (level, node): position (leaf + uRemapped)
// histogrammed at twice the leaf resolution of the subtree.
void ExpectDescentMatchesLeaves(
  const std::vector<float>& mips, const std::vector<float>& leaves, uint level, uvec2 node)
{
  SCOPED_TRACE(
    testing::Message() << "start level " << level << " node " << node.x << "," << node.y);
  const uint n = 1u << kLevels, depth = kLevels - level, side = 1u << depth, res = 2 * side;
  const uvec2 origin = node * side;
  double total = 0.0;
  for (uint y = 0; y < side; ++y)
  {
    for (uint x = 0; x < side; ++x)
    {
      total += leaves[(origin.y + y) * n + origin.x + x];
    }
  }
  const int samples = 60000;
  std::vector<double> observed(res * res, 0.0), expected(res * res, 0.0);
  for (uint y = 0; y < res; ++y)
  {
    for (uint x = 0; x < res; ++x)
    {
      expected[y * res + x] =
        samples * leaves[(origin.y + y / 2) * n + origin.x + x / 2] / total / 4.0;
    }
  }
  VsRng rng = vs_rng_init(uvec2(level, 2u), 3u, 4u);
  int invalid = 0;
  for (int i = 0; i < samples; ++i)
  {
    uvec2 leaf;
    float prob;
    vec2 ur;
    vs_env_descend(mips.data(), level, node, kLevels, vs_rng_vec2(rng), leaf, prob, ur);
    uvec2 local = leaf - origin;
    float value = leaves[leaf.y * n + leaf.x];
    bool valid = local.x < side && local.y < side && value > 0.0f && ur.x >= 0.0f && ur.x < 1.0f &&
                 ur.y >= 0.0f && ur.y < 1.0f &&
                 std::abs(prob - value / total) <= 1e-5 * value / total &&
                 prob == vs_env_leaf_prob(mips.data(), level, node, kLevels, leaf);
    if (!valid)
    {
      ++invalid;
      continue;
    }
    vec2 p = (vec2(local) + ur) * 2.0f;
    observed[uint(p.y) * res + uint(p.x)] += 1.0;
  }
  EXPECT_EQ(invalid, 0);
  vstest::ChiSquareResult chi = vstest::ChiSquare(observed, expected);
  EXPECT_TRUE(chi.failure.empty()) << chi.failure;
  EXPECT_GE(chi.pValue, vstest::kChiSquareSignificance)
    << "chi2 " << chi.chi2 << " dof " << chi.dof;
}

} // namespace

TEST(SamplingWarp, EnvLevelOffsets)
{
  uint expected = 0;
  for (uint level = 0; level <= 15; ++level)
  {
    EXPECT_EQ(vs_env_level_offset(level), expected) << level;
    expected += 1u << (2 * level);
  }
}

TEST(SamplingWarp, EnvMipsAreMeans)
{
  std::vector<float> leaves = TestEnvLeaves();
  std::vector<float> mips = vstest::BuildEnvMips(leaves, kLevels);
  double mean = 0.0;
  for (float v : leaves)
  {
    mean += v;
  }
  mean /= leaves.size();
  EXPECT_NEAR(vs_env_node(mips.data(), 0u, uvec2(0u)), mean, 1e-5 * mean);
  EXPECT_EQ(vs_env_node(mips.data(), kLevels, uvec2(7u, 9u)), leaves[9 * 32 + 7]);
  EXPECT_EQ(vs_env_node(mips.data(), 1u, uvec2(0u, 1u)), 0.0f);
  EXPECT_EQ(vs_env_node(mips.data(), 3u, uvec2(5u, 1u)), 0.0f);
  vec4 c = vs_env_children(mips.data(), 2u, uvec2(1u, 3u));
  EXPECT_EQ(c.y, vs_env_node(mips.data(), 3u, uvec2(3u, 6u)));
  EXPECT_EQ(c.z, vs_env_node(mips.data(), 3u, uvec2(2u, 7u)));
}

TEST(SamplingWarp, EnvDescentMatchesLeaves)
{
  std::vector<float> leaves = TestEnvLeaves();
  std::vector<float> mips = vstest::BuildEnvMips(leaves, kLevels);
  ExpectDescentMatchesLeaves(mips, leaves, 0u, uvec2(0u));
  ExpectDescentMatchesLeaves(mips, leaves, 2u, uvec2(3u, 0u)); // contains the zero level-3 node
  ExpectDescentMatchesLeaves(mips, leaves, 3u, uvec2(6u, 2u));
}

TEST(SamplingWarp, EnvLeafProbSumsToOneInsideTheStartNode)
{
  std::vector<float> leaves = TestEnvLeaves();
  std::vector<float> mips = vstest::BuildEnvMips(leaves, kLevels);
  const uint n = 1u << kLevels;
  struct Start
  {
    uint level;
    uvec2 node;
    double expectedSum;
  };
  for (Start s :
    { Start{ 0u, uvec2(0u), 1.0 }, Start{ 1u, uvec2(1u, 0u), 1.0 }, Start{ 1u, uvec2(0u, 1u), 0.0 },
      Start{ 3u, uvec2(5u, 1u), 0.0 }, Start{ 4u, uvec2(9u, 3u), 1.0 } })
  {
    double sum = 0.0;
    for (uint y = 0; y < n; ++y)
    {
      for (uint x = 0; x < n; ++x)
      {
        float p = vs_env_leaf_prob(mips.data(), s.level, s.node, kLevels, uvec2(x, y));
        ASSERT_TRUE(std::isfinite(p));
        if (uvec2(x, y) >> (kLevels - s.level) != s.node)
        {
          ASSERT_EQ(p, 0.0f);
        }
        sum += p;
      }
    }
    EXPECT_NEAR(sum, s.expectedSum, 1e-5) << "level " << s.level;
  }
}

TEST(SamplingWarp, EnvDescentIntoZeroSubtreeGivesProbZero)
{
  std::vector<float> leaves = TestEnvLeaves();
  std::vector<float> mips = vstest::BuildEnvMips(leaves, kLevels);
  for (vec2 u : { vec2(0.0f), vec2(0.4f, 0.8f), vec2(VS_ONE_MINUS_EPSILON) })
  {
    uvec2 leaf;
    float prob;
    vec2 ur;
    vs_env_descend(mips.data(), 1u, uvec2(0u, 1u), kLevels, u, leaf, prob, ur);
    EXPECT_EQ(prob, 0.0f);
    EXPECT_EQ(leaf >> (kLevels - 1u), uvec2(0u, 1u));
    EXPECT_TRUE(std::isfinite(ur.x) && std::isfinite(ur.y));
  }
}

TEST(SamplingWarp, EnvDescentFromALeafIsTheLeaf)
{
  std::vector<float> leaves = TestEnvLeaves();
  std::vector<float> mips = vstest::BuildEnvMips(leaves, kLevels);
  uvec2 leaf;
  float prob;
  vec2 ur;
  vs_env_descend(mips.data(), kLevels, uvec2(4u, 30u), kLevels, vec2(0.25f, 0.75f), leaf, prob, ur);
  EXPECT_EQ(leaf, uvec2(4u, 30u));
  EXPECT_EQ(prob, 1.0f);
  EXPECT_EQ(ur, vec2(0.25f, 0.75f));
  EXPECT_EQ(vs_env_leaf_prob(mips.data(), kLevels, uvec2(4u, 30u), kLevels, uvec2(4u, 30u)), 1.0f);
}

// Leaves of 1e-30 and a tree whose only light is one 1e-30 leaf.
TEST(SamplingWarp, EnvTinyLeavesStayFinite)
{
  const uint n = 1u << kLevels;
  std::vector<float> lone(n * n, 0.0f);
  lone[17 * n + 23] = 1e-30f;
  std::vector<float> tiny(n * n, 1e-30f);
  for (const std::vector<float>& leaves : { lone, tiny })
  {
    std::vector<float> mips = vstest::BuildEnvMips(leaves, kLevels);
    VsRng rng = vs_rng_init(uvec2(2u, 2u), 2u, 2u);
    for (int i = 0; i < 2000; ++i)
    {
      uvec2 leaf;
      float prob;
      vec2 ur;
      vs_env_descend(mips.data(), 0u, uvec2(0u), kLevels, vs_rng_vec2(rng), leaf, prob, ur);
      ASSERT_GT(leaves[leaf.y * n + leaf.x], 0.0f);
      ASSERT_TRUE(std::isfinite(prob) && prob > 0.0f);
      ASSERT_TRUE(ur.x >= 0.0f && ur.x < 1.0f && ur.y >= 0.0f && ur.y < 1.0f);
    }
  }
}
