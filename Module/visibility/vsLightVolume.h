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
//
// Multiple scattering (issue 39: the preview of full transport). Update with a MultipleScattering
// adds the light that arrives after further scattering in the volume, order by order on the cell grid
// (light_volume_scatter.glsl: the grid's V(c, n) / V(x, n) is the transmittance from c to x upstream,
// so one order is a march along each of the grid's directions, nothing random), with an isotropic
// phase and each cell's extinction-weighted albedo (light_volume_albedo.comp):
//   I = I_1 + I_2 + ... + I_K + the orders K+1 .. Events as a geometric series of I_K's ratio to I_{K-1}
//   (per cell, at most the whole volume's ratio: AddTail).
// The preview's sigma_s I / (4 pi) is then the in-scattered radiance of full transport (Events
// scattering events in all, as the Monte Carlo kernel's MaximumScatteringEvents). It is built again
// when the albedo or the volume's parameters (MultipleScattering::Key), the orders or the events change
// too, never for a camera move. Its bias against Monte Carlo: TestPreview's furnace and box.
//
// VTK's lights (issue 38: MultipleScattering::Lights, sampling/scene_lights.h). Per cell and light, the
// transmittance T_l from the cell's centre towards the light, marched through the volume
// (light_volume_lights.comp; Transmittance(): rgba32f of cells.x x cells.y x 2 cells.z, light l at z +
// (l / 4) cells.z, component l % 4), which the preview interpolates to light each sample directly with
// the phase function (or the surface lobe) towards the light. The lights' direct light sum_l T_l E_l
// joins the first order of the multiple scattering (not the image's I: the preview adds the first order
// itself), so the orders 2 .. Events carry the lights' scattered light too. Built again when a light
// changes (Lights are part of the signature), never for a camera move as such (lights that follow the
// camera change with it: the mapper decides when to pass them; docs/reference.md).
//
// The phase's anisotropy towards the environment (issue 39). With MultipleScattering::Anisotropy != 0 the
// build also keeps the first order's band-1 moment M(cell) = sum_n V(cell, n) E_n w_n (w_n the world
// direction towards texel n's light; Moment(): rgba32f of cells.x x cells.y x 3 cells.z, component a of M
// at z + a cells.z, rgb per channel), from which the preview's single scattering of the environment's light
// is Henyey-Greenstein's up to band 1 (sampling/phase_moments.h): (I + 3 g M.d) / (4 pi), d the camera ray.
// With single scattering M does not depend on g's value, only on whether it is needed: a change from g = 0 to
// g != 0 builds again (to make M) unless M is there, from one g != 0 to another or back to 0 does not (M is kept,
// unread at g = 0), and a camera move never does.
// With multiple scattering and |g| >= VS_HG_ISOTROPIC_G the orders 2 .. Events follow g too (issue 39): the
// first order's light scatters into the second by the real phase (the HG lobe of I_1 and M_1 towards each
// cell, phase_moments.h), and the orders carry on in the similar medium of g (isotropic, sigma_t (1 - a g),
// albedo a (1 - g) / (1 - a g): the similarity relations, phase_moments.h vs_similar_*;
// light_volume_scatter.glsl); each order's band-1 moment is gathered with its light, and Moment() holds the
// sum over all the orders (the tail's as I's: AddTail), read at the preview's last event towards the camera as
// one HG lobe of the whole light. At g < 0 Moment() has 6 layers: 3 .. 5 keep the first order's apart, M_1's
// component a - 3 in rgb and I_1's channel a - 3 in alpha, and the preview reads two lobes, the first order's
// (I_1, M_1) and the other orders' (I - I_1, M - M_1). Why by g's sign: the similar medium's orders are carried
// isotropically, so their own moments M_k hold only where their light comes from, not the direction it keeps;
// forward scattering keeps the direction of the light that entered (the similarity's forward delta), which one
// lobe of the whole light gives them, backward scattering does not (its delta has a negative weight), and one
// lobe then gives the diffuse orders the sun's direction. Measured on ch2 (docs/reference.md): at g = -0.6 the
// preview 1.23 of the estimate with one lobe, 1.09 with two; at g = 0.6 1.005 with one, 1.08 with two.
// Then another g builds again (g is part of the signature), g = 0 builds the isotropic
// orders of before (bit for bit) and a camera move never builds. docs/reference.md: the bias measured.
#ifndef vsLightVolume_h
#define vsLightVolume_h

