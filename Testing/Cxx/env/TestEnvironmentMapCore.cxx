// The CPU environment map core (Module/env/vsEnvironmentMap): lat-long ->
// equal-area octahedral conversion, orientation, rotation, importance pyramid,
// bad texels, and the procedural maps.
#include "vsEnvironmentMap.h"

#include "sampling/octahedral.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;

vs::LatLongImage MakeLatLong(int w, int h, const std::function<glm::vec3(glm::dvec3)>& f)
{
  vs::LatLongImage img;
  img.Width = w;
  img.Height = h;
  img.RGB.resize(3 * std::size_t(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const glm::vec3 c = f(glm::dvec3(vs::LatLongToDirection((i + 0.5) / w, (j + 0.5) / h)));
      float* p = &img.RGB[3 * (std::size_t(j) * w + i)];
      p[0] = c.x;
      p[1] = c.y;
      p[2] = c.z;
    }
  }
  return img;
}

glm::dvec3 TexelCentre(int x, int y, int n)
{
  return glm::dvec3(vs::shared::vs_texel_dir(glm::uvec2(x, y), unsigned(n)));
}

double AngleDeg(glm::dvec3 a, glm::dvec3 b)
{
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / Pi;
}

/* The direction of the brightest texel. */
glm::dvec3 BrightestDirection(const vs::EnvironmentMap& map)
{
  int best = 0;
  const float* lum = map.Mip(map.Levels() - 1);
  for (int i = 1; i < map.Size * map.Size; ++i)
  {
    if (lum[i] > lum[best])
    {
      best = i;
    }
  }
  return TexelCentre(best % map.Size, best / map.Size, map.Size);
}

/* A lat-long that is black except a bright square of pixels around (u, v). */
vs::LatLongImage Spot(int w, int h, double u, double v)
{
  vs::LatLongImage img;
  img.Width = w;
  img.Height = h;
  img.RGB.assign(3 * std::size_t(w) * h, 0.0f);
  const int ci = int(u * w), cj = int(v * h);
  for (int j = cj - 1; j <= cj; ++j)
  {
    for (int i = ci - 1; i <= ci; ++i)
    {
      float* p = &img.RGB[3 * (std::size_t(j) * w + ((i + w) % w))];
      p[0] = p[1] = p[2] = 100.0f;
    }
  }
  return img;
}
} // namespace

TEST(EnvironmentMapCore, LatLongConventions)
{
  // docs/reference.md: phi = 2 pi (0.5 - u) from +X towards +Y, theta = pi v from +Z.
  EXPECT_LT(glm::length(vs::LatLongToDirection(0.5, 0.5) - glm::vec3(1, 0, 0)), 1e-6f);
  EXPECT_LT(glm::length(vs::LatLongToDirection(0.25, 0.5) - glm::vec3(0, 1, 0)), 1e-6f);
  EXPECT_LT(glm::length(vs::LatLongToDirection(0.75, 0.5) - glm::vec3(0, -1, 0)), 1e-6f);
  EXPECT_LT(glm::length(vs::LatLongToDirection(0.0, 0.5) - glm::vec3(-1, 0, 0)), 1e-6f);
  EXPECT_NEAR(vs::LatLongToDirection(0.3, 0.0).z, 1.0f, 1e-6f);
  EXPECT_NEAR(vs::LatLongToDirection(0.3, 1.0).z, -1.0f, 1e-6f);
  for (double u : { 0.01, 0.3, 0.5, 0.77, 0.99 })
  {
    for (double v : { 0.1, 0.5, 0.9 })
    {
      const glm::dvec2 uv = vs::DirectionToLatLong(glm::dvec3(vs::LatLongToDirection(u, v)));
      EXPECT_NEAR(uv.x, u, 1e-6);
      EXPECT_NEAR(uv.y, v, 1e-6);
    }
  }
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(1024, 512), 512);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(1000, 500), 512);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(2048, 1024), 1024);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(3, 2), 2);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(1, 1), 1);
}

