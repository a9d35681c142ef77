// The mapper-managed environment background (EnvironmentAsBackground, issue 14): the renderer gets
// one unpickable vtkSkybox from its second frame on, whatever the number of VisSweep volumes, and
// loses it when no volume wants it (the volume removed, EnvironmentVisible off); a user's own
// skybox is kept and none added; two renderers have one each. GetRadiance() (radiance, alpha and
// variance) is bit for bit that of the opaque image (EnvironmentAsBackground off), with the collision
// and the reservoir camera. Off, the volume paints the environment over the translucent sphere as
// before. A new exposure shows on the skybox in the frame that renders it; a tiled screenshot
// (scale 2) is the window, magnified; picking the sky picks nothing.
#include "vsRenderTestUtilities.h"
#include "vtkEnvironmentMapBackground.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkPropPicker.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <sstream>
#include <vector>

using vstest::Check;

namespace
{
const int W = 64, H = 48;

vtkSmartPointer<vtkVolume> BallVolume(vtkImageData* data, vtkAlgorithmOutput* light, double x, int seed)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.3, 0.2);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetEnvironmentConnection(light);
  mapper->SetSamplingStrategyToEnvironment();
  mapper->SetSamplesPerFrame(3);
  mapper->SetMaximumSamples(9);
  mapper->SetSeed(seed);
  mapper->SetExposure(0.8);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  volume->SetPosition(x, 0.0, 0.0);
  return volume;
}

vtkVisibilitySweepVolumeMapper* MapperOf(vtkVolume* v)
{
  return vtkVisibilitySweepVolumeMapper::SafeDownCast(v->GetMapper());
}

int Skyboxes(vtkRenderer* ren, vtkSkybox** last = nullptr)
{
  int n = 0;
  vtkCollectionSimpleIterator pit;
  vtkProp* prop;
  for (ren->GetViewProps()->InitTraversal(pit); (prop = ren->GetViewProps()->GetNextProp(pit));)
  {
    if (auto* sky = vtkSkybox::SafeDownCast(prop))
    {
      ++n;
      if (last)
      {
        *last = sky;
      }
    }
  }
  return n;
}

void Look(vtkRenderer* ren)
{
  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetFocalPoint(9.5, 9.5, 12.0);
  camera->SetPosition(9.5, -90.0, 12.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  camera->SetClippingRange(50.0, 200.0);
}

struct Scene
{
  vtkNew<vtkEnvironmentMapSource> Light;
  vtkSmartPointer<vtkVolume> Volume;
  vtkNew<vtkActor> Sphere;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(vtkImageData* data, bool background, int estimator = vtkVisibilitySweepVolumeMapper::CollisionCamera)
  {
    this->Light->SetTypeToSunDisk();
    this->Light->SetSunDirection(0.1, -1.0, 0.5);
    this->Light->SetSunAngularRadius(6.0);
    this->Light->SetSunRadiance(6.0, 5.0, 3.0);
    this->Light->SetSkyColor(0.15, 0.3, 0.7);
    this->Light->SetOctahedralSize(64);
    this->Volume = BallVolume(data, this->Light->GetOutputPort(), 0.0, 5);
    MapperOf(this->Volume)->SetEnvironmentAsBackground(background);
    MapperOf(this->Volume)->SetCameraEstimator(estimator);
    this->Renderer->AddVolume(this->Volume);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(-8.0, 9.5, 20.0);
    sphere->SetRadius(4.0);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    this->Sphere->SetMapper(sphereMapper);
    this->Sphere->GetProperty()->SetColor(0.0, 1.0, 0.0);
    this->Sphere->GetProperty()->SetOpacity(0.5);
    this->Renderer->AddActor(this->Sphere);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(W, H);
    this->Window->AddRenderer(this->Renderer);
    Look(this->Renderer);
  }

  std::vector<int> Render(int frames)
  {
    for (int i = 0; i < frames; ++i)
    {
      this->Window->Render();
    }
    return vstest::WindowPixels(this->Window);
  }

  std::vector<int> At(const std::vector<int>& p, double x, double y, double z)
  {
    this->Renderer->SetWorldPoint(x, y, z, 1.0);
    this->Renderer->WorldToDisplay();
    const int px = int(this->Renderer->GetDisplayPoint()[0]), py = int(this->Renderer->GetDisplayPoint()[1]);
    const size_t i = (size_t(py) * W + px) * 3;
    return { p[i], p[i + 1], p[i + 2] };
  }
};

bool SameArray(vtkImageData* a, vtkImageData* b, const char* name)
{
  vtkDataArray* x = a ? a->GetPointData()->GetArray(name) : nullptr;
  vtkDataArray* y = b ? b->GetPointData()->GetArray(name) : nullptr;
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() ||
    x->GetNumberOfComponents() != y->GetNumberOfComponents())
  {
    return false;
  }
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
    for (int c = 0; c < x->GetNumberOfComponents(); ++c)
      if (x->GetComponent(i, c) != y->GetComponent(i, c))
      {
        return false;
      }
  return true;
}

}

