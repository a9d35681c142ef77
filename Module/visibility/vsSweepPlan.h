// vsSweepPlan.h — the geometry of the visibility sweeps (von Radziewsky et al. 2017, Sec. 6, 8),
// computed on the host: for each direction of the D x D equal-area octahedral
// map, the sweep axis (Eq. 6), the start plane on the side the light comes
// from (Eq. 7), the sweeping kernel covering the box projected along the light,
// and the sweep-space filter size (Sec. 8, Eq. 9).
#ifndef vsSweepPlan_h
#define vsSweepPlan_h

#include "vissweepCoreModule.h"
#include "sampling/sweep_params.h"
#include "vsVolumeGeometry.h"

#include <array>
#include <vector>

namespace vs
{
/** The renderer's automatic kernel (VisibilityGridParameters::AutoKernelRaysPerCell): rays per
 *  visibility cell along the grid's longest axis. Measured with TwoStep at equal spp
 *  (docs/benchmarks.md, "Kernel resolution"): the render error of the MRI is the same at 0.6,
 *  1.2 and 2.4 rays per cell, the phantom's and the slatted blind's within 4-7% of one ray per
 *  voxel, for sweeps 2.5-6x faster. The grid itself is coarser (the filters keep one ray per
 *  voxel): the renderer only samples by it. */
constexpr double RendererKernelRaysPerCell = 1.25;

struct VISSWEEPCORE_EXPORT VisibilityGridParameters
{
  enum class Method
  {
    Sweep,
    BruteForce
  };
  enum class Format
  {
    Unorm8,
    Unorm16,
    Float32
  };
  /** Directions per side of the octahedral map: 4, 8 or 16 (D x D directions). */
  uint32_t DirectionResolution = 8;
  /** Voxels per visibility cell along each axis (>= 1). */
  double VoxelsPerCell = 4.0;
  /** Kernel rays along the longer side of the projected box; 0 = automatic, at least 2, at most 128:
   *  one ray per voxel of the longest axis, or AutoKernelRaysPerCell rays per cell of the grid's
   *  longest axis when that is > 0. */
  uint32_t KernelResolution = 0;
  double AutoKernelRaysPerCell = 0.0;
  /** Ray-marching step in world units; 0 = one voxel (the smallest spacing). */
  double StepSize = 0.0;
  bool Filtering = true;
  /** beta / alpha of Eq. 9: widening angle as a fraction of a direction cell's opening angle
   *  (alpha = the full angle of the cone with the cell's solid angle, 28.7 deg at 8 x 8).
   *  Default 0, by measurement: on the MRI (skin TF) against the supersampled brute force,
   *  mean |dV| 0.027 at 0, 0.032 at 1/16, 0.069 at 1/4 and 0.127 at the paper's 1/2; 0.031
   *  unfiltered. The cell-footprint box filter (Sec. 8's base size) is what helps here. */
  double FilterAngleFraction = 0.0;
  Method Algorithm = Method::Sweep;
  /** Brute force: rays per cell and direction (random points of the cell, random directions of the texel). */
  uint32_t BruteForceSamples = 1;
  Format StorageFormat = Format::Unorm8;
  /** Kernel rays stop marching below this transmittance, keeping the value they reached: the grid
   *  then overestimates V by less than this (about half a step of the 8-bit grid, 1/255), and only
   *  where V is already that small. The renderer adds its epsilon (0.01) to V anyway: the pdf
   *  barely changes, and an approximation of the grid costs variance, never bias. Measured on ch2
   *  (renderer's grid): the march 10 % cheaper at 1e-3, 15 % at 4e-3, than at 1e-6 (the old default). */
  float StopTransmittance = 2e-3f;
  /** The world light direction swept for each of the D x D directions (row-major); empty = the
   *  texel centres (SweepPlan::Direction). The renderer sweeps each texel towards where its light
   *  comes from (the environment's radiance-weighted mean direction inside the texel), so that a
   *  sun off the texel's centre is swept along its own direction. */
  std::vector<glm::vec3> Directions;
  /** The sweeps march a pooled extinction volume of P^3 voxels per texel (mean of sigma_t, which
   *  keeps the optical depth through a block; trilinear between texels) with steps P times longer,
   *  built once per volume / transfer function and cached across Compute() calls. 1 = march the
   *  full-resolution volume (post-classified samples, the brute force's integrand); 0 = automatic
   *  (AutomaticPooling()). The brute force always marches the full volume. */
  uint32_t ExtinctionPooling = 0;
  /** Pool by the max instead of the mean (conservative: darker, for comparison). */
  bool MaxPooling = false;
  /** Nearest-neighbour reconstruction of the scalar (a vtkVolumeProperty's nearest
   *  InterpolationType, VTK's default) instead of trilinear: the sweeps and the brute force read the
   *  nearest voxel (the pooled march the pooled texel holding the point: under nearest a mean-pooled
   *  texel is exactly its block's mean extinction). */
  bool NearestInterpolation = false;