// Issue 35, classes 3 and 4: the automatic size follows the map's pixels in both directions, and
// the map's mean radiance (solid-angle weighted) is the source's for any shape. From the width
// alone a map 1-2 pixels wide became a 1 x 1 map holding the upper pole's colour, and a small, very
// wide one a gigantic map (65536 x 1 pixels: 32768^2 texels, 12 GB).
TEST(EnvironmentMapCore, AnyShapeKeepsTheMeanAndABoundedSize)
{
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(1, 2), 1);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(2, 1000), 32);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(65536, 1), 256);
  EXPECT_EQ(vs::EnvironmentMap::DefaultSize(1 << 30, 1 << 30), 1 << 15);
  struct Shape
  {
    int W, H;
  };
  for (const Shape shape : { Shape{ 1, 1 }, Shape{ 1, 2 }, Shape{ 2, 1 }, Shape{ 2, 2 }, Shape{ 3, 1 },
         Shape{ 2, 64 }, Shape{ 4096, 1 }, Shape{ 4096, 2 } })
  {
    vs::LatLongImage img;
    img.Width = shape.W;
    img.Height = shape.H;
    img.RGB.resize(3 * std::size_t(shape.W) * shape.H);
    // Rows of different colours (the upper one bright), columns varying too.
    glm::dvec3 sum(0.0);
    for (int j = 0; j < shape.H; ++j)
    {
      // The row's solid angle over the whole sphere's: (cos theta0 - cos theta1) / 2.
      const double weight = 0.5 * (std::cos(Pi * j / shape.H) - std::cos(Pi * (j + 1) / shape.H)) / shape.W;
      for (int i = 0; i < shape.W; ++i)
      {
        const glm::vec3 c(j == 0 ? 5.0f : 0.5f + 0.1f * float(j % 3), 1.0f + 0.5f * float(i % 2), 0.2f + 0.01f * float(i % 7));
        float* p = &img.RGB[3 * (std::size_t(j) * shape.W + i)];
        p[0] = c.x;
        p[1] = c.y;
        p[2] = c.z;
        sum += weight * glm::dvec3(c);
      }
    }
    const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(img);
    const std::string what = std::to_string(shape.W) + " x " + std::to_string(shape.H);
    EXPECT_LE(double(map.Size) * map.Size, std::max(1.0, 2.0 * shape.W * shape.H)) << what; // the file's pixels
    // The piecewise-constant source's mean against the map's: the same for 1 or 2 rows (the bilinear
    // reading the conversion integrates is symmetric about the equator there), within a little for many.
    const double tolerance = shape.H <= 2 ? 0.002 : 0.03;
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(map.MeanRadiance[c], sum[c], tolerance * sum[c]) << what << ", channel " << c;
    }
  }
}

// An explicit size the machine cannot hold is refused with a clear error (32768^2 texels need
// ~18.6 GB), before anything is allocated.
TEST(EnvironmentMapCore, ExplicitSizeBoundedByMemory)
{
  const double memory = double(::sysconf(_SC_PHYS_PAGES)) * double(::sysconf(_SC_PAGE_SIZE));
  EXPECT_NO_THROW(vs::EnvironmentMap::CheckMemory(1024, "test"));
  if (memory < 2.0 * 18.6e9)
  {
    try
    {
      vs::EnvironmentMap::Allocate(32768);
      ADD_FAILURE() << "a 32768^2 map on a machine of " << memory / 1e9 << " GB was allocated";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find("choose a smaller octahedral size"), std::string::npos) << e.what();
    }
  }
}

