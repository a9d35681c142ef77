/*
 * vsEnvironmentMap.h — environment light on the CPU: equirectangular (lat-long)
 * images converted to the equal-area octahedral map the renderer samples, and
 * the luminance importance pyramid (quadtree) built on it. No VTK types.
 *
 * Conventions (docs/reference.md, "Environment light and its orientation"):
 *  - Lat-long: column u in [0,1) left to right is the azimuth phi = 2 pi (0.5 - u),
 *    measured from +X towards +Y; row v in [0,1) top to bottom is the polar angle
 *    theta = pi v from +Z. +Z is up, the image centre looks along +X, u = 0.25 is +Y.
 *    Pixel (i, j) has its centre at u = (i + 0.5) / W, v = (j + 0.5) / H; row 0 is the top.
 *  - Octahedral map: Size x Size texels (Size a power of two), texel (x, y) covers
 *    uv in [x, x+1) / Size x [y, y+1) / Size, mapped to directions by vs_octa_to_dir
 *    (sampling/octahedral.h). The map is equal-area: every texel subtends
 *    4 pi / Size^2 steradians, and a texel's value is the MEAN radiance over its
 *    solid angle (an integral, not a point sample), so the total power is exact.
 *  - Rotation (degrees about +Z): the radiance arriving from direction d is the
 *    source's radiance at R_z(-rotation) d, so a feature at +X moves to +Y under +90.
 */
#ifndef vsEnvironmentMap_h
#define vsEnvironmentMap_h

#include "sampling/octahedral.h"
#include "sampling/warp.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace vs
{

/* An equirectangular image of linear radiance, RGB interleaved, row 0 = top (+Z). */
struct LatLongImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> RGB; /* 3 * Width * Height floats, row-major */

  glm::vec3 Pixel(int i, int j) const
  {
    const float* p = &this->RGB[3 * (std::size_t(j) * this->Width + i)];
    return glm::vec3(p[0], p[1], p[2]);
  }
  /* Bilinear lookup at a direction: wrap in u, clamp in v (no rotation). */
  glm::vec3 Lookup(glm::vec3 dir) const;
};

/* The direction at lat-long coordinates (u, v) in [0,1)^2, and its inverse (u in [0,1)). */
glm::vec3 LatLongToDirection(double u, double v);
glm::dvec2 DirectionToLatLong(glm::dvec3 dir);

/* The direction at octahedral map coordinates (u, v) in [0,1]^2: vs_octa_to_dir
 * (sampling/octahedral.h) in float, as the renderer maps them. */
inline glm::vec3 OctahedralToDirection(double u, double v)
{
  return shared::vs_octa_to_dir(glm::vec2(float(u), float(v)));
}

/* The integral of luminance over the sphere of a lat-long image, each pixel
 * weighted by its exact solid angle (cos theta_top - cos theta_bottom) * 2 pi / W.
 * Non-finite and negative channels count as 0. */
double LatLongPower(const LatLongImage& image);

/* Luminance with the renderer's weights: vs_luminance (sampling/vs_prelude.h). */
inline float Luminance(glm::vec3 c)
{
  return shared::vs_luminance(c);
}

class EnvironmentMap
{
public:
  /* Octahedral map edge in texels (a power of two); 0 means empty. */
  int Size = 0;
  /* RGB mean radiance per texel, 3 * Size * Size floats, texel (x, y) at y * Size + x. */
  std::vector<float> Radiance;
  /* Luminance quadtree: levels 0..K (Size = 2^K); level l has 2^l x 2^l nodes,
   * row-major, starting at MipOffset(l) = (4^l - 1) / 3, so MipOffset(K) + Size^2
   * floats in all. Level K holds each texel's luminance, every coarser node the
   * mean of its 4 children, level 0 the mean luminance of the whole map. */
  std::vector<float> ImportanceMips;
  /* Mean RGB radiance over the sphere (= mean over texels: the map is equal-area). */
  glm::dvec3 MeanRadiance = glm::dvec3(0.0);
  double MeanLuminance = 0.0;
  /* Source pixels (or texels) with a NaN, infinite or negative channel; those
   * channels were replaced by 0. The VTK classes warn once with this count.
   * Negative channels of at most RingingFraction of the map's mean luminance are
   * not counted here but in RingingTexels (zeroed too, no warning): they are the
   * ringing of lossy compression and gamut clipping that real HDRIs carry, e.g.
   * the shipped maps (Data/envmaps: 299 to 1188 such pixels, the largest 0.79% of
   * the mean), and warning about them on every load said nothing useful. */
  std::int64_t BadTexels = 0;
  std::int64_t RingingTexels = 0;
  static constexpr double RingingFraction = 0.01;
  /* Of those, the ones with a NaN or infinite channel (the rest had a negative one,
   * typically tiny negatives from gamut clipping in real HDRIs). */
  std::int64_t NonFiniteTexels = 0;

