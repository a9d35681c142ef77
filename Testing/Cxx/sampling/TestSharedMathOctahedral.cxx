// The equal-area octahedral map, exactly as the shaders compile it.
#include "sampling/octahedral.h"
#include "sampling/rng.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vs::shared;

TEST(Octahedral, RoundTripDirectionUvDirection)
{
  VsRng rng = vs_rng_init(uvec2(7u, 3u), 0u, 42u);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i)
  {
    // A uniform direction on the sphere.
    vec2 u = vs_rng_vec2(rng);
    float z = 1.0f - 2.0f * u.x;
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * VS_PI * u.y;
    vec3 d(r * std::cos(phi), r * std::sin(phi), z);
    vec3 e = vs_octa_to_dir(vs_dir_to_octa(d));
    worst = std::max(worst, double(glm::length(e - d)));
  }
  EXPECT_LT(worst, 1e-5);
}

TEST(Octahedral, AxesAndSeams)
{
  const vec3 axes[] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
    glm::normalize(vec3(1, 1, 0)), glm::normalize(vec3(-1, 1, -1)), glm::normalize(vec3(1, -1, 1)) };
  for (vec3 d : axes)
  {
    vec2 uv = vs_dir_to_octa(d);
    EXPECT_GE(uv.x, 0.0f);
    EXPECT_LE(uv.x, 1.0f);
    EXPECT_GE(uv.y, 0.0f);
    EXPECT_LE(uv.y, 1.0f);
    EXPECT_LT(glm::length(vs_octa_to_dir(uv) - d), 1e-5f) << d.x << " " << d.y << " " << d.z;
  }
  EXPECT_NEAR(vs_octa_to_dir(vec2(0.5f)).z, 1.0f, 1e-6f);
  EXPECT_NEAR(vs_octa_to_dir(vec2(0.0f)).z, -1.0f, 1e-6f);
}

// Solid angle of a spherical triangle (Van Oosterom and Strackee).
static double TriangleSolidAngle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c)
{
  double num = glm::dot(a, glm::cross(b, c));
  double den = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
  return std::abs(2.0 * std::atan2(num, den));
}

// Every texel of a 2^k x 2^k map covers 4*pi/4^k: integrate each texel's image on
// the sphere by subdividing it into small spherical quads (two triangles each).
TEST(Octahedral, EqualAreaTexels)
{
  for (int k = 1; k <= 5; ++k)
  {
    const int n = 1 << k;
    const int sub = 64 >> (k - 1) < 16 ? 16 : 64 >> (k - 1);
    const double expected = 4.0 * M_PI / (n * n);
    double worst = 0.0, total = 0.0;
    for (int ty = 0; ty < n; ++ty)
    {
      for (int tx = 0; tx < n; ++tx)
      {
        double area = 0.0;
        for (int j = 0; j < sub; ++j)
        {
          for (int i = 0; i < sub; ++i)
          {
            auto P = [&](int a, int b) {
              double u = (tx + double(i + a) / sub) / n;
              double v = (ty + double(j + b) / sub) / n;
              return glm::normalize(glm::dvec3(vs_octa_to_dir(vec2(float(u), float(v)))));
            };
            glm::dvec3 p00 = P(0, 0), p10 = P(1, 0), p01 = P(0, 1), p11 = P(1, 1);
            area += TriangleSolidAngle(p00, p10, p11) + TriangleSolidAngle(p00, p11, p01);
          }
        }
        total += area;
        worst = std::max(worst, std::abs(area / expected - 1.0));
      }
    }
    EXPECT_LT(worst, 1e-3) << "k = " << k;
    EXPECT_NEAR(total, 4.0 * M_PI, 1e-3) << "k = " << k;
  }
}

TEST(Octahedral, TexelLookupMatchesCentre)
{
  for (uint n : { 4u, 8u, 16u })
  {
    for (uint y = 0; y < n; ++y)
    {
      for (uint x = 0; x < n; ++x)
      {
        uvec2 t = vs_dir_to_texel(vs_texel_dir(uvec2(x, y), n), n);
        EXPECT_EQ(t.x, x);
        EXPECT_EQ(t.y, y);
      }
    }
  }
}

