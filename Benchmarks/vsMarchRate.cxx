#include "vsMarchRate.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsDeviceVolume.h"
#include "vsError.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_march_rate.h"

#include <glm/glm.hpp>

#include <algorithm>

namespace vs
{
namespace
{
struct Push
{
  glm::uvec4 Rays;
  glm::vec4 Dims;
  vs::shared::VsTransferFunction TF;
  glm::vec4 Dir;
};
}

MarchRate MeasureMarchRate(const std::shared_ptr<Context>& context, const DeviceVolume& volume,
  const TransferFunctionTable& tf, const std::array<uint32_t, 3>& dims, uint32_t rays, float step, int repeats)
{
  if (rays == 0 || !(step > 0.0f) || repeats < 1)
  {
    throw InputError("march rate: rays, step and repeats must be positive");
  }
  using B = BindingType;
  auto pipeline = SharedPipeline(context, VS_SPIRV(vs_spirv_march_rate),
    { B::StorageImage, B::StorageBuffer, B::StorageBuffer, B::StorageBuffer }, sizeof(Push), "march rate");
  Buffer sums(context, uint64_t(rays) * rays * sizeof(float), "march sums");
  Buffer count(context, sizeof(uint32_t), "march sample count");
  DescriptorSet set(*pipeline);
  set.Bind(0, volume.Image()).Bind(1, tf.Lut()).Bind(2, sums).Bind(3, count);
  Push push{ glm::uvec4(rays, rays, 0u, 0u), glm::vec4(dims[0], dims[1], dims[2], 0.0f), tf.Params(),
    glm::vec4(0.57f, 0.61f, 0.55f, step) };
  MarchRate best;
  for (int r = 0; r <= repeats; ++r) // r = 0 warms up (and compiles)
  {
    count.Fill(0u);
    Batch batch(context);
    batch.BeginTimer("march");
    batch.Dispatch(*pipeline, set, &push, sizeof(push), (rays + 7) / 8, (rays + 7) / 8, 1);
    batch.EndTimer();
    batch.Submit();
    uint32_t samples = 0;
    count.Download(&samples, sizeof(samples));
    const double seconds = batch.Seconds("march");
    if (r > 0 && (best.Seconds == 0.0 || seconds < best.Seconds))
    {
      best.Samples = samples;
      best.Seconds = seconds;
    }
  }
  return best;
}
}
