// Issue 38, item 4: the preview and the emission-absorption mode light with the renderer's vtkLights.
//  - Preview: a key light brightens the preview and builds the light volume again; a camera move builds
//    nothing; a moved light builds it again; switched off, the image is that without it, bit for bit.
//  - A headlight the user made follows the camera: a still camera move builds the light volume again, a
//    drag frame does not (it keeps the light where it was), the next still frame does.
//  - The surface lobe (ShadeOn): the preview's mean radiance under a key light (no sky) within a stated
//    bound of the Monte Carlo estimate's, and the volumetric preview (ShadeOff) outside it: the lobe is
//    what brings the preview to the estimate.
//  - Full transport under the sky and the key light: the preview no more biased than the sky-lit preview.
//  - EmissionAbsorption with ShadeOn is shaded by the key light (brighter), with ShadeOff it is not; and
//    it looks like vtkGPUVolumeRayCastMapper's with ShadeOn (where this VTK has it): a ball under VTK's
//    automatic headlight, and under a key light alone, within 1 grey level in the mean (the key light's
//    side brighter in both).
#include "vsLitBallScene.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#ifdef VISSWEEP_TEST_GPU_VOLUME
#include "vtkGPUVolumeRayCastMapper.h"
#endif

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using vstest::Check;
using vstest::Mean;

namespace
{
// The lit ball in the preview mode.
struct Scene : vstest::LitBallScene
{
  Scene() { this->Mapper->SetRenderModeToPreview(); }

  // The window's mean pixel value (emission-absorption has no radiance image).
  double WindowMean()
  {
    this->Window->Render();
    const std::vector<int> px = vstest::WindowPixels(this->Window);
    double s = 0.0;
    for (int v : px)
      s += v;
    return px.empty() ? 0.0 : s / double(px.size());
  }
};

// Mean |difference| of the window images of VisSweep's emission-absorption mode and VTK's GPU ray caster,
// ShadeOn, on a ball of radial density (96^2, black background), under VTK's automatic headlight or a key
// light alone; the left and right halves' means of each (the key light comes from +x). -1 without the GPU
// mapper.
struct Comparison
{
  double Difference = -1.0, VisLeft = 0.0, VisRight = 0.0, VtkLeft = 0.0, VtkRight = 0.0;
};

std::vector<int> ShadedBall(vtkVolumeMapper* mapper, bool key)
{
  vtkSmartPointer<vtkImageData> data = vstest::FloatVolume(48, [](int x, int y, int z) {
    const double r = std::sqrt((x - 23.5) * (x - 23.5) + (y - 23.5) * (y - 23.5) + (z - 23.5) * (z - 23.5));
    return float(std::max(0.0, 1.0 - r / 20.0));
  });
  mapper->SetInputDataObject(data);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.3, 0.0);
  opacity->AddPoint(0.5, 0.8);
  opacity->AddPoint(1.0, 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.7, 0.5);
  color->AddRGBPoint(1.0, 0.9, 0.7, 0.5);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetAmbient(0.1);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.2);
  property->SetSpecularPower(20.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(96, 96);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  vtkNew<vtkLight> light;
  if (key)
  {
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetPosition(100.0, 23.5, 53.5);
    light->SetFocalPoint(23.5, 23.5, 23.5);
    renderer->AddLight(light);
  }
  window->Render();
  window->Render();
  return vstest::WindowPixels(window);
}

Comparison CompareWithVtk(bool key)
{
  Comparison c;
#ifdef VISSWEEP_TEST_GPU_VOLUME
  vtkNew<vtkGPUVolumeRayCastMapper> gpu;
  gpu->SetSampleDistance(0.25);
  gpu->AutoAdjustSampleDistancesOff();
  vtkNew<vtkVisibilitySweepVolumeMapper> vis;
  vis->SetRenderModeToEmissionAbsorption();
  vis->SetSampleDistance(0.25);
  const std::vector<int> a = ShadedBall(vis, key), b = ShadedBall(gpu, key);
  c.Difference = vstest::MeanAbsoluteDifference(a, b);
  const size_t channels = a.size() / (96 * 96);
  for (size_t i = 0; i < a.size() && channels > 0; ++i)
  {
    const bool left = (i / channels) % 96 < 48;
    (left ? c.VisLeft : c.VisRight) += a[i] / double(a.size() / 2);
    (left ? c.VtkLeft : c.VtkRight) += b[i] / double(b.size() / 2);
  }
#else
  (void)key;
#endif
  return c;
}

}

