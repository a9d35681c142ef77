#include "vtkVisibilityGridFilter.h"

#include "vtkEnvironmentMapAlgorithm.h"

#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsDeviceVolume.h"
#include "vsEnvironmentMap.h"
#include "vsError.h"
#include "vsLightVolume.h"
#include "vsVisibilityGrid.h"
#include "vsVisibilityImage.h"
#include "vsVolumeInput.h"
#include "vsVolumeScene.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkVisibilityGridFilter);
vtkCxxSetObjectMacro(vtkVisibilityGridFilter, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkVisibilityGridFilter, ClippingPlanes, vtkPlaneCollection);

struct vtkVisibilityGridFilter::Internals
{
  std::unique_ptr<vs::VolumeScene> Scene;
  std::unique_ptr<vs::VisibilityGrid> Grid;
  /** The settings and planes the grid was computed with (empty: compute it again). A run that only
   *  changes the environment or its intensity keeps the grid and rebuilds the light volume. */
  std::vector<double> GridKey;
  /** The environment of input port 1 on the device, uploaded again when the image changes. */
  std::unique_ptr<vs::DeviceEnvironment> Environment;
  vtkMTimeType EnvironmentTime = 0;
  std::unique_ptr<vs::LightVolume> Light;

  /** The environment of `image` on the device with at least `side` texels a side. */
  const vs::DeviceEnvironment& UpdateEnvironment(const std::shared_ptr<vs::Context>& context, vtkImageData* image, int side)
  {
    if (!this->Environment || image->GetMTime() != this->EnvironmentTime || this->Environment->Size() < side)
    {
      this->Environment.reset();
      std::string error;
      std::shared_ptr<const vs::EnvironmentMap> map = vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(image, &error);
      if (!map)
      {
        throw vs::InputError("the environment input is not an environment map: " + error);
      }
      this->Environment = std::make_unique<vs::DeviceEnvironment>(context, *map, std::max(8, side));
      this->EnvironmentTime = image->GetMTime();
    }
    return *this->Environment;
  }
};

vtkVisibilityGridFilter::vtkVisibilityGridFilter()
  : FilterAngleFraction(vs::VisibilityGridParameters().FilterAngleFraction)
  , Impl(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

vtkVisibilityGridFilter::~vtkVisibilityGridFilter()
{
  this->SetVolumeProperty(nullptr);
  this->SetClippingPlanes(nullptr);
}

vtkMTimeType vtkVisibilityGridFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->VolumeProperty)
  {
    t = std::max(t, this->VolumeProperty->GetMTime());
  }
  if (this->ClippingPlanes)
  {
    t = std::max(t, this->ClippingPlanes->GetMTime());
    vtkPlane* plane;
    vtkCollectionSimpleIterator it;
    for (this->ClippingPlanes->InitTraversal(it); (plane = this->ClippingPlanes->GetNextPlane(it));)
    {
      t = std::max(t, plane->GetMTime());
    }
  }
  return t;
}

double vtkVisibilityGridFilter::GetNumberOfComputedDirections()
{
  return this->Impl->Grid ? double(this->Impl->Grid->DirectionsComputed()) : 0.0;
}

double vtkVisibilityGridFilter::GetNumberOfIrradianceBuilds()
{
  return this->Impl->Light ? double(this->Impl->Light->Builds()) : 0.0;
}

void vtkVisibilityGridFilter::SetEnvironmentConnection(vtkAlgorithmOutput* port)
{
  this->SetInputConnection(1, port);
}

void vtkVisibilityGridFilter::SetEnvironmentData(vtkImageData* environment)
{
  this->SetInputData(1, environment);
}

int vtkVisibilityGridFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkVisibilityGridFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The output extent follows from the cell count, known only once the data is here: advertise
  // the input's extent so that the executive asks for the whole input, then set the real one.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  int dims[3];
  for (int i = 0; i < 3; ++i)
  {
    dims[i] = std::max(1, extent[2 * i + 1] - extent[2 * i] + 1);
  }
  vs::VolumeGeometry g = vs::VolumeGeometry::Axis(
    { { uint32_t(dims[0]), uint32_t(dims[1]), uint32_t(dims[2]) } });
  // The same cells the grid will have on the device (capped by its largest 3D image). Without a
  // device (no driver, VISSWEEP_DEVICE naming none) the request fails with the reason: an
  // exception must not leave a VTK pipeline call (it ended in std::terminate, issue 13).
  std::array<uint32_t, 3> cells;
  try
  {
    cells = vs::SweepPlan::CellCount(g, std::max(1.0, this->VoxelsPerCell),
      uint32_t(std::max(1, this->DirectionResolution)), vs::Context::Default()->Info().MaxImageDimension3D);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "cannot compute the visibility grid: " << e.what());
    return 0;
  }
  int outExtent[6] = { 0, int(cells[0]) - 1, 0, int(cells[1]) - 1, 0, int(cells[2]) - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), outExtent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  return 1;
}

int vtkVisibilityGridFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole volume, and the whole environment map when there is one.
  for (int port = 0; port < 2; ++port)
  {
    if (vtkInformation* inInfo = inputVector[port]->GetInformationObject(0))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    }
  }
  return 1;
}

int vtkVisibilityGridFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* environment = vtkImageData::GetData(inputVector[1]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  if (!this->VolumeProperty)
  {
    vtkErrorMacro(<< "no volume property: SetVolumeProperty() gives the transfer function");
    return 0;
  }
  vs::VisibilityGridParameters p;
  p.DirectionResolution = uint32_t(std::max(0, this->DirectionResolution));
  p.VoxelsPerCell = this->VoxelsPerCell;
  p.KernelResolution = uint32_t(this->KernelResolution);
  p.StepSize = this->StepSize;
  p.Filtering = this->Filtering;
  p.FilterAngleFraction = this->FilterAngleFraction;
  p.Algorithm = this->Method == BruteForce ? vs::VisibilityGridParameters::Method::BruteForce
                                           : vs::VisibilityGridParameters::Method::Sweep;
  p.BruteForceSamples = uint32_t(this->BruteForceSamples);
  p.NearestInterpolation = this->VolumeProperty->GetInterpolationType() == VTK_NEAREST_INTERPOLATION;
  p.StorageFormat = this->StorageFormat == Float32 ? vs::VisibilityGridParameters::Format::Float32
    : this->StorageFormat == Unorm16               ? vs::VisibilityGridParameters::Format::Unorm16
                                                   : vs::VisibilityGridParameters::Format::Unorm8;
  try
  {
    p.Validate();
    auto ctx = vs::Context::Default();
    if (!this->Impl->Scene)
    {
      this->Impl->Scene = std::make_unique<vs::VolumeScene>(ctx);
      this->Impl->Grid = std::make_unique<vs::VisibilityGrid>(ctx);
    }
    vtkDataArray* scalars = input ? input->GetPointData()->GetScalars() : nullptr;
    auto changes = this->Impl->Scene->Update(input, scalars, this->VolumeProperty, nullptr, this->DensityScale);
    if (changes.Data && this->Impl->Scene->Volume().NonFiniteCount())
    {
      vtkWarningMacro(<< this->Impl->Scene->Volume().NonFiniteCount()
                      << " voxels are NaN or infinite; they are treated as zero extinction");
    }
    std::vector<glm::dvec4> planes;
    if (this->ClippingPlanes)
    {
      vtkPlane* plane;
      vtkCollectionSimpleIterator it;
      for (this->ClippingPlanes->InitTraversal(it); (plane = this->ClippingPlanes->GetNextPlane(it));)
      {
        double n[3], o[3];
        plane->GetNormal(n);
        plane->GetOrigin(o);
        planes.emplace_back(n[0], n[1], n[2], -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2]));
      }
    }
    const vs::VolumeScene& scene = *this->Impl->Scene;
    planes = vs::EffectiveClipPlanes(planes, scene.Geometry()); // only those that cut the volume count
    // The grid is computed again when its settings, planes or extinction changed (the filter also
    // runs for a new environment or intensity, which change only the light volume).
    std::vector<double> key = { double(p.DirectionResolution), p.VoxelsPerCell, double(p.KernelResolution),
      p.StepSize, double(p.Filtering), p.FilterAngleFraction, double(this->Method), double(p.BruteForceSamples),
      double(this->StorageFormat), double(p.NearestInterpolation) };
    for (const glm::dvec4& plane : planes)
    {
      key.insert(key.end(), { plane.x, plane.y, plane.z, plane.w });
    }
    if (key != this->Impl->GridKey || changes.Data || changes.Extinction || changes.Geometry ||
      changes.Interpolation || !this->Impl->Grid->Valid())
    {
      this->Impl->GridKey.clear();
      vs::VisibilityGrid::CheckFits(*ctx, scene.Geometry(), p);
      this->UpdateProgress(0.0);
      this->Impl->Grid->Compute(scene.Volume(), scene.TF(), scene.Majorants(), scene.Geometry(), planes, p, {},
        [this](double f) { this->UpdateProgress(f); });
      this->LastDeviceSeconds = this->Impl->Grid->LastSeconds();
      this->Impl->GridKey = key;
    }
    vs::VisibilityGridToImage(*this->Impl->Grid, scene.Geometry(), output);
    if (environment)
    {
      if (!this->Impl->Light)
      {
        this->Impl->Light = std::make_unique<vs::LightVolume>(ctx);
      }
      const vs::DeviceEnvironment& env =
        this->Impl->UpdateEnvironment(ctx, environment, int(this->Impl->Grid->Side()));
      this->Impl->Light->Update(*this->Impl->Grid, env, this->EnvironmentIntensity);
      vs::LightVolumeToImage(*this->Impl->Light, output);
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    this->Impl->GridKey.clear(); // the next run computes the grid again
    vtkErrorMacro(<< "cannot compute the visibility grid: " << e.what());
    return 0;
  }
}

void vtkVisibilityGridFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DirectionResolution: " << this->DirectionResolution << "\n";
  os << indent << "VoxelsPerCell: " << this->VoxelsPerCell << "\n";
  os << indent << "KernelResolution: " << this->KernelResolution << "\n";
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "Filtering: " << this->Filtering << "\n";
  os << indent << "FilterAngleFraction: " << this->FilterAngleFraction << "\n";
  os << indent << "Method: " << this->GetMethodAsString() << "\n";
  os << indent << "BruteForceSamples: " << this->BruteForceSamples << "\n";
  os << indent << "StorageFormat: " << this->GetStorageFormatAsString() << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "EnvironmentIntensity: " << this->EnvironmentIntensity << "\n";
  os << indent << "Environment: " << (this->GetNumberOfInputConnections(1) > 0 ? "connected" : "(none)") << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "ClippingPlanes: " << this->ClippingPlanes << "\n";
  os << indent << "NumberOfComputedDirections: " << this->GetNumberOfComputedDirections() << "\n";
  os << indent << "LastDeviceSeconds: " << this->LastDeviceSeconds << "\n";
  os << indent << "NumberOfIrradianceBuilds: " << this->GetNumberOfIrradianceBuilds() << "\n";
}