// Radiance = (max(0, x), max(0, y), max(0, z)): a known function of direction
// whose three channels also check the three axes. Texels must hold its mean
// over their solid angle, computed here independently of the lat-long.
TEST(EnvironmentMapCore, SyntheticFunctionAtTexelCentres)
{
  auto f = [](glm::dvec3 d) {
    return glm::vec3(float(std::max(0.0, d.x)), float(std::max(0.0, d.y)), float(std::max(0.0, d.z)));
  };
  const vs::LatLongImage img = MakeLatLong(512, 256, f);
  const int n = 64;
  const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(img, n, 0.0, 1.0, nullptr, 1);
  ASSERT_EQ(map.Size, n);
  double worstMean = 0.0, worstCentre = 0.0;
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      // Reference: the analytic function averaged over a fine grid in the texel
      // (the map is equal-area, so uniform in uv is uniform in solid angle).
      glm::dvec3 ref(0.0);
      const int s = 16;
      for (int b = 0; b < s; ++b)
      {
        for (int a = 0; a < s; ++a)
        {
          const glm::vec2 uv((x + (a + 0.5f) / s) / n, (y + (b + 0.5f) / s) / n);
          ref += glm::dvec3(f(glm::dvec3(vs::shared::vs_octa_to_dir(uv))));
        }
      }
      ref /= double(s * s);
      const glm::dvec3 got(map.Texel(x, y));
      const glm::dvec3 centre(f(TexelCentre(x, y, n)));
      for (int c = 0; c < 3; ++c)
      {
        worstMean = std::max(worstMean, std::abs(got[c] - ref[c]));
        worstCentre = std::max(worstCentre, std::abs(got[c] - centre[c]));
      }
    }
  }
  // Lat-long pixels are 0.7 degrees: bilinear error ~1e-3 at the kinks (x = 0, ...).
  EXPECT_LT(worstMean, 3e-3);
  // Against the point value at the centre: the texel mean differs by the curvature
  // across a ~3 degree texel, and by up to a quarter slope-width at the kinks.
  EXPECT_LT(worstCentre, 0.03);
  // Orientation: +X, +Y, +Z texels are red, green, blue.
  EXPECT_GT(map.Evaluate(glm::vec3(1, 0, 0)).x, 0.95f);
  EXPECT_LT(map.Evaluate(glm::vec3(1, 0, 0)).y, 0.05f);
  EXPECT_GT(map.Evaluate(glm::vec3(0, 1, 0)).y, 0.95f);
  EXPECT_LT(map.Evaluate(glm::vec3(0, 1, 0)).x, 0.05f);
  EXPECT_GT(map.Evaluate(glm::vec3(0, 0, 1)).z, 0.95f);
  // Power: each channel integrates to pi over the sphere.
  EXPECT_NEAR(4.0 * Pi * map.MeanRadiance.x, Pi, 2e-3 * Pi);
  EXPECT_NEAR(4.0 * Pi * map.MeanRadiance.y, Pi, 2e-3 * Pi);
  EXPECT_NEAR(4.0 * Pi * map.MeanRadiance.z, Pi, 2e-3 * Pi);
  EXPECT_NEAR(map.TotalPower(), vs::LatLongPower(img), 2e-3 * map.TotalPower());
}

TEST(EnvironmentMapCore, OrientationTopIsUp)
{
  // Bright top rows (the sky near the zenith): the octahedral centre texels are
  // bright, the corners (-Z) black.
  vs::LatLongImage img;
  img.Width = 128;
  img.Height = 64;
  img.RGB.assign(3 * 128 * 64, 0.0f);
  for (int j = 0; j < 6; ++j)
  {
    for (int i = 0; i < 3 * 128; ++i)
    {
      img.RGB[3 * 128 * j + i] = 1.0f;
    }
  }
  const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(img, 32, 0.0, 1.0, nullptr, 1);
  for (int y = 15; y <= 16; ++y)
  {
    for (int x = 15; x <= 16; ++x)
    {
      EXPECT_NEAR(map.Texel(x, y).x, 1.0f, 1e-5f);
    }
  }
  EXPECT_EQ(map.Texel(0, 0).x, 0.0f);
  EXPECT_EQ(map.Texel(31, 31).x, 0.0f);
  EXPECT_EQ(map.Texel(0, 31).x, 0.0f);
  EXPECT_EQ(map.Evaluate(glm::vec3(1, 0, 0)).x, 0.0f);
}

TEST(EnvironmentMapCore, OrientationAzimuth)
{
  // A spot at column u lands at azimuth phi = 2 pi (0.5 - u) on the horizon.
  struct Case
  {
    double u;
    glm::dvec3 dir;
  };
  for (const Case& c : { Case{ 0.5, { 1, 0, 0 } }, Case{ 0.25, { 0, 1, 0 } }, Case{ 0.75, { 0, -1, 0 } },
         Case{ 0.0, { -1, 0, 0 } }, Case{ 0.375, glm::normalize(glm::dvec3(1, 1, 0)) } })
  {
    const vs::EnvironmentMap map =
      vs::EnvironmentMap::FromLatLong(Spot(256, 128, c.u, 0.5), 64, 0.0, 1.0, nullptr, 1);
    EXPECT_LT(AngleDeg(BrightestDirection(map), c.dir), 4.0) << "u = " << c.u;
  }
  // Above the horizon: v = 0.25 is 45 degrees up.
  const vs::EnvironmentMap map =
    vs::EnvironmentMap::FromLatLong(Spot(256, 128, 0.5, 0.25), 64, 0.0, 1.0, nullptr, 1);
  EXPECT_LT(AngleDeg(BrightestDirection(map), glm::normalize(glm::dvec3(1, 0, 1))), 4.0);
}

