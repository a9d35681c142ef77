// vsEnvironmentMap.cxx — the octahedral environment map on the CPU: sanitising radiance,
// the luminance importance pyramid (Finalize), lookups, and the conversion of lat-long images
// (LatLongPower, FromLatLong: each texel integrated over its solid angle). The procedural maps
// (Constant, TwoToneSky, SunDisk) are in vsEnvironmentMapProcedural.cxx.
#include "vsEnvironmentMap.h"

#include "sampling/octahedral.h"

#include <glm/gtc/constants.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

namespace vs
{
namespace
{
constexpr double Pi = glm::pi<double>();
// Lat-long integration: base sub-sample spacing in source pixels, the per-axis
// refinement of texels whose samples vary by more than RefineFraction of the
// map's power, and the most sub-samples per axis.
constexpr double BaseSpacing = 0.7;
constexpr double RefineFraction = 1e-4;
constexpr int RefineFactor = 4;
constexpr int MaxSub = 32;
// The finest map a lat-long is first converted to when a coarser one is requested.
constexpr int MaxWorkSize = 2048;
// ... and at least this fine: the sub-sample grid of a texel is sized by its corners' directions, which
// for a map of 1 or 2 texels per side coincide (one sample at the texel's centre: a 1 x 1 map held the
// upper pole's colour, not the mean). Box-filtered down afterwards, so the mean is kept.
constexpr int MinWorkSize = 16;

bool Good(float c)
{
  return std::isfinite(c) && c >= 0.0f;
}

/* Zero the bad channels of n RGB triples; counts the triples that had one, and
 * those that had a NaN or infinite one. A triple whose only bad channels are
 * negatives of magnitude at most ringingBound counts as ringing instead. */
void SanitizeRGB(float* rgb, std::size_t n, std::int64_t& bad, std::int64_t& nonFinite, std::int64_t& ringing,
  double ringingBound)
{
  for (std::size_t i = 0; i < n; ++i)
  {
    float* p = rgb + 3 * i;
    if (!(Good(p[0]) && Good(p[1]) && Good(p[2])))
    {
      const auto small = [ringingBound](float c) { return Good(c) || (c < 0.0f && -double(c) <= ringingBound); };
      if (small(p[0]) && small(p[1]) && small(p[2]))
      {
        ++ringing;
        for (int c = 0; c < 3; ++c)
        {
          p[c] = std::max(p[c], 0.0f);
        }
        continue;
      }
      ++bad;
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
      {
        ++nonFinite;
      }
      for (int c = 0; c < 3; ++c)
      {
        p[c] = Good(p[c]) ? p[c] : 0.0f;
      }
    }
  }
}

/* Bilinear lookup in a sanitized lat-long at lat-long coordinate u (any real,
 * wrapped) and polar angle fraction v. */
glm::vec3 BilinearUV(const LatLongImage& img, double u, double v)
{
  const int w = img.Width;
  const int h = img.Height;
  double x = u * w - 0.5;
  double y = v * h - 0.5;
  double xf = std::floor(x);
  double yf = std::floor(y);
  float fx = float(x - xf);
  float fy = float(y - yf);
  long long xi = (long long)xf % w;
  if (xi < 0)
  {
    xi += w;
  }
  int x0 = int(xi);
  int x1 = x0 + 1 == w ? 0 : x0 + 1;
  int y0 = int(yf);
  int y1 = y0 + 1;
  y0 = std::min(std::max(y0, 0), h - 1);
  y1 = std::min(std::max(y1, 0), h - 1);
  glm::vec3 a = img.Pixel(x0, y0), b = img.Pixel(x1, y0);
  glm::vec3 c = img.Pixel(x0, y1), d = img.Pixel(x1, y1);
  return (a * (1.0f - fx) + b * fx) * (1.0f - fy) + (c * (1.0f - fx) + d * fx) * fy;
}

void CheckSize(int size, const char* what)
{
  if (!EnvironmentMap::IsPowerOfTwo(size) || size > (1 << 15))
  {
    throw std::invalid_argument(std::string(what) + ": the octahedral size must be a power of two in [1, 32768], not " +
      std::to_string(size));
  }
}
} // namespace

glm::vec3 LatLongToDirection(double u, double v)
{
  const double phi = 2.0 * Pi * (0.5 - u);
  const double theta = Pi * v;
  return glm::vec3(glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)));
}

glm::dvec2 DirectionToLatLong(glm::dvec3 d)
{
  d = glm::normalize(d);
  double u = 0.5 - std::atan2(d.y, d.x) / (2.0 * Pi);
  if (u >= 1.0)
  {
    u -= 1.0;
  }
  const double v = std::acos(std::min(1.0, std::max(-1.0, d.z))) / Pi;
  return glm::dvec2(u, v);
}

