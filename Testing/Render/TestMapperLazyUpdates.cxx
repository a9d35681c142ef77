// Lazy visibility updates (von Radziewsky et al. 2017, Sec. 9) through the mapper's counters and images:
//  - counters: after a data-only change Full sweeps all 64 directions, RoundRobin the next k,
//    EnvironmentGuided k, Static all at every StaticInterval-th change and none in between;
//    anything else that changes extinction or the grid's layout sweeps everything; majorants
//    are recomputed and accumulation restarts for every new data;
//  - after 64/k RoundRobin changes to the same new data, the grid equals a full grid of it;
//  - a stale grid (RoundRobin right after new data, Static before its refresh) changes the
//    variance, not the mean: per-pixel z-scores against a fresh grid (Full) are consistent with
//    zero, while the same statistic rejects two different volumes (the test has power). A
//    control compares two fresh renders: the radiance here is heavy-tailed (measured: the median
//    pixel's variance from 64-sample batch means is 0.19x its per-sample estimate, the mean
//    ratio 1.00), so studentized z has a variance below 1 (chi2/n about 0.45) for any two
//    unbiased renders; the bounds below assume var(z) = 1 and are conservative for it.
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsRenderTestStatistics.h"
#include "vsRenderTestUtilities.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using vstest::Check;
using vstest::Compare;
using vstest::ConsistentWithZeroMean;
using vstest::Image;
using vstest::MeanVariance;
using vstest::ZStats;

const int NX = 20, NY = 18, NZ = 16;

vtkSmartPointer<vtkFloatArray> Field(const std::function<float(int, int, int)>& f)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetNumberOfTuples(NX * NY * NZ);
  for (int z = 0; z < NZ; ++z)
    for (int y = 0; y < NY; ++y)
      for (int x = 0; x < NX; ++x)
        a->SetValue((z * NY + y) * NX + x, f(x, y, z));
  return a;
}

// Two time steps of "the same simulation": the same grid, different data.
vtkSmartPointer<vtkFloatArray> StepA()
{
  return Field([](int x, int y, int z) { return float((x + 2 * y + 3 * z) % 7) / 6.0f; });
}
vtkSmartPointer<vtkFloatArray> StepB()
{
  return Field([](int x, int y, int z) { return x > 11 || z < 4 ? 1.0f : 0.15f * float((x + y) % 3); });
}

// A volume, a two-tone sky and a mapper in a 24 x 24 window.
struct Scene
{
  vtkNew<vtkImageData> Image;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkEnvironmentMapSource> Sky;
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  explicit Scene(vtkDataArray* data)
  {
    this->Image->SetDimensions(NX, NY, NZ);
    this->Image->GetPointData()->SetScalars(data);
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, 0.3);
    this->Color->AddRGBPoint(0.0, 1, 1, 1);
    this->Color->AddRGBPoint(1.0, 1, 0.5, 0.2);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Sky->SetTypeToTwoToneSky();
    this->Sky->SetUpperColor(2.0, 1.8, 1.5);
    this->Sky->SetLowerColor(0.1, 0.1, 0.2);
    this->Sky->SetOctahedralSize(16);
    this->Mapper->SetInputData(this->Image);
    this->Mapper->SetEnvironmentConnection(this->Sky->GetOutputPort());
    // The lazy updates of animated volumes on a grid swept at once (TestMapperProgressive covers
    // the progressive fill-in and the Auto strategy).
    this->Mapper->SetSamplingStrategyToTwoStep();
    this->Mapper->SetProgressiveVisibility(false);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(24, 24);
    this->Renderer->ResetCamera();
  }

  void SetData(vtkDataArray* data) { this->Image->GetPointData()->SetScalars(data); }

  /** Renders until `spp` samples per pixel (64 per Render()). */
  void Converge(int spp)
  {
    this->Mapper->SetSamplesPerFrame(64);
    this->Mapper->SetMaximumSamples(spp);
    do
    {
      this->Window->Render();
      Check(std::string(this->Mapper->GetLastError()).empty(), this->Mapper->GetLastError());
    } while (!this->Mapper->IsConverged() && vstest::Failures() == 0);
  }
};