TEST(EnvironmentMapCore, Rotation)
{
  // rotation 90: d is looked up at R_z(-90) d, so what the file shows at +X appears at +Y.
  const vs::LatLongImage spot = Spot(256, 128, 0.5, 0.5);
  const vs::EnvironmentMap rotated = vs::EnvironmentMap::FromLatLong(spot, 64, 90.0, 1.0, nullptr, 1);
  EXPECT_LT(AngleDeg(BrightestDirection(rotated), glm::dvec3(0, 1, 0)), 4.0);
  const vs::EnvironmentMap minus = vs::EnvironmentMap::FromLatLong(spot, 64, -90.0, 1.0, nullptr, 1);
  EXPECT_LT(AngleDeg(BrightestDirection(minus), glm::dvec3(0, -1, 0)), 4.0);

  // Rotating by 90 degrees equals shifting the lat-long's columns by W/4 to the left.
  auto f = [](glm::dvec3 d) {
    return glm::vec3(float(1.0 + d.x + 0.5 * d.y * d.y), float(std::max(0.0, d.y)), float(0.2 + d.z * d.z));
  };
  const vs::LatLongImage img = MakeLatLong(256, 128, f);
  vs::LatLongImage shifted = img;
  for (int j = 0; j < img.Height; ++j)
  {
    for (int i = 0; i < img.Width; ++i)
    {
      const int src = (i + img.Width / 4) % img.Width;
      for (int c = 0; c < 3; ++c)
      {
        shifted.RGB[3 * (std::size_t(j) * img.Width + i) + c] =
          img.RGB[3 * (std::size_t(j) * img.Width + src) + c];
      }
    }
  }
  const vs::EnvironmentMap a = vs::EnvironmentMap::FromLatLong(img, 32, 90.0, 1.0, nullptr, 1);
  const vs::EnvironmentMap b = vs::EnvironmentMap::FromLatLong(shifted, 32, 0.0, 1.0, nullptr, 1);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.Radiance.size(); ++i)
  {
    worst = std::max(worst, double(std::abs(a.Radiance[i] - b.Radiance[i])));
  }
  EXPECT_LT(worst, 1e-4);
  // A full turn changes nothing; intensity scales.
  const vs::EnvironmentMap c = vs::EnvironmentMap::FromLatLong(img, 32, 360.0, 2.0, nullptr, 1);
  const vs::EnvironmentMap d = vs::EnvironmentMap::FromLatLong(img, 32, 0.0, 1.0, nullptr, 1);
  EXPECT_NEAR(c.TotalPower(), 2.0 * d.TotalPower(), 1e-5 * c.TotalPower());
}

TEST(EnvironmentMapCore, ImportancePyramidIsExactMeans)
{
  auto f = [](glm::dvec3 d) {
    return glm::vec3(float(std::exp(8.0 * (d.x - 1.0))), float(0.1 + 0.1 * d.z), float(std::abs(d.y)));
  };
  const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(MakeLatLong(256, 128, f), 64, 0.0, 1.0, nullptr, 1);
  ASSERT_EQ(map.Levels(), 7);
  ASSERT_EQ(map.ImportanceMips.size(), vs::EnvironmentMap::MipOffset(7));
  EXPECT_EQ(vs::EnvironmentMap::MipOffset(0), 0u);
  EXPECT_EQ(vs::EnvironmentMap::MipOffset(1), 1u);
  EXPECT_EQ(vs::EnvironmentMap::MipOffset(2), 5u);
  EXPECT_EQ(vs::EnvironmentMap::MipOffset(3), 21u);
  // Finest level = luminance of each texel.
  const float* finest = map.Mip(6);
  for (int y = 0; y < 64; ++y)
  {
    for (int x = 0; x < 64; ++x)
    {
      EXPECT_FLOAT_EQ(finest[y * 64 + x], vs::Luminance(map.Texel(x, y)));
    }
  }
  // Every coarser node is the mean of its 4 children.
  for (int l = 0; l < 6; ++l)
  {
    const int m = 1 << l;
    const float* coarse = map.Mip(l);
    const float* fine = map.Mip(l + 1);
    for (int y = 0; y < m; ++y)
    {
      for (int x = 0; x < m; ++x)
      {
        const double mean = 0.25 *
          (double(fine[2 * y * 2 * m + 2 * x]) + fine[2 * y * 2 * m + 2 * x + 1] +
            fine[(2 * y + 1) * 2 * m + 2 * x] + fine[(2 * y + 1) * 2 * m + 2 * x + 1]);
        EXPECT_NEAR(coarse[y * m + x], mean, 1e-6 * std::abs(mean) + 1e-30) << "level " << l;
      }
    }
  }
  EXPECT_NEAR(map.ImportanceMips[0], map.MeanLuminance, 1e-6 * map.MeanLuminance);
  EXPECT_NEAR(map.TotalPower(), 4.0 * Pi * map.MeanLuminance, 1e-12);
}