// Folding across the edges: the texel one step beyond an edge is the texel the sphere reaches
// by continuing across the seam. From a point just inside the edge (a thousandth of a texel) at
// a texel centre's height, through the seam point at that height, on by as much again
// (extrapolated on the sphere; the step is small, so the map's shear along the seam does not
// move it by a texel): that direction's texel is vs_octa_wrap of the texel beyond the edge.
// All four edges, every texel along them.
TEST(Octahedral, WrapCrossesTheSeams)
{
  for (int n : { 8, 16, 64 })
  {
    int checked = 0;
    for (int i = 0; i < n; ++i)
    {
      const float a = (float(i) + 0.5f) / float(n), e = 1e-3f / float(n);
      // (inside uv, seam uv, texel beyond the edge)
      const struct
      {
        vec2 inside, seam;
        ivec2 beyond;
      } cases[] = { { vec2(e, a), vec2(0.0f, a), ivec2(-1, i) }, { vec2(1.0f - e, a), vec2(1.0f, a), ivec2(n, i) },
        { vec2(a, e), vec2(a, 0.0f), ivec2(i, -1) }, { vec2(a, 1.0f - e), vec2(a, 1.0f), ivec2(i, n) } };
      for (const auto& c : cases)
      {
        const vec3 inside = vs_octa_to_dir(c.inside), seam = vs_octa_to_dir(c.seam);
        const vec3 across = glm::normalize(2.0f * seam - inside);
        const uvec2 expected = vs_dir_to_texel(across, uint(n));
        const uvec2 got = vs_octa_wrap(c.beyond, n);
        EXPECT_EQ(got, expected) << "n " << n << " beyond (" << c.beyond.x << ", " << c.beyond.y << ")";
        ++checked;
      }
    }
    EXPECT_EQ(checked, 4 * n);
  }
  // Inside the map, wrapping changes nothing.
  EXPECT_EQ(vs_octa_wrap(ivec2(3, 5), 8), uvec2(3u, 5u));
}

// Bilinear lookup (the visible background): the weights are a partition of unity, and a smooth
// function stored at texel centres is reproduced to O(1/n) everywhere, seams and corners
// included (a wrong fold would leave errors of order 1 there).
TEST(Octahedral, BilinearLookupIsSeamless)
{
  auto f = [](vec3 d) { return 2.0f + d.x + 0.5f * d.y - 1.5f * d.z + d.x * d.y; };
  for (uint n : { 16u, 64u })
  {
    std::vector<float> map(n * n);
    for (uint y = 0; y < n; ++y)
      for (uint x = 0; x < n; ++x)
        map[y * n + x] = f(vs_texel_dir(uvec2(x, y), n));
    VsRng rng = vs_rng_init(uvec2(n, 1u), 0u, 9u);
    double worst = 0.0, worstSeam = 0.0;
    for (int i = 0; i < 100000; ++i)
    {
      vec2 uv = vs_rng_vec2(rng);
      if (i % 4 == 0)
        uv.x = (i % 8 == 0) ? 0.3f / float(n) * uv.x : 1.0f - 0.3f / float(n) * uv.x; // within a texel of an edge
      float sum = 0.0f, weights = 0.0f;
      for (uint c = 0; c < 4; ++c)
      {
        float w;
        uvec2 t = vs_octa_bilinear_texel(uv, n, c, w);
        ASSERT_GE(w, 0.0f);
        ASSERT_LE(w, 1.0f);
        ASSERT_LT(t.x, n);
        ASSERT_LT(t.y, n);
        sum += w * map[t.y * n + t.x];
        weights += w;
      }
      ASSERT_NEAR(weights, 1.0f, 1e-5f);
      const double err = std::abs(double(sum) - double(f(vs_octa_to_dir(uv))));
      worst = std::max(worst, err);
      if (i % 4 == 0)
        worstSeam = std::max(worstSeam, err);
    }
    std::printf("n %u: worst bilinear error %.4f (next to an edge %.4f)\n", n, worst, worstSeam);
    EXPECT_LT(worst, 12.0 / double(n));
    EXPECT_LT(worstSeam, 12.0 / double(n));
  }
}
