// A good VTK citizen (issue 14): settings VisSweep does not honour are warned about once per
// change, not once per Render() (counted with a WarningEvent observer across repeated
// renders), errors are logged once per change, cropping flags other than the subvolume render, the setters
// clamp or refuse, PrintSelf prints enums as words and the counters, TimeToDraw is set, and
// ReleaseGraphicsResources frees the device resources while the mapper keeps rendering.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkSmartPointer.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkColorTransferFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

using vstest::Ball;
using vstest::Check;

namespace
{

size_t CountContaining(const std::vector<std::string>& messages, const std::string& text)
{
  return size_t(std::count_if(messages.begin(), messages.end(),
    [&](const std::string& m) { return m.find(text) != std::string::npos; }));
}

void RenderTimes(vtkRenderWindow* win, int n)
{
  for (int i = 0; i < n; ++i)
  {
    win->Render();
  }
}

double MeanRadiance(vtkVisibilitySweepVolumeMapper* m)
{
  vtkImageData* r = m->GetRadiance();
  if (!r)
  {
    return -1.0;
  }
  vtkDataArray* a = r->GetPointData()->GetArray("Radiance");
  double sum = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    sum += a->GetComponent(i, 0) + a->GetComponent(i, 1) + a->GetComponent(i, 2);
  }
  return sum / (3.0 * double(a->GetNumberOfTuples()));
}
}

