// The visible environment as a vtkSkybox behind everything (issue 14): vtkEnvironmentMapBackground
// turns the mapper's environment into the lat-long image of a Sphere-projection skybox with the
// mapper's display transform and orientation. A sun above a blue sky, seen at 60 degrees: the
// skybox background (mapper with EnvironmentVisible off) agrees with the mapper's own visible
// environment within 3/255 on average, the sun in the same place (its bright pixels overlap).
// With the skybox a translucent sphere shows over the environment (the mapper's visible
// environment covers it), and a ball in front of the skybox is seen. Regression image.
#include "vsRenderTestUtilities.h"
#include "vtkEnvironmentMapBackground.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <vector>

using vstest::Check;

namespace
{
const int W = 64, H = 48;

vtkSmartPointer<vtkImageData> Ball(int n, float value)
{
  const double c = 0.5 * (n - 1);
  return vstest::FloatVolume(n, [c, n, value](int x, int y, int z) {
    const double r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
    return r < 0.4 * n ? value : 0.0f;
  });
}

struct Scene
{
  vtkNew<vtkEnvironmentMapSource> Environment;
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkEnvironmentMapBackground> Background;
  vtkNew<vtkSkybox> Sky;

  Scene(vtkImageData* data, bool skybox)
  {
    this->Environment->SetTypeToSunDisk();
    this->Environment->SetSunDirection(0.2, 1.0, 0.35);
    this->Environment->SetSunAngularRadius(6.0);
    this->Environment->SetSunRadiance(6.0, 5.0, 3.0);
    this->Environment->SetSkyColor(0.15, 0.3, 0.7);
    this->Environment->SetOctahedralSize(128);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, 0.9);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetInterpolationTypeToLinear();
    this->Mapper->SetInputData(data);
    this->Mapper->SetEnvironmentConnection(this->Environment->GetOutputPort());
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Mapper->SetSamplesPerFrame(4);
    this->Mapper->SetMaximumSamples(4);
    this->Mapper->SetExposure(0.8);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    if (skybox)
    {
      this->Background->SetInputConnection(this->Environment->GetOutputPort());
      this->Background->CopyDisplaySettings(this->Mapper);
      this->Background->SetWidth(512);
      this->Background->ConfigureSkybox(this->Sky);
      this->Renderer->AddActor(this->Sky);
      this->Mapper->EnvironmentVisibleOff();
    }
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(W, H);
    this->Window->AddRenderer(this->Renderer);
    // From in front of the ball (x in [0, 19]) towards the sun's side, 60 degrees.
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(9.5, -40.0, 9.5);
    camera->SetFocalPoint(9.5 + 0.3 * 40.0, 9.5, 9.5 + 0.25 * 40.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(60.0);
    camera->SetClippingRange(1.0, 200.0);
  }

  std::vector<int> Pixels()
  {
    this->Window->Render();
    return vstest::WindowPixels(this->Window);
  }

  // The pixel (x, y) of the last Pixels().
  static std::vector<int> At(const std::vector<int>& p, int x, int y)
  {
    const size_t i = (size_t(y) * W + x) * 3;
    return { p[i], p[i + 1], p[i + 2] };
  }
};


int Bright(const std::vector<int>& p, std::vector<bool>& mask)
{
  int n = 0;
  mask.assign(p.size() / 3, false);
  for (size_t i = 0; i < mask.size(); ++i)
  {
    mask[i] = p[3 * i] + p[3 * i + 1] + p[3 * i + 2] > 600;
    n += mask[i] ? 1 : 0;
  }
  return n;
}
}

int TestEnvironmentMapBackground(int argc, char* argv[])
{
  vtkSmartPointer<vtkImageData> empty = Ball(20, 0.0f), ball = Ball(20, 1.0f);
  Scene own(empty, false), sky(empty, true);
  const std::vector<int> a = own.Pixels(), b = sky.Pixels();
  std::vector<bool> brightA, brightB;
  const int na = Bright(a, brightA), nb = Bright(b, brightB);
  int both = 0;
  for (size_t i = 0; i < brightA.size(); ++i)
  {
    both += brightA[i] && brightB[i] ? 1 : 0;
  }
  const double difference = vstest::MeanAbsoluteDifference(a, b);
  std::cout << "skybox against the mapper's visible environment: mean " << difference << "/255; sun pixels " << na
            << " and " << nb << ", " << both << " in both\n";
  Check(difference < 3.0, "the skybox shows the mapper's visible environment");
  Check(na > 4 && nb > 4 && both >= 0.7 * std::min(na, nb), "the sun is in the same place");

  // A translucent sphere in the view and the ball: both seen over the skybox.
  Scene scene(ball, true);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-6.0, 0.0, 14.0);
  sphere->SetRadius(4.0);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);
  actor->GetProperty()->SetColor(1.0, 0.0, 0.0);
  actor->GetProperty()->SetOpacity(0.5);
  scene.Renderer->AddActor(actor);
  const std::vector<int> c = scene.Pixels();
  auto display = [&](double x, double y, double z, int out[2]) {
    scene.Renderer->SetWorldPoint(x, y, z, 1.0);
    scene.Renderer->WorldToDisplay();
    out[0] = int(scene.Renderer->GetDisplayPoint()[0]);
    out[1] = int(scene.Renderer->GetDisplayPoint()[1]);
  };
  int s[2], v[2];
  display(-6.0, 0.0, 14.0, s);
  display(9.5, 9.5, 9.5, v);
  const std::vector<int> sphereHere = Scene::At(c, s[0], s[1]), skyHere = Scene::At(b, s[0], s[1]);
  const std::vector<int> ballHere = Scene::At(c, v[0], v[1]), skyThere = Scene::At(b, v[0], v[1]);
  std::cout << "at the sphere " << sphereHere[0] << " " << sphereHere[1] << " " << sphereHere[2] << " (sky " << skyHere[0]
            << " " << skyHere[1] << " " << skyHere[2] << "); at the ball " << ballHere[0] << " " << ballHere[1] << " "
            << ballHere[2] << " (sky " << skyThere[0] << " " << skyThere[1] << " " << skyThere[2] << ")\n";
  Check(sphereHere[0] > skyHere[0] + 20 && sphereHere[2] < skyHere[2] - 20, "the translucent sphere shows over the sky");
  Check(std::abs(ballHere[2] - skyThere[2]) > 20, "the ball shows over the sky");
  Check(std::string(scene.Mapper->GetLastError()).empty(), "no error");
  const int result = vtkRegressionTestImageThreshold(scene.Window, 0.05);
  return result == vtkRegressionTester::PASSED ? vstest::ExitCode() : EXIT_FAILURE;
}
