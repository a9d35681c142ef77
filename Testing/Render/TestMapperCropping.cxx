// Cropping to a subvolume and clipping with a plane at the same place are two routes to
// the same image (the box the sweeps and the render use, against a half-space both
// test per sample): their Monte Carlo images must agree within their statistical error
// (per-pixel z-scores from the sample variances, independent seeds), and differ from
// the uncropped image.
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <vector>

namespace
{
enum class Cut
{
  None,
  Crop,
  Clip
};

struct Image
{
  std::vector<double> Mean, Variance; // red channel per pixel; variance of the mean
};

Image Render(vtkImageData* data, Cut cut, int seed)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.5);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
  color->AddRGBPoint(1.0, 0.9, 0.6, 0.4);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  vtkNew<vtkEnvironmentMapSource> env;
  env->SetTypeToSunDisk();
  env->SetSunAngularRadius(12.0);
  env->SetSunDirection(0.3, 1.0, 0.6);
  env->SetOctahedralSize(32);

  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(data);
  m->SetEnvironmentConnection(env->GetOutputPort());
  m->SetSeed(seed);
  m->SetSamplesPerFrame(128);
  m->SetMaximumSamples(256);
  double b[6];
  data->GetBounds(b);
  const double mid = 0.5 * (b[0] + b[1]) + 0.3; // between voxel centres
  if (cut == Cut::Crop)
  {
    m->CroppingOn();
    m->SetCroppingRegionPlanes(b[0], mid, b[2], b[3], b[4], b[5]);
  }
  else if (cut == Cut::Clip)
  {
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(mid, 0.0, 0.0);
    plane->SetNormal(-1.0, 0.0, 0.0); // keeps x <= mid
    m->AddClippingPlane(plane);
  }
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(32, 32);
  ren->ResetCamera();
  win->Render();
  win->Render();
  Image out;
  if (*m->GetLastError() || m->GetAccumulatedSamples() != 256)
  {
    std::cerr << "render failed: " << m->GetLastError() << " (" << m->GetAccumulatedSamples() << " spp)\n";
    return out;
  }
  vtkImageData* radiance = m->GetRadiance(true);
  auto* rgb = vtkFloatArray::SafeDownCast(radiance->GetPointData()->GetArray("Radiance"));
  vtkDataArray* var = radiance->GetPointData()->GetArray("Variance");
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    out.Mean.push_back(rgb->GetComponent(i, 0));
    out.Variance.push_back(var->GetComponent(i, 0) / 256.0);
  }
  return out;
}

struct ZStats
{
  int Pixels = 0;
  double MeanZ = 0.0, FractionAbove4 = 0.0;
};

ZStats Compare(const Image& a, const Image& b)
{
  ZStats s;
  int above = 0;
  for (size_t i = 0; i < a.Mean.size(); ++i)
  {
    const double v = a.Variance[i] + b.Variance[i];
    if (v <= 0.0)
    {
      continue;
    }
    const double z = (a.Mean[i] - b.Mean[i]) / std::sqrt(v);
    s.MeanZ += z;
    above += std::abs(z) > 4.0;
    ++s.Pixels;
  }
  if (s.Pixels)
  {
    s.MeanZ /= s.Pixels;
    s.FractionAbove4 = double(above) / s.Pixels;
  }
  return s;
}
}

int TestMapperCropping(int, char*[])
{
  // A soft ball, denser towards its centre, 20 x 18 x 16 voxels.
  vtkNew<vtkImageData> data;
  data->SetDimensions(20, 18, 16);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfTuples(20 * 18 * 16);
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 18; ++y)
      for (int x = 0; x < 20; ++x)
      {
        double r = std::sqrt(std::pow((x - 9.5) / 9.0, 2) + std::pow((y - 8.5) / 8.0, 2) + std::pow((z - 7.5) / 7.0, 2));
        values->SetValue((z * 18 + y) * 20 + x, float(std::max(0.0, 1.0 - r)));
      }
  data->GetPointData()->SetScalars(values);

  Image crop = Render(data, Cut::Crop, 1), clip = Render(data, Cut::Clip, 2), whole = Render(data, Cut::None, 3);
  if (crop.Mean.empty() || clip.Mean.empty() || whole.Mean.empty())
  {
    return EXIT_FAILURE;
  }
  ZStats same = Compare(crop, clip), different = Compare(crop, whole);
  std::cout << "crop vs clip: " << same.Pixels << " pixels, mean z " << same.MeanZ << ", |z| > 4: "
            << same.FractionAbove4 << "\ncrop vs whole: mean z " << different.MeanZ << ", |z| > 4: "
            << different.FractionAbove4 << "\n";
  int failures = 0;
  if (same.Pixels < 150 || std::abs(same.MeanZ) > 0.25 || same.FractionAbove4 > 0.01)
  {
    std::cerr << "FAILED: cropping and the equivalent clipping plane disagree\n";
    ++failures;
  }
  if (different.FractionAbove4 < 0.1)
  {
    std::cerr << "FAILED: cropping has no visible effect\n";
    ++failures;
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
