// vsEmissionAbsorptionPass.h — emission-absorption ray casting of a DeviceVolume
// into premultiplied RGBA (float), stopped at the opaque depth of each pixel. A volume with an
// extinction factor (the gradient opacity) scales the composite's extinction by it. The lit modes
// (shared::VS_EA_LIGHTING_*: the preview's single scattering, ambient occlusion) read a light volume
// (vsLightVolume.h) instead of emitting the colour.
#ifndef vsEmissionAbsorptionPass_h
#define vsEmissionAbsorptionPass_h

#include "vissweepCoreModule.h"
#include "sampling/ea_params.h"

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
   *  image whose size is not params.grid.cells. */
  std::vector<float> Render(const DeviceVolume& volume, const TransferFunctionTable& tf,
    const MajorantGrid* majorants, const shared::VsEmissionAbsorptionParams& params, const std::vector<float>& depth, bool shade = false,
    uint32_t lighting = shared::VS_EA_LIGHTING_NONE, const Image3D* light = nullptr);

  /** Device seconds of the last Render (0 without timestamp support). */
  double LastSeconds() const { return this->LastSeconds_; }

private:
  /** The pipeline with or without the extinction factor, shading and lighting (made on first use). */
  const ComputePipeline& PipelineFor(bool factor, bool shade, uint32_t lighting);

  std::shared_ptr<Context> Context_;
  std::shared_ptr<ComputePipeline> Pipelines_[2][2][3]; // [factor][shade][lighting]
  std::unique_ptr<Buffer> Params_, Depth_, Out_;
  std::unique_ptr<Image3D> NoLight_; // the 1-texel placeholder of VS_EA_LIGHT and VS_EA_BRICKS (zero)
  double LastSeconds_ = 0.0;
};
}

#endif
