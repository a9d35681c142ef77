// Depth peeling for volumes (issue 14): with UseDepthPeeling and UseDepthPeelingForVolumes on and
// translucent geometry in the scene, VTK's dual depth peeling pass draws the volumes itself, several
// times per frame into its peeling buffers (a striped, corrupt image). VisSweep cannot interleave
// its volume with the peels: it warns once and draws the volume as without depth peeling for
// volumes. A translucent sphere half in front of a ball: the image with depth peeling for volumes
// equals the one without (within 1/255 on average), the volume is seen, one warning, and the
// accumulation goes on across frames.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
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

struct Scene
{
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkActor> Sphere;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(vtkImageData* data, bool peelVolumes)
  {
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, 0.9);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.9, 0.8, 0.7);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    property->SetInterpolationTypeToLinear();
    this->Mapper->SetInputData(data);
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Mapper->SetSamplesPerFrame(4);
    this->Mapper->SetMaximumSamples(8);
    this->Mapper->SetSeed(3);
    this->Mapper->SetExposure(0.5);
    this->Mapper->EnvironmentVisibleOff();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(16.0, -6.0, 9.5);
    sphere->SetRadius(6.0);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(24);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    this->Sphere->SetMapper(sphereMapper);
    this->Sphere->GetProperty()->SetColor(0.2, 0.8, 0.3);
    this->Sphere->GetProperty()->SetOpacity(0.4);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->AddActor(this->Sphere);
    this->Renderer->SetBackground(0.1, 0.1, 0.2);
    this->Renderer->SetUseDepthPeeling(true);
    this->Renderer->SetUseDepthPeelingForVolumes(peelVolumes);
    this->Window->SetMultiSamples(0);
    this->Window->SetAlphaBitPlanes(1);
    this->Window->SetSize(64, 64);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(9.5, 9.5, 9.5);
    camera->SetPosition(9.5, -80.0, 9.5);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Renderer->ResetCamera();
  }
};


}

int TestMapperDepthPeeling(int, char*[])
{
  vtkSmartPointer<vtkImageData> data = Ball(20);
  Scene peeled(data, true), plain(data, false);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(peeled.Mapper);
  for (int i = 0; i < 2; ++i)
  {
    peeled.Window->Render();
    plain.Window->Render();
  }
  const std::vector<int> a = vstest::WindowPixels(peeled.Window), b = vstest::WindowPixels(plain.Window);
  // The volume is seen: the image without the volume differs.
  peeled.Volume->VisibilityOff();
  peeled.Window->Render();
  const std::vector<int> noVolume = vstest::WindowPixels(peeled.Window);
  const double difference = vstest::MeanAbsoluteDifference(a, b),
               volumeShows = vstest::MeanAbsoluteDifference(a, noVolume);
  std::cout << "mean |peeled - plain| = " << difference << "; mean |peeled - without the volume| = " << volumeShows
            << "\n";
  size_t warnings = 0;
  for (const auto& w : recorder->Warnings)
  {
    warnings += w.find("UseDepthPeelingForVolumes") != std::string::npos ? 1u : 0u;
  }
  Check(difference < 1.0, "depth peeling for volumes gives the image without it");
  Check(volumeShows > 2.0, "the volume is seen");
  Check(warnings == 1, "one warning about UseDepthPeelingForVolumes");
  Check(peeled.Mapper->GetAccumulatedSamples() == 8 && peeled.Mapper->GetAccumulationResetCount() == 1,
    "8 spp from one start: the peeling passes did not restart or add samples");
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
