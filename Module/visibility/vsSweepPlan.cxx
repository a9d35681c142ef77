#include "vsSweepPlan.h"
#include "vsError.h"

#include "sampling/octahedral.h"

#include <algorithm>
#include <cmath>

namespace vs
{
void VisibilityGridParameters::Validate() const
{
  const uint32_t d = this->DirectionResolution;
  if (d < 1 || d > 64 || (d & (d - 1)) != 0)
  {
    throw InputError("DirectionResolution must be a power of two (4, 8 or 16), got " + std::to_string(d));
  }
  if (!this->Directions.empty())
  {
    if (this->Directions.size() != size_t(d) * d)
    {
      throw InputError("Directions must hold one direction per texel (" + std::to_string(d * d) + "), got " +
        std::to_string(this->Directions.size()));
    }
    for (const glm::vec3& w : this->Directions)
    {
      const float l = glm::length(w);
      if (!std::isfinite(l) || std::abs(l - 1.0f) > 1e-3f)
      {
        throw InputError("Directions must be unit vectors");
      }
    }
  }
  if (!(this->VoxelsPerCell >= 1.0) || !std::isfinite(this->VoxelsPerCell))
  {
    throw InputError("VoxelsPerCell must be at least 1, got " + std::to_string(this->VoxelsPerCell));
  }
  if (!(this->StepSize >= 0.0) || !std::isfinite(this->StepSize))
  {
    throw InputError("StepSize must be positive (or 0 for one voxel), got " + std::to_string(this->StepSize));
  }
  if (!(this->FilterAngleFraction >= 0.0 && this->FilterAngleFraction <= 1.0))
  {
    throw InputError("FilterAngleFraction (beta/alpha) must be in [0, 1], got " +
      std::to_string(this->FilterAngleFraction));
  }
  if (!(this->AutoKernelRaysPerCell >= 0.0 && this->AutoKernelRaysPerCell <= 1e6))
  {
    throw InputError("AutoKernelRaysPerCell must be in [0, 1e6], got " + std::to_string(this->AutoKernelRaysPerCell));
  }
  if (this->KernelResolution == 1)
  {
    throw InputError("KernelResolution must be 0 (auto) or at least 2");
  }
  if (!(this->StopTransmittance >= 0.0f && this->StopTransmittance < 1.0f))
  {
    throw InputError("StopTransmittance must be in [0, 1), got " + std::to_string(this->StopTransmittance));
  }
  if (this->BruteForceSamples < 1)
  {
    throw InputError("BruteForceSamples must be at least 1");
  }
  if (this->ExtinctionPooling > 16)
  {
    throw InputError("ExtinctionPooling must be 0 (auto) to 16 voxels per pooled texel, got " +
      std::to_string(this->ExtinctionPooling));
  }
}

uint32_t VisibilityGridParameters::PoolingFactor() const
{
  if (this->ExtinctionPooling > 0)
  {
    return this->ExtinctionPooling;
  }
  // Automatic: half a cell (2 voxels at the default 4^3 voxels per cell).
  return std::max<uint32_t>(1, uint32_t(std::floor(this->VoxelsPerCell / 2.0 + 1e-9)));
}

double SweepPlan::CellOpeningAngle(uint32_t side)
{
  const double omega = 4.0 * M_PI / (double(side) * side);
  return 2.0 * std::acos(std::max(-1.0, 1.0 - omega / (2.0 * M_PI)));
}

double SweepPlan::AutomaticVoxelsPerCell(const VolumeGeometry& g)
{
  double longest = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    longest = std::max(longest, double(g.BoxMax[i]) - double(g.BoxMin[i]));
  }
  return std::max(MinAutoVoxelsPerCell, longest / AutoCellsPerAxis);
}