glm::vec3 LatLongImage::Lookup(glm::vec3 dir) const
{
  const glm::dvec2 uv = DirectionToLatLong(glm::dvec3(dir));
  return BilinearUV(*this, uv.x, uv.y);
}

double LatLongPower(const LatLongImage& image)
{
  double total = 0.0;
  for (int j = 0; j < image.Height; ++j)
  {
    const double band = std::cos(Pi * j / image.Height) - std::cos(Pi * (j + 1) / image.Height);
    double row = 0.0;
    for (int i = 0; i < image.Width; ++i)
    {
      glm::vec3 p = image.Pixel(i, j);
      for (int c = 0; c < 3; ++c)
      {
        p[c] = Good(p[c]) ? p[c] : 0.0f;
      }
      row += Luminance(p);
    }
    total += row * band * 2.0 * Pi / image.Width;
  }
  return total;
}

int EnvironmentMap::Levels() const
{
  int levels = 0;
  while ((1 << levels) < this->Size)
  {
    ++levels;
  }
  return this->Size > 0 ? levels + 1 : 0;
}

glm::vec3 EnvironmentMap::Evaluate(glm::vec3 dir) const
{
  const float len = glm::length(dir);
  if (this->Empty() || !(len > 0.0f) || !std::isfinite(len))
  {
    return glm::vec3(0.0f);
  }
  const glm::uvec2 t = shared::vs_dir_to_texel(dir / len, unsigned(this->Size));
  return this->Texel(int(t.x), int(t.y));
}

double EnvironmentMap::TexelSolidAngle() const
{
  return this->Size > 0 ? 4.0 * Pi / (double(this->Size) * this->Size) : 0.0;
}

std::vector<glm::vec3> EnvironmentMap::MeanRadianceLevel(int side) const
{
  if (!IsPowerOfTwo(side) || side > this->Size)
  {
    throw std::invalid_argument("MeanRadianceLevel: " + std::to_string(side) +
      " is not a power of two of at most the map's size " + std::to_string(this->Size));
  }
  const int f = this->Size / side;
  std::vector<glm::dvec3> sum(std::size_t(side) * side, glm::dvec3(0.0));
  for (int y = 0; y < this->Size; ++y)
  {
    for (int x = 0; x < this->Size; ++x)
    {
      sum[std::size_t(y / f) * side + x / f] += glm::dvec3(this->Texel(x, y));
    }
  }
  std::vector<glm::vec3> mean(sum.size());
  for (std::size_t t = 0; t < sum.size(); ++t)
  {
    mean[t] = glm::vec3(sum[t] / (double(f) * f));
  }
  return mean;
}

double EnvironmentMap::TotalPower() const
{
  return 4.0 * Pi * this->MeanLuminance;
}

int EnvironmentMap::DefaultSize(int latLongWidth, int latLongHeight)
{
  const double pixels = double(std::max(0, latLongWidth)) * double(std::max(0, latLongHeight));
  int size = 1;
  while (double(size) * size < pixels / 2.0 && size < (1 << 15))
  {
    size *= 2;
  }
  return size;
}

void EnvironmentMap::CheckMemory(int size, const char* what)
{
  // Radiance (3 floats) and the luminance pyramid (1 float, 4/3 over its levels) per texel.
  const double bytes = double(size) * double(size) * (12.0 + 4.0 * 4.0 / 3.0);
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  const double memory = pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
  if (memory > 0.0 && bytes > 0.5 * memory)
  {
    char text[256];
    std::snprintf(text, sizeof(text),
      "an octahedral map of %d x %d texels needs %.1f GB, more than half of this machine's %.1f GB; "
      "choose a smaller octahedral size",
      size, size, bytes / 1e9, memory / 1e9);
    throw std::invalid_argument(std::string(what) + ": " + text);
  }
}

EnvironmentMap EnvironmentMap::Allocate(int size)
{
  CheckSize(size, "EnvironmentMap");
  CheckMemory(size, "EnvironmentMap");
  EnvironmentMap map;
  map.Size = size;
  map.Radiance.assign(3 * std::size_t(size) * size, 0.0f);
  return map;
}

