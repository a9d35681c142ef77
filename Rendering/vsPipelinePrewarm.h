// vsPipelinePrewarm.h — a Monte Carlo render pipeline made ahead of need on another thread, so that
// the frame that needs it does not wait for its creation: the mapper's first frame's (made while the
// scene converts and uploads) and Auto's TwoStep pipeline (made once the grid has swept a direction).
// The pipeline lands in the context's cache, where the view's pass finds it (waiting for it if the
// render gets there first). Also the guesses of the first frame's pipeline variant made before the
// upload (integer-coded volume, cell walk). Not wrapped.
#ifndef vsPipelinePrewarm_h
#define vsPipelinePrewarm_h

#include "sampling/mc_params.h"

#include <future>
#include <memory>

class vtkDataArray;
class vtkImageData;
class vtkVolume;

namespace vs
{
class Context;

class PipelinePrewarm
{
public:
  PipelinePrewarm() = default;
  ~PipelinePrewarm() { this->Join(); }
  PipelinePrewarm(const PipelinePrewarm&) = delete;
  PipelinePrewarm& operator=(const PipelinePrewarm&) = delete;

  /** Whether MarkStarted() was called: a pipeline is made at most once. */
  bool Started() const { return this->WasStarted; }
  /** Called before Start(), or instead of it when the pipeline is not known yet. */
  void MarkStarted() { this->WasStarted = true; }
  /** Makes the pipeline of `p` (MonteCarloPass::Prewarm) on another thread; yieldCpu: on CPU time
   *  no other thread of the process wants. */
  void Start(std::shared_ptr<Context> context, const vs::shared::VsMonteCarloParams& p, bool table, bool quads,
    bool cellWalk, bool yieldCpu);
  /** Waits for it (its errors are the render's to report: it makes the pipeline again). */
  void Join();

  /** Whether the device volume will be integer-coded (vsDeviceVolume.h quads). */
  static bool GuessQuads(vtkDataArray* scalars);
  /** The same from what a reader tells before it reads: the scalars' VTK type, components, count and
   *  range (an 8-bit type's own range, when the data's is not known yet). */
  static bool GuessQuads(int dataType, int components, uint64_t tuples, const double range[2]);
  /** Whether the first frame walks cells; sets p.worldToIndex when it can tell. */
  static bool GuessCellWalk(vtkImageData* input, vtkDataArray* scalars, vtkVolume* volume, double densityScale,
    vs::shared::VsMonteCarloParams& p);
  /** The same from the volume's shape (extent, spacing, origin, direction: its scalars may not be
   *  read yet) and the scalars' range. */
  static bool GuessCellWalk(vtkImageData* shape, const double range[2], vtkVolume* volume, double densityScale,
    vs::shared::VsMonteCarloParams& p);

private:
  std::future<void> Future;
  bool WasStarted = false;
};
}

#endif