  /** The pooling factor the sweeps use (ExtinctionPooling, or the automatic choice). */
  uint32_t PoolingFactor() const;

  /** Throws InputError naming the parameter when one is out of range. */
  void Validate() const;
};

struct VISSWEEPCORE_EXPORT SweepPlan
{
  std::array<uint32_t, 3> Cells{ { 1, 1, 1 } };
  glm::vec3 CellSize{ 1.0f }; // index units
  uint32_t Side = 8;
  std::vector<shared::VsSweepDirection> Directions; // all D x D, kernel offsets per batch
  /** Directions grouped so that one batch's kernels fit in one storage buffer. */
  std::vector<std::vector<uint32_t>> Batches;
  uint64_t LargestBatchKernelFloats = 0;
  /** Per batch and slice, the kernel filtered along a (cells along a x rays along b per direction). */
  uint64_t LargestBatchFilteredFloats = 0;

  /** Opening angle (radians) of the cone with the solid angle of one of D x D equal-area cells. */
  static double CellOpeningAngle(uint32_t side);
  /** The renderer's automatic cell size: at least MinAutoVoxelsPerCell voxels, and cells of
   *  1/AutoCellsPerAxis of the box's longest axis when that is coarser. What makes the grid
   *  useful is the cell's size against the anatomy, not against the voxel: TwoStep's per-sample
   *  variance on the 0.5 mm MRI (ch2better, 370 voxels) is 0.0198 with 4-voxel cells (93 cells),
   *  0.0178 with 6.6 (56 cells) and 0.0181 with 8 (46 cells), while the 1 mm MRI (ch2, 217
   *  voxels) gains nothing finer than its 4-voxel cells (54 cells) and loses 6% at 8; the coarser
   *  grid sweeps ~3x faster (docs/benchmarks.md). Volumes up to 224 voxels keep 4. */
  static double AutomaticVoxelsPerCell(const VolumeGeometry& g);
  static constexpr double MinAutoVoxelsPerCell = 4.0;
  static constexpr double AutoCellsPerAxis = 56.0;
  /** Cells per axis for a geometry and a cell size in voxels. With maxImageSide > 0, the cells
   *  are capped so that the grid image (cells.x * side) x (cells.y * side) x cells.z fits a
   *  device whose 3D images are at most maxImageSide texels per axis: cells grow beyond
   *  voxelsPerCell along axes that would not fit (a 4096-voxel axis gets 512 cells at D = 8). */
  static std::array<uint32_t, 3> CellCount(
    const VolumeGeometry& g, double voxelsPerCell, uint32_t side = 1, uint32_t maxImageSide = 0);
  /** World light direction of direction index n (the centre of texel (n % D, n / D)). */
  static glm::vec3 Direction(uint32_t n, uint32_t side);
  /** The direction swept for index n: p.Directions[n] when given, else the texel centre. */
  static glm::vec3 Direction(uint32_t n, const VisibilityGridParameters& p);

  /** Plans the sweeps of `directions` (all when empty); maxBatchFloats bounds a batch's kernel. */
  static SweepPlan Make(const VolumeGeometry& g, const VisibilityGridParameters& p,
    uint64_t maxBatchFloats, const std::vector<uint32_t>& directions = {}, uint32_t maxBatchDirections = 8,
    uint32_t maxImageSide = 0);
};
}

#endif
