// Directions without environment light are not swept (README, "Skip rules"):
// Combined and TwoStep pick a grid direction with probability visibility x importance, so the
// visibility of a direction whose importance is 0 is never read. Under a sky with a black
// ground:
//  - the render sweeps only the lit directions and counts the others (UnlitDirections), and
//    the image is the same bit for bit as with every direction swept (SkipUnlitDirections off);
//  - GetVisibilityGrid sweeps what the render skipped and equals the fully swept grid;
//  - lighting the ground, or switching to the Visibility strategy (which samples by visibility
//    alone), sweeps exactly the directions skipped before, and nothing else;
//  - lazy updates after new data sweep k lit directions;
//  - a black environment sweeps nothing and renders black, without an error;
//  - a release keeps the grid, completed, on the host (ReleaseKeepsVisibilityGrid) or, turned off,
//    sweeps and keeps nothing (issue 39: `vissweep render` spent up to a second on it at exit).
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsRenderTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using vstest::Check;

const int N = 16;

vtkSmartPointer<vtkFloatArray> Data(int step)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetNumberOfTuples(N * N * N);
  for (int z = 0; z < N; ++z)
    for (int y = 0; y < N; ++y)
      for (int x = 0; x < N; ++x)
        a->SetValue((z * N + y) * N + x, float((x + 2 * y + 3 * z + step) % 5) / 4.0f);
  return a;
}

// A volume under a two-tone sky whose ground is black, TwoStep, 16 spp in a 20 x 20 window.
struct Scene
{
  vtkNew<vtkImageData> Image;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkEnvironmentMapSource> Sky;
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  explicit Scene(bool skip)
  {
    this->Image->SetDimensions(N, N, N);
    this->Image->GetPointData()->SetScalars(Data(0));
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, 0.4);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Sky->SetTypeToTwoToneSky();
    this->Sky->SetUpperColor(2.0, 1.8, 1.5);
    this->Sky->SetLowerColor(0.0, 0.0, 0.0);
    this->Sky->SetOctahedralSize(32);
    this->Mapper->SetInputData(this->Image);
    this->Mapper->SetEnvironmentConnection(this->Sky->GetOutputPort());
    this->Mapper->SetSamplingStrategyToTwoStep();
    // Which directions are swept, on a grid swept whole in the frame that needs it, along the
    // texel centres: a ground that lights up then changes only which directions are needed
    // (with LightWeightedDirections, the default, it also moves the light's directions and sweeps
    // a new grid: TestMapperSkipRules).
    this->Mapper->SetProgressiveVisibility(false);
    this->Mapper->SetLightWeightedDirections(false);
    this->Mapper->SetSkipUnlitDirections(skip);
    this->Mapper->SetSamplesPerFrame(16);
    this->Mapper->SetMaximumSamples(16);
    this->Mapper->SetSeed(5);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(20, 20);
    this->Renderer->ResetCamera();
  }

  void Render(const std::string& what)
  {
    this->Window->Render();
    Check(std::string(this->Mapper->GetLastError()).empty(), what + ": " + this->Mapper->GetLastError());
  }

  int Swept() { return this->Mapper->GetDirectionsUpdatedLastFrame(); }
  int Unlit() { return this->Mapper->GetUnlitDirections(); }
};

std::vector<float> Values(vtkDataArray* a)
{
  std::vector<float> v;
  if (a)
  {
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        v.push_back(float(a->GetComponent(i, c)));
  }
  return v;
}

std::vector<float> Radiance(Scene& s)
{
  vtkImageData* r = s.Mapper->GetRadiance();
  return r ? Values(r->GetPointData()->GetArray("Radiance")) : std::vector<float>();
}

std::vector<float> Grid(Scene& s)
{
  vtkImageData* g = s.Mapper->GetVisibilityGrid();
  return g ? Values(g->GetPointData()->GetScalars()) : std::vector<float>();
}

void TestSkippedAndIdentical()
{
  Scene skip(true), full(false);
  skip.Render("skip");
  full.Render("full");
  const int unlit = skip.Unlit();
  std::printf("black ground: %d of 64 directions unlit, swept %d (skip) and %d (full)\n", unlit, skip.Swept(),
    full.Swept());
  Check(unlit >= 16 && unlit < 64, "a black ground leaves many, not all, directions unlit: " + std::to_string(unlit));
  Check(skip.Swept() == 64 - unlit, "only the lit directions are swept");
  Check(full.Unlit() == 0 && full.Swept() == 64, "SkipUnlitDirections off sweeps everything");

  const std::vector<float> a = Radiance(skip), b = Radiance(full);
  Check(!a.empty() && a == b, "the image is the same bit for bit with and without the unlit directions");
  float peak = 0.0f;
  for (float x : a)
    peak = std::max(peak, x);
  Check(peak > 0.0f, "the scene is lit (the comparison means something)");

  const std::vector<float> gridFull = Grid(full);
  const int before = skip.Mapper->GetDirectionsUpdatedTotal();
  const std::vector<float> gridSkip = Grid(skip);
  Check(skip.Mapper->GetDirectionsUpdatedTotal() == before + unlit, "GetVisibilityGrid sweeps the skipped directions");
  Check(!gridFull.empty() && gridSkip == gridFull, "the grid handed out is complete: equal to the fully swept one");
  skip.Render("after GetVisibilityGrid");
  Check(skip.Swept() == 0, "nothing left to sweep after GetVisibilityGrid");
}

