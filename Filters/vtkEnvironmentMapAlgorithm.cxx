#include "vtkEnvironmentMapAlgorithm.h"

#include "vsEnvironmentMap.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkEnvironmentMapAlgorithm::vtkEnvironmentMapAlgorithm()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkEnvironmentMapAlgorithm::~vtkEnvironmentMapAlgorithm() = default;

std::shared_ptr<const vs::EnvironmentMap> vtkEnvironmentMapAlgorithm::GetEnvironmentMap() const
{
  return this->Map;
}

double vtkEnvironmentMapAlgorithm::GetTotalPower()
{
  return this->Map ? this->Map->TotalPower() : 0.0;
}

vtkIdType vtkEnvironmentMapAlgorithm::GetBadTexels()
{
  return this->Map ? vtkIdType(this->Map->BadTexels) : 0;
}

int vtkEnvironmentMapAlgorithm::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int size = this->ComputeOutputSize();
  this->InformationFailed = size <= 0;
  // An unknown size (the error is reported) gives an empty extent, not a pipeline failure.
  int extent[6] = { 0, size - 1, 0, size - 1, 0, size > 0 ? 0 : -1 };
  const double s = size > 0 ? 1.0 / size : 1.0;
  double spacing[3] = { s, s, 1.0 };
  double origin[3] = { 0.5 * s, 0.5 * s, 0.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 3);
  return 1;
}

int vtkEnvironmentMapAlgorithm::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  this->Map.reset();
  output->Initialize();
  if (this->InformationFailed)
  {
    return 1; // already reported in RequestInformation
  }
  this->UpdateProgress(0.0);
  std::shared_ptr<vs::EnvironmentMap> map = this->ComputeMap();
  if (!map || map->Empty())
  {
    return 1; // reported by ComputeMap
  }
  if (map->BadTexels > 0)
  {
    vtkWarningMacro(<< this->DescribeSource() << ": " << map->BadTexels
                    << " pixels had a negative, NaN or infinite value (" << map->NonFiniteTexels
                    << " NaN or infinite); those values were replaced by 0.");
  }
  this->Map = map;
  FillImage(*map, output);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkEnvironmentMapAlgorithm::FillImage(const vs::EnvironmentMap& map, vtkImageData* image)
{
  image->Initialize();
  const int n = map.Size;
  if (n <= 0)
  {
    return;
  }
  const double s = 1.0 / n;
  image->SetExtent(0, n - 1, 0, n - 1, 0, 0);
  image->SetSpacing(s, s, 1.0);
  image->SetOrigin(0.5 * s, 0.5 * s, 0.0);
  const vtkIdType texels = vtkIdType(n) * n;

  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(texels);
  std::copy(map.Radiance.begin(), map.Radiance.end(), radiance->GetPointer(0));
  image->GetPointData()->SetScalars(radiance);

  vtkNew<vtkFloatArray> importance;
  importance->SetName("Importance");
  importance->SetNumberOfTuples(texels);
  const float* finest = map.Mip(map.Levels() - 1);
  std::copy(finest, finest + texels, importance->GetPointer(0));
  image->GetPointData()->AddArray(importance);

  vtkFieldData* fd = image->GetFieldData();
  vtkNew<vtkFloatArray> mips;
  mips->SetName("ImportanceMips");
  mips->SetNumberOfTuples(vtkIdType(map.ImportanceMips.size()));
  std::copy(map.ImportanceMips.begin(), map.ImportanceMips.end(), mips->GetPointer(0));
  fd->AddArray(mips);

  vtkNew<vtkIdTypeArray> bad;
  bad->SetName("BadTexels");
  bad->InsertNextValue(vtkIdType(map.BadTexels));
  fd->AddArray(bad);
  vtkNew<vtkIdTypeArray> nonFinite;
  nonFinite->SetName("NonFiniteTexels");
  nonFinite->InsertNextValue(vtkIdType(map.NonFiniteTexels));
  fd->AddArray(nonFinite);

  vtkNew<vtkDoubleArray> mean;
  mean->SetName("MeanRadiance");
  mean->SetNumberOfComponents(3);
  mean->InsertNextTuple3(map.MeanRadiance.x, map.MeanRadiance.y, map.MeanRadiance.z);
  fd->AddArray(mean);
  vtkNew<vtkDoubleArray> power;
  power->SetName("TotalPower");
  power->InsertNextValue(map.TotalPower());
  fd->AddArray(power);
}

bool vtkEnvironmentMapAlgorithm::IsEnvironmentMapImage(vtkImageData* image, std::string* error)
{
  auto fail = [error](const std::string& why) {
    if (error)
    {
      *error = why;
    }
    return false;
  };
  if (!image)
  {
    return fail("no image");
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] != dims[1] || dims[2] != 1 || !vs::EnvironmentMap::IsPowerOfTwo(dims[0]))
  {
    return fail("an octahedral environment map is N x N x 1 with N a power of two, not " +
      std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]));
  }
  vtkDataArray* radiance = image->GetPointData()->GetArray("Radiance");
  if (!radiance || radiance->GetNumberOfComponents() != 3 ||
    radiance->GetNumberOfTuples() != vtkIdType(dims[0]) * dims[1])
  {
    return fail("the image has no 3-component point array \"Radiance\" with one tuple per texel");
  }
  return true;
}

std::shared_ptr<const vs::EnvironmentMap> vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(
  vtkImageData* image, std::string* error)
{
  if (!IsEnvironmentMapImage(image, error))
  {
    return nullptr;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* radiance = image->GetPointData()->GetArray("Radiance");
  auto map = std::make_shared<vs::EnvironmentMap>(vs::EnvironmentMap::Allocate(dims[0]));
  const vtkIdType texels = radiance->GetNumberOfTuples();
  for (vtkIdType i = 0; i < texels; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      map->Radiance[3 * i + c] = float(radiance->GetComponent(i, c));
    }
  }
  map->Finalize();
  if (error)
  {
    error->clear();
  }
  return map;
}

void vtkEnvironmentMapAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Intensity: " << this->Intensity << "\n";
  if (this->Map)
  {
    os << indent << "Size: " << this->Map->Size << "\n";
    os << indent << "MeanRadiance: " << this->Map->MeanRadiance.x << " " << this->Map->MeanRadiance.y
       << " " << this->Map->MeanRadiance.z << "\n";
    os << indent << "TotalPower: " << this->Map->TotalPower() << "\n";
    os << indent << "BadTexels: " << this->Map->BadTexels << "\n";
  }
  else
  {
    os << indent << "Size: (not computed)\n";
  }
}
