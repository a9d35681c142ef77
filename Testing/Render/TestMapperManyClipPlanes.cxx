// More clipping planes than 6 (issue 14): planes that clip nothing of the volume are dropped on the
// host (never an error, whatever their number), and up to 8 planes that cut it (what
// vtkGPUVolumeRayCastMapper supports) reach the render, the sweeps and the emission-absorption
// mode. Checked bit for bit with a fixed seed: one plane x <= 9 alone, the same plane with 12
// planes that keep the whole volume, and 8 nested cutting planes x <= 9, 9.5, ... 12.5 (the
// tightest decides every ray's interval, so the same floats) give the same image, with TwoStep
// (so the sweeps see the planes too). 9 cutting planes are an error, logged once, naming the count.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using vstest::Ball;
using vstest::Check;

namespace
{

void AddPlane(vtkPlaneCollection* planes, double ox, double oy, double oz, double nx, double ny, double nz)
{
  vtkNew<vtkPlane> p;
  p->SetOrigin(ox, oy, oz);
  p->SetNormal(nx, ny, nz);
  planes->AddItem(p);
}

std::vector<float> Radiance(vtkVisibilitySweepVolumeMapper* m)
{
  std::vector<float> out;
  vtkImageData* r = m->GetRadiance();
  if (!r)
  {
    return out;
  }
  vtkDataArray* a = r->GetPointData()->GetArray("Radiance");
  vtkDataArray* alpha = r->GetPointData()->GetArray("Alpha");
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    out.insert(out.end(), { float(a->GetComponent(i, 0)), float(a->GetComponent(i, 1)), float(a->GetComponent(i, 2)),
                            float(alpha->GetComponent(i, 0)) });
  }
  return out;
}
}

int TestMapperManyClipPlanes(int, char*[])
{
  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(Ball(24));
  m->SetSamplingStrategyToTwoStep();
  m->ProgressiveVisibilityOff();
  m->SetSamplesPerFrame(4);
  m->SetMaximumSamples(4);
  m->SetSeed(7);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.8, 0.7);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(32, 32);
  win->AddRenderer(ren);
  ren->ResetCamera();

  auto render = [&](vtkPlaneCollection* planes, const char* what) {
    m->SetClippingPlanes(planes);
    win->Render();
    Check(std::string(m->GetLastError()).empty(), std::string(what) + " renders: " + m->GetLastError());
    return Radiance(m);
  };

  vtkNew<vtkPlaneCollection> none;
  const std::vector<float> full = render(none, "no planes");
  vtkNew<vtkPlaneCollection> one;
  AddPlane(one, 9.0, 0.0, 0.0, -1.0, 0.0, 0.0); // keeps x <= 9
  const std::vector<float> cut = render(one, "one plane");
  Check(!cut.empty() && cut != full, "the plane cuts the ball");

  vtkNew<vtkPlaneCollection> many; // the plane and 12 that keep the whole volume (bounds 0..23)
  AddPlane(many, 9.0, 0.0, 0.0, -1.0, 0.0, 0.0);
  for (int k = 0; k < 12; ++k)
  {
    const double s = k % 2 ? 1.0 : -1.0;
    AddPlane(many, k % 3 == 0 ? (s > 0 ? -1.0 - k : 24.0 + k) : 0.0, k % 3 == 1 ? (s > 0 ? -1.0 - k : 24.0 + k) : 0.0,
      k % 3 == 2 ? (s > 0 ? -1.0 - k : 24.0 + k) : 0.0, k % 3 == 0 ? s : 0.0, k % 3 == 1 ? s : 0.0,
      k % 3 == 2 ? s : 0.0);
  }
  render(none, "no planes again"); // so the next image is accumulated afresh
  Check(render(many, "13 planes, 12 of them clipping nothing") == cut,
    "12 planes that clip nothing change nothing (bit for bit)");

  vtkNew<vtkPlaneCollection> nested; // 8 cutting planes, x <= 9 the tightest
  for (int k = 7; k >= 0; --k)
  {
    AddPlane(nested, 9.0 + 0.5 * k, 0.0, 0.0, -1.0, 0.0, 0.0);
  }
  Check(render(nested, "8 cutting planes") == cut, "8 nested cutting planes clip as the tightest one (bit for bit)");
  Check(m->GetVisibilityUpdateCount() >= 1, "the sweeps ran with the planes");
  m->SetRenderModeToEmissionAbsorption();
  render(nested, "8 cutting planes, emission-absorption");
  m->SetRenderModeToMonteCarlo();
  Check(recorder->Errors.empty(), "no errors up to 8 cutting planes");

  AddPlane(nested, 13.0, 0.0, 0.0, -1.0, 0.0, 0.0); // a 9th
  m->SetClippingPlanes(nested);
  for (int k = 0; k < 3; ++k)
  {
    win->Render();
  }
  Check(std::string(m->GetLastError()).find("9 clipping planes cut the volume") != std::string::npos,
    std::string("9 cutting planes are an error naming the count: ") + m->GetLastError());
  Check(recorder->Errors.size() == 1, "logged once over 3 renders");
  return vstest::ExitCode();
}