// Renders once after a data change and checks the directions swept.
void ExpectSwept(Scene& s, int directions, const std::string& what)
{
  const int majorants = s.Mapper->GetMajorantUpdateCount();
  const int resets = s.Mapper->GetAccumulationResetCount();
  s.Window->Render();
  Check(std::string(s.Mapper->GetLastError()).empty(), s.Mapper->GetLastError());
  Check(s.Mapper->GetDirectionsUpdatedLastFrame() == directions,
    what + ": swept " + std::to_string(s.Mapper->GetDirectionsUpdatedLastFrame()) + " directions, expected " +
      std::to_string(directions));
  Check(s.Mapper->GetMajorantUpdateCount() == majorants + 1, what + ": majorants are recomputed for new data");
  Check(s.Mapper->GetAccumulationResetCount() == resets + 1, what + ": accumulation restarts for new data");
}

void TestCounters()
{
  auto a = StepA(), b = StepB();
  // Full: every direction for every new time step.
  {
    Scene s(a);
    Check(s.Mapper->GetUpdateScheme() == vtkVisibilitySweepVolumeMapper::RoundRobin,
      "RoundRobin is the default (docs/reference.md)");
    s.Mapper->SetUpdateSchemeToFull();
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64, "the first computation is full");
    for (int i = 0; i < 3; ++i)
    {
      s.SetData(i % 2 ? a : b);
      ExpectSwept(s, 64, "Full, change " + std::to_string(i + 1));
    }
    Check(s.Mapper->GetVisibilityUpdateCount() == 4, "Full: one visibility update per change");
  }
  // RoundRobin, k = 4 and 8: N changes sweep N * k directions; other changes sweep everything.
  for (int k : { 4, 8 })
  {
    Scene s(a);
    s.Mapper->SetUpdateSchemeToRoundRobin();
    s.Mapper->SetDirectionsPerFrame(k);
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64, "RoundRobin: the first computation is full");
    const int n = 64 / k + 3;
    for (int i = 0; i < n; ++i)
    {
      s.SetData(i % 2 ? a : b);
      ExpectSwept(s, k, "RoundRobin k=" + std::to_string(k) + ", change " + std::to_string(i + 1));
    }
    Check(s.Mapper->GetDirectionsUpdatedTotal() == 64 + n * k, "RoundRobin: N changes sweep N * k directions");
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 0, "RoundRobin: no change, no sweep");
    s.Opacity->AddPoint(0.5, 0.2);
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64, "RoundRobin: an opacity change sweeps everything");
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(10, 9, 8);
    plane->SetNormal(1, 0, 0);
    s.Mapper->AddClippingPlane(plane);
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64, "RoundRobin: a clipping plane sweeps everything");
    s.SetData(b);
    s.Opacity->AddPoint(0.7, 0.25);
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64, "RoundRobin: new data and a new opacity sweep everything");
    // Conservative: with new data the table is resampled over the new range, so a property
    // change at the same time (even of colour only) is not told apart from an opacity change.
    s.Color->AddRGBPoint(0.5, 0.3, 0.9, 0.3);
    s.SetData(a);
    ExpectSwept(s, 64, "RoundRobin: new data and a property change sweep everything");
    s.SetData(b);
    ExpectSwept(s, k, "RoundRobin: new data alone is lazy again");
    s.Mapper->SetDirectionResolution(4);
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 16, "RoundRobin: a new direction resolution sweeps everything");
  }
  // An opacity change while a strategy without visibility renders is remembered: switching
  // back sweeps everything (the grid was computed for the old opacity).
  {
    Scene s(a);
    s.Window->Render();
    s.Mapper->SetSamplingStrategyToEnvironment();
    s.Opacity->AddPoint(0.5, 0.6);
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 0, "the Environment strategy never sweeps");
    s.Mapper->SetSamplingStrategyToTwoStep();
    s.Window->Render();
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64, "back to TwoStep after an opacity change: a full sweep");
  }
  // EnvironmentGuided: k directions per change (the whole two-tone sky is lit).
  {
    Scene s(a);
    s.Mapper->SetUpdateSchemeToEnvironmentGuided();
    s.Window->Render();
    for (int i = 0; i < 3; ++i)
    {
      s.SetData(i % 2 ? a : b);
      ExpectSwept(s, 4, "EnvironmentGuided, change " + std::to_string(i + 1));
    }
  }
  // Static, interval 4: nothing for 3 changes, everything at the 4th; twice.
  {
    Scene s(a);
    s.Mapper->SetUpdateSchemeToStatic();
    s.Mapper->SetStaticInterval(4);
    s.Window->Render();
    const int updates = s.Mapper->GetVisibilityUpdateCount();
    for (int i = 1; i <= 8; ++i)
    {
      s.SetData(i % 2 ? b : a);
      ExpectSwept(s, i % 4 == 0 ? 64 : 0, "Static interval 4, change " + std::to_string(i));
    }
    Check(s.Mapper->GetVisibilityUpdateCount() == updates + 2, "Static: two refreshes in 8 changes");
  }
}

