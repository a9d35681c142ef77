// A label map under the vtkVolumeProperty's InterpolationType (issue 14): labels 1 and 3 side by
// side, coloured red (1), green (2) and blue (3). Under nearest interpolation (VTK's default) no
// sample may ever read a label 2, so no pixel has any green, in the Monte Carlo mode (the albedo
// is the colour: its green radiance is exactly 0) and in the emission-absorption mode (the window's
// green channel is exactly 0), with and without the sweeps (TwoStep). Under linear interpolation
// the boundary shows the blended label 2 (green) as before. Nearest is honoured, so it warns nothing.
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
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <iostream>
#include <string>

using vstest::Check;

namespace
{
// Labels 1 (x < 8) and 3 (x >= 8) of a 16 x 8 x 8 volume.
vtkSmartPointer<vtkImageData> Labels()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(16, 8, 8);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(16 * 8 * 8);
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x)
        a->SetValue((z * 8 + y) * 16 + x, x < 8 ? 1.0f : 3.0f);
  image->GetPointData()->SetScalars(a);
  return image;
}

struct Colours
{
  double Red = 0.0, Green = 0.0, Blue = 0.0; // the largest value of each channel over the image
};

Colours Largest(vtkDataArray* a, int components)
{
  Colours c;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    c.Red = std::max(c.Red, a->GetComponent(i, 0));
    c.Green = std::max(c.Green, a->GetComponent(i, 1));
    c.Blue = std::max(c.Blue, a->GetComponent(i, 2));
  }
  (void)components;
  return c;
}
}

int TestMapperNearestLabels(int, char*[])
{
  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(Labels());
  m->SetEnvironmentVisible(false); // the white sky would add green to the background
  m->SetSamplesPerFrame(8);
  m->SetMaximumSamples(8);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(1.0, 0.9);
  opacity->AddPoint(3.0, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(1.0, 1.0, 0.0, 0.0);
  color->AddRGBPoint(2.0, 0.0, 1.0, 0.0);
  color->AddRGBPoint(3.0, 0.0, 0.0, 1.0);
  vtkNew<vtkVolumeProperty> property; // VTK's default: nearest interpolation
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(0.25);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(64, 32);
  win->AddRenderer(ren);
  ren->GetActiveCamera()->SetPosition(7.5, 3.5, 40.0); // looking down -z at the boundary x = 7.5
  ren->GetActiveCamera()->SetFocalPoint(7.5, 3.5, 3.5);
  ren->ResetCamera();

  auto monteCarlo = [&](const char* what) {
    m->SetRenderModeToMonteCarlo();
    win->Render();
    Check(std::string(m->GetLastError()).empty(), std::string(what) + " renders: " + m->GetLastError());
    vtkImageData* r = m->GetRadiance();
    if (!r)
    {
      Check(false, std::string(what) + " has a radiance image");
      return Colours();
    }
    Colours c = Largest(r->GetPointData()->GetArray("Radiance"), 3);
    std::cout << what << ": largest radiance red " << c.Red << " green " << c.Green << " blue " << c.Blue << "\n";
    return c;
  };
  auto emissionAbsorption = [&](const char* what) {
    m->SetRenderModeToEmissionAbsorption();
    win->Render();
    Check(std::string(m->GetLastError()).empty(), std::string(what) + " renders: " + m->GetLastError());
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(win);
    grab->ShouldRerenderOff();
    grab->Update();
    Colours c = Largest(grab->GetOutput()->GetPointData()->GetScalars(), 3);
    std::cout << what << ": largest pixel red " << c.Red << " green " << c.Green << " blue " << c.Blue << "\n";
    return c;
  };

  for (bool sweeps : { false, true })
  {
    if (sweeps)
    {
      m->SetSamplingStrategyToTwoStep();
      m->ProgressiveVisibilityOff(); // the grid swept before the frame
    }
    else
    {
      m->SetSamplingStrategyToEnvironment();
    }
    const std::string strategy = sweeps ? " (TwoStep)" : " (Environment)";
    property->SetInterpolationTypeToNearest();
    Colours n = monteCarlo(("Monte Carlo, nearest" + strategy).c_str());
    Check(n.Red > 0.05 && n.Blue > 0.05, "Monte Carlo, nearest" + strategy + ": labels 1 and 3 are seen");
    Check(n.Green == 0.0, "Monte Carlo, nearest" + strategy + ": no pixel shows label 2");
    property->SetInterpolationTypeToLinear();
    Colours l = monteCarlo(("Monte Carlo, linear" + strategy).c_str());
    Check(l.Green > 0.05, "Monte Carlo, linear" + strategy + ": the boundary blends the labels, as before");
  }
  if (m->GetSamplingStrategy() == vtkVisibilitySweepVolumeMapper::TwoStep)
  {
    Check(m->GetVisibilityUpdateCount() >= 2, "the grid was swept again when the interpolation changed");
  }

  property->SetInterpolationTypeToNearest();
  Colours n = emissionAbsorption("emission-absorption, nearest");
  Check(n.Red > 20 && n.Blue > 20, "emission-absorption, nearest: labels 1 and 3 are seen");
  Check(n.Green == 0.0, "emission-absorption, nearest: no pixel shows label 2");
  property->SetInterpolationTypeToLinear();
  Colours l = emissionAbsorption("emission-absorption, linear");
  Check(l.Green > 20, "emission-absorption, linear: the boundary blends the labels, as before");

  for (const auto& w : recorder->Warnings)
  {
    Check(w.find("nearest") == std::string::npos, "nearest interpolation is honoured, not warned about: " + w);
  }
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
