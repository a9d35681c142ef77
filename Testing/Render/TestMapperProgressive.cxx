// Progressive visibility and the Auto strategy through the mapper:
//  - the first frame does not wait for the sweeps (none run in it), the grid then fills in
//    frame by frame, brightest light first, and accumulation never restarts on the way;
//  - the image accumulated across the whole fill-in has the mean of a render whose grid was swept
//    before the first sample (per-pixel z-scores), and so has Auto against Environment sampling
//    (its frame-by-frame choice depends only on earlier samples);
//  - Auto reports its choice, sweeps nothing for a volume too thin to shadow, and under a deadline
//    (RemainingTimeBudget) sweeps only what can pay for itself before it;
//  - the mapper refuses direction resolutions its direction map cannot hold, and a resolution
//    raised after a first render refines the environment's importance levels.
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsRenderTestStatistics.h"
#include "vsRenderTestUtilities.h"

#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
using vstest::Check;

const int NX = 20, NY = 18, NZ = 16;

// A dense blob with a hole under a sun and a dim sky: strong, direction-dependent shadows.
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

  Scene()
  {
    vtkNew<vtkFloatArray> a;
    a->SetNumberOfTuples(NX * NY * NZ);
    for (int z = 0; z < NZ; ++z)
      for (int y = 0; y < NY; ++y)
        for (int x = 0; x < NX; ++x)
        {
          const double dx = x - 9.5, dy = y - 8.5, dz = z - 7.5, r2 = dx * dx + dy * dy + dz * dz;
          a->SetValue((z * NY + y) * NX + x, r2 < 49.0 && !(std::abs(dx) < 2 && std::abs(dy) < 2) ? 1.0f : 0.05f);
        }
    this->Image->SetDimensions(NX, NY, NZ);
    this->Image->GetPointData()->SetScalars(a);
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, 0.5);
    this->Color->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
    this->Color->AddRGBPoint(1.0, 0.9, 0.7, 0.5);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Sky->SetTypeToSunDisk();
    this->Sky->SetSunDirection(0.3, -0.5, 0.8);
    this->Sky->SetSunAngularRadius(3.0);
    this->Sky->SetSunRadiance(400.0, 380.0, 350.0);
    this->Sky->SetSkyColor(0.2, 0.25, 0.4);
    this->Sky->SetOctahedralSize(64);
    this->Mapper->SetInputData(this->Image);
    this->Mapper->SetEnvironmentConnection(this->Sky->GetOutputPort());
    this->Mapper->SetEnvironmentVisible(false);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(24, 24);
    this->Renderer->ResetCamera();
  }

  void Frame()
  {
    this->Window->Render();
    Check(std::string(this->Mapper->GetLastError()).empty(), this->Mapper->GetLastError());
  }

  /** Frames of `perFrame` samples until `spp`. */
  void Converge(int spp, int perFrame)
  {
    this->Mapper->SetSamplesPerFrame(perFrame);
    this->Mapper->SetMaximumSamples(spp);
    do
    {
      this->Frame();
    } while (!this->Mapper->IsConverged() && vstest::Failures() == 0);
  }
};

