#include "vsVisibilityGrid.h"
#include "vsSerial.h"
#include "vsBatch.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsError.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsPipeline.h"
#include "vsTransferFunctionTable.h"
#include "sampling/interpolation.h"

#include "vs_spirv_sweep_filter.h"
#include "vs_spirv_sweep_march.h"
#include "vs_spirv_sweep_march_pooled.h"
#include "vs_spirv_sweep_project_r16.h"
#include "vs_spirv_sweep_project_r32f.h"
#include "vs_spirv_sweep_project_r8.h"
#include "vs_spirv_visibility_bruteforce.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>
#include <string_view>

#include <sys/resource.h>

namespace vs
{
namespace
{
/** The most floats one of the sweeps' work buffers (the kernel stack, the filtered slices) holds:
 *  bound by the storage buffers they are written as and the texel buffers they are read through
 *  (maxTexelBufferElements can be below maxStorageBufferRange / 4 on a GPU), at most 64 MiB. */
uint64_t WorkBufferFloats(const DeviceInfo& info)
{
  uint64_t floats = std::min<uint64_t>(info.MaxStorageBufferRange, 64ull << 20) / sizeof(float);
  if (info.MaxTexelBufferElements > 0)
  {
    floats = std::min<uint64_t>(floats, info.MaxTexelBufferElements);
  }
  return floats;
}

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

vk::Format ToVk(VisibilityGridParameters::Format f)
{
  switch (f)
  {
    case VisibilityGridParameters::Format::Unorm8:
      return vk::Format::eR8Unorm;
    case VisibilityGridParameters::Format::Unorm16:
      return vk::Format::eR16Unorm;
    default:
      return vk::Format::eR32Sfloat;
  }
}

bool SameLayout(const VisibilityGridParameters& a, const VisibilityGridParameters& b)
{
  return a.DirectionResolution == b.DirectionResolution && a.VoxelsPerCell == b.VoxelsPerCell &&
    a.KernelResolution == b.KernelResolution && a.StepSize == b.StepSize && a.Filtering == b.Filtering &&
    a.FilterAngleFraction == b.FilterAngleFraction && a.Algorithm == b.Algorithm &&
    a.BruteForceSamples == b.BruteForceSamples && a.StorageFormat == b.StorageFormat &&
    a.StopTransmittance == b.StopTransmittance && a.AutoKernelRaysPerCell == b.AutoKernelRaysPerCell &&
    a.Directions == b.Directions && a.ExtinctionPooling == b.ExtinctionPooling && a.MaxPooling == b.MaxPooling &&
    a.NearestInterpolation == b.NearestInterpolation;
}



bool SameGeometry(const VolumeGeometry& a, const VolumeGeometry& b)
{
  // The box too: cropping changes it, and with it the cells' placement.
  return a.Dims == b.Dims && a.WorldToIndex == b.WorldToIndex && a.BoxMin == b.BoxMin && a.BoxMax == b.BoxMax &&
    a.CropFlags == b.CropFlags && (a.CropFlags == 0 || (a.CropLo == b.CropLo && a.CropHi == b.CropHi));
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

struct SlicePush
{
  uint32_t first;
  uint32_t firstDirection;
};
struct ChunkPush
{
  uint32_t firstSlice;
  uint32_t count;
  uint32_t firstDirection;
};
}

VisibilityGrid::VisibilityGrid(std::shared_ptr<Context> context)
  : Context_(std::move(context))
{
}

VisibilityGrid::~VisibilityGrid() = default;

uint64_t VisibilityGrid::Bytes() const
{
  return this->Image_ ? this->Image_->Bytes() : 0;
}

void VisibilityGrid::CheckFits(Context& context, const VolumeGeometry& geometry, const VisibilityGridParameters& p)
{
  p.Validate();
  const uint32_t d = p.DirectionResolution;
  auto cells = SweepPlan::CellCount(geometry, p.VoxelsPerCell, d, context.Info().MaxImageDimension3D);
  Image3D::CheckLimits(context, cells[0] * d, cells[1] * d, cells[2], ToVk(p.StorageFormat), "visibility grid");
  if (!context.Info().WriteWithoutFormat)
  {
    throw DeviceLimitError("the device '" + context.Info().Name +
      "' cannot write storage images without a format (shaderStorageImageWriteWithoutFormat), "
      "which the visibility sweeps need");
  }
}

bool VisibilityGrid::Allocate(
  const VolumeGeometry& geometry, const VisibilityGridParameters& parameters, bool clear, float clearValue)
{
  parameters.Validate();
  if (this->Image_ && SameLayout(parameters, this->Parameters_) && SameGeometry(geometry, this->Geometry_))
  {
    return false;
  }
  const auto& info = this->Context_->Info();
  const uint64_t maxFloats = WorkBufferFloats(info);
  CheckFits(*this->Context_, geometry, parameters);
  this->Image_.reset();
  this->Plan_ = SweepPlan::Make(geometry, parameters, maxFloats, {}, 8, info.MaxImageDimension3D);
  const auto& c = this->Plan_.Cells;
  const uint32_t d = parameters.DirectionResolution;
  this->Image_ = std::make_unique<Image3D>(this->Context_, c[0] * d, c[1] * d, c[2], ToVk(parameters.StorageFormat),
    "visibility grid");
  this->Parameters_ = parameters;
  this->Geometry_ = geometry;
  this->ResetSources();
  if (clear)
  {
    this->Image_->Clear(clearValue);
  }
  this->ContentSerial_ = NewSerial();
  return true;
}

void VisibilityGrid::Clear(float value)
{
  if (!this->Image_)
  {
    throw InputError("the visibility grid has no image to clear");
  }
  this->Image_->Clear(std::clamp(value, 0.0f, 1.0f));
  this->ResetSources();
  this->ContentSerial_ = NewSerial();
}

void VisibilityGrid::ResetSources()
{
  const uint32_t count = this->Parameters_.DirectionResolution * this->Parameters_.DirectionResolution;
  this->Sources_.resize(count);
  for (uint32_t n = 0; n < count; ++n)
  {
    this->Sources_[n] = n;
  }
  this->UploadSources();
}

void VisibilityGrid::UploadSources()
{
  const uint64_t bytes = this->Sources_.size() * sizeof(uint32_t);
  if (!this->SourceBuffer_ || this->SourceBuffer_->Size() != bytes)
  {
    this->SourceBuffer_ = std::make_unique<Buffer>(this->Context_, bytes, "visibility direction sources");
  }
  this->SourceBuffer_->Upload(this->Sources_.data(), bytes);
}

const Buffer& VisibilityGrid::DirectionSourceBuffer() const
{
  if (!this->SourceBuffer_)
  {
    throw InputError("the visibility grid has no directions yet");
  }
  return *this->SourceBuffer_;
}

void VisibilityGrid::RedirectDirections(const std::vector<std::pair<uint32_t, uint32_t>>& redirects)
{
  if (!this->Image_)
  {
    throw InputError("the visibility grid has no image to fill");
  }
  if (redirects.empty())
  {
    return;
  }
  const uint32_t count = uint32_t(this->Sources_.size());
  for (const auto& [to, from] : redirects)
  {
    if (to >= count || from >= count)
    {
      throw InputError("direction " + std::to_string(std::max(to, from)) + " is not one of the grid's " +
        std::to_string(count));
    }
  }
  for (const auto& [to, from] : redirects)
  {
    if (this->Sources_[from] != from)
    {
      throw InputError("direction " + std::to_string(to) + " cannot read direction " + std::to_string(from) +
        ", which itself reads another");
    }
  }
  for (const auto& [to, from] : redirects)
  {
    this->Sources_[to] = from;
  }
  this->UploadSources();
  this->ContentSerial_ = NewSerial();
}

void VisibilityGrid::Compute(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, const VolumeGeometry& geometry, const std::vector<glm::dvec4>& worldClipPlanes,
  const VisibilityGridParameters& parameters, const std::vector<uint32_t>& requested, const Progress& progress)
{
  const auto wallStart = std::chrono::steady_clock::now();
  parameters.Validate();
  if (worldClipPlanes.size() > shared::VS_MAX_CLIP_PLANES)
  {
    throw InputError("at most " + std::to_string(shared::VS_MAX_CLIP_PLANES) +
      " clipping planes that cut the volume are supported, got " + std::to_string(worldClipPlanes.size()));
  }
  const auto& info = this->Context_->Info();
  const uint64_t maxFloats = WorkBufferFloats(info);

  std::vector<uint32_t> directions = requested;
  // A new layout swept in part: the other directions read 0, never the fresh image's garbage.
  this->Allocate(geometry, parameters, !directions.empty());
  if (directions.empty())
  {
    for (uint32_t n = 0; n < parameters.DirectionResolution * parameters.DirectionResolution; ++n)
    {
      directions.push_back(n);
    }
  }
  this->Plan_ = SweepPlan::Make(geometry, parameters, maxFloats, directions, 8, info.MaxImageDimension3D);

  // What every dispatch shares.
  shared::VsSweepGlobals g{};
  g.worldToIndex = glm::mat4(geometry.WorldToIndex);
  g.boxMin = glm::vec4(geometry.BoxMin, 0.0f);
  g.boxMax = glm::vec4(geometry.BoxMax, 0.0f);
  g.cellSize = glm::vec4(this->Plan_.CellSize, 0.0f);
  g.grid = glm::uvec4(this->Plan_.Cells[0], this->Plan_.Cells[1], this->Plan_.Cells[2], this->Plan_.Side);
  auto dims = volume.Dims();
  g.dims = glm::vec4(float(dims[0]), float(dims[1]), float(dims[2]), 0.0f);
  auto t = tf.Params();
  g.tf = glm::vec4(t[0], t[1], t[2], t[3]);
  const double step = parameters.StepSize > 0.0 ? parameters.StepSize : geometry.MinSpacing;
  g.march = glm::vec4(float(step), float(majorants.BrickSize()), parameters.StopTransmittance,
    float(parameters.NearestInterpolation ? shared::VS_INTERPOLATION_NEAREST : shared::VS_INTERPOLATION_LINEAR));
  auto bricks = majorants.Bricks();
  g.bricks = glm::uvec4(bricks[0], bricks[1], bricks[2], uint32_t(worldClipPlanes.size()));
  // World planes to index space: n.(M x + o) + w = (M^T n).x + (n.o + w).
  const glm::dmat3 m(geometry.IndexToWorld);
  const glm::dvec3 o(geometry.IndexToWorld[3]);
  for (size_t i = 0; i < worldClipPlanes.size(); ++i)
  {
    glm::dvec3 n(worldClipPlanes[i]);
    g.clipPlanes[i] = glm::vec4(glm::vec3(glm::transpose(m) * n), float(glm::dot(n, o) + worldClipPlanes[i].w));
  }
  g.bruteForce = glm::uvec4(parameters.BruteForceSamples, 1u, 0u, 0u);
  // The occupied box: the bricks of nonzero majorant (each covers voxels [b B, (b + 1) B]),
  // widened by a pooled texel's reach (P voxels, and one for nearest-neighbour cells and rounding).
  {
    const auto& m = majorants.Majorants();
    const uint32_t B = majorants.BrickSize();
    glm::ivec3 lo(std::numeric_limits<int>::max()), hi(std::numeric_limits<int>::min());
    size_t i = 0;
    for (uint32_t z = 0; z < bricks[2]; ++z)
      for (uint32_t y = 0; y < bricks[1]; ++y)
        for (uint32_t x = 0; x < bricks[0]; ++x, ++i)
        {
          if (i < m.size() && !(m[i] == 0.0f))
          {
            lo = glm::min(lo, glm::ivec3(int(x), int(y), int(z)));
            hi = glm::max(hi, glm::ivec3(int(x), int(y), int(z)));
          }
        }
    if (m.size() != size_t(bricks[0]) * bricks[1] * bricks[2])
    {
      // Not the layout expected: no skipping.
      g.occupiedMin = g.boxMin;
      g.occupiedMax = g.boxMax;
    }
    else if (lo.x > hi.x)
    {
      // Nothing occludes: a degenerate box outside the volume, which no ray's interval overlaps.
      g.occupiedMin = g.occupiedMax = glm::vec4(geometry.BoxMin - 8.0f, 0.0f);
    }
    else
    {
      const float margin = float(parameters.Algorithm == VisibilityGridParameters::Method::Sweep
                                     ? parameters.PoolingFactor()
                                     : 1u) +
        1.0f;
      const glm::vec3 a = glm::vec3(lo) * float(B) - margin;
      const glm::vec3 b = glm::vec3(hi + 1) * float(B) + margin;
      g.occupiedMin = glm::vec4(glm::max(a, geometry.BoxMin), 0.0f);
      g.occupiedMax = glm::vec4(glm::min(b, geometry.BoxMax), 0.0f);
    }
  }
  g.cropLo = glm::vec4(geometry.CropLo, 0.0f);
  g.cropHi = glm::vec4(geometry.CropHi, 0.0f);
  g.crop = glm::uvec4(geometry.CropFlags, 0u, 0u, 0u);
  const uint32_t factor = parameters.Algorithm == VisibilityGridParameters::Method::Sweep ? parameters.PoolingFactor() : 1u;
  if (factor > 1)
  {
    const uint32_t brick = PooledExtinction::BrickTexels(factor);
    glm::uvec3 pooled, poolBricks;
    for (int i = 0; i < 3; ++i)
    {
      pooled[i] = (dims[i] + factor - 1) / factor;
      poolBricks[i] = (pooled[i] + brick - 1) / brick;
    }
    g.pool = glm::vec4(float(factor), float(brick), 0.5f * float(factor - 1), float(step * factor));
    g.poolDims = glm::uvec4(pooled, 0u);
    g.poolBricks = glm::uvec4(poolBricks, 0u);
  }
  Buffer globals(this->Context_, sizeof(g), "sweep globals");
  globals.Upload(&g, sizeof(g));

  this->LastSeconds_ = 0.0;
  this->LastDispatches_ = 0;
  this->LastStageSeconds_.clear();
  this->LastStageCpuSeconds_.clear();
  if (parameters.Algorithm == VisibilityGridParameters::Method::Sweep)
  {
    this->RunSweeps(volume, tf, majorants, globals, progress);
  }
  else
  {
    this->RunBruteForce(volume, tf, majorants, globals, directions, progress);
  }
  this->DirectionsComputed_ += directions.size();
  // Computed directions read their own values again.
  bool redirected = false;
  for (uint32_t n : directions)
  {
    redirected |= this->Sources_[n] != n;
    this->Sources_[n] = n;
  }
  if (redirected)
  {
    this->UploadSources();
  }
  this->ContentSerial_ = NewSerial();
  this->LastWallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
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
      std::vector<B>{ B::StorageImage, B::UniformTexelBuffer, B::StorageImage, B::StorageBuffer, B::StorageBuffer,
        B::StorageBuffer, B::StorageBuffer, B::StorageImage },
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
  tapsA = tapsA > MaxUnrolledTaps ? 0u : tapsA;
  tapsB = tapsB > MaxUnrolledTaps ? 0u : tapsB;
  {
    using B = BindingType;
    this->Filter_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_filter),
      std::vector<B>{ B::StorageBuffer, B::StorageBuffer, B::UniformTexelBuffer, B::StorageBuffer }, sizeof(ChunkPush),
      "sweep filter (" + std::to_string(tapsA) + " taps)", { tapsA });
    // The projection stores into an image of known format (faster on lavapipe than format-less stores).
    const std::vector<B> bindings{ B::StorageBuffer, B::StorageBuffer, B::UniformTexelBuffer, B::StorageImage };
    this->Project_ = FormatPipeline(this->Context_, this->Parameters_.StorageFormat,
      VS_SPIRV_PER_FORMAT(vs_spirv_sweep_project), bindings, sizeof(ChunkPush), "sweep project",
      ", " + std::to_string(tapsB) + " taps", { tapsB });
  }
  const uint32_t nearest = this->Parameters_.NearestInterpolation ? 1u : 0u;
  if (!this->MarchPooled_ || this->MarchPooledNearest_ != nearest)
  {
    using B = BindingType;
    this->MarchPooled_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_sweep_march_pooled),
      std::vector<B>{ B::StorageImage, B::UniformTexelBuffer, B::StorageImage, B::StorageBuffer, B::StorageBuffer,
        B::StorageBuffer, B::StorageBuffer },
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
    march.Bind(0, this->Pool_->Pooled()).Bind(2, this->Pool_->Occupancy());
  }
  else
  {
    march.Bind(0, volume.Image()).Bind(2, majorants.Image());
    march.Bind(7, volume.Factor() ? *volume.Factor() : volume.Image()); // unread without a factor
  }
  march.BindTexels(1, tf.Lut(), vk::Format::eR32Sfloat).Bind(3, globals).Bind(4, dirs).Bind(5, state).Bind(6, stack);
  DescriptorSet project(*this->Project_);
  project.Bind(0, globals).Bind(1, dirs).BindTexels(2, filtered, vk::Format::eR32Sfloat).Bind(3, *this->Image_);
  DescriptorSet filter(*this->Filter_);
  filter.Bind(0, globals).Bind(1, dirs).BindTexels(2, stack, vk::Format::eR32Sfloat).Bind(3, filtered);

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
      dispatch("filter", *this->Filter_, filter, cp, (ga + 7) / 8, chunk, nd);
      dispatch("project", *this->Project_, project, cp, (gb + 7) / 8, chunk, nd);
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