TEST(EnvironmentMapCore, BadTexelsZeroedAndCounted)
{
  vs::LatLongImage img = MakeLatLong(64, 32, [](glm::dvec3 d) { return glm::vec3(float(1.0 + d.x)); });
  vs::LatLongImage clean = img;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Bad
  {
    int pixel, channel;
    float value;
  };
  const Bad bads[] = { { 10, 0, nan }, { 200, 1, inf }, { 300, 2, -inf }, { 400, 0, -0.5f }, { 400, 2, nan },
    { 2047, 1, -1e-3f } };
  for (const Bad& b : bads)
  {
    img.RGB[3 * b.pixel + b.channel] = b.value;
    clean.RGB[3 * b.pixel + b.channel] = 0.0f;
  }
  const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(img, 16, 0.0, 1.0, nullptr, 1);
  EXPECT_EQ(map.BadTexels, 4);       // pixels 10, 200, 300, 400
  EXPECT_EQ(map.NonFiniteTexels, 4); // 10, 200, 300, 400
  EXPECT_EQ(map.RingingTexels, 1);   // 2047: -1e-3 is 0.1% of the mean luminance (~1), zeroed without a warning
  for (float v : map.Radiance)
  {
    EXPECT_TRUE(std::isfinite(v) && v >= 0.0f);
  }
  for (float v : map.ImportanceMips)
  {
    EXPECT_TRUE(std::isfinite(v) && v >= 0.0f);
  }
  // Exactly the conversion of the image with those channels set to 0.
  const vs::EnvironmentMap ref = vs::EnvironmentMap::FromLatLong(clean, 16, 0.0, 1.0, nullptr, 1);
  EXPECT_EQ(ref.BadTexels, 0);
  EXPECT_EQ(map.Radiance, ref.Radiance);
  EXPECT_NEAR(vs::LatLongPower(img), vs::LatLongPower(clean), 1e-12);
}

