// vsVisibilityGridSweeps.cxx — VisibilityGrid's plane sweeps (the default algorithm): the march,
// filter and projection pipelines (specialised per storage format and for the plan's tap counts),
// their work buffers, the dispatch loop over the plan's batches of directions, and the pooled
// extinction volume the march reads (cached across Compute calls). The grid's image, its
// direction sources, the globals every pass reads and the brute-force reference are in
// vsVisibilityGrid.cxx.
#include "vsVisibilityGrid.h"
#include "sampling/bindings.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"

#include "vs_spirv_sweep_filter.h"
#include "vs_spirv_sweep_march.h"
#include "vs_spirv_sweep_march_pooled.h"
#include "vs_spirv_sweep_project_r16.h"
#include "vs_spirv_sweep_project_r32f.h"
#include "vs_spirv_sweep_project_r8.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <sys/resource.h>

namespace vs
{
namespace
{
/** One shader's SPIR-V, compiled once per storage format of the grid (VS_VIS_FORMAT). */
struct PerFormatSpirv
{
  const uint32_t* Code[3]; // r8, r16, r32f
  size_t Bytes[3];
};
#define VS_SPIRV_PER_FORMAT(name)                                                                          \
  PerFormatSpirv                                                                                         \
  {                                                                                                      \
    { name##_r8, name##_r16, name##_r32f }, { sizeof(name##_r8), sizeof(name##_r16), sizeof(name##_r32f) } \
  }

/** The pipeline of `spirv` for the grid's storage format, named "<name> (<format><detail>)". */
std::shared_ptr<ComputePipeline> FormatPipeline(const std::shared_ptr<Context>& context,
  VisibilityGridParameters::Format format, const PerFormatSpirv& spirv, const std::vector<BindingType>& bindings,
  uint32_t pushBytes, const std::string& name, const std::string& detail,
  const std::vector<uint32_t>& specialization = {})
{
  const int i = format == VisibilityGridParameters::Format::Unorm8 ? 0
    : format == VisibilityGridParameters::Format::Unorm16          ? 1
                                                                    : 2;
  static const char* const formats[3] = { "r8", "r16", "r32f" };
  return SharedPipeline(context, spirv.Code[i], spirv.Bytes[i], bindings, pushBytes,
    name + " (" + formats[i] + detail + ")", specialization);
}

// User and system CPU seconds of this process so far (all threads: lavapipe's too).
double ProcessCpuSeconds()
{
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// The kernel rays one box of `width` rays and the linear read beside it weigh at most
// (vs_kernel_taps: ceil(hi1) - floor(lo0), and hi1 - lo0 <= max(width, 1) + 1), on a line of n rays.
uint32_t KernelTaps(float width, uint32_t n)
{
  const double w = std::max(1.0, double(width));
  return uint32_t(std::min<double>(std::ceil(w * (1.0 + 1e-6)) + 2.0, double(std::max<uint32_t>(n, 1))));
}
// Beyond this, the filter and the projection loop over the taps instead of unrolling them.
constexpr uint32_t MaxUnrolledTaps = 16;

struct ChunkPush
{
  uint32_t firstSlice;
  uint32_t count;
  uint32_t firstDirection;
};
}

/** The most floats one of the sweeps' work buffers (the kernel stack, the filtered slices) holds:
 *  bound by the storage buffers they are written as and the texel buffers they are read through
 *  (maxTexelBufferElements can be below maxStorageBufferRange / 4 on a GPU), at most 64 MiB. */
uint64_t VisibilityGrid::WorkBufferFloats(const DeviceInfo& info)
{
  uint64_t floats = std::min<uint64_t>(info.MaxStorageBufferRange, 64ull << 20) / sizeof(float);
  if (info.MaxTexelBufferElements > 0)
  {
    floats = std::min<uint64_t>(floats, info.MaxTexelBufferElements);
  }
  return floats;
}

void VisibilityGrid::RunSweeps(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, Buffer& globals, const Progress& progress)
{
  // The full-resolution march reads the extinction factor (the gradient opacity) where there is one.
  const uint32_t extinctionFactor = volume.Factor() ? 1u : 0u;
  if (!this->March_ || this->MarchFactor_ != extinctionFactor)
  {
    using B = BindingType;
    this->March_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_march),
      BindingTypes(shared::VS_SWEEP_BINDING_COUNT,
        { { shared::VS_SWEEP_VOLUME, B::StorageImage }, { shared::VS_SWEEP_TF, B::UniformTexelBuffer },
          { shared::VS_SWEEP_MAJORANT, B::StorageImage }, { shared::VS_SWEEP_GLOBALS, B::StorageBuffer },
          { shared::VS_SWEEP_DIRECTIONS, B::StorageBuffer }, { shared::VS_SWEEP_STATE, B::StorageBuffer },
          { shared::VS_SWEEP_STACK, B::StorageBuffer }, { shared::VS_SWEEP_FACTOR_IMAGE, B::StorageImage } }),
      sizeof(ChunkPush), extinctionFactor ? "sweep march (gradient opacity)" : "sweep march", { 0u, extinctionFactor });
    this->MarchFactor_ = extinctionFactor;
  }
  // The filter and the projection are specialised for the most kernel rays a box (and the linear
  // read beside it) covers along a and along b in this plan: their tap loops then unroll.
  const SweepPlan& plan = this->Plan_;
  uint32_t tapsA = 1, tapsB = 1;
  for (const auto& batch : plan.Batches)
  {
    for (uint32_t n : batch)
    {
      const auto& s = plan.Directions[n];
      const uint32_t k = s.axes.x;
      float tMax = 0.0f;
      for (uint32_t slice : { 0u, plan.Cells[k] - 1u })
      {
        tMax = std::max(tMax, std::abs(shared::vs_slice_t(this->Geometry_.BoxMin[k], plan.CellSize[k], plan.Cells[k],
                                s.planeOrigin[k], s.travel[k], s.kernel.z == 1u, slice)));
      }
      tapsA = std::max(tapsA, KernelTaps(s.filterSize.x + 2.0f * tMax * s.filterSize.z, s.kernel.x));
      tapsB = std::max(tapsB, KernelTaps(s.filterSize.y + 2.0f * tMax * s.filterSize.w, s.kernel.y));
    }
  }
  // Their workgroups are one row of one subgroup (the device's subgroup size, not lavapipe's 8).
  const uint32_t rowWidth = this->Context_->Info().RowWorkgroupWidth();
  tapsA = tapsA > MaxUnrolledTaps ? 0u : tapsA;
  tapsB = tapsB > MaxUnrolledTaps ? 0u : tapsB;
  {
    using B = BindingType;
    this->Filter_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_filter),
      BindingTypes(shared::VS_FILTER_BINDING_COUNT,
        { { shared::VS_FILTER_GLOBALS, B::StorageBuffer }, { shared::VS_FILTER_DIRECTIONS, B::StorageBuffer },
          { shared::VS_FILTER_STACK, B::UniformTexelBuffer }, { shared::VS_FILTER_FILTERED, B::StorageBuffer } }),
      sizeof(ChunkPush),
      "sweep filter (" + std::to_string(tapsA) + " taps)", { tapsA, rowWidth });
    // The projection stores into an image of known format (faster on lavapipe than format-less stores).
    const std::vector<B> bindings = BindingTypes(shared::VS_PROJECT_BINDING_COUNT,
      { { shared::VS_PROJECT_GLOBALS, B::StorageBuffer }, { shared::VS_PROJECT_DIRECTIONS, B::StorageBuffer },
        { shared::VS_PROJECT_FILTERED, B::UniformTexelBuffer }, { shared::VS_PROJECT_VISIBILITY, B::StorageImage } });
    this->Project_ = FormatPipeline(this->Context_, this->Parameters_.StorageFormat,
      VS_SPIRV_PER_FORMAT(vs_spirv_sweep_project), bindings, sizeof(ChunkPush), "sweep project",
      ", " + std::to_string(tapsB) + " taps", { tapsB, rowWidth });
  }
  const uint32_t nearest = this->Parameters_.NearestInterpolation ? 1u : 0u;
  if (!this->MarchPooled_ || this->MarchPooledNearest_ != nearest)
  {
    using B = BindingType;
    this->MarchPooled_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_march_pooled),
      BindingTypes(shared::VS_SWEEP_POOLED_BINDING_COUNT,
        { { shared::VS_SWEEP_VOLUME, B::StorageImage }, { shared::VS_SWEEP_TF, B::UniformTexelBuffer },
          { shared::VS_SWEEP_MAJORANT, B::StorageImage }, { shared::VS_SWEEP_GLOBALS, B::StorageBuffer },
          { shared::VS_SWEEP_DIRECTIONS, B::StorageBuffer }, { shared::VS_SWEEP_STATE, B::StorageBuffer },
          { shared::VS_SWEEP_STACK, B::StorageBuffer } }),
      sizeof(ChunkPush),
      nearest ? "sweep march (pooled, nearest)" : "sweep march (pooled)", { nearest });
    this->MarchPooledNearest_ = nearest;
  }
  const uint64_t budget = WorkBufferFloats(this->Context_->Info());

  // Directions in batch order, so a batch is a contiguous range of the buffer; per batch, the
  // slices per chunk so that its kernel stack (rays x slices) and the kernel filtered along a
  // (cells along a x rays along b, per slice) fit one buffer each.
  std::vector<shared::VsSweepDirection> ordered;
  std::vector<uint32_t> firsts, chunks;
  uint64_t stackFloats = 1, stateFloats = 1, filteredFloats = 1;
  for (const auto& batch : plan.Batches)
  {
    firsts.push_back(uint32_t(ordered.size()));
    uint64_t rays = 0, filtered = 0;
    uint32_t slices = 1;
    for (uint32_t n : batch)
    {
      const auto& s = plan.Directions[n];
      ordered.push_back(s);
      rays += uint64_t(s.kernel.x) * s.kernel.y;
      filtered += uint64_t(plan.Cells[s.axes.y]) * s.kernel.y;
      slices = std::max(slices, plan.Cells[s.axes.x]);
    }
    const uint64_t perSlice = std::max<uint64_t>(std::max(rays, filtered), 1);
    uint32_t chunk = uint32_t(std::max<uint64_t>(1, std::min<uint64_t>(slices, budget / perSlice)));
    chunks.push_back(chunk);
    stackFloats = std::max(stackFloats, rays * chunk);
    filteredFloats = std::max(filteredFloats, filtered * chunk);
    stateFloats = std::max(stateFloats, rays);
  }
  Buffer dirs(this->Context_, ordered.size() * sizeof(shared::VsSweepDirection), "sweep directions");
  dirs.Upload(ordered.data(), ordered.size() * sizeof(shared::VsSweepDirection));
  Buffer state(this->Context_, stateFloats * sizeof(float), "sweeping kernel");
  Buffer stack(this->Context_, stackFloats * sizeof(float), "sweeping kernel per slice");
  Buffer filtered(this->Context_, filteredFloats * sizeof(float), "sweeping kernel filtered along a");
  // The pooled extinction volume (cached), or the full-resolution volume with its majorants.
  const bool pooled = this->Parameters_.PoolingFactor() > 1;
  if (pooled)
  {
    const double cpu0 = ProcessCpuSeconds();
    if (!this->Pool_)
    {
      this->Pool_ = std::make_unique<PooledExtinction>(this->Context_);
    }
    const double seconds = this->Pool_->Ensure(volume, tf, majorants, this->PoolSettings());
    if (seconds > 0.0)
    {
      this->LastStageCpuSeconds_["pool"] += ProcessCpuSeconds() - cpu0;
    }
    this->LastSeconds_ += seconds;
    if (seconds > 0.0)
    {
      this->LastStageSeconds_["pool"] += seconds;
    }
  }
  const ComputePipeline& marchPipeline = pooled ? *this->MarchPooled_ : *this->March_;
  DescriptorSet march(marchPipeline);
  if (pooled)
  {
    march.Bind(shared::VS_SWEEP_VOLUME, this->Pool_->Pooled()).Bind(shared::VS_SWEEP_MAJORANT, this->Pool_->Occupancy());
  }
  else
  {
    march.Bind(shared::VS_SWEEP_VOLUME, volume.Image()).Bind(shared::VS_SWEEP_MAJORANT, majorants.Image());
    // unread without a factor
    march.Bind(shared::VS_SWEEP_FACTOR_IMAGE, volume.Factor() ? *volume.Factor() : volume.Image());
  }
  march.BindTexels(shared::VS_SWEEP_TF, tf.Lut(), vk::Format::eR32Sfloat)
    .Bind(shared::VS_SWEEP_GLOBALS, globals)
    .Bind(shared::VS_SWEEP_DIRECTIONS, dirs)
    .Bind(shared::VS_SWEEP_STATE, state)
    .Bind(shared::VS_SWEEP_STACK, stack);
  DescriptorSet project(*this->Project_);
  project.Bind(shared::VS_PROJECT_GLOBALS, globals)
    .Bind(shared::VS_PROJECT_DIRECTIONS, dirs)
    .BindTexels(shared::VS_PROJECT_FILTERED, filtered, vk::Format::eR32Sfloat)
    .Bind(shared::VS_PROJECT_VISIBILITY, *this->Image_);
  DescriptorSet filter(*this->Filter_);
  filter.Bind(shared::VS_FILTER_GLOBALS, globals)
    .Bind(shared::VS_FILTER_DIRECTIONS, dirs)
    .BindTexels(shared::VS_FILTER_STACK, stack, vk::Format::eR32Sfloat)
    .Bind(shared::VS_FILTER_FILTERED, filtered);

  for (size_t bi = 0; bi < plan.Batches.size(); ++bi)
  {
    const auto& batch = plan.Batches[bi];
    uint32_t slices = 0, ra = 0, rb = 0, ga = 0, gb = 0;
    for (uint32_t n : batch)
    {
      const auto& s = plan.Directions[n];
      slices = std::max(slices, plan.Cells[s.axes.x]);
      ra = std::max(ra, s.kernel.x);
      rb = std::max(rb, s.kernel.y);
      ga = std::max(ga, plan.Cells[s.axes.y]);
      gb = std::max(gb, plan.Cells[s.axes.z]);
    }
    const uint32_t nd = uint32_t(batch.size());
    const uint32_t chunk = chunks[bi];
    // Profiling: every dispatch in its own submission, timed on the device and in process CPU
    // seconds (which, unlike device time, other processes on the machine barely change).
    const bool profiling = this->Profiling_;
    Batch cmd(this->Context_);
    auto dispatch = [&](const char* name, const ComputePipeline& pipeline, const DescriptorSet& set,
                      const ChunkPush& push, uint32_t gx, uint32_t gy, uint32_t gz) {
      if (!profiling)
      {
        cmd.Dispatch(pipeline, set, &push, sizeof(push), gx, gy, gz);
        cmd.Barrier();
        return;
      }
      const double cpu0 = ProcessCpuSeconds();
      Batch one(this->Context_);
      one.BeginTimer(name);
      one.Dispatch(pipeline, set, &push, sizeof(push), gx, gy, gz);
      one.EndTimer();
      one.Submit();
      this->LastStageCpuSeconds_[name] += ProcessCpuSeconds() - cpu0;
      this->LastStageSeconds_[name] += one.Seconds(name);
      this->LastSeconds_ += one.Seconds(name);
      this->LastDispatches_ += one.DispatchCount();
    };
    if (!profiling)
      cmd.BeginTimer("sweep");
    for (uint32_t first = 0; first < slices; first += chunk)
    {
      ChunkPush cp{ first, chunk, firsts[bi] };
      dispatch("march", marchPipeline, march, cp, (ra + 7) / 8, (rb + 7) / 8, nd);
      // The filter along a and the interpolation along a (Filtering off: the interpolation only).
      dispatch("filter", *this->Filter_, filter, cp, (ga + rowWidth - 1) / rowWidth, chunk, nd);
      dispatch("project", *this->Project_, project, cp, (gb + rowWidth - 1) / rowWidth, chunk, nd);
    }
    if (!profiling)
    {
      cmd.EndTimer();
      cmd.Submit();
      this->LastSeconds_ += cmd.Seconds("sweep");
      this->LastDispatches_ += cmd.DispatchCount();
    }
    if (progress)
    {
      progress(double(bi + 1) / double(plan.Batches.size()));
    }
  }
}