void VisibilityGrid::RunBruteForce(const DeviceVolume& volume, const TransferFunctionTable& tf,
  const MajorantGrid& majorants, Buffer& globals, const std::vector<uint32_t>& directions, const Progress& progress)
{
  const uint32_t extinctionFactor = volume.Factor() ? 1u : 0u;
  if (!this->Brute_ || this->BruteFactor_ != extinctionFactor)
  {
    using B = BindingType;
    this->Brute_ = SharedPipeline(this->Context_, VS_SPIRV(vs_spirv_visibility_bruteforce),
      std::vector<B>{ B::StorageImage, B::UniformTexelBuffer, B::StorageImage, B::StorageBuffer, B::StorageImage,
        B::StorageImage },
      sizeof(SlicePush), extinctionFactor ? "visibility brute force (gradient opacity)" : "visibility brute force",
      { 0u, extinctionFactor });
    this->BruteFactor_ = extinctionFactor;
  }
  DescriptorSet set(*this->Brute_);
  set.Bind(0, volume.Image()).BindTexels(1, tf.Lut(), vk::Format::eR32Sfloat).Bind(2, majorants.Image()).Bind(3, globals).Bind(4, *this->Image_);
  set.Bind(5, volume.Factor() ? *volume.Factor() : volume.Image()); // unread without a factor
  const auto& c = this->Plan_.Cells;
  const uint32_t cells = c[0] * c[1] * c[2];
  const uint32_t maxGroups = this->Context_->Info().MaxComputeWorkGroupCount[0];
  size_t done = 0;
  for (uint32_t n : directions)
  {
    Batch cmd(this->Context_);
    cmd.BeginTimer("bruteforce");
    for (uint32_t first = 0; first < cells; first += maxGroups * 64)
    {
      SlicePush push{ first, n };
      uint32_t groups = std::min(maxGroups, (cells - first + 63) / 64);
      cmd.Dispatch(*this->Brute_, set, &push, sizeof(push), groups, 1, 1);
    }
    cmd.EndTimer();
    cmd.Submit();
    this->LastSeconds_ += cmd.Seconds("bruteforce");
    this->LastDispatches_ += cmd.DispatchCount();
    ++done;
    if (progress)
    {
      progress(double(done) / double(directions.size()));
    }
  }
}

