// The mapper's Preview mode (issue 15): the MRI (Colin27 shrunk 4x) under the sunrise HDRI renders
// without error, deterministically, building the visibility grid and the light volume once: a camera
// move does not build the light volume again, a new intensity does. AmbientOcclusion renders without
// error, and an empty volume renders (the environment alone). No regression image: the checks are on
// GetRadiance() and the counters.
// The preview's error against Monte Carlo (issue 15's goal) is a benchmark figure: `vissweep bench preview`.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkDataArray.h"
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

using vstest::Check;

namespace
{
std::vector<double> RadianceOf(vtkVisibilitySweepVolumeMapper* mapper)
{
  std::vector<double> out;
  vtkImageData* radiance = mapper->GetRadiance();
  if (!radiance)
  {
    return out;
  }
  vtkDataArray* a = radiance->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.push_back(a->GetComponent(i, c));
    }
  }
  return out;
}

bool AllFinite(const std::vector<double>& v)
{
  for (double x : v)
  {
    if (!std::isfinite(x))
    {
      return false;
    }
  }
  return !v.empty();
}
}

// An empty volume (the opacity 0 everywhere): no grid, no light volume, the environment alone.
static int TestEmptyVolume(vtkVisibilitySweepVolumeMapper* mapper, vtkVolume* volume, vtkVolumeProperty* property,
  vtkRenderWindow* win, vstest::ErrorRecorder* errors)
{
  vtkNew<vtkVolumeProperty> clear;
  clear->DeepCopy(property);
  vtkNew<vtkPiecewiseFunction> zero;
  zero->AddPoint(0, 0);
  zero->AddPoint(255, 0);
  clear->SetScalarOpacity(zero);
  volume->SetProperty(clear);
  mapper->SetEnvironmentVisible(true);
  mapper->SetRenderModeToPreview();
  win->Render();
  Check(std::string(mapper->GetLastError()).empty(), std::string("an empty volume renders: ") + mapper->GetLastError());
  const std::vector<double> empty = RadianceOf(mapper);
  Check(AllFinite(empty), "the empty volume's radiance is finite");
  Check(errors->Errors.empty(), "no vtkErrorMacro");
  return vstest::ExitCode();
}

