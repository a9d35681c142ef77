#include "vsBenchDenoise.h"
#include "vsBenchOutput.h"
#include "vsBenchScene.h"
#include "vsToolCommand.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace vstool
{
namespace
{
struct DenoiseOptions
{
  std::string SceneFile;
  int Size = 256;
  int ReferenceSpp = 256;
  int SamplesPerFrame = 1;
  std::vector<double> Times = { 1.0, 2.0, 4.0, 8.0 };
  std::vector<int> Radii = { 6 };
  std::string Json;
};

using Clock = std::chrono::steady_clock;

double SquaredError(const std::vector<double>& x, const std::vector<double>& ref)
{
  if (x.size() != ref.size() || ref.empty())
  {
    return std::nan("");
  }
  double e = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    e += (x[i] - ref[i]) * (x[i] - ref[i]);
  }
  return e;
}

struct Variant
{
  std::string Name;
  bool HandOver = false;
  int Radius = 0; // 0: no filter
};

struct Point
{
  double Seconds = 0.0, Error = std::nan("");
  int Spp = 0;
  double Share = 0.0;
  bool Denoised = false;
};

int Run(const DenoiseOptions& o)
{
  CheckBenchOutputs({ { "--json", o.Json } });
  Scene scene;
  SceneObjects objects = BuildRadianceScene(o.SceneFile, o.Size, scene);
  vtkVisibilitySweepVolumeMapper* mapper = objects.Mapper;
  vtkRenderWindow* win = objects.Window;
  vtkCamera* camera = objects.Renderer->GetActiveCamera();
  const double still = 0.0001, dragging = std::max(15.0, mapper->GetInteractiveUpdateRate());
  mapper->SetMaximumSamples(1 << 30);
  mapper->InteractivePreviewOn();
  std::vector<double> times = o.Times;
  std::sort(times.begin(), times.end());
  const int seed = mapper->GetSeed();

  std::printf("scene %s at %d x %d (the volume's radiance, environment not visible), strategy %s\n",
    o.SceneFile.c_str(), o.Size, o.Size, scene.Render.Strategy.c_str());
  // Everything compiled and built before anything is timed: pipelines, the grid, the light volume, the filter.
  camera->Azimuth(3.0);
  win->SetDesiredUpdateRate(dragging);
  win->Render();
  CheckRender(mapper);
  win->SetDesiredUpdateRate(still);
  mapper->DisplayDenoiseOn();
  mapper->SetSamplesPerFrame(2);
  for (int i = 0; i < 6; ++i)
  {
    win->Render();
    CheckRender(mapper);
  }
  mapper->DisplayDenoiseOff();
  camera->Azimuth(-3.0);

  // The reference: Monte Carlo at the measured view, another seed.
  const auto r0 = Clock::now();
  mapper->SetSeed(seed + 7919);
  mapper->SetSamplesPerFrame(std::min(o.ReferenceSpp, 8));
  do
  {
    win->Render();
    CheckRender(mapper);
  } while (mapper->GetAccumulatedSamples() < o.ReferenceSpp);
  const std::vector<double> reference = ImageRgb(mapper->GetRadiance());
  const std::vector<double> referenceVariance = ImageRgb(mapper->GetRadiance(true), "Variance");
  const int referenceSpp = mapper->GetAccumulatedSamples();
  double norm = 0.0, referenceNoise = 0.0;
  for (size_t i = 0; i < reference.size(); ++i)
  {
    norm += reference[i] * reference[i];
    referenceNoise += i < referenceVariance.size() ? referenceVariance[i] / referenceSpp : 0.0;
  }
  if (!(norm > 0.0))
  {
    throw std::runtime_error("the reference is black: nothing to compare");
  }
  std::printf("reference: %d spp in %.1f s; its own noise, relative to it: %.3e (subtracted from the figures below)\n",
    referenceSpp, SecondsSince(r0), referenceNoise / norm);
  mapper->SetSeed(seed);

  std::vector<Variant> variants = { { "estimate alone", false, 0 }, { "hand-over (as it is)", true, 0 } };
  for (int r : o.Radii)
  {
    variants.push_back({ "denoised r=" + std::to_string(r), false, r });
    variants.push_back({ "hand-over + denoised r=" + std::to_string(r), true, r });
  }
  std::vector<std::vector<Point>> results;
  for (const Variant& v : variants)
  {
    mapper->SetDisplayDenoise(v.Radius > 0);
    if (v.Radius > 0)
    {
      mapper->SetDisplayDenoiseRadius(v.Radius);
    }
    mapper->SetSamplesPerFrame(o.SamplesPerFrame);
    // Elsewhere first, so that the view below restarts its accumulation.
    camera->Azimuth(3.0);
    win->SetDesiredUpdateRate(v.HandOver ? dragging : still);
    win->Render();
    CheckRender(mapper);
    camera->Azimuth(-3.0);
    if (v.HandOver)
    {
      win->Render(); // the drag's last frame: the preview of the measured view
      CheckRender(mapper);
      win->SetDesiredUpdateRate(still);
    }
    std::vector<Point> points;
    const auto t0 = Clock::now();
    size_t next = 0;
    while (next < times.size())
    {
      win->Render();
      CheckRender(mapper);
      const double t = SecondsSince(t0);
      while (next < times.size() && t >= times[next])
      {
        Point p;
        p.Seconds = t;
        p.Spp = mapper->GetAccumulatedSamples();
        p.Share = mapper->GetLastPreviewShare();
        p.Denoised = mapper->GetLastDisplayDenoised();
        p.Error = (SquaredError(ImageRgb(mapper->GetDisplayedRadiance()), reference) - referenceNoise) / norm;
        points.push_back(p);
        ++next;
      }
    }
    results.push_back(points);
    std::printf("  %-28s", v.Name.c_str());
    for (const Point& p : points)
    {
      std::printf("  %.2f s: %.3e (%d spp%s%s)", p.Seconds, p.Error, p.Spp,
        p.Share > 0.0 ? (", share " + std::to_string(p.Share).substr(0, 4)).c_str() : "", p.Denoised ? ", filtered" : "");
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  mapper->DisplayDenoiseOff();

  nlohmann::json report;
  report["scene"] = o.SceneFile;
  report["size"] = o.Size;
  report["reference_spp"] = referenceSpp;
  report["reference_noise"] = referenceNoise / norm;
  std::printf("\nrelative MSE of what the window shows against the reference (its noise subtracted); in brackets the\n"
              "ratio to the estimate alone at the same time (same seed: the same samples):\n%-28s", "seconds after still");
  for (double t : times)
  {
    std::printf(" %20.0f", t);
  }
  std::printf("\n");
  for (size_t k = 0; k < variants.size(); ++k)
  {
    std::printf("%-28s", variants[k].Name.c_str());
    nlohmann::json row = { { "variant", variants[k].Name }, { "hand_over", variants[k].HandOver },
      { "radius", variants[k].Radius } };
    for (size_t i = 0; i < results[k].size(); ++i)
    {
      const Point& p = results[k][i];
      const double ratio = p.Error / results[0][i].Error;
      std::printf(" %11.3e (%5.2fx)", p.Error, ratio);
      row["points"].push_back({ { "seconds", p.Seconds }, { "relative_mse", p.Error }, { "spp", p.Spp },
        { "preview_share", p.Share }, { "denoised", p.Denoised } });
    }
    std::printf("\n");
    report["variants"].push_back(row);
  }
  if (!o.Json.empty())
  {
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}
}

void AddBenchDenoise(CLI::App& bench)
{
  auto o = std::make_shared<DenoiseOptions>();
  auto* cmd = bench.add_subcommand("denoise",
    "relative MSE of the image shown against a converged render at given seconds after the view became still: "
    "the estimate, the hand-over from the preview, the estimate through the display filter (DisplayDenoise), both");
  cmd->add_option("scene", o->SceneFile, "the scene file")->required();
  cmd->add_option("--size", o->Size, "image width and height (default 256)")->check(CLI::Range(8, 4096));
  cmd->add_option("--reference-spp", o->ReferenceSpp, "the reference's spp (default 256; its noise is subtracted)")
    ->check(CLI::Range(2, 1 << 20));
  cmd->add_option("--samples-per-frame", o->SamplesPerFrame, "samples per pixel of each timed frame (default 1)")
    ->check(CLI::Range(1, 1024));
  cmd->add_option("--times", o->Times, "the seconds after the view became still to compare at (default 1,2,4,8)")
    ->delimiter(',')
    ->check(CLI::Range(0.0, 3600.0));
  cmd->add_option("--radius", o->Radii, "the filter's DisplayDenoiseRadius, one or more (default 6)")
    ->delimiter(',')
    ->check(CLI::Range(1, 32));
  cmd->add_option("--json", o->Json, "write the figures as JSON");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
