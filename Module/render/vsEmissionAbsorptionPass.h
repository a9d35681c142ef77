// vsEmissionAbsorptionPass.h — emission-absorption ray casting of a DeviceVolume
// into premultiplied RGBA (float), stopped at the opaque depth of each pixel. A volume with an
// extinction factor (the gradient opacity) scales the composite's extinction by it. The lit modes
// (shared::VS_EA_LIGHTING_*: the preview's single scattering, ambient occlusion) read a light volume
// (vsLightVolume.h) instead of emitting the colour.
#ifndef vsEmissionAbsorptionPass_h
#define vsEmissionAbsorptionPass_h

#include "vissweepCoreModule.h"
#include "sampling/ea_params.h"

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace vs
{
class Buffer;
class ComputePipeline;
class Context;
class DeviceVolume;
class Image3D;
class MajorantGrid;
class TransferFunctionTable;

class VISSWEEPCORE_EXPORT EmissionAbsorptionPass
{
public:
  explicit EmissionAbsorptionPass(std::shared_ptr<Context> context);
  ~EmissionAbsorptionPass();

  /** Renders params.camera.width by .height pixels. `majorants` (of `volume` under `tf`), or nullptr:
   *  the composite skips the bricks whose majorant is 0 (params.volume's majorant fields are set
   *  from it; without, nothing is skipped). `depth` has one window depth in [0,1] per pixel
   *  (1 = nothing opaque); empty means no opaque geometry. `shade`: Phong-shade the composite with
   *  params.shading and params.light. Returns RGBA, rows bottom-up.
   *  `lighting` (shared::VS_EA_LIGHTING_*) other than NONE lights the composite from `light`, an
   *  rgba32f image of params.grid.cells texels (vsLightVolume.h); `light` nullptr: a zero light of
   *  one texel (for a volume without extinction, whose lit image is transparent anyway; params.grid
   *  is then set to one cell). Without NONE, `shade` is ignored. Throws InputError for a light
   *  image whose size is not params.grid.cells.
   *  params.display (shared::VS_EA_DISPLAY_* flags): with VS_EA_DISPLAY_ENVIRONMENT the pixels of
   *  depth 1 see `environment` (the environment's radiance per texel of its equal-area map of
   *  params.environmentSize^2 texels, DeviceEnvironment::Radiance), added to the returned radiance
   *  through the transmittance; with VS_EA_DISPLAY_IMAGE the pass also makes the window image
   *  (display_transform.h), then in LastDisplay(). Throws InputError for VS_EA_DISPLAY_ENVIRONMENT
   *  without an environment of that size.
   *  params.lightCount > 0 (issue 38): with `shade` and no lighting, the Phong lights; in the preview, its
   *  lights, lit through `lightTransmittance` (LightVolume::Transmittance of the same build as `light`), and
   *  `shade` is the surface lobe there (params.surface*). Throws InputError for more than VS_MAX_SCENE_LIGHTS
   *  or a preview with lights without their transmittance.
   *  `lightMoment` (issue 39; LightVolume::Moment of the same build as `light`): with params.anisotropy != 0 the
   *  preview's single scattering of the environment is Henyey-Greenstein's up to band 1 (ea_render.comp); without
   *  it, or with g = 0, isotropic (the same pipeline as before); a moment of 6 layers (the first order's apart)
   *  is read as two lobes. Throws InputError for a moment whose size is not the light volume's with 3 or 6
   *  layers. */
  std::vector<float> Render(const DeviceVolume& volume, const TransferFunctionTable& tf,
    const MajorantGrid* majorants, const shared::VsEmissionAbsorptionParams& params, const std::vector<float>& depth, bool shade = false,
    uint32_t lighting = shared::VS_EA_LIGHTING_NONE, const Image3D* light = nullptr, const Buffer* environment = nullptr,
    const Image3D* lightTransmittance = nullptr, const Image3D* lightMoment = nullptr);

  /** The premultiplied window image (RGBA, rows bottom-up) of the last Render with
   *  VS_EA_DISPLAY_IMAGE; empty after one without. */
  const std::vector<float>& LastDisplay() const { return this->LastDisplay_; }

  /** Device seconds of the last Render (0 without timestamp support). */
  double LastSeconds() const { return this->LastSeconds_; }

private:
  /** The pipeline with or without the extinction factor, shading, lighting, a projection (a blend
   *  other than the composite), the window image and VTK's lights (made on first use; ea_render.comp's
   *  specialization constants). */
  const ComputePipeline& PipelineFor(bool factor, bool shade, uint32_t lighting, bool projection, bool display,
    bool lights, uint32_t anisotropic);

  std::shared_ptr<Context> Context_;
  std::map<std::array<uint32_t, 7>, std::shared_ptr<ComputePipeline>> Pipelines_;
  std::unique_ptr<Buffer> Params_, Depth_, Out_, Display_;
  std::unique_ptr<Image3D> NoLight_; // the 1-texel placeholder of VS_EA_LIGHT and VS_EA_BRICKS (zero)
  double LastSeconds_ = 0.0;
  std::vector<float> LastDisplay_;
};
}

#endif
