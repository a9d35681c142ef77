// vsLightVolume.h — the light volume: per visibility cell, the environment light that reaches it,
//   I(cell) = sum over the D x D grid directions n of V(cell, n) E_n,   E_n = integral over texel n of L_env,
// in RGB (radiance x sr; for the isotropic phase function the in-scattered radiance at the cell is
// sigma_s / (4 pi) I). E_n is exact for the environment the renderer looks up (piecewise constant per
// texel of its equal-area map, which nests in the grid's texels; DeviceEnvironment::RadianceLevel),
// times the renderer's intensity. Rotations are part of the map (the reader turns the source), so a
// rotated environment is a new DeviceEnvironment.
//
// Storage: one rgba32f 3D image of cells.x x cells.y x cells.z texels; rgb = I, a = the mean
// visibility over the sphere. Built on the device (light_volume.glsl) and kept until the grid's
// values (VisibilityGrid::ContentSerial), the environment (DeviceEnvironment::Serial) or the
// intensity change: a camera move changes none of them.
#ifndef vsLightVolume_h
#define vsLightVolume_h

#include "vissweepCoreModule.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace vs
{
class Buffer;
class Context;
class DeviceEnvironment;
class Image3D;
class VisibilityGrid;

class VISSWEEPCORE_EXPORT LightVolume
{
public:
  explicit LightVolume(std::shared_ptr<Context> context);
  ~LightVolume();

  /** Makes the light volume current for this grid, environment and intensity (>= 0, a finite float): builds
   *  it unless it was built from exactly these. Returns whether it built. Throws InputError for a grid
   *  not computed yet, an environment coarser than the grid's directions or a bad intensity. */
  bool Update(const VisibilityGrid& grid, const DeviceEnvironment& environment, double intensity = 1.0);

  /** Per direction n of a side x side grid, E_n: the environment's RGB radiance (times `intensity`)
   *  integrated over the solid angle of texel n, 4 pi / side^2. Throws InputError as Update. */
  static std::vector<glm::vec3> DirectionRadiance(
    const DeviceEnvironment& environment, uint32_t side, double intensity);

  bool Valid() const { return this->Image_ != nullptr; }
  /** The rgba32f image (after a successful Update). */
  const Image3D& Image() const { return *this->Image_; }
  std::array<uint32_t, 3> Cells() const { return this->Cells_; }
  /** RGBA per cell, cell (x, y, z) at 4 * ((z * cells.y + y) * cells.x + x); empty before a build. */
  std::vector<float> Download() const;

  /** Builds since this object was made. */
  uint64_t Builds() const { return this->Builds_; }
  /** Device seconds of the last build's dispatch, and its host wall-clock seconds (E_n, upload,
   *  dispatch, wait). */
  double LastSeconds() const { return this->LastSeconds_; }
  double LastWallSeconds() const { return this->LastWallSeconds_; }

private:
  struct Signature
  {
    uint64_t Grid = 0, Environment = 0;
    double Intensity = -1.0;
    bool operator==(const Signature& o) const
    {
      return Grid == o.Grid && Environment == o.Environment && Intensity == o.Intensity;
    }
  };

  std::shared_ptr<Context> Context_;
  std::unique_ptr<Image3D> Image_;
  std::unique_ptr<Buffer> Radiance_; // E_n, one vec4 per direction
  std::array<uint32_t, 3> Cells_{ { 0, 0, 0 } };
  Signature Built_;
  uint64_t Builds_ = 0;
  double LastSeconds_ = 0.0, LastWallSeconds_ = 0.0;
};
}

#endif
