// vsMajorantGrid.h — the maximum extinction per brick of B^3 voxels (default 8),
// conservative over the trilinear footprint of the brick (voxels [bB, (b+1)B]), which is also
// the set of voxels nearest-neighbour samples in the brick read (a point p reads voxel
// floor(p + 0.5)): one majorant serves both interpolation types. Delta tracking and
// ratio tracking use it as their majorant; sweeps and the brute force skip
// samples in bricks whose majorant is 0 (empty space).
//
// With the majorants, how far empty space extends around every brick (vsEmptySpaceDistance.h),
// for the render kernel to cross it in one step, and a lower bound of the extinction per brick
// (the control of residual and decomposition tracking); the render kernel reads all three of a
// brick in one load (TrackingImage).
//
// Two steps so each change does only the work it needs: the scalar range of every
// brick (a device pass over the voxels, on a data change) and the majorants from
// those ranges and the transfer function (host, on a transfer-function change).
//
// With an extinction factor per voxel (the gradient opacity, vsDeviceVolume.h SetFactor), a
// sample's extinction is sigma_t(s) x g, g interpolated from the same footprint of voxels as s:
// the brick majorant is then the brick's max sigma_t x its max g (and the control min x min),
// each widened by a few ulps for the rounding of the interpolation (SetFactor).
#ifndef vsMajorantGrid_h
#define vsMajorantGrid_h

#include "vissweepCoreModule.h"

#include <array>
#include <memory>
#include <vector>

namespace vs
{
class BrickRanges;
class Context;
class DeviceVolume;
class Image3D;
struct TransferFunctionSamples;

class VISSWEEPCORE_EXPORT MajorantGrid
{
public:
  static constexpr uint32_t DefaultBrickSize = 8;
  MajorantGrid(std::shared_ptr<Context> context, uint32_t brickSize = DefaultBrickSize);
  ~MajorantGrid();

  /** Recomputes the scalar range of every brick (after the volume's data changed): a device pass over
   *  the volume, or, given the scalars the volume was made from (x fastest), the same ranges on the
   *  host, which is ~10x faster than lavapipe's pass and lets the first frame skip it. */
  void UpdateRanges(const DeviceVolume& volume, const float* hostScalars = nullptr);
  /** The same from brick ranges the host made while the volume uploaded (vsBrickRanges.h: every
   *  slice added, the volume's dims and this grid's brick size). */
  void UpdateRanges(const DeviceVolume& volume, const BrickRanges& ranges);
  /** The extinction factor per voxel (the volume's dims, as given to UpdateRanges), or none
   *  (nullptr): its range per brick over the same footprint as the scalars'. Call before
   *  UpdateMajorants, after UpdateRanges (which drops the factor: new data, new factor). */
  void SetFactor(const float* factor);
  bool HasFactor() const { return !this->FactorRanges_.empty(); }
  /** Recomputes the majorants from the ranges (after the transfer function changed) and uploads them. */
  void UpdateMajorants(const TransferFunctionSamples& tf);

  const Image3D& Image() const { return *this->Image_; }
  /** Per brick: a lower bound of the extinction in it (the smallest the transfer function gives
   *  any scalar of the brick's range; 0 where a voxel is not finite): residual and decomposition
   *  tracking's control. */
  const std::vector<float>& Controls() const { return this->Controls_; }
  /** What the render kernel's majorant walk reads of a brick, in one load (rgba32f): the majorant,
   *  the control, the empty-space distance (below), 0. */
  const Image3D& TrackingImage() const { return *this->TrackingImage_; }
  /** Per brick: 0 where the majorant is not 0, else the chessboard distance in bricks to the
   *  nearest brick where it is not (EmptySpaceDistance, capped at kMaxEmptyDistance). */
  const std::vector<float>& EmptyDistances() const { return this->EmptyDistances_; }
  static constexpr uint32_t kMaxEmptyDistance = 1u << 16;
  std::array<uint32_t, 3> Bricks() const { return this->Bricks_; }
  uint32_t BrickSize() const { return this->BrickSize_; }
  const std::vector<float>& Majorants() const { return this->Majorants_; }
  /** Per brick: the scalar range's min and max ((1, 0) where no voxel is finite), 1 where a voxel
   *  is not finite (else 0), 0. */
  const std::vector<float>& Ranges() const { return this->Ranges_; }
  /** Fraction of bricks with majorant 0. */
  double EmptyFraction() const;
  float MaxMajorant() const;
  /** Device seconds of the last range pass (0 when the host computed the ranges). */
  double LastSeconds() const { return this->LastSeconds_; }
  /** Host seconds of the last range computation on the host (0 when the device did it). */
  double LastHostSeconds() const { return this->LastHostSeconds_; }
  /** Times each step ran (to test that work is skipped). */
  uint64_t RangeUpdates() const { return this->RangeUpdates_; }
  uint64_t MajorantUpdates() const { return this->MajorantUpdates_; }

private:
  // After new ranges: the images sized to `bricks`, the majorants and factor dropped.
  void SetRanges(std::array<uint32_t, 3> bricks);

  std::shared_ptr<Context> Context_;
  uint32_t BrickSize_;
  std::array<uint32_t, 3> Bricks_{ { 0, 0, 0 } };
  std::vector<float> Ranges_; // min, max, non-finite flag, 0 per brick
  std::vector<float> FactorRanges_; // min, max of the factor per brick (empty: no factor)
  std::array<uint32_t, 3> Dims_{ { 0, 0, 0 } };
  std::vector<float> Majorants_, Controls_;
  std::unique_ptr<Image3D> Image_, TrackingImage_;
  std::vector<float> EmptyDistances_;
  double LastSeconds_ = 0.0, LastHostSeconds_ = 0.0;
  uint64_t RangeUpdates_ = 0, MajorantUpdates_ = 0;
};
}

#endif
