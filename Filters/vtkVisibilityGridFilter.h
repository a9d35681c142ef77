/**
 * @class   vtkVisibilityGridFilter
 * @brief   The 5D visibility grid of a volume (von Radziewsky et al. 2017): transmittance towards D x D directions per cell.
 *
 * Input: a vtkImageData volume with point scalars and, via SetVolumeProperty(), the
 * transfer function that turns them into extinction (sigma_t = -ln(1 - alpha) / unit
 * distance, as VisSweep's renderer; the property's InterpolationType chooses nearest, VTK's
 * default, or trilinear reconstruction of the scalar). Output: a vtkImageData whose points are the
 * visibility cells' centres, aligned with the input (origin, spacing, direction):
 * - point array "Visibility": D*D components, V(cell, direction n), direction n being
 *   the centre of texel (n % D, n / D) of the equal-area octahedral map (field data
 *   "Directions" lists them);
 * - point scalars "MeanVisibility": the mean over the sphere (1 - ambient occlusion);
 * - point array "Irradiance", when an environment is given (input port 1, SetEnvironmentConnection):
 *   3 components (linear RGB), the environment light reaching the cell, the light volume
 *   sum_n V(cell, n) E_n over the D x D directions, E_n the environment's radiance (times
 *   EnvironmentIntensity) integrated over the solid angle 4 pi / D^2 of direction n's texel
 *   (radiance x sr; under a constant sky of radiance L and no occluder, 4 pi L). For the renderer's
 *   isotropic phase function the single-scattered radiance at the cell is albedo x sigma_t / (4 pi) x
 *   Irradiance. A new environment or intensity rebuilds only this array, not the grid;
 * - field data with the parameters and the device time.
 *
 * Computed on the Vulkan device by plane sweeps (Method Sweep, default) or by brute-force
 * ray marching (BruteForce, the reference). Clipping planes remove occluders on their
 * negative side. Progress events per batch of directions.
 *
 * @code{.py}
 * f = vissweep.vtkVisibilityGridFilter()
 * f.SetInputConnection(reader.GetOutputPort())
 * f.SetVolumeProperty(volume_property)
 * f.Update()   # f.GetOutput().GetPointData().GetArray("Visibility")
 * f.SetEnvironmentConnection(env_reader.GetOutputPort())  # adds "Irradiance"
 * @endcode
 */
#ifndef vtkVisibilityGridFilter_h
#define vtkVisibilityGridFilter_h

#include "vissweepFiltersModule.h"
#include "vtkImageAlgorithm.h"

#include <memory>

class vtkAlgorithmOutput;
class vtkPlaneCollection;
class vtkVolumeProperty;

class VISSWEEPFILTERS_EXPORT vtkVisibilityGridFilter : public vtkImageAlgorithm
{
public:
  static vtkVisibilityGridFilter* New();
  vtkTypeMacro(vtkVisibilityGridFilter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    Sweep = 0,
    BruteForce = 1
  };
  enum StorageFormats
  {
    Unorm8 = 0,
    Unorm16 = 1,
    Float32 = 2
  };

