#include "vsRadianceImage.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <algorithm>

namespace vs
{
void RadianceImage::Fill(vtkImageData* image, const std::vector<float>& mean, uint32_t w, uint32_t h,
  const std::vector<uint8_t>& environmentPixels, float opaqueAlpha)
{
  image->Initialize();
  image->SetDimensions(int(w), int(h), 1);
  vtkNew<vtkFloatArray> rgb;
  rgb->SetName("Radiance");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(vtkIdType(w) * h);
  vtkNew<vtkFloatArray> alpha;
  alpha->SetName("Alpha");
  alpha->SetNumberOfTuples(vtkIdType(w) * h);
  for (vtkIdType i = 0; i < vtkIdType(w) * h; ++i)
  {
    rgb->SetTuple3(i, mean[4 * i], mean[4 * i + 1], mean[4 * i + 2]);
    alpha->SetValue(i, environmentPixels.empty() || !environmentPixels[i] ? mean[4 * i + 3] : opaqueAlpha);
  }
  image->GetPointData()->SetScalars(rgb);
  image->GetPointData()->AddArray(alpha);
}

void RadianceImage::AddVariance(vtkImageData* image, std::vector<double> var,
  const std::vector<uint8_t>& environmentPixels, double alphaVariance)
{
  const double v = alphaVariance;
  if (!environmentPixels.empty())
  {
    for (size_t i = 0; i < environmentPixels.size() && 4 * i + 3 < var.size(); ++i)
    {
      if (environmentPixels[i])
      {
        var[4 * i + 3] = v;
      }
    }
  }
  vtkNew<vtkDoubleArray> array;
  array->SetName("Variance");
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(vtkIdType(var.size() / 4));
  std::copy(var.begin(), var.end(), array->GetPointer(0));
  image->GetPointData()->AddArray(array);
}
}