void EnvironmentMap::Finalize()
{
  const int n = this->Size;
  const std::size_t texels = std::size_t(n) * n;
  // The ringing bound: RingingFraction of the mean luminance of the good parts (equal-area texels).
  double lum = 0.0;
  for (std::size_t i = 0; i < texels; ++i)
  {
    const float* p = &this->Radiance[3 * i];
    lum += Luminance(glm::vec3(Good(p[0]) ? p[0] : 0.0f, Good(p[1]) ? p[1] : 0.0f, Good(p[2]) ? p[2] : 0.0f));
  }
  const double bound = texels ? RingingFraction * lum / double(texels) : 0.0;
  SanitizeRGB(this->Radiance.data(), texels, this->BadTexels, this->NonFiniteTexels, this->RingingTexels, bound);
  const int levels = this->Levels();
  this->ImportanceMips.assign(levels > 0 ? MipOffset(levels - 1) + texels : 0, 0.0f);
  this->MeanRadiance = glm::dvec3(0.0);
  this->MeanLuminance = 0.0;
  if (levels == 0)
  {
    return;
  }
  float* finest = this->ImportanceMips.data() + MipOffset(levels - 1);
  glm::dvec3 sum(0.0);
  double lumSum = 0.0;
  for (std::size_t i = 0; i < texels; ++i)
  {
    const glm::vec3 c(this->Radiance[3 * i], this->Radiance[3 * i + 1], this->Radiance[3 * i + 2]);
    finest[i] = Luminance(c);
    sum += glm::dvec3(c);
    lumSum += finest[i];
  }
  this->MeanRadiance = sum / double(texels);
  this->MeanLuminance = lumSum / double(texels);
  for (int l = levels - 2; l >= 0; --l)
  {
    const int m = 1 << l;
    const float* fine = this->ImportanceMips.data() + MipOffset(l + 1);
    float* coarse = this->ImportanceMips.data() + MipOffset(l);
    for (int y = 0; y < m; ++y)
    {
      for (int x = 0; x < m; ++x)
      {
        const std::size_t f = std::size_t(2 * y) * (2 * m) + 2 * x;
        coarse[std::size_t(y) * m + x] = float(
          0.25 * (double(fine[f]) + double(fine[f + 1]) + double(fine[f + 2 * m]) + double(fine[f + 2 * m + 1])));
      }
    }
  }
}

