#include "vsPipelinePrewarm.h"

#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsError.h"
#include "vsMajorantGrid.h"
#include "vsMonteCarloPass.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeInput.h"
#include "vsVolumeScene.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkVolume.h"

#include <algorithm>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace
{
// Lets the calling thread run only on CPU time no other thread of the process wants (Linux: a
// thread has its own nice value). For work that is ahead of need: a caller that needs its result
// waits for it (std::call_once in Context::Pipeline), and while it waits the CPU is the thread's.
void YieldTheCpuToOtherThreads()
{
#if defined(__linux__)
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
}
}

namespace vs
{
void PipelinePrewarm::Start(std::shared_ptr<Context> context, const vs::shared::VsMonteCarloParams& p, bool table,
  bool quads, bool cellWalk, bool yieldCpu)
{
  this->Future = std::async(std::launch::async, [context, p, table, quads, cellWalk, yieldCpu]() {
    if (yieldCpu)
    {
      YieldTheCpuToOtherThreads();
    }
    vs::MonteCarloPass pass(context);
    pass.Prewarm(p, table, quads, cellWalk);
  });
}

void PipelinePrewarm::Join()
{
  if (this->Future.valid())
  {
    try
    {
      this->Future.get();
    }
    catch (...)
    {
    }
  }
}

bool PipelinePrewarm::GuessQuads(vtkDataArray* scalars)
{
  if (!scalars)
  {
    return false;
  }
  double range[2] = { 0.0, -1.0 };
  if (scalars->GetNumberOfComponents() == 1 && scalars->GetDataType() != VTK_FLOAT && scalars->GetDataType() != VTK_DOUBLE)
  {
    scalars->GetRange(range, 0); // only for integers: a float volume is never integer-coded
  }
  return GuessQuads(scalars->GetDataType(), scalars->GetNumberOfComponents(), uint64_t(scalars->GetNumberOfTuples()), range);
}

bool PipelinePrewarm::GuessQuads(int dataType, int components, uint64_t tuples, const double range[2])
{
  // Whether the device volume will be integer-coded (vsDeviceVolume.h quads): integer scalars of one
  // component spanning at most 255 (the upload decides; a wrong guess only wastes this thread's work).
  return components == 1 && dataType != VTK_FLOAT && dataType != VTK_DOUBLE && tuples * 4 <= vs::DeviceVolume::kMaxQuadBytes &&
    range[0] <= range[1] && range[1] - range[0] <= 255.0;
}

bool PipelinePrewarm::GuessCellWalk(vtkImageData* input, vtkDataArray* scalars, vtkVolume* volume,
  double densityScale, vs::shared::VsMonteCarloParams& p)
{
  // Only for input the scene update will accept: sampling a property without functions would
  // give it default ones (a change, and its error logged again).
  if (!vs::CheckImage(input, scalars).empty())
  {
    return false;
  }
  double range[2];
  scalars->GetRange(range, 0);
  return GuessCellWalk(input, range, volume, densityScale, p);
}

bool PipelinePrewarm::GuessCellWalk(vtkImageData* shape, const double range[2], vtkVolume* volume,
  double densityScale, vs::shared::VsMonteCarloParams& p)
{
  vtkVolumeProperty* property = volume->GetProperty();
  // The cell walk of optically thick bricks (MonteCarloPass::NeedsCellWalk) from the transfer
  // function's largest extinction over the scalars' range: the largest majorant the upload will
  // find when some brick reaches the function's peak, as it usually does (a wrong guess costs the
  // first frame a compile of its own, ~0.2 s: blind_sunrise's first frames did before).
  bool cellWalk = false;
  if (shape && property && vs::CheckProperty(property).empty() && range[0] <= range[1])
  {
    try
    {
      const vs::VolumeGeometry geometry = vs::ComputeGeometry(shape, volume->GetMatrix());
      if (!vs::CheckGeometry(geometry).empty())
      {
        throw vs::InputError(vs::CheckGeometry(geometry));
      }
      const vs::TransferFunctionSamples samples = vs::VolumeScene::SampleRenderedTransferFunction(
        property, float(range[0]), float(range[1]), densityScale, geometry);
      float extinction = 0.0f;
      for (size_t i = 3; i < samples.Entries.size(); i += 4)
      {
        extinction = std::max(extinction, samples.Entries[i]);
      }
      p.volume.worldToIndex = glm::mat4(geometry.WorldToIndex);
      cellWalk = vs::MonteCarloPass::NeedsCellWalk(double(extinction), vs::MajorantGrid::DefaultBrickSize, p);
    }
    catch (const std::exception&)
    {
      // The scene update refuses this input with its own error: no guess needed.
    }
  }
  return cellWalk;
}
}
