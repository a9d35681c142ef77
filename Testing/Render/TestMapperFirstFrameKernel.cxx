// The first frame's render kernel is the one the mapper starts making beside the volume's upload
// (its prewarm), so the first image waits for one pipeline at most: for a thin volume and for one
// whose bricks are optically thick (the trackers' cell walk, a kernel of its own), the first frame
// leaves exactly one new render kernel in the context, the one it ran. Before the prewarm guessed
// the cell walk from the transfer function, the thick volume's first frame made a second kernel
// on the render thread (~0.2 s on lavapipe).
//
// Issue 39: PrecompileRenderKernel makes that kernel from what a reader tells before reading (the
// shape and the scalar type of an 8-bit volume), before the data exists, and the first render runs
// it; and an explicit TwoStep's kernel is made ahead, from its first flat-grid frame, not at the
// frame where the grid fills in (ch2better's waited 1.4 s for it). A renderer's lights are part of the
// guess: the key-lit MRI's first frame waited 0.2 s for a kernel with lights when the prewarm made one
// without.
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsContext.h"
#include "vsRenderTestUtilities.h"

#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> RenderKernels()
{
  std::vector<std::string> kernels;
  for (const std::string& name : vs::Context::Default()->PipelineNames())
    if (name.rfind("monte carlo", 0) == 0)
      kernels.push_back(name);
  return kernels;
}

std::vector<std::string> NewSince(const std::vector<std::string>& before)
{
  std::vector<std::string> made;
  for (const std::string& name : RenderKernels())
    if (std::find(before.begin(), before.end(), name) == before.end())
      made.push_back(name);
  return made;
}