int TestMapperPreviewLights(int, char*[])
{
  Scene s;
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  double position[3], focal[3], up[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  const std::vector<float> unlit = s.Preview();
  const int builds0 = s.Mapper->GetLightVolumeBuildCount();

  vtkSmartPointer<vtkLight> key = vstest::KeyLight();
  s.Renderer->AddLight(key);
  const std::vector<float> lit = s.Preview();
  std::cout << "preview mean without lights " << Mean(unlit) << ", with a key light " << Mean(lit) << "\n";
  Check(Mean(lit) > 1.2 * Mean(unlit), "a key light brightens the preview");
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 1, "adding a light builds the light volume again");

  s.Renderer->GetActiveCamera()->Azimuth(30.0);
  s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 1, "a camera move builds no light volume");
  key->SetPosition(-100.0, 40.0, 60.0);
  const std::vector<float> moved = s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 2, "a moved light builds the light volume again");
  key->SwitchOff();
  camera->SetPosition(position);
  camera->SetFocalPoint(focal);
  camera->SetViewUp(up);
  const std::vector<float> off = s.Preview();
  Check(off == unlit, "a light switched off is no light: the preview without it, bit for bit");

  // A headlight the user made (intensity 1.5) follows the camera.
  vtkNew<vtkLight> head;
  head->SetLightTypeToHeadlight();
  head->SetIntensity(1.5);
  s.Renderer->AddLight(head);
  s.Preview();
  int b = s.Mapper->GetLightVolumeBuildCount();
  s.Renderer->GetActiveCamera()->Azimuth(20.0);
  s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == b + 1, "a still camera move moves the headlight: built again");
  s.Window->SetDesiredUpdateRate(15.0); // dragging
  s.Renderer->GetActiveCamera()->Azimuth(20.0);
  s.Preview();
  s.Renderer->GetActiveCamera()->Azimuth(20.0);
  s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == b + 1, "drag frames keep the headlight where it was: nothing built");
  s.Window->SetDesiredUpdateRate(0.0001); // still
  s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == b + 2, "the still frame after the drag builds it for the headlight");
  head->SwitchOff();

  // The surface lobe against the estimate: the key light alone (no sky), one scattering event (the preview's
  // multiple scattering has its own, documented bias), Lambert plus a GGX lobe.
  key->SwitchOn();
  s.Mapper->SetEnvironmentIntensity(0.0);
  s.Mapper->SetMaximumScatteringEvents(1);
  s.Property->ShadeOn();
  s.Property->SetDiffuse(0.8);
  s.Property->SetSpecular(0.2);
  s.Property->SetSpecularPower(20.0);
  const std::vector<float> surfacePreview = s.Preview();
  const std::vector<float> surfaceEstimate = s.Estimate(256);
  s.Property->ShadeOff();
  const std::vector<float> volumetricPreview = s.Preview();
  const double m = Mean(surfaceEstimate), ps = Mean(surfacePreview), pv = Mean(volumetricPreview);
  std::printf("key light, ShadeOn: estimate %.5f, preview with the surface lobe %.5f (%+.1f%%), volumetric preview "
              "%.5f (%+.1f%%)\n",
    m, ps, 100.0 * (ps / m - 1.0), pv, 100.0 * (pv / m - 1.0));
  const double bound = 0.10;
  Check(std::abs(ps / m - 1.0) < bound, "the preview with the surface lobe within 10% of the estimate's mean");
  Check(std::abs(pv / m - 1.0) > bound, "the volumetric preview is not: the test can tell");
  s.Mapper->SetEnvironmentIntensity(1.0);

  // Full transport (4 events) under the sky and the key light, ShadeOff: what the hand-over blends. On this
  // small ball (24 voxels, a few cells across) the sky-lit preview is +12.4% from its estimate (the light
  // volume's resolution: docs/reference.md "The light volume"); with the key light the preview's bias is no
  // larger (+9.2% measured), and the preview without the light's term is far off (-31.8%).
  s.Mapper->SetMaximumScatteringEvents(4);
  const std::vector<float> fullPreview = s.Preview();
  const std::vector<float> fullEstimate = s.Estimate(256);
  key->SwitchOff();
  const std::vector<float> skyPreview = s.Preview();
  const std::vector<float> skyEstimate = s.Estimate(256);
  key->SwitchOn();
  const double fm = Mean(fullEstimate), fp = Mean(fullPreview), sp = Mean(skyPreview);
  std::printf("sky and key light, 4 events: estimate %.5f, preview %.5f (%+.1f%%); the preview without the key "
              "light %.5f (%+.1f%%); the sky alone: preview %+.1f%% from its estimate\n",
    fm, fp, 100.0 * (fp / fm - 1.0), sp, 100.0 * (sp / fm - 1.0), 100.0 * (sp / Mean(skyEstimate) - 1.0));
  const double skyBias = std::abs(sp / Mean(skyEstimate) - 1.0);
  Check(std::abs(fp / fm - 1.0) < skyBias + 0.02,
    "with a key light and the sky, the preview's bias against the estimate's mean is at most the sky-lit preview's "
    "(+ 2%): the light adds no bias of its own beyond the light volume's");
  Check(std::abs(sp / fm - 1.0) > skyBias + 0.02, "without the key light's term it is not: the test can tell");

  // EmissionAbsorption: Phong with the renderer's lights (the automatic headlight and the key light).
  s.Mapper->SetRenderModeToEmissionAbsorption();
  s.Property->ShadeOn();
  key->SwitchOff();
  const double shadedWithout = s.WindowMean();
  key->SwitchOn();
  const double shadedWith = s.WindowMean();
  s.Property->ShadeOff();
  key->SwitchOff();
  const double flatWithout = s.WindowMean();
  key->SwitchOn();
  const double flatWith = s.WindowMean();
  std::cout << "emission-absorption: shaded " << shadedWithout << " -> " << shadedWith << " with the key light, unshaded "
            << flatWithout << " -> " << flatWith << "\n";
  Check(shadedWith > shadedWithout + 2.0, "ShadeOn: the key light brightens the emission-absorption image");
  Check(std::abs(flatWith - flatWithout) < 0.5, "ShadeOff: the lights change nothing");
  Check(std::string(s.Mapper->GetLastError()).empty(), std::string("no error: ") + s.Mapper->GetLastError());

  for (bool withKey : { false, true })
  {
    const Comparison c = CompareWithVtk(withKey);
    if (c.Difference < 0.0)
    {
      std::cout << "this VTK has no RenderingVolumeOpenGL2: vtkGPUVolumeRayCastMapper not compared\n";
      break;
    }
    std::printf("ShadeOn, %s: mean |VisSweep - vtkGPUVolumeRayCastMapper| %.2f grey levels; left/right half VisSweep "
                "%.1f/%.1f, VTK %.1f/%.1f\n",
      withKey ? "a key light from +x" : "VTK's automatic headlight", c.Difference, c.VisLeft, c.VisRight, c.VtkLeft,
      c.VtkRight);
    Check(c.Difference < 1.0, "the emission-absorption mode's shading looks like VTK's GPU mapper's (mean |diff| < 1)");
    if (withKey)
    {
      Check(c.VisRight > c.VisLeft + 2.0 && c.VtkRight > c.VtkLeft + 2.0, "the key light's side is brighter in both");
    }
  }
  return vstest::ExitCode();
}