void TestEnvironmentAndStrategyChanges()
{
  {
    Scene s(true);
    s.Render("first");
    const int unlit = s.Unlit();
    s.Sky->SetLowerColor(0.1, 0.1, 0.2); // the ground lights up
    s.Render("lit ground");
    Check(s.Unlit() == 0, "a lit ground leaves no direction unlit");
    Check(s.Swept() == unlit, "lighting the ground sweeps exactly the directions skipped before: " +
        std::to_string(s.Swept()) + " vs " + std::to_string(unlit));
    s.Sky->SetLowerColor(0.0, 0.0, 0.0);
    s.Render("dark ground again");
    Check(s.Swept() == 0, "darkening the ground again sweeps nothing");
  }
  {
    Scene s(true);
    s.Render("first");
    const int unlit = s.Unlit();
    s.Mapper->SetSamplingStrategyToVisibility();
    s.Render("Visibility");
    Check(s.Unlit() == 0, "the Visibility strategy needs every direction");
    Check(s.Swept() == unlit, "switching to Visibility sweeps exactly the skipped directions");
    s.Mapper->SetSamplingStrategyToCombined();
    s.Render("Combined");
    Check(s.Swept() == 0 && s.Unlit() == unlit, "Combined skips the same directions, already swept");
  }
}

void TestLazyUpdatesSweepLitDirections()
{
  Scene s(true);
  s.Mapper->SetUpdateSchemeToRoundRobin();
  s.Mapper->SetDirectionsPerFrame(4);
  s.Render("first");
  const int lit = 64 - s.Unlit();
  int total = 0;
  for (int step = 1; step <= 4; ++step)
  {
    s.Image->GetPointData()->SetScalars(Data(step));
    s.Render("step " + std::to_string(step));
    Check(s.Swept() == 4, "RoundRobin sweeps k lit directions per new time step, got " + std::to_string(s.Swept()));
    total += s.Swept();
  }
  Check(s.Mapper->GetDirectionsUpdatedTotal() == lit + total, "no unlit direction is swept by the lazy updates");
}

void TestBlackEnvironment()
{
  Scene s(true);
  s.Sky->SetUpperColor(0.0, 0.0, 0.0);
  s.Render("black sky");
  Check(s.Unlit() == 64 && s.Swept() == 0, "a black environment sweeps nothing");
  const std::vector<float> r = Radiance(s);
  bool black = !r.empty();
  for (float x : r)
    black = black && x == 0.0f;
  Check(black, "a black environment renders black");
}

void TestReleaseKeepsGrid()
{
  for (const bool keep : { true, false })
  {
    Scene s(true);
    s.Mapper->SetReleaseKeepsVisibilityGrid(keep);
    s.Render(keep ? "keep" : "drop");
    const int unlit = s.Unlit(), before = s.Mapper->GetDirectionsUpdatedTotal();
    s.Mapper->ReleaseGraphicsResources(s.Window);
    if (keep)
    {
      Check(s.Mapper->GetDirectionsUpdatedTotal() == before + unlit, "a release that keeps the grid completes it");
      Check(s.Mapper->GetVisibilityGrid() != nullptr, "the grid stays on the host after the release");
    }
    else
    {
      Check(s.Mapper->GetDirectionsUpdatedTotal() == before, "ReleaseKeepsVisibilityGridOff: no sweeps at the release");
      Check(s.Mapper->GetVisibilityGrid() == nullptr, "ReleaseKeepsVisibilityGridOff: no grid after the release");
    }
    s.Render(keep ? "keep: after the release" : "drop: after the release");
  }
}
}

int TestMapperUnlitDirections(int, char*[])
{
  TestSkippedAndIdentical();
  TestEnvironmentAndStrategyChanges();
  TestLazyUpdatesSweepLitDirections();
  TestBlackEnvironment();
  TestReleaseKeepsGrid();
  return vstest::ExitCode();
}
