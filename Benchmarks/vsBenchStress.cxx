#include "vsBenchStress.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"
#include "vsRenderCommand.h"
#include "vsSceneFile.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

namespace vstool
{
namespace
{
struct Options
{
  std::string Scene = ExampleScene("tiny.json");
  std::string Json;
  int Changes = 10000;
  int Samples = 1000000;
  int Size = 16;
};

long ResidentKilobytes()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * 4;
}

int NonFinite(vtkVisibilitySweepVolumeMapper* m)
{
  vtkImageData* r = m->GetRadiance();
  if (!r)
    return 0;
  vtkDataArray* a = r->GetPointData()->GetArray("Radiance");
  int bad = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      bad += !std::isfinite(a->GetComponent(i, c));
  return bad;
}

int Run(const Options& o)
{
  CheckBenchOutputs({ { "--json", o.Json } });
  Scene scene = ReadSceneFile(o.Scene);
  scene.Render.Width = scene.Render.Height = o.Size;
  nlohmann::json report;
  report["scene"] = o.Scene;

  // 1. Random churn.
  {
    SceneObjects s = BuildScene(scene);
    auto* m = s.Mapper.Get();
    m->SetInteractiveUpdateRate(0.0);
    m->SetSamplesPerFrame(1);
    m->SetMaximumSamples(1 << 30);
    vtkPiecewiseFunction* opacity = s.Property->GetScalarOpacity();
    vtkNew<vtkPiecewiseFunction> original;
    original->DeepCopy(opacity);
    double range[2];
    s.Image->GetScalarRange(range);
    double b[6];
    s.Image->GetBounds(b);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    vtkNew<vtkPlane> plane;
    int errors = 0, nonFinite = 0;
    long rssWarm = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < o.Changes; ++i)
    {
      switch (int(U(rng) * 6))
      {
        case 0:
          opacity->AddPoint(range[0] + U(rng) * (range[1] - range[0]), U(rng));
          if (opacity->GetSize() > 16)
            opacity->DeepCopy(original);
          break;
        case 1:
          s.Renderer->GetActiveCamera()->Azimuth(360.0 * U(rng));
          s.Renderer->GetActiveCamera()->Elevation(30.0 * U(rng) - 15.0);
          s.Renderer->GetActiveCamera()->OrthogonalizeViewUp();
          s.Renderer->ResetCameraClippingRange();
          break;
        case 2:
          m->SetEnvironmentIntensity(2.0 * U(rng));
          break;
        case 3:
          m->SetSamplingStrategy(int(U(rng) * 5));
          break;
        case 4:
          m->RemoveAllClippingPlanes();
          if (U(rng) < 0.5)
          {
            plane->SetOrigin(b[0] + U(rng) * (b[1] - b[0]), b[2] + U(rng) * (b[3] - b[2]), b[4] + U(rng) * (b[5] - b[4]));
            plane->SetNormal(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
            m->AddClippingPlane(plane);
          }
          break;
        default:
          m->SetCropping(U(rng) < 0.5);
          m->SetCroppingRegionPlanes(b[0], b[0] + U(rng) * (b[1] - b[0]), b[2], b[3], b[4] + U(rng) * (b[5] - b[4]), b[5]);
          break;
      }
      s.Window->Render();
      errors += *m->GetLastError() != '\0';
      nonFinite += NonFinite(m);
      if (i == std::min(100, o.Changes - 1))
        rssWarm = ResidentKilobytes();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const long growth = ResidentKilobytes() - rssWarm;
    std::printf("churn: %d random changes, a render after each, in %.1f s: %d errors, %d non-finite values, "
                "resident memory %+ld KB after the first 100\n",
      o.Changes, seconds, errors, nonFinite, growth);
    report["churn"] = { { "changes", o.Changes }, { "seconds", seconds }, { "errors", errors },
      { "non_finite", nonFinite }, { "rss_growth_kb", growth } };
  }

  // 2. A long accumulation: the halves of the run agree within their statistical error.
  {
    SceneObjects s = BuildScene(scene);
    auto* m = s.Mapper.Get();
    m->SetInteractiveUpdateRate(0.0);
    const int half = o.Samples / 2;
    m->SetMaximumSamples(2 * half);
    m->SetSamplesPerFrame(std::min(half, 1 << 16));
    const auto t0 = std::chrono::steady_clock::now();
    while (m->GetAccumulatedSamples() < half)
      s.Window->Render();
    vtkNew<vtkFloatArray> first;
    vtkNew<vtkDoubleArray> firstVar;
    first->DeepCopy(m->GetRadiance(true)->GetPointData()->GetArray("Radiance"));
    firstVar->DeepCopy(m->GetRadiance(true)->GetPointData()->GetArray("Variance"));
    while (m->GetAccumulatedSamples() < 2 * half)
      s.Window->Render();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    vtkDataArray* all = m->GetRadiance(true)->GetPointData()->GetArray("Radiance");
    double worst = 0.0;
    int nonFinite = 0;
    for (vtkIdType i = 0; i < all->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c)
      {
        const double m1 = first->GetComponent(i, c), m2 = 2.0 * all->GetComponent(i, c) - m1;
        const double se = std::sqrt(2.0 * firstVar->GetComponent(i, c) / half);
        if (!std::isfinite(m2))
          ++nonFinite;
        else if (se > 0.0)
          worst = std::max(worst, std::abs(m1 - m2) / se);
      }
    std::printf("accumulation: %d samples per pixel on %d x %d in %.1f s: the halves differ by at most %.2f "
                "standard errors; %d non-finite values\n",
      2 * half, o.Size, o.Size, seconds, worst, nonFinite);
    report["accumulation"] = { { "samples", 2 * half }, { "seconds", seconds }, { "worst_half_difference_sigma", worst },
      { "non_finite", nonFinite } };
  }
  if (!o.Json.empty())
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
  return 0;
}
}

void AddBenchStress(CLI::App& bench)
{
  auto o = std::make_shared<Options>();
  auto* cmd = bench.add_subcommand("stress", "long stress runs: random churn and a very long accumulation");
  cmd->add_option("scene", o->Scene, "scene file (default: Examples/Scenes/tiny.json)");
  cmd->add_option("--changes", o->Changes, "random changes, a render after each (default 10000)")
    ->check(CLI::Range(1, 100000000));
  cmd->add_option("--samples", o->Samples, "samples per pixel of the long accumulation (default 1000000)")
    ->check(CLI::Range(2, 1 << 30));
  cmd->add_option("--size", o->Size, "image width and height (default 16)")->check(CLI::Range(1, 4096));
  cmd->add_option("--json", o->Json, "write the figures as JSON");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