#include "vissweepCoreModule.h"
#include "sampling/scene_lights.h"
#include "sampling/volume_params.h"

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
class DeviceVolume;
class Image3D;
class TransferFunctionTable;
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

  /** What multiple scattering needs: the volume and transfer function the grid was computed from,
   *  their parameters as every pass sees them (Params.boxMin: the grid's origin), the orders computed
   *  on the grid (1: single scattering, as Update above) and the scattering events in all (the orders
   *  beyond `Orders` up to `Events` are a geometric tail). */
  struct MultipleScattering
  {
    const DeviceVolume* Volume = nullptr;
    const TransferFunctionTable* TF = nullptr;
    shared::VsVolumeParams Params{};
    uint32_t Orders = 4;
    uint32_t Events = 1024;
    /** The orders march every DirectionStride-th direction per axis of the grid's D x D, each standing
     *  for its DirectionStride^2 block, the orders taking turns over the block (1: every direction;
     *  at most D / 2). */
    uint32_t DirectionStride = 2;
    /** Samples per axis of each cell for its albedo. */
    uint32_t AlbedoSamples = 4;
    /** The tail's ratio between successive orders is clamped to this (< 1). */
    float MaxRatio = 0.98f;
    /** VTK's lights (world space; at most VS_MAX_SCENE_LIGHTS), whatever the orders: their transmittance
     *  per cell (Transmittance()) and, with multiple scattering, their scattered light. They need Volume
     *  and TF, as multiple scattering does. */
    std::vector<shared::VsSceneLight> Lights;
    /** The lights' march step in world units (<= 0: the smallest voxel spacing of Params). */
    float LightStep = 0.0f;
    /** The phase's Henyey-Greenstein g (the preview's): != 0 builds the band-1 moment too (Moment()),
     *  whatever the orders; with multiple scattering the orders 2 .. Events follow g's value (above). */
    float Anisotropy = 0.0f;
  };
  /** Update with multiple scattering (Orders >= 2 and Events >= 2; else as Update above) and the lights.
   *  Throws InputError as Update, for a missing volume or transfer function, and for more than
   *  VS_MAX_SCENE_LIGHTS lights. */
  bool Update(const VisibilityGrid& grid, const DeviceEnvironment& environment, double intensity,
    const MultipleScattering& scattering);

  /** Per direction n of a side x side grid, E_n: the environment's RGB radiance (times `intensity`)
   *  integrated over the solid angle of texel n, 4 pi / side^2. Throws InputError as Update. */
  static std::vector<glm::vec3> DirectionRadiance(
    const DeviceEnvironment& environment, uint32_t side, double intensity);

  bool Valid() const { return this->Image_ != nullptr; }
  /** The rgba32f image (after a successful Update). */
  const Image3D& Image() const { return *this->Image_; }
  /** The transmittance towards each light of the last build (layout above); nullptr when it had none. */
  const Image3D* Transmittance() const { return this->Built_.Lights != 0 ? this->Transmittance_.get() : nullptr; }
  /** The band-1 moment of the last build (layout above; the first order's, with multiple scattering and
   *  g != 0 all the orders'); nullptr when it was built with
   *  Anisotropy 0 (an Update with Anisotropy 0 keeps one that is there). */
  const Image3D* Moment() const { return this->Built_.Moment ? this->Moment_.get() : nullptr; }
  /** The band-1 moment per cell, as Download() (cells.x x cells.y x 3 cells.z, or 6 cells.z with the first
   *  order's apart: layout above); empty without one. */
  std::vector<float> DownloadMoment() const;
  /** The lights of the last build. */
  const std::vector<shared::VsSceneLight>& Lights() const { return this->BuiltLights_; }
  /** The transmittance towards each light per cell, as Download() (cells.x x cells.y x 2 cells.z); empty
   *  without lights. */
  std::vector<float> DownloadTransmittance() const;
  std::array<uint32_t, 3> Cells() const { return this->Cells_; }
  /** RGBA per cell, cell (x, y, z) at 4 * ((z * cells.y + y) * cells.x + x); empty before a build. */
  std::vector<float> Download() const;

  /** Builds since this object was made. */
  uint64_t Builds() const { return this->Builds_; }
  /** Device seconds of the last build's dispatch, and its host wall-clock seconds (E_n, upload,
   *  dispatch, wait). */
  double LastSeconds() const { return this->LastSeconds_; }
  double LastWallSeconds() const { return this->LastWallSeconds_; }
  /** Device seconds of the last build's multiple scattering (0 for single scattering). */
  double LastScatterSeconds() const { return this->LastScatterSeconds_; }

private:
  struct Signature
  {
    uint64_t Grid = 0, Environment = 0;
    double Intensity = -1.0;
    uint64_t Scattering = 0; // 0: single scattering; else a hash of MultipleScattering's inputs
    uint64_t Lights = 0;     // 0: no lights; else a hash of the lights and what their march reads
    bool Moment = false;     // the band-1 moment (Anisotropy != 0)
    /** Whether a build of signature `built` serves this one: the same inputs, and the moment if this needs it
     *  (a build with the moment serves g = 0 too: the preview does not read it there). */
    bool ServedBy(const Signature& built) const
    {
      return Grid == built.Grid && Environment == built.Environment && Intensity == built.Intensity &&
        Scattering == built.Scattering && Lights == built.Lights && (!Moment || built.Moment);
    }
  };
  void Scatter(const VisibilityGrid& grid, const MultipleScattering& scattering, bool lit, bool similar);
  void LightPass(const VisibilityGrid& grid, const MultipleScattering& scattering);
  void AddTail(const Image3D& last, const Image3D& before, uint32_t events, float maxRatio,
    const Image3D* momentSum = nullptr, const Image3D* lastMoment = nullptr);

  std::shared_ptr<Context> Context_;
  std::unique_ptr<Image3D> Image_;
  std::unique_ptr<Image3D> Moment_; // the band-1 moment (Anisotropy != 0): the first order's, with the others'
  std::unique_ptr<Image3D> MomentSum_, OrderMoment_; // the orders 2 .. K's band-1 moment, the last order's
  std::unique_ptr<Buffer> Radiance_; // E_n, one vec4 per direction
  // Multiple scattering: per cell the albedo, two orders' emission and light (ping-pong); the steps per
  // direction, the albedo pass's parameters.
  std::unique_ptr<Image3D> Albedo_, EmitA_, EmitB_, OrderA_, OrderB_;
  std::unique_ptr<Buffer> Steps_, AlbedoParams_;
  // VTK's lights: per cell the direct light and the transmittance towards each light; their parameters.
  std::unique_ptr<Image3D> Direct_, Transmittance_;
  std::unique_ptr<Buffer> SceneParams_;
  std::vector<shared::VsSceneLight> BuiltLights_;
  std::array<uint32_t, 3> Cells_{ { 0, 0, 0 } };
  Signature Built_;
  uint64_t Builds_ = 0;
  double LastSeconds_ = 0.0, LastWallSeconds_ = 0.0, LastScatterSeconds_ = 0.0;
};
}

#endif
