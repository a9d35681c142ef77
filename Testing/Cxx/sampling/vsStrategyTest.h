// vsStrategyTest.h — what the sampling strategies' tests share: synthetic visibility maps and
// environments, the strategies called exactly as the shaders compile them, and their chi-square test.
#ifndef vsStrategyTest_h
#define vsStrategyTest_h
#include "sampling/rng.h"
#include "sampling/strategies.h"
#include "vsChiSquare.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace vs::shared;

namespace
{

using Map = std::array<float, 256>; // D x D, index y*D + x

const char* StrategyName(uint s)
{
  static const char* names[] = { "uniform", "environment", "visibility", "combined", "two-step" };
  return names[s];
}

// ------------------------------------------------------- visibility maps

Map RandomVisibility(uint D)
{
  Map m{};
  VsRng rng = vs_rng_init(uvec2(D, 1u), 2u, 3u);
  for (uint i = 0; i < D * D; ++i)
  {
    m[i] = vs_rng_float(rng);
  }
  return m;
}

Map OneHotVisibility(uint D)
{
  Map m{};
  m[(D / 4) * D + D - 2] = 1.0f;
  return m;
}

// Mostly occluded, a few open directions, plus the sweep's ε = 0.01.
Map EpsilonFloorVisibility(uint D)
{
  Map m{};
  for (uint i = 0; i < D * D; ++i)
  {
    m[i] = 0.01f + (i % 5u == 1u ? 0.8f : 0.0f);
  }
  return m;
}

Map NearZeroVisibility(uint D)
{
  Map m = RandomVisibility(D);
  for (uint i = 0; i < D * D; i += 2)
  {
    m[i] = 1e-30f;
  }
  return m;
}

struct NamedMap
{
  const char* name;
  Map (*make)(uint);
};

const NamedMap kVisibilityMaps[] = { { "random", RandomVisibility },
  { "one-hot", OneHotVisibility }, { "epsilon floor", EpsilonFloorVisibility },
  { "near zero", NearZeroVisibility } };

// --------------------------------------------------------- environments
// Leaves are luminances of the N x N equal-area octahedral map, at texel centres.

const vec3 kSunDirection = glm::normalize(vec3(0.3f, -0.4f, 0.8f));

template<typename F>
std::vector<float> EnvFromFunction(uint K, F luminance)
{
  const uint n = 1u << K;
  std::vector<float> leaves(n * n);
  for (uint y = 0; y < n; ++y)
  {
    for (uint x = 0; x < n; ++x)
    {
      leaves[y * n + x] = luminance(vs_texel_dir(uvec2(x, y), n), uvec2(x, y), n);
    }
  }
  return leaves;
}

std::vector<float> ConstantEnv(uint K)
{
  return EnvFromFunction(K, [](vec3, uvec2, uint) { return 1.0f; });
}

// A dim sky and a small sun (4 degrees across) at least one texel wide, 1e4 x brighter.
std::vector<float> SunEnv(uint K)
{
  return EnvFromFunction(K,
    [](vec3 d, uvec2 t, uint n)
    {
      bool sun = glm::dot(d, kSunDirection) > std::cos(glm::radians(2.0f)) ||
                 t == vs_dir_to_texel(kSunDirection, n);
      return sun ? 2000.0f : 0.2f;
    });
}

std::vector<float> TwoToneEnv(uint K)
{
  return EnvFromFunction(K, [](vec3 d, uvec2, uint) { return d.z > 0.0f ? 1.0f : 0.05f; });
}

// Random light, zero over whole subtrees: the level-1 quadrant (0,0) and the
// level-3 node (5,6).
std::vector<float> ZeroSubtreeEnv(uint K)
{
  VsRng rng = vs_rng_init(uvec2(9u, 9u), 9u, 9u);
  return EnvFromFunction(K,
    [&](vec3, uvec2 t, uint n)
    {
      float v = vs_rng_float(rng) + 0.1f;
      bool quadrant = t.x < n / 2 && t.y < n / 2;
      bool node = n >= 8 && t.x / (n / 8) == 5u && t.y / (n / 8) == 6u;
      return quadrant || node ? 0.0f : v;
    });
}

struct NamedEnv
{
  const char* name;
  std::vector<float> (*make)(uint);
};

const NamedEnv kEnvironments[] = { { "constant", ConstantEnv }, { "sun", SunEnv },
  { "two-tone", TwoToneEnv }, { "zero subtrees", ZeroSubtreeEnv } };

// ----------------------------------------------------------------- scenes

struct Scene
{
  std::string name;
  uint D = 8; // direction resolution of the visibility / product map
  uint K = 5; // env quadtree levels: N = 2^K
  Map visibility{};
  Map product{};
  std::vector<float> mips;
};

Scene MakeScene(const NamedMap& vis, const NamedEnv& env, uint D, uint K)
{
  Scene s;
  s.name = std::string(vis.name) + " visibility, " + env.name + " environment, D " +
           std::to_string(D) + ", K " + std::to_string(K);
  s.D = D;
  s.K = K;
  s.visibility = vis.make(D);
  s.mips = vstest::BuildEnvMips(env.make(K), K);
  for (uint y = 0; y < D; ++y)
  {
    for (uint x = 0; x < D; ++x)
    {
      s.product[y * D + x] = vs_product_weight(s.mips.data(), s.visibility[y * D + x], uvec2(x, y), D);
    }
  }
  return s;
}

// The strategy's map: visibility for Visibility, the product otherwise.
Map ValuesFor(uint strategy, const Scene& s)
{
  return strategy == VS_STRATEGY_VISIBILITY ? s.visibility : s.product;
}

// sample() and pdf() of a strategy through the dispatchers.
struct Sampler
{
  const float* mips; // the scene's env mips (warp.h)
  uint strategy;
  Map values;
  uint D, K;