void TestFirstFrameDoesNotWait()
{
  Scene s;
  Check(s.Mapper->GetSamplingStrategy() == vtkVisibilitySweepVolumeMapper::Auto, "Auto is the default strategy");
  Check(s.Mapper->GetProgressiveVisibility(), "progressive visibility is on by default");
  s.Mapper->SetSamplingStrategyToTwoStep();
  s.Mapper->SetSweepFrameFraction(0.0); // one direction per frame
  s.Frame();
  Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 0, "the first frame sweeps nothing");
  Check(s.Mapper->GetDirectionsUpdatedTotal() == 0, "no sweep before the first image");
  // TwoStep over a grid of one value per cell is Environment sampling: rendered as such, no table.
  Check(s.Mapper->GetEffectiveStrategy() == vtkVisibilitySweepVolumeMapper::Environment,
    std::string("TwoStep's first frame (grid at visibility 1) samples the environment, got ") +
      s.Mapper->GetEffectiveStrategyAsString());
  Check(s.Mapper->GetDirectionTableBuildCount() == 0, "no direction table for a grid at visibility 1");
  const int pending = s.Mapper->GetPendingDirections();
  Check(pending > 0 && pending <= 64, "the grid's directions are pending after the first frame: " + std::to_string(pending));
  const int resets = s.Mapper->GetAccumulationResetCount();
  int frames = 1;
  while (s.Mapper->GetPendingDirections() > 0 && frames < 200)
  {
    const int before = s.Mapper->GetPendingDirections();
    s.Frame();
    ++frames;
    Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 1, "one direction per frame at budget 0, frame " + std::to_string(frames));
    Check(s.Mapper->GetPendingDirections() == before - 1, "the pending count falls by the directions swept");
    // One swept direction, copied into the others (FillUnsweptDirections): still one value per cell.
    const bool flat = s.Mapper->GetDirectionsUpdatedTotal() <= 1;
    Check(s.Mapper->GetEffectiveStrategy() ==
        (flat ? vtkVisibilitySweepVolumeMapper::Environment : vtkVisibilitySweepVolumeMapper::TwoStep),
      "frame " + std::to_string(frames) + " with " + std::to_string(s.Mapper->GetDirectionsUpdatedTotal()) +
        " directions swept renders as " + s.Mapper->GetEffectiveStrategyAsString());
  }
  Check(s.Mapper->GetDirectionTableBuildCount() > 0, "TwoStep builds its table once the grid is not flat");
  Check(frames == pending + 1, "the grid is complete after one frame per pending direction");
  Check(s.Mapper->GetAccumulationResetCount() == resets, "filling in never restarts accumulation");
  Check(s.Mapper->GetAccumulatedSamples() == frames, "every frame's sample was kept");
  s.Frame();
  Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 0, "a complete grid sweeps nothing more");
  // A budget of many directions per frame.
  s.Opacity->AddPoint(0.5, 0.2);
  s.Mapper->SetSweepFrameFraction(1000.0);
  s.Frame();
  Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 0, "an opacity change: again nothing in the first frame");
  s.Frame();
  s.Frame();
  Check(s.Mapper->GetPendingDirections() == 0, "a large budget fills the grid in a couple of frames");
  // Off: everything before the frame that needs it.
  s.Mapper->SetProgressiveVisibility(false);
  s.Opacity->AddPoint(0.7, 0.3);
  s.Frame();
  Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 64 - s.Mapper->GetUnlitDirections() &&
      s.Mapper->GetPendingDirections() == 0,
    "progressive off: the whole grid in the frame that needs it");
}