std::vector<float> VisibilityGrid::Download() const
{
  if (!this->Image_)
  {
    return {};
  }
  const auto& c = this->Plan_.Cells;
  const uint32_t d = this->Plan_.Side;
  const uint64_t texels = uint64_t(c[0]) * d * c[1] * d * c[2];
  std::vector<float> raw(texels);
  const uint32_t bytes = Image3D::TexelBytes(this->Image_->Format());
  std::vector<uint8_t> data(texels * bytes);
  this->Image_->Download(data.data(), data.size());
  for (uint64_t i = 0; i < texels; ++i)
  {
    if (bytes == 1)
    {
      raw[i] = data[i] / 255.0f;
    }
    else if (bytes == 2)
    {
      uint16_t v;
      std::memcpy(&v, &data[2 * i], 2);
      raw[i] = v / 65535.0f;
    }
    else
    {
      std::memcpy(&raw[i], &data[4 * i], 4);
    }
  }
  // Image (x * D + u, y * D + v, z) -> cell-major, direction-minor; a redirected direction reads
  // its source's values.
  std::vector<float> out(texels);
  const uint64_t w = uint64_t(c[0]) * d, h = uint64_t(c[1]) * d;
  for (uint32_t z = 0; z < c[2]; ++z)
    for (uint32_t y = 0; y < c[1]; ++y)
      for (uint32_t x = 0; x < c[0]; ++x)
        for (uint32_t n = 0; n < d * d; ++n)
        {
          const uint32_t m = this->Sources_[n];
          uint64_t tx = uint64_t(x) * d + m % d, ty = uint64_t(y) * d + m / d;
          out[((uint64_t(z) * c[1] + y) * c[0] + x) * d * d + n] = raw[(z * h + ty) * w + tx];
        }
  return out;
}
}
