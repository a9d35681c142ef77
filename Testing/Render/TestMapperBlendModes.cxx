// The projection blend modes (issue 14) through the emission-absorption path, as
// vtkGPUVolumeRayCastMapper computes them, on a volume whose projections along the view are known:
// s(x, y, z) = x / 15 * h(z), h = 1 on the slices z = 7, 8 and 0.25 elsewhere (trilinear in z
// between them), an opacity of 1 and a grey colour ramp, seen along -z with a parallel camera.
// Per pixel, with m the maximum x / 15 of its ray:
//   MIP      colour(max s) x opacity = m
//   MinIP    0.25 m
//   average  mean over the ray of opacity x s normalised = m x (integral of h over [0, 15]) / 15 = 0.35 m
//   additive integral of opacity x s normalised per unit distance u = 8: m x 5.25 / 8 = 0.656 m
// MIP, MinIP, average and additive render the same image in either RenderMode (they are not light
// transport) and after one render IsConverged() is true.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using vstest::Check;

namespace
{
vtkSmartPointer<vtkImageData> Slab()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(16, 16, 16);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(16 * 16 * 16);
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x)
        a->SetValue((z * 16 + y) * 16 + x, float(x) / 15.0f * (z == 7 || z == 8 ? 1.0f : 0.25f));
  image->GetPointData()->SetScalars(a);
  return image;
}

// The window's red channel (0..255) per pixel.
std::vector<double> Grab(vtkRenderWindow* win)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(win);
  grab->ShouldRerenderOff();
  grab->Update();
  vtkDataArray* a = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<double> red(size_t(a->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    red[size_t(i)] = a->GetComponent(i, 0);
  }
  return red;
}
}

int TestMapperBlendModes(int, char*[])
{
  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(Slab());
  m->SetSampleDistance(0.25);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 1.0);
  opacity->AddPoint(1.0, 1.0);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(1.0, 1.0, 1.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(8.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(48, 48);
  win->AddRenderer(ren);
  vtkCamera* camera = ren->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(7.5, 7.5, 7.5);
  camera->SetPosition(7.5, 7.5, 60.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  ren->ResetCamera();

  auto render = [&](int blend, int mode) {
    m->SetBlendMode(blend);
    m->SetRenderMode(mode);
    win->Render();
    Check(std::string(m->GetLastError()).empty(), "renders: " + std::string(m->GetLastError()));
    Check(m->IsConverged(), "a projection is complete after one render");
    return Grab(win);
  };
  const int mc = vtkVisibilitySweepVolumeMapper::MonteCarlo, ea = vtkVisibilitySweepVolumeMapper::EmissionAbsorption;
  const std::vector<double> mip = render(vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, mc);
  const std::vector<double> minip = render(vtkVolumeMapper::MINIMUM_INTENSITY_BLEND, mc);
  const std::vector<double> average = render(vtkVolumeMapper::AVERAGE_INTENSITY_BLEND, mc);
  const std::vector<double> additive = render(vtkVolumeMapper::ADDITIVE_BLEND, mc);
  const std::vector<double> mipEA = render(vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, ea);

  struct Expected
  {
    const char* Name;
    const std::vector<double>* Image;
    double Ratio;
  };
  const Expected expected[] = { { "MinIP", &minip, 0.25 }, { "average", &average, 0.35 },
    { "additive", &additive, 5.25 / 8.0 } };
  double brightest = 0.0;
  int compared = 0;
  for (size_t i = 0; i < mip.size(); ++i)
  {
    brightest = std::max(brightest, mip[i]);
    Check(std::abs(mipEA[i] - mip[i]) <= 1.0, "MIP is the same projection in either render mode");
    if (mip[i] < 80.0)
    {
      continue;
    }
    ++compared;
    for (const Expected& e : expected)
    {
      const double want = e.Ratio * mip[i];
      if (std::abs((*e.Image)[i] - want) > 0.04 * want + 1.5)
      {
        Check(false, std::string(e.Name) + " at pixel " + std::to_string(i) + ": " + std::to_string((*e.Image)[i]) +
            ", expected " + std::to_string(want) + " (MIP " + std::to_string(mip[i]) + ")");
      }
    }
  }
  std::cout << "compared " << compared << " pixels; brightest MIP " << brightest << "\n";
  Check(compared > 300, "enough pixels to compare");
  Check(brightest > 240.0, "the MIP of the brightest column is the colour of s = 1");

  // Iso-surface: not supported, said once; composite renders as before.
  m->SetBlendModeToIsoSurface();
  m->SetRenderModeToMonteCarlo();
  m->SetSampleDistance(0.0); // the projections' step; set in the Monte Carlo mode it is warned about (issue 38)
  m->SetMaximumSamples(2);
  for (int k = 0; k < 3; ++k)
  {
    win->Render();
  }
  size_t iso = 0;
  for (const auto& w : recorder->Warnings)
  {
    iso += w.find("ISOSURFACE_BLEND") != std::string::npos;
  }
  Check(iso == 1, "iso-surface blend warns once over 3 renders");
  Check(recorder->Warnings.size() == 1, "the projections warned nothing");
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