void TestFillInAndAutoAreUnbiased()
{
  const int spp = 768;
  Scene swept;
  swept.Mapper->SetSamplingStrategyToTwoStep();
  swept.Mapper->SetProgressiveVisibility(false);
  swept.Mapper->SetSeed(3);
  swept.Converge(spp, 64);
  const vstest::Image reference = vstest::Grab(swept.Mapper);

  Scene filling;
  filling.Mapper->SetSamplingStrategyToTwoStep();
  filling.Mapper->SetSweepFrameFraction(0.0); // one direction per frame: 64 frames of 8 spp fill in
  filling.Mapper->SetSeed(4);
  filling.Converge(spp, 8);
  Check(filling.Mapper->GetAccumulationResetCount() == 1, "one accumulation across the fill-in");
  const vstest::ZStats z = vstest::Compare(vstest::Grab(filling.Mapper), reference);
  std::printf("filled in progressively vs swept first: %d pixels, mean z %.3f, chi2/n %.3f, |z|>3 %.3f\n", z.Pixels,
    z.MeanZ, z.Chi2 / std::max(1, z.Pixels), z.Beyond3);
  Check(vstest::ConsistentWithZeroMean(z), "a grid filling in must not change the mean");

  Scene env;
  env.Mapper->SetSamplingStrategyToEnvironment();
  env.Mapper->SetSeed(5);
  env.Converge(spp, 64);
  const vstest::ZStats ze = vstest::Compare(vstest::Grab(env.Mapper), reference);
  std::printf("Environment vs TwoStep: %d pixels, mean z %.3f, chi2/n %.3f, |z|>3 %.3f\n", ze.Pixels, ze.MeanZ,
    ze.Chi2 / std::max(1, ze.Pixels), ze.Beyond3);
  Check(vstest::ConsistentWithZeroMean(ze), "two unbiased strategies must agree");

  Scene automatic;
  automatic.Mapper->SetSeed(6);
  automatic.Mapper->SetSweepFrameFraction(4.0);
  automatic.Mapper->SetAutoProbeFraction(4.0); // tiny frames: let the grid fill in within the test
  automatic.Converge(spp, 4);
  const vstest::ZStats za = vstest::Compare(vstest::Grab(automatic.Mapper), reference);
  std::printf("Auto vs TwoStep: %d pixels, mean z %.3f, chi2/n %.3f, |z|>3 %.3f; last frame %s, %d directions "
              "swept\n",
    za.Pixels, za.MeanZ, za.Chi2 / std::max(1, za.Pixels), za.Beyond3,
    automatic.Mapper->GetEffectiveStrategyAsString(), automatic.Mapper->GetDirectionsUpdatedTotal());
  Check(vstest::ConsistentWithZeroMean(za), "Auto's choices must not change the mean");
  Check(automatic.Mapper->GetAccumulationResetCount() == 1, "Auto's choices never restart accumulation");
  Check(automatic.Mapper->GetDirectionsUpdatedTotal() > 0, "Auto sweeps a volume that shadows");

  // The power check: the same statistic rejects a different image (twice the density).
  Scene denser;
  denser.Mapper->SetSamplingStrategyToEnvironment();
  denser.Mapper->SetDensityScale(2.0);
  denser.Mapper->SetSeed(8);
  denser.Converge(spp, 64);
  Check(!vstest::ConsistentWithZeroMean(vstest::Compare(vstest::Grab(denser.Mapper), reference)),
    "the z statistic must reject a different density");
}

void TestAutoReportsAndSkips()
{
  Scene s;
  s.Mapper->SetAutoProbeFraction(4.0); // tiny frames: let the grid fill in within the test
  s.Mapper->SetSweepFrameFraction(4.0);
  s.Frame();
  Check(s.Mapper->GetEffectiveStrategy() == vtkVisibilitySweepVolumeMapper::Environment,
    std::string("Auto's first frame samples the environment, got ") + s.Mapper->GetEffectiveStrategyAsString());
  Check(std::string(s.Mapper->GetSamplingStrategyAsString()) == "Auto", "the strategy prints as Auto");
  bool sawTwoStep = false;
  for (int i = 0; i < 120; ++i)
  {
    s.Frame();
    sawTwoStep = sawTwoStep || s.Mapper->GetEffectiveStrategy() == vtkVisibilitySweepVolumeMapper::TwoStep;
  }
  Check(sawTwoStep, "Auto measures TwoStep once the grid has the light's directions");

  Scene thin;
  thin.Mapper->SetDensityScale(1e-4);
  for (int i = 0; i < 20; ++i)
    thin.Frame();
  Check(thin.Mapper->GetDirectionsUpdatedTotal() == 0 && thin.Mapper->GetPendingDirections() == 0,
    "Auto sweeps nothing for a volume too thin to shadow");
  Check(thin.Mapper->GetEffectiveStrategy() == vtkVisibilitySweepVolumeMapper::Environment,
    "a thin volume: Environment sampling");
}