TEST(EnvironmentMapCore, AllBlackMap)
{
  vs::LatLongImage img;
  img.Width = 64;
  img.Height = 32;
  img.RGB.assign(3 * 64 * 32, 0.0f);
  const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(img, 0, 0.0, 1.0, nullptr, 1);
  EXPECT_EQ(map.Size, 32);
  EXPECT_EQ(map.BadTexels, 0);
  for (float v : map.Radiance)
  {
    EXPECT_EQ(v, 0.0f);
  }
  for (float v : map.ImportanceMips)
  {
    EXPECT_EQ(v, 0.0f);
  }
  EXPECT_EQ(map.TotalPower(), 0.0);
  EXPECT_EQ(map.MeanLuminance, 0.0);
  EXPECT_EQ(map.Evaluate(glm::vec3(0.3f, -0.2f, 0.9f)), glm::vec3(0.0f));
  EXPECT_EQ(map.Evaluate(glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(EnvironmentMapCore, InvalidArguments)
{
  vs::LatLongImage img;
  EXPECT_THROW(vs::EnvironmentMap::FromLatLong(img), std::invalid_argument);
  img.Width = 8;
  img.Height = 4;
  img.RGB.assign(3 * 32, 1.0f);
  EXPECT_THROW(vs::EnvironmentMap::FromLatLong(img, 12), std::invalid_argument);
  EXPECT_THROW(vs::EnvironmentMap::Constant(0, glm::vec3(1.0f)), std::invalid_argument);
  EXPECT_THROW(vs::EnvironmentMap::SunDisk(8, glm::vec3(0.0f), 1.0, glm::vec3(1.0f)), std::invalid_argument);
  EXPECT_NO_THROW(vs::EnvironmentMap::FromLatLong(img, 1));
  // Threads do not change the result.
  const vs::LatLongImage f = MakeLatLong(128, 64, [](glm::dvec3 d) { return glm::vec3(float(1.0 + d.x * d.y)); });
  EXPECT_EQ(vs::EnvironmentMap::FromLatLong(f, 32, 10.0, 1.0, nullptr, 1).Radiance,
    vs::EnvironmentMap::FromLatLong(f, 32, 10.0, 1.0, nullptr, 3).Radiance);
}

TEST(EnvironmentMapCore, EvaluateIsTheTexel)
{
  const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(
    MakeLatLong(128, 64, [](glm::dvec3 d) { return glm::vec3(float(2.0 + d.x + 0.3 * d.z)); }), 16, 0.0, 1.0,
    nullptr, 1);
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      EXPECT_EQ(map.Evaluate(glm::vec3(TexelCentre(x, y, 16)) * 3.0f), map.Texel(x, y));
    }
  }
}

TEST(EnvironmentMapCore, ConstantAndTwoTone)
{
  const vs::EnvironmentMap c = vs::EnvironmentMap::Constant(16, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_NEAR(c.MeanRadiance.y, 2.0, 1e-12);
  EXPECT_NEAR(c.TotalPower(), 4.0 * Pi * vs::Luminance(glm::vec3(1, 2, 3)), 1e-5);

  for (int n : { 1, 2, 4, 32 })
  {
    const glm::vec3 up(2.0f, 1.0f, 0.5f), low(0.0f, 0.25f, 0.0f);
    const vs::EnvironmentMap t = vs::EnvironmentMap::TwoToneSky(n, up, low);
    // Exactly half the sphere each.
    EXPECT_NEAR(t.MeanRadiance.x, 1.0, 1e-6) << n;
    EXPECT_NEAR(t.MeanRadiance.y, 0.625, 1e-6) << n;
    if (n >= 4)
    {
      EXPECT_EQ(t.Evaluate(glm::vec3(0, 0, 1)), up);
      EXPECT_EQ(t.Evaluate(glm::vec3(0.1f, 0.2f, -1)), low);
      // Horizon texels (split by the diamond's diagonal) hold the exact half mix.
      EXPECT_NEAR(t.Evaluate(glm::vec3(1, 0.01f, 0.0001f)).x, 1.0f, 1e-6f);
    }
  }
}

// A sun smaller than a texel keeps its power: 4 pi mean = 2 pi (1 - cos r) L ~ pi r^2 L.
TEST(EnvironmentMapCore, SunDiskKeepsPower)
{
  const glm::vec3 radiance(5e4f, 4e4f, 3e4f);
  const glm::vec3 dirs[] = { { 1, 0, 1 }, { 0, 0, 1 }, { 0, 0, -1 }, { 1, 1, 0 }, { -0.3f, 0.8f, 0.1f },
    { 0.2f, -0.7f, -0.5f }, { 1, 0, 0 } };
  for (int n : { 8, 64, 256 })
  {
    for (double rDeg : { 0.27, 2.0, 20.0 })
    {
      for (glm::vec3 d : dirs)
      {
        const vs::EnvironmentMap sun = vs::EnvironmentMap::SunDisk(n, d, rDeg, radiance);
        const double r = rDeg * Pi / 180.0;
        const double exact = 2.0 * Pi * (1.0 - std::cos(r)) * vs::Luminance(radiance);
        EXPECT_NEAR(sun.TotalPower(), exact, 0.01 * exact) << "n " << n << " r " << rDeg << " d " << d.x
                                                           << " " << d.y << " " << d.z;
        if (rDeg < 1.0)
        {
          EXPECT_NEAR(sun.TotalPower(), Pi * r * r * vs::Luminance(radiance), 0.01 * exact);
        }
        // The sun's texel is the brightest and lies towards the sun.
        EXPECT_LT(AngleDeg(BrightestDirection(sun), glm::normalize(glm::dvec3(d))),
          rDeg + 2.0 * 180.0 / n + 1.0);
      }
    }
  }
  // Sky around the sun: the sky covers the rest of the sphere.
  const vs::EnvironmentMap withSky =
    vs::EnvironmentMap::SunDisk(64, glm::vec3(0, 1, 1), 1.0, glm::vec3(1000.0f), glm::vec3(0.5f));
  const double rr = Pi / 180.0;
  const double omega = 2.0 * Pi * (1.0 - std::cos(rr));
  EXPECT_NEAR(withSky.TotalPower(), 1000.0 * omega + 0.5 * (4.0 * Pi - omega), 0.002 * withSky.TotalPower());
  // A tiny sun (below 1e-5 rad) becomes a point carrying the disk's power.
  const vs::EnvironmentMap tiny = vs::EnvironmentMap::SunDisk(32, glm::vec3(1, 2, 3), 1e-4, glm::vec3(1e9f));
  const double rt = 1e-4 * Pi / 180.0;
  EXPECT_NEAR(tiny.TotalPower(), 2.0 * Pi * (1.0 - std::cos(rt)) * 1e9, 0.01 * Pi * rt * rt * 1e9);
}