int TestMapperPreview(int argc, char* argv[])
{
  auto brain = vstest::ShrunkBrain(vstest::Argument(argc, argv, "-D"), 4);
  auto env = vstest::SunriseEnvironment();
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(brain);
  mapper->SetEnvironmentConnection(env->GetOutputPort());
  mapper->SetRenderModeToPreview();
  vtkNew<vstest::ErrorRecorder> errors;
  errors->Watch(mapper);
  auto property = vstest::BrainProperty();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(64, 64);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetViewUp(0, 0, 1);
  cam->SetFocalPoint(90, 108, 90);
  cam->SetPosition(90 + 300, 108 + 420, 90 + 120);
  ren->ResetCamera();

  // Renders, deterministically, the light volume once.
  win->Render();
  Check(std::string(mapper->GetLastError()).empty(), std::string("preview renders: ") + mapper->GetLastError());
  Check(std::string(mapper->GetRenderModeAsString()) == "Preview", "GetRenderModeAsString is Preview");
  const std::vector<double> first = RadianceOf(mapper);
  Check(AllFinite(first), "the preview's radiance is finite");
  Check(mapper->GetLightVolumeBuildCount() == 1, "one light volume built, got " + std::to_string(mapper->GetLightVolumeBuildCount()));
  // While the view is still, successive renders average 8 frames with the pixels' offsets rotated (issue
  // 39, item 1: the fixed pattern's moire averages out, as in the Monte Carlo mode's hand-over): the second
  // render is another image, IsConverged() once the 8 are in, and further renders redraw that mean.
  // (The renderer's second frame adds the skybox the environment is shown on: the window image changes,
  // and the frames start again from the fixed pattern: the same radiance, the first frame.)
  win->Render();
  Check(RadianceOf(mapper) == first, "the fixed pattern again once the skybox is there");
  Check(!mapper->IsConverged(), "a still preview is not complete after its first frame");
  win->Render();
  Check(RadianceOf(mapper) != first, "the second still render averages a frame of rotated offsets");
  int frames = 2;
  while (!mapper->IsConverged() && frames < 100)
  {
    win->Render();
    ++frames;
  }
  Check(frames == 8, "a still preview is complete after 8 frames, got " + std::to_string(frames));
  const std::vector<double> mean = RadianceOf(mapper);
  win->Render();
  Check(RadianceOf(mapper) == mean, "then a render redraws the mean");
  Check(mapper->GetLightVolumeBuildCount() == 1, "unchanged frames build no light volume");
  {
    // Deterministic: another mapper's 8 frames of the same view are the same bits.
    vtkNew<vtkVisibilitySweepVolumeMapper> other;
    other->SetInputData(brain);
    other->SetEnvironmentConnection(env->GetOutputPort());
    other->SetRenderModeToPreview();
    vtkNew<vtkVolume> otherVolume;
    otherVolume->SetMapper(other);
    otherVolume->SetProperty(property);
    vtkNew<vtkRenderer> otherRen;
    otherRen->AddVolume(otherVolume);
    otherRen->SetActiveCamera(cam);
    vtkNew<vtkRenderWindow> otherWin;
    otherWin->SetMultiSamples(0);
    otherWin->AddRenderer(otherRen);
    otherWin->SetSize(64, 64);
    otherWin->Render();
    Check(RadianceOf(other) == first, "another mapper's first frame is the same");
    for (int i = 0; i < 100 && !other->IsConverged(); ++i)
      otherWin->Render();
    Check(RadianceOf(other) == mean, "and its mean of 8 frames");
    // The mean is closer to a march of a tenth of the step (its first frame) than the fixed pattern is.
    other->SetSampleDistance(0.1 * brain->GetSpacing()[0]);
    otherWin->Render();
    const std::vector<double> fine = RadianceOf(other);
    double e0 = 0.0, e8 = 0.0;
    for (size_t i = 0; i < fine.size() && i < first.size() && i < mean.size(); ++i)
    {
      e0 += (first[i] - fine[i]) * (first[i] - fine[i]);
      e8 += (mean[i] - fine[i]) * (mean[i] - fine[i]);
    }
    std::cout << "squared error against a tenth of the step: fixed pattern " << e0 << ", mean of 8 frames " << e8 << "\n";
    Check(e8 < 0.7 * e0, "the mean of the rotated frames is closer to the fine march than the fixed pattern");
  }
  // A camera move: a new image, the same light volume.
  cam->Azimuth(30);
  win->Render();
  Check(RadianceOf(mapper) != first, "the camera move changed the image");
  Check(mapper->GetLightVolumeBuildCount() == 1,
    "a camera move builds no light volume, got " + std::to_string(mapper->GetLightVolumeBuildCount()));
  cam->Azimuth(-30);
  // A new intensity does.
  mapper->SetEnvironmentIntensity(2.0);
  win->Render();
  Check(mapper->GetLightVolumeBuildCount() == 2, "a new intensity builds the light volume again");
  mapper->SetEnvironmentIntensity(1.0);
  // Under full transport (issue 39) the light volume carries multiple scattering: what it reads builds
  // it again (the albedo, the events, the orders), a camera move does not (above); with one order (single
  // scattering) the preview is darker.
  win->Render();
  Check(mapper->GetLightVolumeBuildCount() == 3, "the intensity back builds again");
  const std::vector<double> full = RadianceOf(mapper);
  mapper->SetPreviewScatteringOrders(1);
  win->Render();
  Check(mapper->GetLightVolumeBuildCount() == 4, "one order builds the light volume again");
  const std::vector<double> single = RadianceOf(mapper);
  double sumFull = 0.0, sumSingle = 0.0;
  for (size_t i = 0; i < full.size() && i < single.size(); ++i)
  {
    if (full[i] != single[i]) // the volume's pixels (those of the environment alone are the same)
    {
      sumFull += full[i];
      sumSingle += single[i];
    }
  }
  std::cout << "preview radiance: single scattering " << sumSingle / sumFull << " of full transport\n";
  Check(sumSingle < 0.8 * sumFull, "the single-scattering preview is darker than full transport's");
  mapper->SetPreviewScatteringOrders(4);
  mapper->SetMaximumScatteringEvents(2);
  win->Render();
  Check(mapper->GetLightVolumeBuildCount() == 5, "new events build the light volume again");
  mapper->SetMaximumScatteringEvents(1024);
  vtkColorTransferFunction* albedo = property->GetRGBTransferFunction();
  albedo->AddRGBPoint(128, 0.5, 0.5, 0.5);
  win->Render();
  Check(mapper->GetLightVolumeBuildCount() == 6, "a new albedo builds the light volume again, got " +
      std::to_string(mapper->GetLightVolumeBuildCount()));
  albedo->RemovePoint(128);
  win->Render();
  Check(RadianceOf(mapper) == full && mapper->GetLightVolumeBuildCount() == 7, "and back: the same preview");

  // A clipping plane opens the head: the preview follows it (a new grid and light volume).
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(90, 108, 90);
  plane->SetNormal(-1, 0, 0);
  mapper->AddClippingPlane(plane);
  win->Render();
  Check(std::string(mapper->GetLastError()).empty(), std::string("a clipped preview renders: ") + mapper->GetLastError());
  Check(RadianceOf(mapper) != first && AllFinite(RadianceOf(mapper)), "the clipping plane changed the preview");
  Check(mapper->GetLightVolumeBuildCount() == 8, "the clipped grid has its own light volume");
  mapper->RemoveAllClippingPlanes();
  // Without an environment: the constant white sky, as the Monte Carlo mode.
  mapper->SetEnvironmentConnection(nullptr);
  win->Render();
  Check(std::string(mapper->GetLastError()).empty(), std::string("a preview without environment renders: ") + mapper->GetLastError());
  Check(AllFinite(RadianceOf(mapper)), "the preview under the white sky is finite");
  mapper->SetEnvironmentConnection(env->GetOutputPort());

  // Ambient occlusion renders.
  mapper->SetRenderModeToAmbientOcclusion();
  win->Render();
  Check(std::string(mapper->GetLastError()).empty(), std::string("ambient occlusion renders: ") + mapper->GetLastError());

  return TestEmptyVolume(mapper, volume, property, win, errors);
}