int TestMapperVtkSettings(int, char*[])
{
  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(Ball(16));
  m->SetSamplingStrategyToEnvironment(); // no sweeps: these checks are about the integration
  m->SetMaximumSamples(4);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);

  vtkNew<vtkVolumeProperty> property; // VTK's defaults: nearest interpolation, shading off
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(24, 24);
  win->AddRenderer(ren);
  ren->ResetCamera();

  // Nearest interpolation (VTK's default) is honoured (TestMapperNearestLabels), so neither it nor
  // linear warns.
  RenderTimes(win, 3);
  Check(std::string(m->GetLastError()).empty(), std::string("renders: ") + m->GetLastError());
  Check(m->GetTimeToDraw() > 0.0, "TimeToDraw is set after a render");
  property->SetInterpolationTypeToLinear();
  RenderTimes(win, 2);
  property->SetInterpolationTypeToNearest();
  RenderTimes(win, 2);
  Check(recorder->Warnings.empty(), "nearest and linear interpolation warn nothing");
  property->SetInterpolationTypeToLinear();

  // Shading (in Monte Carlo mode), blend modes and depth peeling for volumes: once per change each.
  property->ShadeOn();
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Warnings, "Shade is on") == 0,
    "ShadeOn in the Monte Carlo mode is honoured (issue 38, TestMapperShading): no warning");
  m->SetRenderModeToEmissionAbsorption();
  RenderTimes(win, 2);
  Check(CountContaining(recorder->Warnings, "Shade is on") == 0,
    "ShadeOn in emission-absorption mode is honoured (TestMapperShading): no warning");
  m->SetRenderModeToMonteCarlo();
  property->ShadeOff();

  vtkNew<vtkPiecewiseFunction> gradient;
  gradient->AddPoint(0.0, 0.0);
  gradient->AddPoint(1.0, 1.0);
  property->SetGradientOpacity(gradient);
  RenderTimes(win, 3);
  // Honoured since issue 14 (TestMapperGradientOpacity measures it): no warning, no error.
  Check(CountContaining(recorder->Warnings, "gradient opacity") == 0, "gradient opacity is honoured: no warning");
  Check(std::string(m->GetLastError()).empty(), std::string("gradient opacity renders: ") + m->GetLastError());
  property->DisableGradientOpacityOn();
  RenderTimes(win, 2);
  Check(CountContaining(recorder->Warnings, "gradient opacity") == 0, "disabled gradient opacity warns nothing");

  // MIP, MinIP, average and additive are honoured (TestMapperBlendModes); iso-surface and slice are not.
  const size_t beforeBlend = recorder->Warnings.size();
  m->SetBlendModeToMaximumIntensity();
  RenderTimes(win, 2);
  m->SetBlendModeToMinimumIntensity();
  RenderTimes(win, 2);
  m->SetBlendModeToAverageIntensity();
  RenderTimes(win, 2);
  m->SetBlendModeToAdditive();
  RenderTimes(win, 2);
  Check(recorder->Warnings.size() == beforeBlend, "the projections (MIP, MinIP, average, additive) warn nothing");
  Check(m->IsConverged(), "a projection is complete after one render (a convergence loop ends)");
  m->SetBlendModeToIsoSurface();
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Warnings, "ISOSURFACE_BLEND") == 1, "iso-surface warns once");
  m->SetBlendModeToSlice();
  RenderTimes(win, 2);
  Check(CountContaining(recorder->Warnings, "SLICE_BLEND") == 1, "another blend mode is a new warning");
  m->SetBlendModeToComposite();

  ren->UseDepthPeelingOn();
  ren->UseDepthPeelingForVolumesOn();
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Warnings, "UseDepthPeelingForVolumes") == 1, "depth peeling for volumes warns once");
  ren->UseDepthPeelingOff();
  ren->UseDepthPeelingForVolumesOff();
  const size_t warnings = recorder->Warnings.size();
  RenderTimes(win, 2);
  Check(recorder->Warnings.size() == warnings, "honoured settings warn nothing");
  Check(recorder->Errors.empty(), "no errors so far");

  // vtkGPUVolumeRayCastMapper's settings that mean something else here (issue 38, item 5): once each,
  // not at every render of a converging view.
  m->SetSampleDistance(0.5);
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Warnings, "SampleDistance is not a step") == 1,
    "SampleDistance in the Monte Carlo mode warns once");
  m->SetRenderModeToEmissionAbsorption();
  RenderTimes(win, 2);
  Check(CountContaining(recorder->Warnings, "SampleDistance is not a step") == 1,
    "SampleDistance is the emission-absorption mode's step: no warning there");
  m->SetSampleDistance(0.0);
  m->SetRenderModeToMonteCarlo();
  m->AutoAdjustSampleDistancesOff();
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Warnings, "AutoAdjustSampleDistances off") == 1,
    "AutoAdjustSampleDistances off warns once");
  m->AutoAdjustSampleDistancesOn();
  // More lights than the estimate takes (issue 38): one warning naming how many and which.
  std::vector<vtkSmartPointer<vtkLight>> lights;
  ren->RemoveAllLights(); // VTK's automatic headlight (made at the first render) would be light 1
  for (int i = 0; i < 10; ++i)
  {
    auto light = vtkSmartPointer<vtkLight>::New();
    light->SetLightTypeToSceneLight();
    light->SetPosition(10.0 * i, 30.0, 30.0);
    light->SetFocalPoint(8.0, 8.0, 8.0);
    light->SetIntensity(0.1);
    ren->AddLight(light);
    lights.push_back(light);
  }
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Warnings, "the renderer has 10 switched-on lights") == 1 &&
      CountContaining(recorder->Warnings, "the first 8; it leaves out the lights at positions 9 and 10") == 1,
    "10 lights: one warning naming the 8 used and the 2 left out");
  lights[9]->SwitchOff();
  RenderTimes(win, 2);
  Check(CountContaining(recorder->Warnings, "at position 9 of vtkRenderer::GetLights()") == 1,
    "9 lights: a new warning naming the one left out");
  lights[8]->SwitchOff();
  const size_t beforeEight = recorder->Warnings.size();
  RenderTimes(win, 2);
  Check(recorder->Warnings.size() == beforeEight, "8 lights: nothing left out, no warning");
  ren->RemoveAllLights();
  RenderTimes(win, 1);
  Check(recorder->Errors.empty(), "no errors so far");

  // Cropping region flags other than the subvolume are honoured (TestMapperCroppingRegions).
  double bounds[6];
  m->GetInput()->GetBounds(bounds);
  m->CroppingOn();
  m->SetCroppingRegionPlanes(bounds);
  m->SetCroppingRegionFlagsToFence();
  RenderTimes(win, 2);
  m->SetCroppingRegionFlagsToInvertedCross();
  RenderTimes(win, 2);
  Check(recorder->Errors.empty() && std::string(m->GetLastError()).empty(), "fence and inverted cross render");
  m->CroppingOff();

  // Errors: once per change. More than 8 clipping planes that cut the volume are one.
  vtkNew<vtkPlaneCollection> planes;
  auto addCut = [&](double x) {
    vtkNew<vtkPlane> p;
    p->SetOrigin(x, 0.0, 0.0);
    p->SetNormal(-1.0, 0.0, 0.0);
    planes->AddItem(p);
  };
  for (int k = 0; k < 9; ++k)
  {
    addCut(7.0 + 0.5 * k);
  }
  m->SetClippingPlanes(planes);
  RenderTimes(win, 3);
  Check(CountContaining(recorder->Errors, "9 clipping planes cut the volume") == 1, "an error is logged once over 3 renders");
  Check(std::string(m->GetLastError()).find("9 clipping planes") != std::string::npos,
    "GetLastError() holds the error on every failed render");
  addCut(12.0);
  RenderTimes(win, 2);
  Check(CountContaining(recorder->Errors, "10 clipping planes cut the volume") == 1, "another error is a new error");
  m->RemoveAllClippingPlanes();
  win->Render();
  Check(std::string(m->GetLastError()).empty(), "rendering again once the planes are gone");

  // Setters clamp or refuse.
  const size_t errors = recorder->Errors.size();
  m->SetDirectionResolution(6);
  Check(m->GetDirectionResolution() == 8, "DirectionResolution 6 is refused");
  Check(recorder->Errors.size() == errors + 1 && CountContaining(recorder->Errors, "2, 4, 8 or 16") == 1,
    "refusing DirectionResolution names the supported values");
  m->SetDirectionResolution(32);
  Check(m->GetDirectionResolution() == 8, "DirectionResolution 32 is refused");
  for (int d : { 2, 4, 16, 8 })
  {
    m->SetDirectionResolution(d);
    Check(m->GetDirectionResolution() == d, "DirectionResolution " + std::to_string(d) + " is accepted");
  }
  Check(vtkNew<vtkVisibilitySweepVolumeMapper>()->GetVoxelsPerCell() == 0.0, "VoxelsPerCell is automatic (0) by default");
  m->SetVoxelsPerCell(-3.0);
  Check(m->GetVoxelsPerCell() == 0.0, "VoxelsPerCell is clamped to at least 0 (automatic)");
  m->SetVoxelsPerCell(1e9);
  Check(m->GetVoxelsPerCell() == 256.0, "VoxelsPerCell is clamped to at most 256");
  m->SetVoxelsPerCell(4.0);
  m->SetSeed(-5);
  Check(m->GetSeed() == 0, "Seed is clamped to non-negative values");
  m->SetSeed(1);

  // Enums as words.
  Check(std::string(m->GetRenderModeAsString()) == "MonteCarlo", "GetRenderModeAsString");
  m->SetCellModeToTrilinear();
  Check(std::string(m->GetCellModeAsString()) == "TrilinearCells", "GetCellModeAsString");
  m->SetCellModeToStochastic();
  Check(std::string(m->GetCellModeAsString()) == "StochasticCell", "GetCellModeAsString (stochastic)");
  std::ostringstream print;
  m->Print(print);
  for (const char* line : { "RenderMode: MonteCarlo", "CellMode: StochasticCell", "UpdateScheme: RoundRobin",
         "AccumulationResetCount: ", "EnvironmentUploadCount: ", "MajorantUpdateCount: ", "LastSweepSeconds: ",
         "TimeToDraw: ", "MonteCarlo tracking is exact",
         "Environment: none connected: a constant white sky of radiance 1 (the default)" })
  {
    Check(print.str().find(line) != std::string::npos, std::string("PrintSelf prints '") + line + "'");
  }

  // Label gradient opacities (a label-map mask VisSweep has no input for) warn once per change too.
  {
    vtkNew<vtkVolumeProperty> labelled;
    labelled->SetScalarOpacity(opacity);
    labelled->SetColor(color);
    labelled->SetLabelGradientOpacity(1, gradient);
    volume->SetProperty(labelled);
    RenderTimes(win, 3);
    Check(CountContaining(recorder->Warnings, "label gradient opacities") == 1,
      "label gradient opacities warn once over 3 renders");
    volume->SetProperty(property);
  }

  // ReleaseGraphicsResources frees the device resources; the mapper renders again afterwards.
  RenderTimes(win, 4);
  Check(m->IsConverged(), "converged before the release");
  const double before = MeanRadiance(m);
  const int uploads = m->GetVolumeUploadCount();
  const int environmentUploads = m->GetEnvironmentUploadCount();
  m->ReleaseGraphicsResources(win);
  Check(MeanRadiance(m) == before, "the last radiance stays available after the release");
  Check(m->GetRadiance(true) == nullptr, "its variance went with the device accumulator");
  RenderTimes(win, 4);
  Check(std::string(m->GetLastError()).empty(), std::string("renders after the release: ") + m->GetLastError());
  Check(m->GetVolumeUploadCount() == uploads + 1, "the volume is uploaded again after the release");
  Check(m->GetEnvironmentUploadCount() == environmentUploads + 1, "the environment is uploaded again");
  Check(m->IsConverged(), "converges again after the release");
  const double after = MeanRadiance(m);
  std::cout << "mean radiance before the release " << before << ", after " << after << "\n";
  Check(before > 0.0 && std::abs(after - before) <= 0.05 * before, "the same image after the release");
  return vstest::ExitCode();
}
