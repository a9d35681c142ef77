// vsPooledExtinction.h — the coarse extinction volume the visibility sweeps march: sigma_t
// (post-classified at the voxels, times the gradient-opacity factor where there is one) pooled by
// the mean (or the max) over blocks of P^3 voxels, and the occupancy of its bricks, for skipping
// empty space (sweep_pool.comp, sweep_pool_occupancy.comp).
//
// Built at once (Ensure: a blocking sweep), or slab by slab within a time budget (Advance: the
// progressive grid, so that no frame waits for the whole build; on the 0.5 mm MRI the build is
// ~0.5 s of device time, ten frames' worth). The result is the same either way: every texel is a
// function of its block only.
#ifndef vsPooledExtinction_h
#define vsPooledExtinction_h

#include "vissweepCoreModule.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>

namespace vs
{
class Context;
class ComputePipeline;
class DeviceVolume;
class Image3D;
class MajorantGrid;
class TransferFunctionTable;

class VISSWEEPCORE_EXPORT PooledExtinction
{
public:
  explicit PooledExtinction(std::shared_ptr<Context> context);
  ~PooledExtinction();

  /** How to pool: P voxels per texel and axis (> 1), the mean or the max, and the cropping regions
   *  whose hidden voxels pool as 0. */
  struct Settings
  {
    uint32_t Factor = 2;
    bool Max = false;
    uint32_t CropFlags = 0;
    glm::vec3 CropLo{ 0.0f }, CropHi{ 0.0f };
  };

  /** Whether the pooled volume is complete and was built from these inputs. */
  bool IsCurrent(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const Settings& settings) const;
  /** Builds what is missing at once; returns its device seconds (0 when current). */
  double Ensure(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const Settings& settings);
  /** Builds the next slabs of pooled slices while their estimated device time (from the slabs
   *  before) fits budgetSeconds (the first slab whatever the budget, to learn its cost; later calls with less
   *  than a slab's estimated time build nothing), and the occupancy after the last;
   *  returns the device seconds spent (0 when current). New inputs restart the build. */
  double Advance(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const Settings& settings, double budgetSeconds);

  /** The pooled volume and its brick occupancy (valid once IsCurrent). */
  const Image3D& Pooled() const { return *this->Pooled_; }
  const Image3D& Occupancy() const { return *this->Occupancy_; }
  /** Completed builds since this object was made. */
  uint64_t Builds() const { return this->Builds_; }
  /** Estimated device seconds to finish the build in progress: its slices left at the measured
   *  seconds per slice; 0 when complete, and while unknown (no build started, or no slab built yet). */
  double RemainingSeconds() const;
  /** Whether an integer-coded volume is pooled from its quads (the default; the same bits as from its
   *  float image, which is then never made: vsDeviceVolume.h). Off: from the float image. */
  void SetVolumeQuads(bool on) { this->VolumeQuads_ = on; }
  /** Pooled texels per occupancy brick side: 8 voxels, as the majorant grid's bricks (at least 1). */
  static uint32_t BrickTexels(uint32_t factor);
  /** Pooled slices per slab (the pool dispatch's workgroup depth). */
  static constexpr uint32_t SlabSlices = 4;

private:
  /** What the pooled volume was built from. A DeviceVolume's data cannot change after upload, so
   *  new data is a new object (or, reusing an address, new majorant ranges: counted and hashed). */
  struct Key
  {
    const void* Volume = nullptr;
    const void* TF = nullptr;
    const void* Majorants = nullptr;
    uint64_t RangeUpdates = 0, MajorantUpdates = 0;
    size_t TFHash = 0, MajorantHash = 0;
    std::array<uint32_t, 3> Dims{ { 0, 0, 0 } };
    std::array<float, 2> Range{ { 0.0f, 0.0f } };
    uint64_t NonFinite = 0;
    uint64_t ExtinctionFactor = 0; // the volume's FactorSerial (the gradient opacity; 0: none)
    Settings Pooling;
    bool operator==(const Key& o) const;
  };
  static Key MakeKey(const DeviceVolume& volume, const TransferFunctionTable& tf, const MajorantGrid& majorants,
    const Settings& settings);
  void Start(const Key& key, const DeviceVolume& volume);
  /** Pools slices [z0, z1) of the pooled volume; returns its device seconds. */
  double PoolSlices(const DeviceVolume& volume, const TransferFunctionTable& tf, uint32_t z0, uint32_t z1);
  double Finish();

  std::shared_ptr<Context> Context_;
  std::shared_ptr<ComputePipeline> Pool_, OccupancyPipeline_;
  std::unique_ptr<Image3D> Pooled_, Occupancy_;
  std::unique_ptr<Image3D> NoImage_, NoQuads_; // placeholders for the volume binding not read
  Key Key_;              // of the build in progress or done
  bool Started_ = false; // Key_ describes a build (in progress unless Complete_)
  bool Complete_ = false;
  uint32_t NextSlice_ = 0;        // the first pooled slice not built yet
  double SecondsPerSlice_ = 0.0;  // measured on the slabs so far
  glm::ivec3 PooledDims_{ 0 }, Bricks_{ 0 };
  uint64_t Builds_ = 0;
  bool VolumeQuads_ = true;
  bool FromQuads_ = false; // the build in progress reads the quads (chosen at Start)
};
}

#endif
