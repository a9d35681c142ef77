// Issue 35 ("hostile input, round three"), the mapper's classes:
//  - class 5: GetRadiance() is what the last render computed, or nothing. After a switch of render
//    mode or blend mode it returned the previous Monte Carlo or preview image, where a fresh mapper
//    returns none: a host saving "the current render" saved an old one.
//  - class 6: an environment input that is not a map (with EnvironmentAsBackground on, the
//    default) gives one error and a defined image (the renderer's background): the skybox drew
//    blocky garbage and its filter logged pipeline errors at every render.
//  - class 9: "warned once per change" holds per renderer: depth peeling for volumes on in one of
//    two views warned at every frame.
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsRenderTestUtilities.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTrivialProducer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using vstest::Check;

namespace
{
// Every error and warning VTK displays (those of objects no test can watch, such as the skybox's filter).
class CountingOutputWindow : public vtkOutputWindow
{
public:
  static CountingOutputWindow* New() { return new CountingOutputWindow; }
  void DisplayErrorText(const char* text) override
  {
    ++this->Errors;
    std::cerr << "ERROR: " << text;
  }
  void DisplayWarningText(const char* text) override { std::cerr << "WARNING: " << text; }
  void DisplayGenericWarningText(const char* text) override { std::cerr << "WARNING: " << text; }
  void DisplayText(const char* text) override { std::cerr << text; }
  int Errors = 0;
};

struct Scene
{
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  explicit Scene(vtkImageData* data)
  {
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, 0.8);
    this->Color->AddRGBPoint(0.0, 0.9, 0.8, 0.7);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Property->SetInterpolationTypeToLinear();
    this->Mapper->SetInputData(data);
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Mapper->SetSamplesPerFrame(2);
    this->Mapper->SetMaximumSamples(2);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.3, 0.4);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(24, 24);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }
};

void TestRadianceIsTheLastRenders()
{
  Scene s(vstest::Ball(12));
  auto* m = s.Mapper.Get();
  s.Window->Render();
  Check(m->GetRadiance() != nullptr, "a Monte Carlo render makes a radiance image");
  m->SetRenderModeToEmissionAbsorption();
  s.Window->Render();
  Check(m->GetRadiance() == nullptr, "after Monte Carlo, an emission-absorption render has no radiance");
  m->SetRenderModeToPreview();
  s.Window->Render();
  vtkImageData* preview = m->GetRadiance();
  Check(preview != nullptr, "a preview render makes a radiance image");
  m->SetRenderModeToAmbientOcclusion();
  s.Window->Render();
  Check(m->GetRadiance() == nullptr, "after the preview, an ambient-occlusion render has no radiance");
  m->SetRenderModeToMonteCarlo();
  s.Window->Render();
  Check(m->GetRadiance() != nullptr, "back in the Monte Carlo mode, its image");
  m->SetBlendModeToMaximumIntensity();
  s.Window->Render();
  Check(m->GetRadiance() == nullptr, "after Monte Carlo, a MIP projection has no radiance");
  m->SetBlendModeToComposite();
  m->SetRenderModeToPreview();
  s.Window->Render();
  Check(m->GetRadiance() != nullptr, "the preview again");
}

