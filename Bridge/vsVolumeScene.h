// vsVolumeScene.h — a VTK volume (image data + vtkVolumeProperty + prop matrix)
// turned into the core's device state: the scalar volume, the transfer-function
// table and the majorant grid. Update() redoes only what a change needs:
//   data changed            -> upload, brick ranges, majorants
//   extinction changed      -> table, majorants (opacity, unit distance, density scale)
//   only albedo changed     -> table
//   gradient opacity        -> factor volume (vsGradientOpacity.h), majorants (reported as Extinction)
// With new data the table is resampled over the new scalar range, so Extinction is reported
// even when the transfer function itself is unchanged; TransferFunction tells the two apart
// (a new time step under the same transfer function: Data without TransferFunction).
// and reports which of these happened, so callers (the mapper, the visibility grid
// filter, the tool) know whether visibility must be recomputed.
// Internal to VisSweep (hidden from the wrappers).
#ifndef vsVolumeScene_h
#define vsVolumeScene_h

#if !defined(__VTK_WRAP__)
#include "vissweepBridgeModule.h"
#include "vsPhaseTimes.h"
#include "vsVolumeGeometry.h"

#include "vtkType.h"

#include <cstdint>

#include <memory>
#include <string>
#include <vector>

class vtkDataArray;
class vtkImageData;
class vtkMatrix4x4;
class vtkVolumeProperty;

namespace vs
{
class Context;
class DeviceVolume;
class MajorantGrid;
class TransferFunctionTable;
struct TransferFunctionSamples;

class VISSWEEPBRIDGE_EXPORT VolumeScene
{
public:
  struct Changes
  {
    bool Data = false;       // the voxels were uploaded again
    bool Extinction = false; // sigma_t changed somewhere (data, opacity, unit distance, density scale)
    bool Albedo = false;     // the colour transfer function changed
    bool Geometry = false;   // the index <-> world transform changed (prop matrix, spacing, origin)
    bool TransferFunction = false; // the vtkVolumeProperty or the density scale changed (any column)
    bool Interpolation = false; // the property's InterpolationType changed (extinction between voxels)
  };

  explicit VolumeScene(std::shared_ptr<Context> context);
  ~VolumeScene();

  /** Brings the device state up to date. Throws vs::Error (or InputError with the reason
   *  for bad input: no scalars, several components, empty extent, empty transfer function). */
  Changes Update(vtkImageData* image, vtkDataArray* scalars, vtkVolumeProperty* property,
    vtkMatrix4x4* volumeMatrix, double densityScale);

  bool Ready() const { return this->Volume_ != nullptr; }
  const std::shared_ptr<Context>& GetContext() const { return this->Context_; }
  const DeviceVolume& Volume() const { return *this->Volume_; }
  const TransferFunctionTable& TF() const { return *this->TF_; }
  const MajorantGrid& Majorants() const { return *this->Majorants_; }
  const VolumeGeometry& Geometry() const { return this->Geometry_; }

  /** The largest extinction (per world unit) the renderer resolves in `geometry` (issue 13, item 4):
   *  the device holds positions along a ray to about FLT_EPSILON x the largest index x the largest
   *  voxel edge; a medium whose mean free path is shorter than kResolvedFreePaths of those steps
   *  scatters at points float rounds by more than the depth light penetrates, so a shadow ray
   *  starts inside the opaque medium half the time (at 1e9 the image was several percent dark,
   *  and at 1e20 the ball vanished). The table clamps extinction to this bound: the medium is
   *  opaque at it (a mean free path of 1/32 of that resolution), and so is its image.
   *  At most TransferFunctionSamples::kMaxExtinction. */
  static float MaxResolvedExtinction(const VolumeGeometry& geometry);
  /** The transfer function's table over scalars [smin, smax] as the scene renders it: extinction
   *  clamped to MaxResolvedExtinction(geometry). */
  static TransferFunctionSamples SampleRenderedTransferFunction(vtkVolumeProperty* property, float smin, float smax,
    double densityScale, const VolumeGeometry& geometry);
  static constexpr double kResolvedFreePaths = 32.0;
  float ExtinctionCap() const { return this->ExtinctionCap_; }

  /** Counters of the work done (for tests of the skip rules). */
  int Uploads() const { return this->Uploads_; }

  /** The property's InterpolationType as the shaders take it (sampling/interpolation.h:
   *  VS_INTERPOLATION_LINEAR or VS_INTERPOLATION_NEAREST). */
  uint32_t Interpolation() const { return this->Interpolation_; }
  int TableBuilds() const { return this->TableBuilds_; }
  /** Whether the extinction is scaled by the gradient-opacity factor (Volume().Factor() is set). */
  bool HasGradientOpacity() const { return !this->FactorSignature_.empty(); }
  /** The factor per voxel on the host (empty without one): the voxel picker's march. */
  const std::vector<float>& HostFactor() const { return this->HostFactor_; }
  /** Times the factor volume was computed or dropped (for tests and the render's signature). */
  int FactorBuilds() const { return this->FactorBuilds_; }
  /** Host seconds the last factor computation took (gradients, GO and upload). */
  double LastFactorSeconds() const { return this->LastFactorSeconds_; }
  /** The last Update()'s work by phase (vsPhaseTimes.h), host wall seconds: convert (the scalars to
   *  float), upload (the device volume and its 8-bit quads), ranges (the bricks' scalar ranges),
   *  factor, table, majorants; only the phases that ran. */
  const PhaseTimes& LastPhases() const { return *this->LastPhases_; }

private:
  std::shared_ptr<Context> Context_;
  std::unique_ptr<DeviceVolume> Volume_;
  std::unique_ptr<TransferFunctionTable> TF_;
  std::unique_ptr<MajorantGrid> Majorants_;
  VolumeGeometry Geometry_;
  vtkMTimeType DataTime_ = 0;
  vtkDataArray* Scalars_ = nullptr;
  vtkMTimeType PropertyTime_ = 0;
  double DensityScale_ = -1.0;
  float ExtinctionCap_ = -1.0f;
  int Uploads_ = 0, TableBuilds_ = 0, FactorBuilds_ = 0;
  std::vector<double> FactorSignature_; // vsGradientOpacity.h: empty = no factor
  std::vector<float> HostFactor_;
  double LastFactorSeconds_ = 0.0;
  uint32_t Interpolation_ = 0;
  std::unique_ptr<PhaseTimes> LastPhases_;
};
}
#endif

#endif