PooledExtinction::Settings VisibilityGrid::PoolSettings() const
{
  PooledExtinction::Settings settings;
  settings.Factor = this->Parameters_.PoolingFactor();
  settings.Max = this->Parameters_.MaxPooling;
  settings.CropFlags = this->Geometry_.CropFlags;
  settings.CropLo = this->Geometry_.CropLo;
  settings.CropHi = this->Geometry_.CropHi;
  return settings;
}

uint64_t VisibilityGrid::PoolBuilds() const
{
  return this->Pool_ ? this->Pool_->Builds() : 0;
}

double VisibilityGrid::PoolRemainingSeconds() const
{
  return this->Pool_ ? this->Pool_->RemainingSeconds() : 0.0;
}

double VisibilityGrid::AdvancePool(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, double budgetSeconds, bool& ready)
{
  ready = true;
  if (this->Parameters_.Algorithm != VisibilityGridParameters::Method::Sweep || this->Parameters_.PoolingFactor() <= 1)
  {
    return 0.0;
  }
  if (!this->Pool_)
  {
    this->Pool_ = std::make_unique<PooledExtinction>(this->Context_);
  }
  const PooledExtinction::Settings settings = this->PoolSettings();
  const double seconds = this->Pool_->Advance(volume, tf, majorants, settings, budgetSeconds);
  ready = this->Pool_->IsCurrent(volume, tf, majorants, settings);
  return seconds;
}
}