  bool Empty() const { return this->Size <= 0; }
  /* Number of pyramid levels, K + 1. */
  int Levels() const;
  /* Where level l (0..15, the levels of the largest map) starts in ImportanceMips: the layout the
   * renderer reads, vs_env_level_offset (sampling/warp.h). */
  static std::size_t MipOffset(int level) { return shared::vs_env_level_offset(uint32_t(level)); }
  const float* Mip(int level) const { return this->ImportanceMips.data() + MipOffset(level); }

  glm::vec3 Texel(int x, int y) const
  {
    const float* p = &this->Radiance[3 * (std::size_t(y) * this->Size + x)];
    return glm::vec3(p[0], p[1], p[2]);
  }
  /* Radiance arriving from direction dir (need not be normalized): the value of
   * the texel that holds it (nearest). Piecewise constant per texel, which is
   * exactly the function the texel-based importance sampling integrates. */
  glm::vec3 Evaluate(glm::vec3 dir) const;
  /* The mean RGB radiance over each texel of a side x side octahedral map (row-major) laid over this
   * one: side a power of two of at most Size. Such a texel is the union of (Size / side)^2 of this
   * map's texels, all of the same solid angle, so this is its exact mean radiance (summed in double),
   * and times 4 pi / side^2 the exact integral of the radiance the renderer looks up over it. Throws
   * std::invalid_argument for another side. */
  std::vector<glm::vec3> MeanRadianceLevel(int side) const;
  /* The integral of luminance over the sphere: 4 pi * MeanLuminance. */
  double TotalPower() const;
  /* Solid angle of one texel, 4 pi / Size^2. */
  double TexelSolidAngle() const;

  /* Replace NaN, infinite and negative channels of Radiance by 0 (adding them to
   * BadTexels), then rebuild ImportanceMips and the means. Call after editing Radiance. */
  void Finalize();

  /* Default octahedral size for a lat-long of width x height pixels: the smallest power of two N
   * with N^2 >= width x height / 2, the texels of a 2:1 map's pixels (1024 x 512 -> 512), at
   * least 1 and at most 32768. It follows the pixels in both directions: from the width alone a
   * 1- or 2-pixel-wide map became 1 x 1 (the upper pole's colour), a 65536 x 1 map 32768^2 (12 GB). */
  static int DefaultSize(int latLongWidth, int latLongHeight);
  /* Throws std::invalid_argument (naming `what`) when a map of size x size texels needs more than
   * half of this machine's physical memory (with its importance pyramid, ~17 bytes per texel). */
  static void CheckMemory(int size, const char* what);
  static bool IsPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

  /* Progress callback, called with values in [0, 1] from the calling thread. */
  using ProgressFunction = std::function<void(double)>;

  /* Converts a lat-long image by integrating it over each octahedral texel: each
   * texel is supersampled on a stratified grid of sub-samples (vs_octa_to_dir,
   * bilinear lookup with wrap in u and clamp in v) with a spacing of at most 0.7
   * source pixel, and texels whose samples vary by more than 1e-4 of the map's
   * power (a sun) again 4x finer per axis. A size below the source's resolution
   * is converted at DefaultSize(width, height) (at least 16, at most 2048: the sub-samples of a
   * texel are sized by its corners, which a coarser map's texels do not resolve) and box-filtered
   * down, which is exact on the nested equal-area texels, so the map's mean radiance is the
   * source's for any shape. size = 0 chooses DefaultSize(width, height). Bad source channels are zeroed and counted in BadTexels.
   * threads = 0 uses the hardware concurrency; the result does not depend on it.
   * Throws std::invalid_argument for an empty image or a size that is not a power of two. */
  static EnvironmentMap FromLatLong(const LatLongImage& image, int size = 0,
    double rotationDeg = 0.0, double intensity = 1.0, const ProgressFunction& progress = nullptr,
    int threads = 0);

  /* Procedural maps (size must be a power of two); texels are exact (or adaptively
   * refined) means over their solid angle. */
  static EnvironmentMap Constant(int size, glm::vec3 rgb);
  /* A disk of angular radius angularRadiusDeg around direction (normalized here)
   * with uniform radiance `radiance`, in front of a constant sky: inside the disk
   * the sun replaces the sky. A disk smaller than a texel keeps its power: the
   * texel holds the sky plus the disk's share of its solid angle times
   * (radiance - sky). The disk's power is 2 pi (1 - cos r) * radiance. */
  static EnvironmentMap SunDisk(int size, glm::vec3 direction, double angularRadiusDeg,
    glm::vec3 radiance, glm::vec3 sky = glm::vec3(0.0f));
  /* `upper` for z > 0, `lower` for z < 0; texels on the horizon get the exact mix. */
  static EnvironmentMap TwoToneSky(int size, glm::vec3 upper, glm::vec3 lower);

  /* Allocates a black map of the given size (not finalized). */
  static EnvironmentMap Allocate(int size);
};

} // namespace vs

#endif