  /** The transfer function (component 0) and unit distance that define extinction. */
  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);

  ///@{
  /** The environment (input port 1, optional): a vtkEnvironmentMapReader / vtkEnvironmentMapSource
   *  output, as vtkVisibilitySweepVolumeMapper takes it. With one, the output has "Irradiance". */
  void SetEnvironmentConnection(vtkAlgorithmOutput* port);
  void SetEnvironmentData(vtkImageData* environment);
  ///@}
  ///@{
  /** Scales the environment's radiance in "Irradiance" (the mapper's EnvironmentIntensity). Default 1. */
  vtkSetClampMacro(EnvironmentIntensity, double, 0.0, VTK_FLOAT_MAX);
  vtkGetMacro(EnvironmentIntensity, double);
  ///@}

  /** Planes whose negative side holds no occluders (as vtkVolumeMapper's clipping planes). */
  void SetClippingPlanes(vtkPlaneCollection* planes);
  vtkGetObjectMacro(ClippingPlanes, vtkPlaneCollection);

  ///@{
  /** Directions per side of the octahedral map (4, 8 or 16). Default 8. */
  vtkSetMacro(DirectionResolution, int);
  vtkGetMacro(DirectionResolution, int);
  ///@}
  ///@{
  /** Voxels per visibility cell along each axis (>= 1). Default 4. */
  vtkSetMacro(VoxelsPerCell, double);
  vtkGetMacro(VoxelsPerCell, double);
  ///@}
  ///@{
  /** Kernel rays along the longer side of the projected volume; 0 (default) = automatic: one
   *  per voxel of the longest axis, 2 to 128. */
  vtkSetClampMacro(KernelResolution, int, 0, 1 << 14);
  vtkGetMacro(KernelResolution, int);
  ///@}
  ///@{
  /** Ray-marching step in world units; 0 (default) = one voxel. */
  vtkSetMacro(StepSize, double);
  vtkGetMacro(StepSize, double);
  ///@}
  ///@{
  /** Sweep-space filtering (Sec. 8). Default on. */
  vtkSetMacro(Filtering, bool);
  vtkGetMacro(Filtering, bool);
  vtkBooleanMacro(Filtering, bool);
  ///@}
  ///@{
  /** beta / alpha of Eq. 9. Default as VisibilityGridParameters. */
  vtkSetMacro(FilterAngleFraction, double);
  vtkGetMacro(FilterAngleFraction, double);
  ///@}
  ///@{
  /** Sweep (default) or BruteForce. */
  vtkSetClampMacro(Method, int, Sweep, BruteForce);
  vtkGetMacro(Method, int);
  void SetMethodToSweep() { this->SetMethod(Sweep); }
  void SetMethodToBruteForce() { this->SetMethod(BruteForce); }
  const char* GetMethodAsString() { return this->Method == BruteForce ? "BruteForce" : "Sweep"; }
  ///@}
  ///@{
  /** BruteForce: rays per cell and direction (random points of the cell and directions of the texel). */
  vtkSetClampMacro(BruteForceSamples, int, 1, 4096);
  vtkGetMacro(BruteForceSamples, int);
  ///@}
  ///@{
  /** Device storage of the grid before it is read back (the output is float). Default Unorm8. */
  vtkSetClampMacro(StorageFormat, int, Unorm8, Float32);
  vtkGetMacro(StorageFormat, int);
  void SetStorageFormatToUnorm8() { this->SetStorageFormat(Unorm8); }
  void SetStorageFormatToUnorm16() { this->SetStorageFormat(Unorm16); }
  void SetStorageFormatToFloat32() { this->SetStorageFormat(Float32); }
  const char* GetStorageFormatAsString()
  {
    return this->StorageFormat == Float32 ? "Float32" : this->StorageFormat == Unorm16 ? "Unorm16" : "Unorm8";
  }
  ///@}
  ///@{
  /** Multiplies the extinction. Default 1. */
  vtkSetMacro(DensityScale, double);
  vtkGetMacro(DensityScale, double);
  ///@}

  /** Directions computed since the filter was made (sweeps or brute force). */
  double GetNumberOfComputedDirections();
  /** Device seconds of the last computation. */
  vtkGetMacro(LastDeviceSeconds, double);
  /** Times "Irradiance" (the light volume) was built since the filter was made. */
  double GetNumberOfIrradianceBuilds();

  vtkMTimeType GetMTime() override;

protected:
  vtkVisibilityGridFilter();
  ~vtkVisibilityGridFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkVolumeProperty* VolumeProperty = nullptr;
  vtkPlaneCollection* ClippingPlanes = nullptr;
  int DirectionResolution = 8;
  double VoxelsPerCell = 4.0;
  int KernelResolution = 0;
  double StepSize = 0.0;
  bool Filtering = true;
  double FilterAngleFraction;
  int Method = Sweep;
  int BruteForceSamples = 1;
  int StorageFormat = Unorm8;
  double DensityScale = 1.0;
  double EnvironmentIntensity = 1.0;
  double LastDeviceSeconds = 0.0;

private:
  vtkVisibilityGridFilter(const vtkVisibilityGridFilter&) = delete;
  void operator=(const vtkVisibilityGridFilter&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