// Waits (up to a minute) for a kernel made on another thread to land in the context.
std::vector<std::string> WaitForNew(const std::vector<std::string>& before)
{
  for (int i = 0; i < 600; ++i)
  {
    const std::vector<std::string> made = NewSince(before);
    if (!made.empty())
      return made;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return {};
}

struct Scene
{
  vtkSmartPointer<vtkImageData> Image;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  // A ball of 8-bit scalars (0..200), its kernel's name distinct by `interpolation`'s and the opacity.
  Scene(double peakOpacity, bool nearest)
  {
    auto ball = vstest::Ball(24);
    vtkNew<vtkUnsignedCharArray> bytes;
    vtkDataArray* values = ball->GetPointData()->GetScalars();
    bytes->SetNumberOfTuples(values->GetNumberOfTuples());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
      bytes->SetValue(i, static_cast<unsigned char>(std::clamp(values->GetTuple1(i), 0.0, 1.0) * 200.0));
    this->Image = vtkSmartPointer<vtkImageData>::New();
    this->Image->CopyStructure(ball);
    this->Image->GetPointData()->SetScalars(bytes);
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(255.0, peakOpacity);
    this->Color->AddRGBPoint(0.0, 1, 1, 1);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    if (nearest)
      this->Property->SetInterpolationTypeToNearest();
    else
      this->Property->SetInterpolationTypeToLinear();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetSize(32, 32);
    this->Window->AddRenderer(this->Renderer);
  }

  void Render(const std::string& what)
  {
    this->Window->Render();
    const char* error = this->Mapper->GetLastError();
    vstest::Check(!error || !*error, what + ": renders (" + std::string(error ? error : "") + ")");
  }
};

void TestPrecompiledFromTheHeader()
{
  using vstest::Check;
  Scene s(0.05, false);
  s.Mapper->SetSamplingStrategyToEnvironment();
  // The shape a reader tells after UpdateInformation: no scalars yet.
  vtkNew<vtkImageData> shape;
  shape->CopyStructure(s.Image);
  const std::vector<std::string> before = RenderKernels();
  s.Mapper->PrecompileRenderKernel(s.Volume, shape, VTK_UNSIGNED_CHAR, 0.0, 255.0);
  const std::vector<std::string> precompiled = WaitForNew(before);
  Check(precompiled.size() == 1, "PrecompileRenderKernel makes one kernel before the data exists, got " +
      std::to_string(precompiled.size()));
  s.Mapper->SetInputData(s.Image);
  s.Renderer->ResetCamera();
  s.Render("precompiled");
  const std::vector<std::string> made = NewSince(before);
  for (const std::string& name : made)
    std::printf("precompiled: %s\n", name.c_str());
  Check(made == precompiled, "the first render runs the precompiled kernel and makes no other");
  Check(!made.empty() && made.front().find("quads") != std::string::npos,
    "an 8-bit volume's kernel reads its quads");
}

// A scene light (not VTK's automatic headlight) in the renderer: the kernel is specialized on it.
void AddKeyLight(vtkRenderer* renderer)
{
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->SetPosition(1.0, 0.5, 0.5);
  key->SetFocalPoint(0.0, 0.0, 0.0);
  key->SetIntensity(1.5);
  renderer->AddLight(key);
}

// The kernel of a renderer with lights, at the first render (the prewarm beside the upload) and from
// the header (PrecompileRenderKernel given the renderer): the first frame makes no other.
void TestLightsInTheGuess()
{
  using vstest::Check;
  for (bool fromHeader : { false, true })
  {
    const std::string what = fromHeader ? "precompiled with the renderer's lights" : "the first frame with lights";
    Scene s(0.05, fromHeader); // nearest for one, linear for the other: kernels of their own
    s.Mapper->SetSamplingStrategyToEnvironment();
    // Ray-marched shadows: a kernel no other case here makes, lit or not (one made before would hide
    // a wrongly guessed kernel as not new).
    s.Mapper->SetTransmittanceEstimatorToRayMarching();
    AddKeyLight(s.Renderer);
    const std::vector<std::string> before = RenderKernels();
    std::vector<std::string> precompiled;
    if (fromHeader)
    {
      vtkNew<vtkImageData> shape;
      shape->CopyStructure(s.Image);
      s.Mapper->PrecompileRenderKernel(s.Volume, shape, VTK_UNSIGNED_CHAR, 0.0, 255.0, s.Renderer);
      precompiled = WaitForNew(before);
      Check(precompiled.size() == 1, what + ": one kernel before the data exists, got " +
          std::to_string(precompiled.size()));
    }
    s.Mapper->SetInputData(s.Image);
    s.Renderer->ResetCamera();
    s.Render(what);
    const std::vector<std::string> made = NewSince(before);
    for (const std::string& name : made)
      std::printf("%s: %s\n", what.c_str(), name.c_str());
    Check(made.size() == 1, what + ": the first frame leaves one new render kernel, got " + std::to_string(made.size()));
    Check(!made.empty() && made.front().find("scene lights") != std::string::npos, what + ": a kernel with lights");
    if (fromHeader)
      Check(made == precompiled, what + ": the first render runs the precompiled kernel");
  }
}

void TestTwoStepKernelMadeAhead()
{
  using vstest::Check;
  Scene s(0.6, false);
  s.Mapper->SetSamplingStrategyToTwoStep(); // progressive visibility (the default): a flat grid first
  s.Mapper->SetInputData(s.Image);
  s.Renderer->ResetCamera();
  const std::vector<std::string> before = RenderKernels();
  s.Render("TwoStep's first frame");
  Check(s.Mapper->GetEffectiveStrategy() == vtkVisibilitySweepVolumeMapper::Environment,
    "TwoStep's first frame, on a flat grid, samples the environment");
  // Without another render TwoStep's kernel appears: made ahead, from the first frame.
  auto twoStep = [&]() {
    std::vector<std::string> kernels;
    for (const std::string& name : NewSince(before))
      if (name.find("two-step") != std::string::npos)
        kernels.push_back(name);
    return kernels;
  };
  std::vector<std::string> ahead;
  for (int i = 0; i < 600 && ahead.empty(); ++i)
  {
    ahead = twoStep();
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (const std::string& name : ahead)
    std::printf("TwoStep, ahead of the grid: %s\n", name.c_str());
  Check(ahead.size() == 1, "TwoStep's kernel is made ahead of the frame that needs it (got " +
      std::to_string(ahead.size()) + ")");
  const std::vector<std::string> all = NewSince(before);
  for (int frame = 0; frame < 20 && s.Mapper->GetEffectiveStrategy() != vtkVisibilitySweepVolumeMapper::TwoStep; ++frame)
    s.Render("TwoStep, frame " + std::to_string(frame));
  Check(s.Mapper->GetEffectiveStrategy() == vtkVisibilitySweepVolumeMapper::TwoStep, "the grid fills in: TwoStep");
  Check(NewSince(before) == all, "the TwoStep frames run the kernel made ahead and make no other");
}
}

int TestMapperFirstFrameKernel(int, char*[])
{
  using vstest::Check;
  for (bool thick : { false, true })
  {
    const std::string what = thick ? "optically thick bricks" : "a thin volume";
    auto image = vstest::Ball(24);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, thick ? 0.95 : 0.02);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 1, 1, 1);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    // Kernels of their own for each volume (the interpolation is in the name), so that a kernel one
    // volume made cannot hide another's extra one.
    if (thick)
      property->SetInterpolationTypeToNearest();
    else
      property->SetInterpolationTypeToLinear();
    vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
    mapper->SetInputData(image);
    mapper->SetDensityScale(thick ? 30.0 : 1.0);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkRenderer> renderer;
    renderer->AddVolume(volume);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(32, 32);
    window->AddRenderer(renderer);
    renderer->ResetCamera();

    const std::vector<std::string> before = RenderKernels();
    window->Render();
    const char* error = mapper->GetLastError();
    Check(!error || !*error, what + ": renders (" + std::string(error ? error : "") + ")");
    std::vector<std::string> made;
    for (const std::string& name : RenderKernels())
      if (std::find(before.begin(), before.end(), name) == before.end())
        made.push_back(name);
    Check(made.size() == 1, what + ": the first frame leaves one new render kernel, got " + std::to_string(made.size()));
    for (const std::string& name : made)
      std::printf("%s: %s\n", what.c_str(), name.c_str());
    const bool walks = !made.empty() && made.front().find("cell walk") != std::string::npos;
    Check(walks == thick, what + (thick ? ": its kernel walks the cells of thick bricks" : ": its kernel has no cell walk"));
  }
  TestPrecompiledFromTheHeader();
  TestLightsInTheGuess();
  TestTwoStepKernelMadeAhead();
  return vstest::ExitCode();
}