void TestInvalidEnvironment()
{
  vtkNew<CountingOutputWindow> counter;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkOutputWindow::SetInstance(counter);
  {
    Scene s(vstest::Ball(12));
    // A sky first, shown as the background (a skybox from the second frame on) ...
    vtkNew<vtkEnvironmentMapSource> sky;
    sky->SetTypeToTwoToneSky();
    sky->SetOctahedralSize(16);
    s.Mapper->SetEnvironmentConnection(sky->GetOutputPort());
    s.Window->Render();
    s.Window->Render();
    Check(counter->Errors == 0, "no errors with a valid sky");
    // ... then an image that is no environment map (3 x 5 pixels, no "Radiance").
    vtkNew<vtkImageData> notAMap;
    notAMap->SetDimensions(3, 5, 1);
    notAMap->AllocateScalars(VTK_FLOAT, 1);
    vtkNew<vtkTrivialProducer> producer;
    producer->SetOutput(notAMap);
    s.Mapper->SetEnvironmentConnection(producer->GetOutputPort());
    for (int i = 0; i < 4; ++i)
    {
      s.Window->Render();
    }
    Check(std::string(s.Mapper->GetLastError()).find("not an environment map") != std::string::npos,
      std::string("the mapper says what is wrong: ") + s.Mapper->GetLastError());
    std::cout << counter->Errors << " errors logged over 4 renders\n";
    Check(counter->Errors == 1, "one error over 4 renders, not one per render");
    // The window shows the renderer's background, everywhere.
    const std::vector<int> pixels = vstest::WindowPixels(s.Window);
    const int expected[3] = { 51, 77, 102 }; // (0.2, 0.3, 0.4) in 8 bits
    int off = 0;
    for (size_t i = 0; i + 2 < pixels.size(); i += 3)
    {
      for (int c = 0; c < 3; ++c)
      {
        off += std::abs(pixels[i + size_t(c)] - expected[c]) > 1 ? 1 : 0;
      }
    }
    Check(off == 0, "the window shows the renderer's background (" + std::to_string(off) + " channel values differ)");
    Check(s.Mapper->GetRadiance() == nullptr, "no radiance from a failed render");
  }
  vtkOutputWindow::SetInstance(previous);
}

void TestWarnedOncePerView()
{
  vtkSmartPointer<vtkImageData> data = vstest::Ball(12);
  Scene s(data);
  s.Mapper->SetRenderModeToEmissionAbsorption();
  vtkNew<vtkRenderer> peeled;
  vtkNew<vtkRenderWindow> window;
  peeled->AddVolume(s.Volume);
  peeled->SetUseDepthPeeling(true);
  peeled->SetUseDepthPeelingForVolumes(true);
  window->SetMultiSamples(0);
  window->SetAlphaBitPlanes(1);
  window->SetSize(24, 24);
  window->AddRenderer(peeled);
  peeled->ResetCamera();
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(s.Mapper);
  for (int i = 0; i < 4; ++i)
  {
    s.Window->Render();
    window->Render();
  }
  size_t warnings = 0;
  for (const auto& w : recorder->Warnings)
  {
    warnings += w.find("UseDepthPeelingForVolumes") != std::string::npos ? 1u : 0u;
  }
  std::cout << warnings << " depth peeling warnings over 4 frames of two views\n";
  Check(warnings == 1, "one warning for the view with depth peeling for volumes, not one per frame");
  Check(recorder->Errors.empty(), "no errors");
}
}

// Minor: the clamped settings refuse NaN (it passes every clamp: InteractiveUpdateRate took it).
void TestNaNSettings()
{
  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m->SetInteractiveUpdateRate(nan);
  m->SetVoxelsPerCell(nan);
  m->SetDefensiveWeight(nan);
  m->SetVisibilityEpsilon(nan);
  m->SetFilterAngleFraction(nan);
  m->SetSweepFrameFraction(nan);
  m->SetAutoProbeFraction(nan);
  Check(recorder->Errors.size() == 7, "seven NaN settings, seven errors (" + std::to_string(recorder->Errors.size()) + ")");
  Check(m->GetInteractiveUpdateRate() == 1.0 && m->GetVoxelsPerCell() == 0.0, "the settings are kept");
  Check(std::isfinite(m->GetDefensiveWeight()) && std::isfinite(m->GetVisibilityEpsilon()) &&
      std::isfinite(m->GetFilterAngleFraction()) && std::isfinite(m->GetSweepFrameFraction()) &&
      std::isfinite(m->GetAutoProbeFraction()),
    "no setting holds NaN");
  m->SetInteractiveUpdateRate(-3.0);
  m->SetVoxelsPerCell(1e30);
  Check(m->GetInteractiveUpdateRate() == 0.0 && m->GetVoxelsPerCell() == 256.0, "other values are clamped as before");
}

int TestMapperHostileInput(int, char*[])
{
  TestNaNSettings();
  TestRadianceIsTheLastRenders();
  TestInvalidEnvironment();
  TestWarnedOncePerView();
  return vstest::ExitCode();
}