int TestMapperEnvironmentBackground(int, char*[])
{
  vtkSmartPointer<vtkImageData> data = vstest::Ball(20);

  // The skybox: none in the first frame, one from the second, unpickable.
  Scene scene(data, true);
  scene.Render(1);
  Check(Skyboxes(scene.Renderer) == 0, "the first frame has no skybox (the volume paints the environment)");
  const std::vector<int> shown = scene.Render(2);
  vtkSkybox* sky = nullptr;
  Check(Skyboxes(scene.Renderer, &sky) == 1 && sky && !sky->GetPickable(), "one unpickable skybox from the second frame");

  // GetRadiance() is that of the opaque image, bit for bit, with either camera estimator.
  for (int estimator : { int(vtkVisibilitySweepVolumeMapper::CollisionCamera), int(vtkVisibilitySweepVolumeMapper::ReservoirCamera) })
  {
    Scene on(data, true, estimator), off(data, false, estimator);
    on.Render(3);
    off.Render(3);
    vtkImageData* a = MapperOf(on.Volume)->GetRadiance(true);
    vtkImageData* b = MapperOf(off.Volume)->GetRadiance(true);
    const std::string which = estimator ? " (reservoir camera)" : " (collision camera)";
    Check(MapperOf(on.Volume)->GetAccumulatedSamples() == 9 && MapperOf(on.Volume)->GetAccumulationResetCount() == 1,
      "9 spp from one start" + which);
    Check(SameArray(a, b, "Radiance"), "the radiance is the opaque image's" + which);
    Check(SameArray(a, b, "Alpha"), "the alpha is the opaque image's" + which);
    Check(SameArray(a, b, "Variance"), "the variance is the opaque image's" + which);
  }

  // Off: the volume paints the environment over the translucent sphere, as before; no skybox.
  Scene old(data, false);
  const std::vector<int> painted = old.Render(3);
  const std::vector<int> sphereOn = scene.At(shown, -8.0, 9.5, 20.0), sphereOff = old.At(painted, -8.0, 9.5, 20.0);
  std::cout << "sphere with the background " << sphereOn[0] << " " << sphereOn[1] << " " << sphereOn[2]
            << ", painted over " << sphereOff[0] << " " << sphereOff[1] << " " << sphereOff[2] << "\n";
  Check(sphereOn[1] > sphereOff[1] + 30, "the sphere is seen with the background, covered without");
  Check(Skyboxes(old.Renderer) == 0, "no skybox when EnvironmentAsBackground is off");

  // A new exposure shows on the skybox in the frame that renders it.
  MapperOf(scene.Volume)->SetExposure(0.4);
  const std::vector<int> darker = scene.Render(1);
  Scene fresh(data, true);
  MapperOf(fresh.Volume)->SetExposure(0.4);
  const std::vector<int> expected = fresh.Render(3);
  const std::vector<int> skyNow = scene.At(darker, 9.5, 9.5, 35.0), skyExpected = fresh.At(expected, 9.5, 9.5, 35.0);
  std::cout << "sky after the exposure change " << skyNow[0] << " " << skyNow[1] << " " << skyNow[2] << " (expected "
            << skyExpected[0] << " " << skyExpected[1] << " " << skyExpected[2] << ")\n";
  Check(vstest::MaxAbsoluteDifference(skyNow, skyExpected) <= 1, "the skybox follows the exposure at once");

  // A tiled screenshot is the window, magnified (each 2x2 block against its pixel).
  const std::vector<int> window = vstest::WindowPixels(scene.Window), tiled = vstest::WindowPixels(scene.Window, 2);
  double sum = 0.0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c)
      {
        double block = 0.0;
        for (int k = 0; k < 4; ++k)
        {
          block += tiled[(size_t(2 * y + k / 2) * 2 * W + 2 * x + k % 2) * 3 + c];
        }
        sum += std::abs(block / 4.0 - window[(size_t(y) * W + x) * 3 + c]);
      }
  std::cout << "tiled screenshot against the window: mean " << sum / (W * H * 3) << "/255\n";
  Check(sum / (W * H * 3) < 6.0, "the tiled screenshot shows the background");
  Check(Skyboxes(scene.Renderer) == 1, "still one skybox after the tiles");

  // Picking the sky picks nothing; the volume is picked.
  vtkNew<vtkPropPicker> picker;
  scene.Renderer->SetWorldPoint(9.5, 9.5, 35.0, 1.0);
  scene.Renderer->WorldToDisplay();
  const double* skyPoint = scene.Renderer->GetDisplayPoint();
  Check(!picker->Pick(skyPoint[0], skyPoint[1], 0.0, scene.Renderer) || picker->GetViewProp() == nullptr,
    "picking the sky picks nothing");
  scene.Renderer->SetWorldPoint(9.5, 9.5, 9.5, 1.0);
  scene.Renderer->WorldToDisplay();
  const double* ballPoint = scene.Renderer->GetDisplayPoint();
  picker->Pick(ballPoint[0], ballPoint[1], 0.0, scene.Renderer);
  Check(picker->GetViewProp() == scene.Volume.Get(), "picking the ball picks the volume");

  // Two VisSweep volumes: one skybox. Two renderers: one each.
  vtkSmartPointer<vtkVolume> second = BallVolume(data, scene.Light->GetOutputPort(), 24.0, 6);
  scene.Renderer->AddVolume(second);
  vtkNew<vtkRenderer> other;
  other->SetViewport(0.5, 0.0, 1.0, 1.0);
  scene.Renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkSmartPointer<vtkVolume> third = BallVolume(data, scene.Light->GetOutputPort(), 0.0, 7);
  other->AddVolume(third);
  Look(other);
  scene.Window->AddRenderer(other);
  scene.Render(2);
  Check(Skyboxes(scene.Renderer) == 1, "two volumes, one skybox");
  Check(Skyboxes(other) == 1, "the second renderer has its own skybox");

  // No volume wants it: removed at the renderer's next frame. A user's own skybox: none added.
  scene.Renderer->RemoveVolume(second);
  MapperOf(scene.Volume)->EnvironmentVisibleOff();
  scene.Render(1);
  Check(Skyboxes(scene.Renderer) == 0, "EnvironmentVisible off: the skybox is removed");
  MapperOf(scene.Volume)->EnvironmentVisibleOn();
  scene.Render(1);
  Check(Skyboxes(scene.Renderer) == 1, "EnvironmentVisible on again: the skybox is back");
  other->RemoveVolume(third);
  scene.Render(1);
  Check(Skyboxes(other) == 0, "the volume removed: no skybox left behind");
  vtkNew<vtkEnvironmentMapBackground> own;
  own->SetInputConnection(scene.Light->GetOutputPort());
  vtkNew<vtkSkybox> ownSky;
  own->ConfigureSkybox(ownSky);
  other->AddActor(ownSky);
  other->AddVolume(third);
  scene.Render(2);
  Check(Skyboxes(other) == 1, "a user's skybox: none added");

  std::ostringstream printed;
  MapperOf(scene.Volume)->Print(printed);
  Check(printed.str().find("EnvironmentAsBackground: On") != std::string::npos, "PrintSelf prints the setting");
  for (vtkVolume* v : { scene.Volume.Get(), second.Get(), third.Get() })
  {
    Check(std::string(MapperOf(v)->GetLastError()).empty(), "no error");
  }
  return vstest::ExitCode();
}