std::vector<float> VisibilityValues(vtkVisibilitySweepVolumeMapper* m)
{
  vtkImageData* grid = m->GetVisibilityGrid();
  vtkDataArray* v = grid ? grid->GetPointData()->GetArray("Visibility") : nullptr;
  std::vector<float> out;
  if (v)
    for (vtkIdType i = 0; i < v->GetNumberOfValues(); ++i)
      out.push_back(float(v->GetVariantValue(i).ToDouble()));
  return out;
}

// After 64 / k RoundRobin changes, all with the new data, every direction was swept for it once:
// the grid is the full grid of the new data; one change earlier it is not yet.
void TestRoundRobinCycleRefreshesEverything()
{
  auto a = StepA(), b = StepB();
  Scene full(b);
  full.Window->Render();
  const std::vector<float> reference = VisibilityValues(full.Mapper);
  Scene s(a);
  s.Mapper->SetUpdateSchemeToRoundRobin();
  s.Window->Render();
  Check(VisibilityValues(s.Mapper) != reference, "the two time steps differ in visibility");
  for (int i = 0; i < 16; ++i)
  {
    if (i == 0)
      s.SetData(b);
    else
      b->Modified(); // the same data uploaded again: a data change
    s.Window->Render();
    if (i == 14)
      Check(VisibilityValues(s.Mapper) != reference, "15 of 16 round-robin changes leave stale directions");
  }
  Check(VisibilityValues(s.Mapper) == reference, "16 round-robin changes of 4 directions refresh the whole grid");
}

// Issue 35, class 2: the Preview and AmbientOcclusion images *are* the grid's light, so after a data
// change (the default RoundRobin scheme, or a grid left stale by Monte Carlo frames before a switch
// to them) their image and grid are those of a fresh mapper. They stayed A's in 60 of 64 directions,
// and once nothing was pending never recovered.
// The Preview's radiance (its window image also depends on whether the skybox is in the frame yet),
// or AmbientOcclusion's window image (it has no radiance).
std::vector<float> LitImage(Scene& s)
{
  std::vector<float> out;
  if (s.Mapper->GetRenderMode() == vtkVisibilitySweepVolumeMapper::Preview)
  {
    vtkImageData* r = s.Mapper->GetRadiance();
    vtkDataArray* a = r ? r->GetPointData()->GetArray("Radiance") : nullptr;
    for (vtkIdType i = 0; a && i < a->GetNumberOfValues(); ++i)
      out.push_back(float(a->GetVariantValue(i).ToDouble()));
    return out;
  }
  for (int v : vstest::WindowPixels(s.Window))
    out.push_back(float(v));
  return out;
}

