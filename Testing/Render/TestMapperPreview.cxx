// The mapper's Preview mode (issue 15): the MRI (Colin27 shrunk 4x) under the sunrise HDRI renders
// without error, deterministically, building the visibility grid and the light volume once: a camera
// move does not build the light volume again, a new intensity does. AmbientOcclusion renders without
// error, and an empty volume renders (the environment alone). No regression image: the checks are on
// GetRadiance() and the counters.
// With -convergence (Render.TestMapperPreviewConvergence, label "convergence"): the goal, that
// the preview's relative MSE against a well-converged Monte Carlo image (1024 spp) is below that of
// Monte Carlo at 16 spp, at the mapper's default grid; the finer grids' errors are printed beside it.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkImageData.h"
#include "vtkImageShrink3D.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <chrono>
#include <cmath>
#include <cstdio>
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

// sum (x - ref)^2 / sum ref^2 over every pixel's rgb.
double RelativeMSE(const std::vector<double>& x, const std::vector<double>& ref)
{
  if (x.size() != ref.size() || ref.empty())
  {
    return 1e9;
  }
  double num = 0.0, den = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    num += (x[i] - ref[i]) * (x[i] - ref[i]);
    den += ref[i] * ref[i];
  }
  return den > 0.0 ? num / den : 1e9;
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

// Renders Monte Carlo to `spp` with `seed` and returns the radiance.
std::vector<double> MonteCarlo(vtkVisibilitySweepVolumeMapper* mapper, vtkRenderWindow* win, int spp, int seed)
{
  mapper->SetRenderModeToMonteCarlo();
  mapper->SetSeed(seed);
  mapper->SetMaximumSamples(spp);
  mapper->SetSamplesPerFrame(std::min(spp, 64));
  // IsConverged() still says the preview's last render was complete: render first.
  int frames = 0;
  do
  {
    win->Render();
  } while (++frames < 4 * spp && !mapper->IsConverged());
  Check(mapper->GetAccumulatedSamples() == spp, "Monte Carlo reached " + std::to_string(spp) + " spp");
  return RadianceOf(mapper);
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
  auto full = vstest::ReadBrain(vstest::Argument(argc, argv, "-D"));
  vtkNew<vtkImageShrink3D> shrink;
  shrink->SetInputData(full);
  shrink->SetShrinkFactors(4, 4, 4);
  shrink->AveragingOn();
  shrink->Update();
  vtkNew<vtkEnvironmentMapReader> env;
  env->SetFileName((std::string(VISSWEEP_DATA) + "/envmaps/sunrise.exr").c_str());
  env->SetOctahedralSize(128);
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputConnection(shrink->GetOutputPort());
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
  win->Render();
  Check(RadianceOf(mapper) == first, "two preview renders are identical");
  Check(mapper->GetLightVolumeBuildCount() == 1, "an unchanged frame builds no light volume");
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

  // A clipping plane opens the head: the preview follows it (a new grid and light volume).
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(90, 108, 90);
  plane->SetNormal(-1, 0, 0);
  mapper->AddClippingPlane(plane);
  win->Render();
  Check(std::string(mapper->GetLastError()).empty(), std::string("a clipped preview renders: ") + mapper->GetLastError());
  Check(RadianceOf(mapper) != first && AllFinite(RadianceOf(mapper)), "the clipping plane changed the preview");
  Check(mapper->GetLightVolumeBuildCount() == 3, "the clipped grid has its own light volume");
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

  bool convergence = false;
  for (int i = 1; i < argc; ++i)
  {
    convergence = convergence || std::string(argv[i]) == "-convergence";
  }
  if (!convergence)
  {
    return TestEmptyVolume(mapper, volume, property, win, errors);
  }
  // Convergence: the volume's own radiance (the environment not visible, so that its exact term does
  // not dominate the norm), preview against Monte Carlo at 16 spp, both against 1024 spp.
  mapper->SetEnvironmentVisible(false);
  mapper->SetRenderModeToPreview();
  const auto t0 = std::chrono::steady_clock::now();
  win->Render();
  const double previewSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<double> preview = RadianceOf(mapper);
  const std::vector<double> mc16 = MonteCarlo(mapper, win, 16, 5);
  const std::vector<double> reference = MonteCarlo(mapper, win, 1024, 77);
  const double previewError = RelativeMSE(preview, reference), mcError = RelativeMSE(mc16, reference);
  std::printf("relative MSE against Monte Carlo at 1024 spp (64 x 64, ch2 / 4, sunrise): preview %.3e, "
              "Monte Carlo 16 spp %.3e (preview frame %.3f s)\n",
    previewError, mcError, previewSeconds);
  Check(previewError < mcError, "the preview is closer to the converged image than Monte Carlo at 16 spp");
  // The same at finer grids (information: the preview's bias is the grid's resolution).
  for (double voxelsPerCell : { 2.0, 1.0 })
  {
    mapper->SetVoxelsPerCell(voxelsPerCell);
    mapper->SetRenderModeToPreview();
    win->Render();
    std::printf("preview at %g voxels per cell: relative MSE %.3e\n", voxelsPerCell, RelativeMSE(RadianceOf(mapper), reference));
  }
  return vstest::ExitCode();
}



