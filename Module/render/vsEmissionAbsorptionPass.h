// vsEmissionAbsorptionPass.h — emission-absorption ray casting of a DeviceVolume
// into premultiplied RGBA (float), stopped at the opaque depth of each pixel. A volume with an
// extinction factor (the gradient opacity) scales the composite's extinction by it.
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
class TransferFunctionTable;

class VISSWEEPCORE_EXPORT EmissionAbsorptionPass
{
public:
  explicit EmissionAbsorptionPass(std::shared_ptr<Context> context);
  ~EmissionAbsorptionPass();

  /** Renders params.camera.width by .height pixels. `depth` has one window depth in [0,1] per pixel
   *  (1 = nothing opaque); empty means no opaque geometry. `shade`: Phong-shade the composite with
   *  params.shading and params.light. Returns RGBA, rows bottom-up. */
  std::vector<float> Render(const DeviceVolume& volume, const TransferFunctionTable& tf,
    const shared::VsEmissionAbsorptionParams& params, const std::vector<float>& depth, bool shade = false);

  /** Device seconds of the last Render (0 without timestamp support). */
  double LastSeconds() const { return this->LastSeconds_; }

private:
  /** The pipeline with or without the extinction factor and shading (made on first use). */
  const ComputePipeline& PipelineFor(bool factor, bool shade);

  std::shared_ptr<Context> Context_;
  std::shared_ptr<ComputePipeline> Pipelines_[2][2]; // [factor][shade]
  std::unique_ptr<Buffer> Params_, Depth_, Out_;
  double LastSeconds_ = 0.0;
};
}

#endif