void TestLitModesAfterDataChange()
{
  auto a = StepA(), b = StepB();
  for (int mode : { vtkVisibilitySweepVolumeMapper::Preview, vtkVisibilitySweepVolumeMapper::AmbientOcclusion })
  {
    Scene fresh(b);
    fresh.Mapper->SetRenderMode(mode);
    fresh.Window->Render();
    Check(std::string(fresh.Mapper->GetLastError()).empty(), fresh.Mapper->GetLastError());
    const std::vector<float> reference = LitImage(fresh);
    const std::vector<float> referenceGrid = VisibilityValues(fresh.Mapper);
    const std::string name = mode == vtkVisibilitySweepVolumeMapper::Preview ? "Preview" : "AmbientOcclusion";

    Scene changed(a);
    changed.Mapper->SetRenderMode(mode);
    changed.Mapper->SetUpdateSchemeToRoundRobin();
    changed.Window->Render();
    Check(LitImage(changed) != reference, name + ": the two time steps look different");
    changed.SetData(b);
    changed.Window->Render();
    Check(std::string(changed.Mapper->GetLastError()).empty(), changed.Mapper->GetLastError());
    Check(LitImage(changed) == reference, name + ": after new data the image is a fresh mapper's");
    Check(VisibilityValues(changed.Mapper) == referenceGrid, name + ": after new data the grid is a fresh mapper's");

    // Monte Carlo frames update the grid lazily (4 of 64 directions); a switch to the mode then
    // must not show the stale grid's light.
    Scene switched(a);
    switched.Mapper->SetUpdateSchemeToRoundRobin();
    switched.Mapper->SetMaximumSamples(1);
    switched.Window->Render();
    switched.SetData(b);
    switched.Window->Render();
    switched.Mapper->SetRenderMode(mode);
    switched.Window->Render();
    Check(std::string(switched.Mapper->GetLastError()).empty(), switched.Mapper->GetLastError());
    Check(LitImage(switched) == reference,
      name + ": after lazy Monte Carlo updates, the switch to the mode shows a fresh mapper's image");
  }
}

// Volume B rendered with a grid that is still (mostly or wholly) volume A's, against B with a
// fresh grid: the same mean.
void TestStaleGridIsUnbiased()
{
  const int spp = 1024;
  auto a = StepA(), b = StepB();
  Scene fresh(b);
  fresh.Mapper->SetSeed(7);
  fresh.Converge(spp);
  const Image reference = vstest::Grab(fresh.Mapper);

  // Control: B with a fresh grid and another seed. Its z statistics are the baseline.
  Scene again(b);
  again.Mapper->SetSeed(5);
  again.Converge(spp);
  const ZStats control = Compare(vstest::Grab(again.Mapper), reference);
  std::printf("control, fresh vs fresh grid: %d pixels, mean z %.3f, chi2/n %.3f, |z|>3 %.3f\n", control.Pixels,
    control.MeanZ, control.Chi2 / std::max(1, control.Pixels), control.Beyond3);
  Check(ConsistentWithZeroMean(control), "two renders of the same scene must agree");

  Scene other(a);
  other.Mapper->SetSeed(9);
  other.Converge(spp);
  const ZStats power = Compare(vstest::Grab(other.Mapper), reference);
  std::printf("volume A vs volume B: %d pixels, mean z %.3f, chi2/n %.3f, |z|>3 %.3f\n", power.Pixels, power.MeanZ,
    power.Chi2 / std::max(1, power.Pixels), power.Beyond3);
  Check(!ConsistentWithZeroMean(power), "the z statistic must reject two different volumes");

  for (int scheme : { vtkVisibilitySweepVolumeMapper::RoundRobin, vtkVisibilitySweepVolumeMapper::StaticUpdate })
  {
    Scene stale(a);
    stale.Mapper->SetUpdateScheme(scheme);
    stale.Mapper->SetSeed(11);
    stale.Window->Render(); // the grid of A
    stale.SetData(b);
    stale.Converge(spp);   // B with 4 (RoundRobin) or 0 (Static) of 64 directions swept for B
    Check(stale.Mapper->GetDirectionsUpdatedTotal() == 64 + (scheme == vtkVisibilitySweepVolumeMapper::RoundRobin ? 4 : 0),
      "the grid is stale while B renders");
    const Image image = vstest::Grab(stale.Mapper);
    const ZStats z = Compare(image, reference);
    std::printf("%s stale grid vs fresh grid: %d pixels, mean z %.3f, chi2/n %.3f, |z|>3 %.3f, "
                "variance ratio %.3f\n",
      stale.Mapper->GetUpdateSchemeAsString(), z.Pixels, z.MeanZ, z.Chi2 / std::max(1, z.Pixels), z.Beyond3,
      MeanVariance(image) / MeanVariance(reference));
    Check(ConsistentWithZeroMean(z), std::string(stale.Mapper->GetUpdateSchemeAsString()) +
        ": a stale grid must not change the mean");
  }
}
}

int TestMapperLazyUpdates(int, char*[])
{
  TestCounters();
  TestRoundRobinCycleRefreshesEverything();
  TestLitModesAfterDataChange();
  TestStaleGridIsUnbiased();
  return vstest::ExitCode();
}
