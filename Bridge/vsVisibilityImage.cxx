#include "vsVisibilityImage.h"

#include "vsError.h"
#include "vsLightVolume.h"
#include "vsSweepPlan.h"
#include "vsVisibilityGrid.h"
#include "vsVolumeGeometry.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

namespace vs
{
void VisibilityGridToImage(const VisibilityGrid& grid, const VolumeGeometry& physical, vtkImageData* out)
{
  out->Initialize();
  const auto cells = grid.Cells();
  const glm::vec3 cs = grid.CellSize();
  const uint32_t side = grid.Side(), dd = side * side;
  // Cell (i,j,k) centre in index space: BoxMin + (c + 0.5) * cellSize.
  glm::dvec3 first = glm::dvec3(physical.BoxMin) + 0.5 * glm::dvec3(cs);
  glm::dvec3 origin = glm::dvec3(physical.IndexToWorld * glm::dvec4(first, 1.0));
  double spacing[3], direction[9];
  for (int c = 0; c < 3; ++c)
  {
    glm::dvec3 axis(physical.IndexToWorld[c]);
    double len = glm::length(axis);
    spacing[c] = len * cs[c];
    for (int r = 0; r < 3; ++r)
    {
      direction[3 * r + c] = len > 0 ? axis[r] / len : (r == c ? 1.0 : 0.0);
    }
  }
  out->SetDimensions(int(cells[0]), int(cells[1]), int(cells[2]));
  out->SetOrigin(origin.x, origin.y, origin.z);
  out->SetSpacing(spacing);
  out->SetDirectionMatrix(direction);

  std::vector<float> values = grid.Download();
  const vtkIdType n = vtkIdType(cells[0]) * cells[1] * cells[2];
  vtkNew<vtkFloatArray> visibility;
  visibility->SetName("Visibility");
  visibility->SetNumberOfComponents(int(dd));
  visibility->SetNumberOfTuples(n);
  std::copy(values.begin(), values.end(), visibility->GetPointer(0));
  vtkNew<vtkFloatArray> mean;
  mean->SetName("MeanVisibility");
  mean->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    // Equal-area directions: the mean over components is the mean over the sphere.
    double sum = 0.0;
    for (uint32_t d = 0; d < dd; ++d)
    {
      sum += values[size_t(i) * dd + d];
    }
    mean->SetValue(i, float(sum / dd));
  }
  out->GetPointData()->AddArray(visibility);
  out->GetPointData()->SetScalars(mean);

  vtkNew<vtkFloatArray> dirs;
  dirs->SetName("Directions");
  dirs->SetNumberOfComponents(3);
  dirs->SetNumberOfTuples(dd);
  for (uint32_t d = 0; d < dd; ++d)
  {
    glm::vec3 w = SweepPlan::Direction(d, grid.Parameters()); // the direction each texel was swept along
    dirs->SetTuple3(d, w.x, w.y, w.z);
  }
  out->GetFieldData()->AddArray(dirs);
  const auto& p = grid.Parameters();
  auto scalar = [&](const char* name, double v) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(v);
    out->GetFieldData()->AddArray(a);
  };
  scalar("DirectionResolution", p.DirectionResolution);
  scalar("VoxelsPerCell", p.VoxelsPerCell);
  scalar("KernelResolution", p.KernelResolution);
  scalar("StepSize", p.StepSize);
  scalar("Filtering", p.Filtering ? 1 : 0);
  scalar("FilterAngleFraction", p.FilterAngleFraction);
  scalar("BruteForceSamples", p.BruteForceSamples);
  scalar("DeviceSeconds", grid.LastSeconds());
  vtkNew<vtkStringArray> method;
  method->SetName("Method");
  method->InsertNextValue(p.Algorithm == VisibilityGridParameters::Method::Sweep ? "Sweep" : "BruteForce");
  out->GetFieldData()->AddArray(method);
}

void LightVolumeToImage(const LightVolume& light, vtkImageData* out)
{
  const auto cells = light.Cells();
  int dims[3];
  out->GetDimensions(dims);
  if (!light.Valid() || dims[0] != int(cells[0]) || dims[1] != int(cells[1]) || dims[2] != int(cells[2]))
  {
    throw InputError("the light volume was not built from this image's grid");
  }
  const std::vector<float> rgba = light.Download();
  const vtkIdType n = vtkIdType(cells[0]) * cells[1] * cells[2];
  vtkNew<vtkFloatArray> irradiance;
  irradiance->SetName("Irradiance");
  irradiance->SetNumberOfComponents(3);
  irradiance->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    irradiance->SetTypedTuple(i, &rgba[4 * size_t(i)]);
  }
  out->GetPointData()->AddArray(irradiance);
}
}