std::array<uint32_t, 3> SweepPlan::CellCount(
  const VolumeGeometry& g, double voxelsPerCell, uint32_t side, uint32_t maxImageSide)
{
  std::array<uint32_t, 3> cells;
  for (int i = 0; i < 3; ++i)
  {
    double extent = std::max(0.0, double(g.BoxMax[i]) - double(g.BoxMin[i]));
    cells[i] = std::max<uint32_t>(1, uint32_t(std::ceil(extent / voxelsPerCell - 1e-9)));
    if (maxImageSide > 0)
    {
      const uint32_t limit = std::max<uint32_t>(1, i < 2 ? maxImageSide / std::max<uint32_t>(side, 1) : maxImageSide);
      cells[i] = std::min(cells[i], limit);
    }
  }
  return cells;
}

glm::vec3 SweepPlan::Direction(uint32_t n, uint32_t side)
{
  return shared::vs_texel_dir(glm::uvec2(n % side, n / side), side);
}

glm::vec3 SweepPlan::Direction(uint32_t n, const VisibilityGridParameters& p)
{
  return n < p.Directions.size() ? p.Directions[n] : Direction(n, p.DirectionResolution);
}

SweepPlan SweepPlan::Make(const VolumeGeometry& g, const VisibilityGridParameters& p,
  uint64_t maxBatchFloats, const std::vector<uint32_t>& requested, uint32_t maxBatchDirections, uint32_t maxImageSide)
{
  p.Validate();
  SweepPlan plan;
  plan.Side = p.DirectionResolution;
  plan.Cells = CellCount(g, p.VoxelsPerCell, p.DirectionResolution, maxImageSide);
  for (int i = 0; i < 3; ++i)
  {
    plan.CellSize[i] = (g.BoxMax[i] - g.BoxMin[i]) / float(plan.Cells[i]);
  }
  const uint32_t count = plan.Side * plan.Side;
  std::vector<uint32_t> directions = requested;
  if (directions.empty())
  {
    for (uint32_t n = 0; n < count; ++n)
    {
      directions.push_back(n);
    }
  }
  // Automatic: one ray per voxel of the longest axis (an accurate grid: the filters' default), or
  // AutoKernelRaysPerCell per cell (the renderer's, RendererKernelRaysPerCell); at most 128 rays
  // (the paper's Table 1 setting for a 512^3 volume).
  const uint32_t longestVoxels = *std::max_element(g.Dims.begin(), g.Dims.end());
  const uint32_t longestCells = *std::max_element(plan.Cells.begin(), plan.Cells.end());
  const double autoRays = p.AutoKernelRaysPerCell > 0.0 ? std::ceil(p.AutoKernelRaysPerCell * double(longestCells))
                                                        : double(longestVoxels);
  const uint32_t rays = p.KernelResolution ? p.KernelResolution : uint32_t(std::clamp(autoRays, 2.0, 128.0));
  const double tanBeta = std::tan(p.FilterAngleFraction * CellOpeningAngle(plan.Side));
  const glm::dmat3 toIndex(g.WorldToIndex);

  plan.Directions.resize(count);
  std::vector<uint64_t> kernelFloats(count, 0);
  for (uint32_t n : directions)
  {
    if (n >= count)
    {
      throw InputError("direction index " + std::to_string(n) + " out of range");
    }
    shared::VsSweepDirection& s = plan.Directions[n];
    const glm::dvec3 w(Direction(n, p));
    const glm::dvec3 d = toIndex * (-w); // light travel, index units per world unit
    // Eq. 6: the axis the light crosses cell slices fastest along; ties go to the lower axis.
    int k = 0;
    double best = -1.0;
    for (int i = 0; i < 3; ++i)
    {
      double rate = std::abs(d[i]) / plan.CellSize[i];
      if (rate > best * (1.0 + 1e-6))
      {
        best = rate;
        k = i;
      }
    }
    const int a = k == 0 ? 1 : 0;
    const int b = k == 2 ? 1 : 2;
    const bool descending = d[k] < 0.0;
    const double start = descending ? g.BoxMax[k] : g.BoxMin[k]; // Eq. 7
    // The box's corners projected along d onto the start plane bound the kernel.
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (int c = 0; c < 8; ++c)
    {
      glm::dvec3 corner((c & 1) ? g.BoxMax[0] : g.BoxMin[0], (c & 2) ? g.BoxMax[1] : g.BoxMin[1],
        (c & 4) ? g.BoxMax[2] : g.BoxMin[2]);
      glm::dvec3 q = corner + ((start - corner[k]) / d[k]) * d;
      amin = std::min(amin, q[a]);
      amax = std::max(amax, q[a]);
      bmin = std::min(bmin, q[b]);
      bmax = std::max(bmax, q[b]);
    }
    const double longer = std::max(amax - amin, bmax - bmin);
    const double h = longer > 0.0 ? longer / double(rays - 1) : 1.0;
    const uint32_t ra = uint32_t(std::ceil((amax - amin) / h - 1e-9)) + 1;
    const uint32_t rb = uint32_t(std::ceil((bmax - bmin) / h - 1e-9)) + 1;

    glm::vec3 origin;
    origin[k] = float(start);
    origin[a] = float(amin);
    origin[b] = float(bmin);
    s.travel = glm::vec4(glm::vec3(d), 0.0f);
    s.planeOrigin = glm::vec4(origin, 0.0f);
    s.kernelStep = glm::vec4(float(h), float(h), 0.0f, 0.0f);
    // Sec. 8: a cell projected along d onto the plane, in kernel texels; Eq. 9 widening per world unit.
    if (p.Filtering)
    {
      double baseA = (plan.CellSize[a] + plan.CellSize[k] * std::abs(d[a] / d[k])) / h;
      double baseB = (plan.CellSize[b] + plan.CellSize[k] * std::abs(d[b] / d[k])) / h;
      double widenA = tanBeta / (g.Spacing(a) * h);
      double widenB = tanBeta / (g.Spacing(b) * h);
      s.filterSize = glm::vec4(float(baseA), float(baseB), float(widenA), float(widenB));
    }
    else
    {
      s.filterSize = glm::vec4(0.0f);
    }
    s.axes = glm::uvec4(uint32_t(k), uint32_t(a), uint32_t(b), 0u);
    s.kernel = glm::uvec4(ra, rb, descending ? 1u : 0u, n);
    kernelFloats[n] = uint64_t(ra) * rb;
  }

  // Group directions into batches whose kernels fit together; assign offsets within a batch.
  std::vector<uint32_t> current;
  uint64_t used = 0, filtered = 0;
  for (uint32_t n : directions)
  {
    if (kernelFloats[n] > maxBatchFloats)
    {
      throw DeviceLimitError("the sweeping kernel of direction " + std::to_string(n) + " has " +
        std::to_string(kernelFloats[n]) + " rays, more than one storage buffer holds (" +
        std::to_string(maxBatchFloats) + "); lower KernelResolution");
    }
    if (used + kernelFloats[n] > maxBatchFloats || current.size() >= std::max(1u, maxBatchDirections))
    {
      plan.Batches.push_back(current);
      current.clear();
      used = 0;
      filtered = 0;
    }
    plan.Directions[n].axes.w = uint32_t(used);
    plan.Directions[n].filtered = glm::uvec4(uint32_t(filtered), 0u, 0u, 0u);
    used += kernelFloats[n];
    filtered += uint64_t(plan.Cells[plan.Directions[n].axes.y]) * plan.Directions[n].kernel.y;
    current.push_back(n);
    plan.LargestBatchKernelFloats = std::max(plan.LargestBatchKernelFloats, used);
    plan.LargestBatchFilteredFloats = std::max(plan.LargestBatchFilteredFloats, filtered);
  }
  if (!current.empty())
  {
    plan.Batches.push_back(current);
  }
  return plan;
}
}
