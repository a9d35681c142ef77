// vsVisibilityGrid.h — the 5D visibility grid of von Radziewsky et al. 2017 (Sec. 5, 6, 8) on the
// device: V(cell, direction) = transmittance from the cell towards the light
// direction, for D x D equal-area directions and cells of VoxelsPerCell^3 voxels.
// Computed by plane sweeps (default) or by brute-force ray marching (the reference).
//
// Storage: one 3D image of (cells.x * D) x (cells.y * D) x cells.z texels, cell c's
// directions as a D x D tile (direction n at (n % D, n / D)), so the renderer reads
// a cell's octahedral map as one tile. Format r8 (default), r16 or r32f.
#ifndef vsVisibilityGrid_h
#define vsVisibilityGrid_h

#include "vissweepCoreModule.h"
#include "vsPooledExtinction.h"
#include "vsSweepPlan.h"
#include "vsVolumeGeometry.h"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace vs
{
class Buffer;
class ComputePipeline;
class Context;
struct DeviceInfo;
class DeviceVolume;
class Image3D;
class MajorantGrid;
class TransferFunctionTable;

class VISSWEEPCORE_EXPORT VisibilityGrid
{
public:
  /** Called with the fraction done (0..1) after each batch of directions. */
  using Progress = std::function<void(double)>;

  explicit VisibilityGrid(std::shared_ptr<Context> context);
  ~VisibilityGrid();

  /** Computes the grid, or only `directions` of it (all when empty). With a subset the other
   *  directions keep what they held (lazy updates: the grid already has this geometry and these
   *  parameters) or, in a new layout, read 0 (directions the renderer never needs, such as those
   *  without environment light). worldClipPlanes: (n, w) keeping dot(n, x) + w >= 0;
   *  voxels on the removed side do not occlude. Throws InputError / DeviceLimitError. */
  void Compute(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const VolumeGeometry& geometry, const std::vector<glm::dvec4>& worldClipPlanes,
    const VisibilityGridParameters& parameters, const std::vector<uint32_t>& directions = {},
    const Progress& progress = Progress());

  /** Makes the image for this geometry and these parameters unless the grid already has them;
   *  a new image reads `clearValue` everywhere when `clear`. Returns whether it made one. No
   *  sweeps: for a renderer that needs none of the directions yet (no environment light anywhere,
   *  or a progressive fill-in that starts at visibility 1). */
  bool Allocate(const VolumeGeometry& geometry, const VisibilityGridParameters& parameters, bool clear = true,
    float clearValue = 0.0f);
  /** Sets every entry of an allocated grid to `value` (in [0, 1]). */
  void Clear(float value);
  /** Fill-in without copies: in every cell, direction `first` reads the values of direction
   *  `second` of the same cell, for each pair, until `first` is computed (Compute) or the grid is
   *  cleared or made anew. The `second`s must read their own values. Every reader honours it: the
   *  direction table, the render kernel's maps (through DirectionSources) and Download. Costs no
   *  device time (copying the directions' values cost ch2's progressive sweeps 3-4x their own time). */
  void RedirectDirections(const std::vector<std::pair<uint32_t, uint32_t>>& redirects);
  /** Per direction n, the direction whose values n reads: n itself unless redirected. */
  const std::vector<uint32_t>& DirectionSources() const { return this->Sources_; }
  /** DirectionSources() on the device (D x D uints), for the direction table's builder. */
  const Buffer& DirectionSourceBuffer() const;

  /** Throws DeviceLimitError when the grid for this geometry and these parameters cannot exist. */
  static void CheckFits(Context& context, const VolumeGeometry& geometry, const VisibilityGridParameters& p);

  bool Valid() const { return this->Image_ != nullptr; }
  const Image3D& Image() const { return *this->Image_; }
  std::array<uint32_t, 3> Cells() const { return this->Plan_.Cells; }
  glm::vec3 CellSize() const { return this->Plan_.CellSize; }
  uint32_t Side() const { return this->Plan_.Side; }
  const VisibilityGridParameters& Parameters() const { return this->Parameters_; }
  uint64_t Bytes() const;

  /** All values as floats: index (cell z, y, x, direction n) -> ((z * cy + y) * cx + x) * D*D + n. */
  std::vector<float> Download() const;

  /** Device seconds of the last Compute, and its dispatch count. */
  double LastSeconds() const { return this->LastSeconds_; }
  uint32_t LastDispatches() const { return this->LastDispatches_; }
  /** With profiling on, every sweep dispatch gets its own timer and LastStageSeconds() holds the
   *  device seconds of the last Compute per stage ("march", "filter", "project", ...). */
  void SetProfiling(bool on) { this->Profiling_ = on; }
  const std::map<std::string, double>& LastStageSeconds() const { return this->LastStageSeconds_; }
  /** With profiling on, the process CPU seconds (user + system, all threads) per stage of the last
   *  Compute: each dispatch is then submitted alone, so this is the work each stage took, which
   *  other processes on a shared machine change far less than its device time. */
  const std::map<std::string, double>& LastStageCpuSeconds() const { return this->LastStageCpuSeconds_; }
  /** Host wall-clock seconds of the last Compute (planning, buffers, submits, waits). */
  double LastWallSeconds() const { return this->LastWallSeconds_; }
  /** Times the pooled extinction volume was built (it is cached across Compute calls). */
  uint64_t PoolBuilds() const;
  /** Estimated device seconds AdvancePool still needs (PooledExtinction::RemainingSeconds: 0 when
   *  the pool is built, not used, or its cost is not measured yet). */
  double PoolRemainingSeconds() const;
  /** Progressive grids: builds the pooled extinction volume this grid's sweeps will march (when its
   *  parameters pool and it is not current) for about budgetSeconds of device time, so that no
   *  frame waits for the whole build; returns the device seconds spent. True in `ready` once it
   *  is current (Compute then does not build it). */
  double AdvancePool(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    double budgetSeconds, bool& ready);
  /** Changes whenever the grid's values may have changed (a new image, Clear, Compute): a
   *  process-wide serial (vsSerial.h), so caches of derived data can tell old values from new. */
  uint64_t ContentSerial() const { return this->ContentSerial_; }
  /** Directions swept (or brute-forced) since this object was made. */
  uint64_t DirectionsComputed() const { return this->DirectionsComputed_; }

private:
  void RunSweeps(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    Buffer& globals, const Progress& progress);
  /** The most floats one of the sweeps' work buffers holds on this device: the plan's budget. */
  static uint64_t WorkBufferFloats(const DeviceInfo& info);
  void RunBruteForce(const DeviceVolume& volume, const TransferFunctionTable& tf,
    const MajorantGrid& majorants, Buffer& globals, const std::vector<uint32_t>& directions,
    const Progress& progress);

  std::shared_ptr<Context> Context_;
  VisibilityGridParameters Parameters_;
  SweepPlan Plan_;
  VolumeGeometry Geometry_;
  std::unique_ptr<Image3D> Image_;
  std::vector<uint32_t> Sources_;          // DirectionSources()
  std::unique_ptr<Buffer> SourceBuffer_;   // its device copy
  void ResetSources();
  void UploadSources();
  /** The pooling of this grid's parameters and geometry. */
  PooledExtinction::Settings PoolSettings() const;

  std::shared_ptr<ComputePipeline> March_, MarchPooled_, Filter_, Project_, Brute_;
  uint32_t MarchPooledNearest_ = ~0u; // the specialization MarchPooled_ was made for
  uint32_t MarchFactor_ = ~0u, BruteFactor_ = ~0u; // March_'s and Brute_'s (the extinction factor)
  std::unique_ptr<PooledExtinction> Pool_;          // the pooled extinction the sweeps march (cached)
  double LastSeconds_ = 0.0;
  double LastWallSeconds_ = 0.0;
  bool Profiling_ = false;
  std::map<std::string, double> LastStageSeconds_, LastStageCpuSeconds_;
  uint32_t LastDispatches_ = 0;
  uint64_t DirectionsComputed_ = 0;
  uint64_t ContentSerial_ = 0;
};
}

#endif