// Issue 39: under a deadline Auto sweeps only what can pay for itself before it. A deadline 1 ms
// away repays nothing but the first slab and direction (swept to learn their cost); without one,
// or with a far one, the same frames fill the grid in. A sample target is a horizon too: the samples
// left to MaximumSamples at the last frame's cost (vs::GridSchedule::RemainingSeconds), the nearer of
// the two when both are set. With 3 samples the view converges in 3 frames, and the 37 frames after
// it add none: they swept the whole grid before (64 directions), for samples that never came.
void TestAutoSweepsOnlyWhatTheDeadlineRepays()
{
  struct Case
  {
    double Deadline;
    int MaximumSamples;
    const char* Name;
  };
  const Case cases[] = { { 1e-3, 4096, "deadline 1 ms" }, { 0.0, 4096, "no deadline, 4096 spp" },
    { 1e6, 4096, "deadline 1e6 s" }, { 0.0, 3, "no deadline, 3 spp" }, { 1e6, 3, "deadline 1e6 s, 3 spp" } };
  int swept[5] = { 0, 0, 0, 0, 0 };
  for (int k = 0; k < 5; ++k)
  {
    Scene s;
    s.Mapper->SetAutoProbeFraction(4.0); // tiny frames: let the grid fill in within the test
    s.Mapper->SetSweepFrameFraction(4.0);
    s.Mapper->SetMaximumSamples(cases[k].MaximumSamples);
    const vtkMTimeType mtime = s.Mapper->GetMTime();
    s.Mapper->SetRemainingTimeBudget(cases[k].Deadline);
    Check(s.Mapper->GetMTime() == mtime, "the remaining time budget is the loop's state: it modifies nothing");
    for (int i = 0; i < 40; ++i)
    {
      s.Frame();
    }
    swept[k] = s.Mapper->GetDirectionsUpdatedTotal();
    Check(s.Mapper->GetAccumulationResetCount() == 1, "a deadline restarts nothing");
    std::printf("directions swept in 40 frames, %s: %d\n", cases[k].Name, swept[k]);
  }
  Check(swept[0] <= 1, "a deadline 1 ms away repays no sweep beyond the first direction, swept " + std::to_string(swept[0]));
  Check(swept[1] > 1 && swept[2] > 1, "without a deadline, or a far one, the same frames fill the grid in");
  Check(swept[3] <= 1 && swept[4] <= 1,
    "the samples left to a near target repay no sweep beyond the first direction, swept " + std::to_string(swept[3]) +
      " and " + std::to_string(swept[4]));

  // RenderUntilConverged sets it per frame and gives the caller's value back; NaN is refused.
  Scene s;
  s.Mapper->SetMaximumSamples(4);
  s.Mapper->SetRemainingTimeBudget(7.0);
  s.Mapper->RenderUntilConverged(s.Window, 30.0);
  Check(s.Mapper->GetRemainingTimeBudget() == 7.0, "RenderUntilConverged gives the caller's deadline back");
  vtkObject::GlobalWarningDisplayOff();
  s.Mapper->SetRemainingTimeBudget(std::nan(""));
  vtkObject::GlobalWarningDisplayOn();
  Check(s.Mapper->GetRemainingTimeBudget() == 7.0, "NaN is refused, the setting kept");
}

void TestDirectionResolutionLimits()
{
  Scene s;
  s.Mapper->SetSamplingStrategyToTwoStep();
  s.Mapper->SetProgressiveVisibility(false);
  s.Frame();
  const int uploads = s.Mapper->GetEnvironmentUploadCount();
  s.Mapper->SetDirectionResolution(16);
  s.Frame();
  Check(s.Mapper->GetDirectionsUpdatedLastFrame() == 256 - s.Mapper->GetUnlitDirections(),
    "16 x 16 directions after raising the resolution");
  Check(s.Mapper->GetEnvironmentUploadCount() >= uploads, "the environment is refined when needed");
  for (int d : { 32, 64, 3 })
  {
    vtkObject::GlobalWarningDisplayOff();
    s.Mapper->SetDirectionResolution(d); // refused by the setter, naming 2, 4, 8 or 16
    vtkObject::GlobalWarningDisplayOn();
    Check(s.Mapper->GetDirectionResolution() == 16,
      "DirectionResolution " + std::to_string(d) + " is refused; the renderer's direction map holds 16 x 16");
    s.Frame();
  }
}
}

int TestMapperProgressive(int, char*[])
{
  TestFirstFrameDoesNotWait();
  TestFillInAndAutoAreUnbiased();
  TestAutoReportsAndSkips();
  TestAutoSweepsOnlyWhatTheDeadlineRepays();
  TestDirectionResolutionLimits();
  return vstest::ExitCode();
}
