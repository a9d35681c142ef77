// vsMonteCarloPass.h — progressive Monte Carlo single scattering (von Radziewsky et al. 2017) on the
// device: each Render() adds samples per pixel to compensated float accumulators
// of (rgb, alpha) and of their squares; Mean() and Variance() read them back.
// Reset() restarts accumulation (camera, transfer function, light... changed).
#ifndef vsMonteCarloPass_h
#define vsMonteCarloPass_h

#include "vissweepCoreModule.h"
#include "sampling/mc_params.h"

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vs
{
class Buffer;
class ComputePipeline;
class Context;
class DeviceEnvironment;
class DeviceVolume;
class DirectionTable;
class Image3D;
class MajorantGrid;
class TransferFunctionTable;
class VisibilityGrid;
enum class BindingType; // vsPipeline.h

class VISSWEEPCORE_EXPORT MonteCarloPass
{
public:
  explicit MonteCarloPass(std::shared_ptr<Context> context);
  ~MonteCarloPass();

  /** Clears the accumulators for a width x height image. */
  void Reset(uint32_t width, uint32_t height);

  /** Adds params.samplesPerFrame samples per pixel. `grid` may be null for Uniform and Environment;
   *  `depth` has one window depth per pixel (empty: nothing opaque). params.camera.frame (first sample
   *  index) is set from the samples accumulated so far. */
  void Render(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const VisibilityGrid* grid, const DeviceEnvironment& environment, shared::VsMonteCarloParams params,
    const std::vector<float>& depth);

  /** Creates the pipeline a Render with these parameters would use (an r8 grid or none; the cell
   *  walk if `cellWalk`; the 8-bit quads if `quads`, the volume has them, and the interpolation is
   *  linear, as Render decides), so that its creation (SPIR-V to the device's code: a large part of the
   *  first frame on lavapipe) can run on another thread while the caller prepares the scene. The
   *  caller must not use this pass on another thread meanwhile. Exceptions are the caller's to take
   *  or drop: the Render that needs the pipeline reports the same error. */
  void Prewarm(const shared::VsMonteCarloParams& params, bool table, bool quads = false, bool cellWalk = false);
  /** Whether some majorant segment may reach the tracking's refinement depth (mc_render.glsl's
   *  cell walk): the brick majorant times the longest world path through a brick, with a margin. */
  static bool NeedsCellWalk(const MajorantGrid& majorants, const shared::VsMonteCarloParams& params);
  /** The same from a bound of the largest brick majorant and the brick size, e.g. before the
   *  volume's majorants exist (the prewarm of the first frame's kernel). */
  static bool NeedsCellWalk(double maxMajorant, uint32_t brickSize, const shared::VsMonteCarloParams& params);
  /** The render kernel's descriptor set layout (sampling/bindings.h VS_MC_*), the same for every variant. */
  static std::vector<BindingType> KernelBindings();

  /** Per pixel (rgb, alpha) means, rows bottom-up. */
  std::vector<float> Mean() const;
  /** Per pixel variance of one sample of (rgb, alpha) (for standard errors: variance / samples). */
  std::vector<double> Variance() const; // double: radiance² leaves float's range below ~1e-19

  /** The sum over pixels of the accumulated squares of radiance (mean of r, g, b), in radiance²:
   *  what Auto's strategy selector differences between frames (vsStrategySelector.h). */
  double SquareSum() const;

  uint32_t Samples() const { return this->Samples_; }
  uint32_t Width() const { return this->Width_; }
  uint32_t Height() const { return this->Height_; }
  /** Benchmarks: render with the instrumented kernel (mc_render_count.comp, r8 grids or none),
   *  which counts reads; same samples, slower. */
  void SetCountLookups(bool on) { this->CountLookups_ = on; }
  /** Whether the trackers cross empty space (bricks of majorant 0) a cube of bricks at a time
   *  (MajorantGrid::TrackingImage) or a brick at a time. The image is the same bit for bit;
   *  on by default, off only to measure or test it. */
  void SetEmptySpaceSkipping(bool on) { this->EmptySpaceSkipping_ = on; }
  /** Whether trilinear samples read an integer-coded volume's 8-bit quads (DeviceVolume::Quads,
   *  2 texel reads instead of 8; the same floats) where it has them. On by default. */
  void SetVolumeQuads(bool on) { this->VolumeQuads_ = on; }
  bool GetVolumeQuads() const { return this->VolumeQuads_; }
  /** Whether the last Render read the volume's quads. */
  bool LastUsedVolumeQuads() const { return this->LastUsedQuads_; }
  /** The name of the kernel pipeline the last Render ran (its module and specialization). */
  const std::string& LastPipelineName() const { return this->LastPipelineName_; }
  bool GetEmptySpaceSkipping() const { return this->EmptySpaceSkipping_; }
  /** Reads of the last counted Render: trilinear volume samples, majorant-brick loads, visibility texels. */
  std::array<uint64_t, 3> LastLookups() const { return this->LastLookups_; }
  /** Of the last counted Render: the tracking steps the lanes took over the steps their SIMD
   *  groups ran times the group's width (1: no lane ever waited for another). */
  double LastLaneOccupancy() const { return this->LastLaneOccupancy_; }
  /** Of the last counted Render: the shadow rays traced, and those whose transmittance was below
   *  0.01 (blocked: their light sample scored next to nothing). */
  std::array<uint64_t, 2> LastShadowRays() const { return this->LastShadowRays_; }

  /** Samples per pixel one dispatch adds at most (the rest of a Render's samples go to further
   *  dispatches), clamped to [1, kMaxSamplesPerDispatch]; the image is the same bit for bit for
   *  any value. Fewer dispatches cost less on lavapipe; on a GPU a long dispatch may hit the
   *  driver's watchdog. */
  void SetSamplesPerDispatch(uint32_t n) { this->SamplesPerDispatch_ = std::min(std::max(n, 1u), kMaxSamplesPerDispatch); }
  /** The most samples per pixel a dispatch aims at. The kernel's loop budget (VS_LOOP_BUDGET, which
   *  keeps it below lavapipe's loop limiter) decides how many it completes; the rest follow in the
   *  next dispatches, so any value gives the same image. */
  static constexpr uint32_t kMaxSamplesPerDispatch = 4096;
  /** Catch-up dispatches a Render may need at most (or one per sample of the frame, if more) before
   *  it reports a kernel error. */
  static constexpr uint32_t kMaxCatchUpRounds = 256;
  /** Catch-up dispatches (after the planned ones) the last Render needed: pixels whose samples took
   *  more than the kernel's loop budget allowed in their dispatch. */
  uint32_t LastCatchUps() const { return this->LastCatchUps_; }
  uint32_t SamplesPerDispatch() const { return this->SamplesPerDispatch_; }

  /** The grid strategies read each cell's precomputed direction table (vsDirectionTable.h) under
   *  stochastic cells (on by default), or build the map at every scatter event (off; trilinear
   *  cells always do). Both are unbiased; the table is faster. */
  void SetDirectionTable(bool on) { this->UseTable_ = on; }
  bool GetDirectionTable() const { return this->UseTable_; }
  /** Lets passes share one table (a mapper's progressive, Auto and interactive passes render the
   *  same grid): it is made on first use otherwise. */
  void ShareDirectionTable(std::shared_ptr<DirectionTable> table) { this->Table_ = std::move(table); }
  /** With a ratio r > 0, a table made from an earlier state of the grid (still a valid pdf) is
   *  rebuilt for the grid's new values only once the pass has rendered r times the last build's
   *  device time with it, so that rebuilding costs at most ~1/r of the render time while a grid
   *  fills in (kTableRebuildRatio, what the mapper sets then). The default 0 rebuilds at every
   *  change, so that an image does not depend on timing. A new environment, layout, ε or map is
   *  rebuilt before the next sample whatever the ratio. */
  void SetTableRebuildRatio(double ratio) { this->TableRebuildRatio_ = std::max(0.0, ratio); }
  static constexpr double kTableRebuildRatio = 4.0;
  /** Whether the last Render read a direction table; its builds so far, and the device seconds of
   *  the last Render's build (0 when it reused the table; included in LastSeconds). */
  bool LastUsedDirectionTable() const { return this->LastUsedTable_; }
  uint64_t DirectionTableBuilds() const;
  double LastDirectionTableSeconds() const { return this->LastTableSeconds_; }

  /** Scattering events per path (per sample of a pixel), averaged over every pixel and sample since
   *  the last Reset: the paths' mean length under full transport (rays that miss the volume count
   *  0). Single scattering reports 1, an upper bound, without counting. */
  double MeanEventsPerPath() const
  {
    const double paths = double(this->Samples_) * this->Width_ * this->Height_;
    return paths > 0.0 ? double(this->Events_) / paths : 0.0;
  }

  /** Device seconds of the last Render and of all Renders since the last Reset. */
  double LastSeconds() const { return this->LastSeconds_; }
  double TotalSeconds() const { return this->TotalSeconds_; }

  /** The specializations whose pipelines the pass holds: at most kMaxPipelineVariants, the least
   *  recently used let go first. */
  size_t PipelineVariants() const { return this->Pipelines_.size(); }
  static constexpr size_t kMaxPipelineVariants = 16;

  /** Whether params ask for full transport (more than one event, or an anisotropic phase): the path
   *  estimator (mc_path.glsl) instead of the single-scattering one. */
  static bool FullTransport(const shared::VsMonteCarloParams& params);
  /** Throws InputError naming the setting, the value and the range for an anisotropy outside (-1, 1)
   *  or not finite, or an event limit outside [1, VS_MAX_SCATTERING_EVENTS] (0 is read as 1). */
  static void CheckScattering(const shared::VsMonteCarloParams& params);

private:
  const ComputePipeline& PipelineFor(
    const VisibilityGrid* grid, const shared::VsMonteCarloParams& params, bool refine, bool table, bool quads);
  /** Whether params ask for TwoStep's defensive mixture (mc_params.h defensiveWeight > 0). */
  static bool Defensive(const shared::VsMonteCarloParams& params);

  std::shared_ptr<Context> Context_;
  // Per specialization (mc_render.glsl's constant_ids): r8, r16, r32f visibility; r8 counting reads.
  // Per specialization: the modules for the r8, r16 and r32f grids, counting reads, and no grid.
  std::map<std::vector<uint32_t>, std::array<std::shared_ptr<ComputePipeline>, 5>> Pipelines_;
  std::map<std::vector<uint32_t>, uint64_t> PipelineUse_; // when each variant was last asked for
  uint64_t PipelineClock_ = 0;
  std::string LastPipelineName_;
  std::unique_ptr<Buffer> Lookups_;
  bool CountLookups_ = false;
  bool EmptySpaceSkipping_ = true;
  bool VolumeQuads_ = true;
  bool LastUsedQuads_ = false;
  std::unique_ptr<Image3D> NoQuads_;
  std::unique_ptr<Image3D> NoVolume_; // bound for the float image when the kernel reads the quads
  uint32_t SamplesPerDispatch_ = 16;
  std::array<uint64_t, 3> LastLookups_{};
  double LastLaneOccupancy_ = 1.0;
  std::array<uint64_t, 2> LastShadowRays_{};
  std::unique_ptr<Image3D> NoGrid_;
  std::shared_ptr<DirectionTable> Table_;
  std::unique_ptr<Buffer> NoTable_;
  bool UseTable_ = true, LastUsedTable_ = false;
  double LastTableSeconds_ = 0.0;
  double TableRebuildRatio_ = 0.0;
  std::unique_ptr<Buffer> Params_, Depth_, Sum_, Comp_, Squares_, Progress_;
  // Full transport's paths in flight between dispatches (path_state.glsl), made on first use.
  std::unique_ptr<Buffer> PathPosition_, PathDirection_, PathThroughput_, PathRadiance_, NoPaths_;
  uint32_t LastCatchUps_ = 0;
  std::vector<float> LastDepth_;
  uint32_t Width_ = 0, Height_ = 0, Samples_ = 0;
  uint64_t Events_ = 0; // scattering events since the last Reset (MeanEventsPerPath)
  float SquareScale_ = 1.0f; // radiance scale of the sums of squares (mc_params.h squareScale)
  double LastSeconds_ = 0.0, TotalSeconds_ = 0.0;
};
}

#endif