  vec3 Sample(vec2 u, float& pdf)
  {
    return vs_sample_direction(mips, strategy, values.data(), D, K, u, pdf);
  }
  float Pdf(vec3 dir)
  {
    return vs_pdf_direction(mips, strategy, values.data(), D, K, dir);
  }
};

Sampler MakeSampler(uint strategy, const Scene& s)
{
  return Sampler{ s.mips.data(), strategy, ValuesFor(strategy, s), s.D, s.K };
}

testing::AssertionResult StrategyMatchesPdf(uint strategy, const Scene& s)
{
  Sampler sampler = MakeSampler(strategy, s);
  vstest::SamplerTestOptions o;
  o.bins =
    64; // finer than the env leaves (K <= 5) and map texels (D <= 16): tests uniformity within them
  o.sub = 2;
  o.samples = 60000;
  o.seed = strategy * 100u + s.D + s.K;
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf([&](vec2 u, float& pdf) { return sampler.Sample(u, pdf); },
           [&](vec3 d) { return sampler.Pdf(d); }, o)
         << " (" << StrategyName(strategy) << ", " << s.name << ")";
}

// The map with its sum pyramid behind it (warp.h), as the render kernel builds it.
std::vector<float> WithPyramid(const Map& values, uint D)
{
  std::vector<float> v((4 * D * D - 1) / 3, 0.0f);
  std::copy(values.begin(), values.begin() + D * D, v.begin());
  for (uint size = D / 2; size > 0; size /= 2)
  {
    for (uint i = 0; i < size * size; ++i)
    {
      v[vs_pyramid_offset(D, size) + i] = vs_pyramid_parent(v.data(), D, 2 * size, uvec2(i % size, i / size));
    }
  }
  return v;
}

// The same strategy through the pyramid form of the map (the render kernel's, warp.h).
testing::AssertionResult PyramidStrategyMatchesPdf(uint strategy, const Scene& s)
{
  const std::vector<float> v = WithPyramid(ValuesFor(strategy, s), s.D);
  vstest::SamplerTestOptions o;
  o.bins = 64;
  o.sub = 2;
  o.samples = 60000;
  o.seed = strategy * 100u + s.D + s.K + 7u;
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf(
           [&](vec2 u, float& pdf)
           { return vs_sample_direction_pyramid(s.mips.data(), strategy, v.data(), s.D, s.K, u, pdf); },
           [&](vec3 d) { return vs_pdf_direction_pyramid(s.mips.data(), strategy, v.data(), s.D, s.K, d); }, o)
         << " (pyramid, " << StrategyName(strategy) << ", " << s.name << ")";
}

// The cell's direction table (direction_table.h), packed node by node from the pyramid, behind
// `pad` entries of another cell (so that `base` is exercised).
std::vector<uint32_t> TableOf(const Map& values, uint D, uint pad)
{
  const std::vector<float> v = WithPyramid(values, D);
  std::vector<uint32_t> table(pad, 0xdeadbeefu);
  for (uint level = 0; (1u << level) < D; ++level)
  {
    const uint n = 1u << level;
    for (uint i = 0; i < n * n; ++i)
    {
      const uvec2 node = vs_table_node_from_pyramid(v.data(), D, level, uvec2(i % n, i / n));
      table.push_back(node.x);
      table.push_back(node.y);
    }
  }
  return table;
}

// The same strategy through the cell's precomputed table (the render kernel's default form).
testing::AssertionResult TableStrategyMatchesPdf(uint strategy, const Scene& s)
{
  const uint pad = 5;
  const std::vector<uint32_t> table = TableOf(ValuesFor(strategy, s), s.D, pad);
  if (table.size() != pad + 2 * vs_table_nodes(s.D))
  {
    return testing::AssertionFailure() << "table of " << table.size() - pad << " uints, expected "
                                       << 2 * vs_table_nodes(s.D);
  }
  vstest::SamplerTestOptions o;
  o.bins = 64;
  o.sub = 2;
  o.samples = 60000;
  o.seed = strategy * 100u + s.D + s.K + 11u;
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf(
           [&](vec2 u, float& pdf)
           { return vs_sample_direction_table(s.mips.data(), strategy, table.data(), pad, s.D, s.K, u, pdf); },
           [&](vec3 d) { return vs_pdf_direction_table(s.mips.data(), strategy, table.data(), pad, s.D, s.K, d); },
           o)
         << " (table, " << StrategyName(strategy) << ", " << s.name << ")";
}

// The defensive mixture of TwoStep with Environment sampling, from the table or the pyramid.
testing::AssertionResult DefensiveMatchesPdf(const Scene& s, float alpha, bool table)
{
  const Map values = ValuesFor(VS_STRATEGY_TWO_STEP, s);
  const std::vector<uint32_t> t = TableOf(values, s.D, 3);
  const std::vector<float> v = WithPyramid(values, s.D);
  vstest::SamplerTestOptions o;
  o.bins = 64;
  o.sub = 2;
  o.samples = 60000;
  o.seed = s.D + s.K + uint(alpha * 100.0f) + (table ? 1u : 0u);
  o.edgeResolution = int(std::max(s.D, 1u << s.K));
  return vstest::SamplerMatchesPdf(
           [&](vec2 u, float& pdf) {
             return table ? vs_sample_defensive_table(s.mips.data(), t.data(), 3u, s.D, s.K, alpha, u, pdf)
                          : vs_sample_defensive_pyramid(s.mips.data(), v.data(), s.D, s.K, alpha, u, pdf);
           },
           [&](vec3 d) {
             return table ? vs_pdf_defensive_table(s.mips.data(), t.data(), 3u, s.D, s.K, alpha, d)
                          : vs_pdf_defensive_pyramid(s.mips.data(), v.data(), s.D, s.K, alpha, d);
           },
           o)
    << " (defensive, alpha " << alpha << (table ? ", table, " : ", pyramid, ") << s.name << ")";
}

} // namespace

#endif