EnvironmentMap EnvironmentMap::FromLatLong(const LatLongImage& image, int size, double rotationDeg,
  double intensity, const ProgressFunction& progress, int threads)
{
  if (image.Width <= 0 || image.Height <= 0 ||
    image.RGB.size() != 3 * std::size_t(image.Width) * image.Height)
  {
    throw std::invalid_argument("EnvironmentMap::FromLatLong: empty or inconsistent lat-long image (" +
      std::to_string(image.Width) + " x " + std::to_string(image.Height) + ", " +
      std::to_string(image.RGB.size()) + " floats)");
  }
  if (size == 0)
  {
    size = DefaultSize(image.Width, image.Height);
  }
  CheckSize(size, "EnvironmentMap::FromLatLong");
  CheckMemory(size, "EnvironmentMap::FromLatLong");
  if (!std::isfinite(rotationDeg) || !std::isfinite(intensity))
  {
    throw std::invalid_argument("EnvironmentMap::FromLatLong: rotation and intensity must be finite");
  }

  // A sanitized copy of the source: bad channels become 0 before any filtering,
  // so one NaN cannot spread to the neighbouring texels.
  LatLongImage src;
  src.Width = image.Width;
  src.Height = image.Height;
  src.RGB = image.RGB;
  // The conversion runs at the source's own resolution (the default size, at
  // most MaxWorkSize) or finer; a smaller requested map is then box-filtered
  // 2x2 at a time, which is exact: an octahedral texel is the union of its 4
  // children, all of equal solid angle.
  const int work = std::max(size, std::clamp(DefaultSize(src.Width, src.Height), MinWorkSize, MaxWorkSize));
  EnvironmentMap map = Allocate(work);
  // The ringing bound: RingingFraction of the source's mean luminance over the sphere (negative
  // and non-finite channels count as 0 in LatLongPower).
  const double ringingBound = RingingFraction * LatLongPower(src) / (4.0 * Pi);
  SanitizeRGB(src.RGB.data(), std::size_t(src.Width) * src.Height, map.BadTexels, map.NonFiniteTexels,
    map.RingingTexels, ringingBound);

  const int n = work;
  // Directions of the texel corners, (n+1)^2, to size each texel's sub-sample grid.
  std::vector<glm::vec3> corners(std::size_t(n + 1) * (n + 1));
  for (int y = 0; y <= n; ++y)
  {
    for (int x = 0; x <= n; ++x)
    {
      corners[std::size_t(y) * (n + 1) + x] = OctahedralToDirection(double(x) / n, double(y) / n);
    }
  }
  // Sub-sample spacing: at most ~0.7 source pixel (the smaller of the pixel's
  // polar and equatorial azimuthal extents). The bilinear reconstruction of a
  // one-pixel peak is 2 pixels wide, so this grid always sees it; texels whose
  // samples vary by a noticeable share of the map's power (a sun, a lamp) are
  // then integrated again 4x finer per axis, so narrow bright features keep their
  // power (0.1% on real skies instead of ~1% at this spacing alone).
  const double pixelAngle = std::min(Pi / src.Height, 2.0 * Pi / src.Width);
  const double spacing = BaseSpacing * pixelAngle;
  const double texelSolidAngle = map.TexelSolidAngle();
  const double refineThreshold = RefineFraction * LatLongPower(src);
  // Rotation: d is looked up as R_z(-rotation) d, i.e. at azimuth phi - rotation,
  // which is the lat-long coordinate u + rotation / 360.
  const double uShift = rotationDeg / 360.0 - std::floor(rotationDeg / 360.0);
  const float scale = float(intensity);

  // Mean of an sx x sy grid of sub-samples over texel (x, y); the luminance range seen.
  auto integrate = [&](int x, int y, int sx, int sy, float& lumMin, float& lumMax) {
    glm::dvec3 sum(0.0);
    lumMin = std::numeric_limits<float>::max();
    lumMax = 0.0f;
    for (int b = 0; b < sy; ++b)
    {
      const double v = (y + (b + 0.5) / sy) / n;
      for (int a = 0; a < sx; ++a)
      {
        const double u = (x + (a + 0.5) / sx) / n;
        const glm::vec3 d = OctahedralToDirection(u, v);
        const double lu = 0.5 - std::atan2(double(d.y), double(d.x)) / (2.0 * Pi) + uShift;
        const double lv = std::acos(std::min(1.0, std::max(-1.0, double(d.z)))) / Pi;
        const glm::vec3 c = BilinearUV(src, lu, lv);
        const float l = Luminance(c);
        lumMin = std::min(lumMin, l);
        lumMax = std::max(lumMax, l);
        sum += glm::dvec3(c);
      }
    }
    return glm::vec3(sum / double(sx * sy));
  };

  auto doRow = [&](int y) {
    for (int x = 0; x < n; ++x)
    {
      const glm::vec3& c00 = corners[std::size_t(y) * (n + 1) + x];
      const glm::vec3& c10 = corners[std::size_t(y) * (n + 1) + x + 1];
      const glm::vec3& c01 = corners[std::size_t(y + 1) * (n + 1) + x];
      const glm::vec3& c11 = corners[std::size_t(y + 1) * (n + 1) + x + 1];
      // Chord lengths ~ angles: the texel's extent along x and y.
      const double ex = std::max(glm::length(c10 - c00), glm::length(c11 - c01));
      const double ey = std::max(glm::length(c01 - c00), glm::length(c11 - c10));
      const int sx = std::min(MaxSub, std::max(1, int(std::ceil(ex / spacing))));
      const int sy = std::min(MaxSub, std::max(1, int(std::ceil(ey / spacing))));
      float lumMin, lumMax;
      glm::vec3 mean = integrate(x, y, sx, sy, lumMin, lumMax);
      if ((lumMax - lumMin) * texelSolidAngle > refineThreshold)
      {
        mean = integrate(x, y, sx * RefineFactor, sy * RefineFactor, lumMin, lumMax);
      }
      mean *= scale;
      float* out = &map.Radiance[3 * (std::size_t(y) * n + x)];
      out[0] = mean.x;
      out[1] = mean.y;
      out[2] = mean.z;
    }
  };

  if (threads <= 0)
  {
    threads = int(std::max(1u, std::thread::hardware_concurrency()));
  }
  threads = std::min(threads, n);
  std::atomic<int> nextRow(0);
  auto worker = [&](bool report) {
    for (int y = nextRow++; y < n; y = nextRow++)
    {
      doRow(y);
      if (report && progress && (y % 16 == 0))
      {
        progress(std::min(1.0, double(nextRow.load()) / n));
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
  {
    pool.emplace_back(worker, false);
  }
  worker(true);
  for (std::thread& t : pool)
  {
    t.join();
  }
  while (map.Size > size)
  {
    const int m = map.Size / 2;
    std::vector<float> coarse(3 * std::size_t(m) * m);
    for (int y = 0; y < m; ++y)
    {
      for (int x = 0; x < m; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          auto at = [&](int xx, int yy) { return double(map.Radiance[3 * (std::size_t(yy) * map.Size + xx) + c]); };
          coarse[3 * (std::size_t(y) * m + x) + c] = float(
            0.25 * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1)));
        }
      }
    }
    map.Radiance.swap(coarse);
    map.Size = m;
  }
  map.Finalize();
  if (progress)
  {
    progress(1.0);
  }
  return map;
}


} // namespace vs
