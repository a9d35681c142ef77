#include "vsBenchOverhead.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"
#include "vsRenderCommand.h"
#include "vsSceneFile.h"

#include "vsContext.h"
#include "vsKernelOptions.h"
#include "vsMarchRate.h"
#include "vsVolumeScene.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vtkVolume.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace vstool
{
namespace
{
struct Options
{
  std::string Scene = ExampleScene("brain_sunrise.json");
  std::string Json;
  int Width = 256, Height = 256, Spp = 4, Repeats = 3;
  std::vector<std::string> Strategies{ "uniform", "environment", "visibility", "combined", "two-step" };
  bool CellModes = true;
  bool Quick = false;
  int ShadowRays = 0; // 0: the scene's (render.shadow_rays)
  std::string Camera = "collision";
  std::string Control; // empty: the mapper's default
  std::string Sampler; // empty: the mapper's default
  std::string Transmittance; // empty: the mapper's default
  std::vector<double> Defensive{ 0.0 }; // TwoStep's defensive weights to measure
  int MaxEvents = 0;      // 0: the scene's render.max_scattering_events
  std::string LightEvents; // "LO:HI": next-event estimation alone, at those events only
  int RouletteDepth = 0;   // 0: the mapper's default
};

struct Measurement
{
  std::string Strategy, CellMode;
  double Defensive = 0.0;
  double SecondsPerFrame = 0.0; // device seconds of one frame of `spp` samples per pixel (median)
  double PathsPerSecond = 0.0;
  double Variance = 0.0;        // mean over pixels and rgb of the variance of one sample
  double MeanRadiance = 0.0;
  double Lookups[3] = { 0, 0, 0 }; // per path: volume samples, majorant loads, visibility texels
  double LaneOccupancy = 1.0;      // tracking steps the lanes took / steps their SIMD groups ran x width
  double SweepSeconds = 0.0;
  double EventsPerPath = 0.0;      // scattering events per path (full transport)
  double BlockedShadowRays = 0.0;  // the fraction of shadow rays with transmittance below 0.01
  double ShadowRaysPerPath = 0.0;
};

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

void RenderChecked(SceneObjects& objects)
{
  objects.Window->Render();
  const char* error = objects.Mapper->GetLastError();
  if (error && *error)
  {
    throw std::runtime_error(std::string("render failed: ") + error);
  }
}

Measurement Measure(
  SceneObjects& objects, const Options& o, const std::string& strategy, int cellMode, bool table = true,
  double defensive = 0.0)
{
  vtkVisibilitySweepVolumeMapper* mapper = objects.Mapper;
  mapper->SetDirectionTable(table);
  mapper->SetDefensiveWeight(defensive);
  mapper->SetSamplingStrategy(StrategyIndex(strategy, "--strategies"));
  mapper->SetCellMode(cellMode);
  if (o.ShadowRays > 0)
  {
    mapper->SetShadowRays(o.ShadowRays);
  }
  using vs::KernelOptionId;
  mapper->SetCameraEstimator(vs::KernelOptionValueOf(KernelOptionId::CameraEstimator, o.Camera));
  if (!o.Sampler.empty())
  {
    mapper->SetSampler(vs::KernelOptionValueOf(KernelOptionId::Sampler, o.Sampler));
  }
  if (!o.Control.empty())
  {
    mapper->SetControlExtinction(vs::KernelOptionValueOf(KernelOptionId::ControlExtinction, o.Control));
  }
  if (!o.Transmittance.empty())
  {
    mapper->SetTransmittanceEstimator(vs::KernelOptionValueOf(KernelOptionId::Transmittance, o.Transmittance));
  }
  mapper->SetMaximumSamples(1 << 30);
  mapper->SetSamplesPerFrame(o.Spp);
  Measurement m;
  m.Strategy = strategy;
  m.Defensive = defensive;
  const bool usesGrid = strategy == "visibility" || strategy == "combined" || strategy == "two-step";
  m.CellMode = cellMode == vtkVisibilitySweepVolumeMapper::TrilinearCells ? "trilinear"
    : !usesGrid                                                          ? "-"
    : table                                                              ? "table"
                                                                         : "stoch-map";
  const int sweepsBefore = mapper->GetVisibilityUpdateCount();
  RenderChecked(objects); // warm-up: sweeps (if this strategy needs them first), pipeline creation
  if (mapper->GetVisibilityUpdateCount() > sweepsBefore)
  {
    m.SweepSeconds = mapper->GetLastSweepSeconds();
  }
  std::vector<double> seconds;
  for (int r = 0; r < o.Repeats; ++r)
  {
    RenderChecked(objects);
    seconds.push_back(mapper->GetLastDeviceSeconds());
  }
  const double pixels = double(o.Width) * o.Height;
  m.SecondsPerFrame = Median(seconds);
  m.PathsPerSecond = m.SecondsPerFrame > 0.0 ? pixels * o.Spp / m.SecondsPerFrame : 0.0;

  vtkImageData* radiance = mapper->GetRadiance(true);
  vtkDataArray* var = radiance->GetPointData()->GetArray("Variance");
  auto* rgb = vtkFloatArray::SafeDownCast(radiance->GetPointData()->GetArray("Radiance"));
  double v = 0.0, mean = 0.0;
  for (vtkIdType i = 0; i < var->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      v += var->GetComponent(i, c);
      mean += rgb->GetComponent(i, c);
    }
  }
  m.Variance = v / (3.0 * double(var->GetNumberOfTuples()));
  m.MeanRadiance = mean / (3.0 * double(rgb->GetNumberOfTuples()));

  // One instrumented frame of the timed frames' size for the read counts (32-bit counters; at most
  // 1024 spp x 4096^2 pixels would overflow them, the bench's sizes are far below). Its lane
  // occupancy is that of a normal frame: a lane whose path ended starts the pixel's next sample
  // (regeneration) while others still trace.
  mapper->SetSamplesPerFrame(o.Spp);
  mapper->CountLookupsOn();
  RenderChecked(objects);
  mapper->CountLookupsOff();
  for (int k = 0; k < 3; ++k)
  {
    m.Lookups[k] = mapper->GetLastLookupCounts()[k] / (pixels * o.Spp);
  }
  m.LaneOccupancy = mapper->GetLastLaneOccupancy();
  const double* shadow = mapper->GetLastShadowRayCounts();
  m.BlockedShadowRays = shadow[0] > 0.0 ? shadow[1] / shadow[0] : 0.0;
  m.ShadowRaysPerPath = shadow[0] / (pixels * o.Spp);
  m.EventsPerPath = mapper->GetMeanScatteringEvents();
  return m;
}

int Run(const Options& given)
{
  CheckBenchOutputs({ { "--json", given.Json } });
  Options o = given;
  if (o.Quick)
  {
    o.Width = std::min(o.Width, 64);
    o.Height = std::min(o.Height, 64);
    o.Spp = 1;
    o.Repeats = 1;
  }
  Scene scene = ReadSceneFile(o.Scene);
  scene.Render.Width = o.Width;
  scene.Render.Height = o.Height;
  SceneObjects objects = BuildScene(scene);
  vtkVisibilitySweepVolumeMapper* mapper = objects.Mapper;
  mapper->SetInteractiveUpdateRate(0.0); // always full-resolution frames
  mapper->SetProgressiveVisibility(false); // per-sample figures of a complete grid: swept in the warm-up frame
  if (o.MaxEvents > 0)
  {
    mapper->SetMaximumScatteringEvents(o.MaxEvents);
  }
  if (o.RouletteDepth > 0)
  {
    mapper->SetRussianRouletteDepth(o.RouletteDepth);
  }
  if (!o.LightEvents.empty())
  {
    // Next-event estimation alone, at events LO..HI only: the light sample's variance at that depth.
    int lo = 0, hi = 0;
    char colon = 0;
    std::istringstream in(o.LightEvents);
    if (!(in >> lo >> colon >> hi) || colon != ':' || lo < 1 || hi < lo || !in.eof())
    {
      throw std::runtime_error("--light-events " + o.LightEvents + ": expected LO:HI with 1 <= LO <= HI");
    }
    mapper->SetMultipleImportanceSampling(vtkVisibilitySweepVolumeMapper::LightSamplingOnly);
    mapper->SetLightEventRange(lo, hi);
  }

  std::printf("scene %s, %d x %d, %d spp per timed frame, median of %d frames (device time of the render pass)\n",
    o.Scene.c_str(), o.Width, o.Height, o.Spp, o.Repeats);
  std::vector<Measurement> results;
  for (const auto& s : o.Strategies)
  {
    const bool usesGrid = s == "visibility" || s == "combined" || s == "two-step";
    // TwoStep at each defensive weight asked for; the others once.
    for (double alpha : s == "two-step" ? o.Defensive : std::vector<double>{ 0.0 })
    {
      results.push_back(Measure(objects, o, s, vtkVisibilitySweepVolumeMapper::StochasticCell, true, alpha));
    }
    if (usesGrid && o.CellModes)
    {
      // The same stochastic cell with the map built at each scatter event instead of the table.
      results.push_back(Measure(objects, o, s, vtkVisibilitySweepVolumeMapper::StochasticCell, false));
      results.push_back(Measure(objects, o, s, vtkVisibilitySweepVolumeMapper::TrilinearCells));
    }
  }
  const Measurement* uniform = nullptr;
  for (const auto& m : results)
  {
    if (m.Strategy == "uniform")
    {
      uniform = &m;
    }
  }

  nlohmann::json report;
  report["scene"] = o.Scene;
  report["width"] = o.Width;
  report["height"] = o.Height;
  report["spp_per_frame"] = o.Spp;
  report["repeats"] = o.Repeats;
  report["max_scattering_events"] = mapper->GetMaximumScatteringEvents();
  report["light_events"] = o.LightEvents;
  report["roulette_depth"] = mapper->GetRussianRouletteDepth();
  std::printf("\n%-12s %-10s %5s %12s %9s %10s %10s %9s %6s %11s %10s %8s %8s\n", "strategy", "cells", "alpha", "paths/s",
    "cost/Uni", "vol/path", "vis/path", "Mvol/s", "lanes", "var/sample", "eff/Uni", "ev/path", "T<0.01");
  for (const auto& m : results)
  {
    // Equal-time error of an unbiased estimator ~ variance x time per sample: efficiency = 1 / (var t).
    const double t = m.PathsPerSecond > 0.0 ? 1.0 / m.PathsPerSecond : 0.0;
    const double eff = m.Variance > 0.0 && t > 0.0 ? 1.0 / (m.Variance * t) : 0.0;
    const double effU = uniform && uniform->Variance > 0.0 ? uniform->Variance / uniform->PathsPerSecond : 0.0;
    const double relEff = effU > 0.0 ? eff * effU : 0.0;
    const double cost = uniform && m.PathsPerSecond > 0.0 ? uniform->PathsPerSecond / m.PathsPerSecond : 0.0;
    const double volRate = m.PathsPerSecond * m.Lookups[0];
    std::printf("%-12s %-10s %5.2f %12.0f %9.2f %10.1f %10.1f %9.1f %6.2f %11.3g %10.2f %8.2f %8.3f\n", m.Strategy.c_str(),
      m.CellMode.c_str(), m.Defensive, m.PathsPerSecond, cost, m.Lookups[0], m.Lookups[2], volRate / 1e6,
      m.LaneOccupancy, m.Variance, relEff, m.EventsPerPath, m.BlockedShadowRays);
    report["strategies"].push_back({ { "strategy", m.Strategy }, { "cell_mode", m.CellMode },
      { "defensive_weight", m.Defensive },
      { "seconds_per_frame", m.SecondsPerFrame }, { "paths_per_second", m.PathsPerSecond },
      { "time_per_sample_relative_to_uniform", cost }, { "volume_samples_per_path", m.Lookups[0] },
      { "majorant_loads_per_path", m.Lookups[1] }, { "visibility_texels_per_path", m.Lookups[2] },
      { "lane_occupancy", m.LaneOccupancy },
      { "volume_samples_per_second", volRate }, { "variance_per_sample", m.Variance },
      { "mean_radiance", m.MeanRadiance }, { "efficiency_relative_to_uniform", relEff },
      { "sweep_seconds", m.SweepSeconds }, { "scattering_events_per_path", m.EventsPerPath },
      { "shadow_rays_per_path", m.ShadowRaysPerPath }, { "blocked_shadow_ray_fraction", m.BlockedShadowRays } });
  }
  std::printf("(cost/Uni: device time per sample relative to Uniform; vol, vis: trilinear volume samples and\n"
              " visibility texels read per path; lanes: SIMD occupancy of the tracking loops, the steps the lanes\n"
              " took over the steps their groups ran x the group's width; eff/Uni: 1/(variance x time per sample) relative to Uniform,\n"
              " i.e. how much faster the error falls at equal time; ev/path: scattering events per path; T<0.01: the\n"
              " fraction of shadow rays whose transmittance was below 0.01, from the counted frame)\n");

  // The device's ceiling: the plainest trilinear ray march over the same volume.
  vs::VolumeScene plain(vs::Context::Default());
  plain.Update(objects.Image, objects.Image->GetPointData()->GetScalars(), objects.Volume->GetProperty(),
    objects.Volume->GetMatrix(), mapper->GetDensityScale());
  const auto& dims = plain.Geometry().Dims;
  vs::MarchRate rate = vs::MeasureMarchRate(plain.GetContext(), plain.Volume(), plain.TF(),
    { uint32_t(dims[0]), uint32_t(dims[1]), uint32_t(dims[2]) }, o.Quick ? 64 : 512, 0.5f, o.Repeats);
  double best = 0.0;
  for (const auto& m : results)
  {
    best = std::max(best, m.PathsPerSecond * m.Lookups[0]);
  }
  std::printf("\nplain ray march (trilinear + classification, 8 imageLoads each): %.1f M samples/s = %.0f M imageLoad/s\n"
              "render kernel, best strategy: %.1f M volume samples/s = %.0f%% of the plain march\n",
    rate.SamplesPerSecond() / 1e6, 8.0 * rate.SamplesPerSecond() / 1e6, best / 1e6,
    rate.SamplesPerSecond() > 0.0 ? 100.0 * best / rate.SamplesPerSecond() : 0.0);
  report["plain_march"] = { { "samples", rate.Samples }, { "seconds", rate.Seconds },
    { "samples_per_second", rate.SamplesPerSecond() }, { "imageloads_per_second", 8.0 * rate.SamplesPerSecond() } };
  if (!o.Json.empty())
  {
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}
}

void AddBenchOverhead(CLI::App& bench)
{
  auto o = std::make_shared<Options>();
  auto* cmd = bench.add_subcommand("overhead",
    "samples per second of each strategy against Uniform, their equal-time efficiency, and the kernel's "
    "volume-read rate against a plain ray march");
  cmd->add_option("scene", o->Scene, "scene file (default: Examples/Scenes/brain_sunrise.json)");
  cmd->add_option("--width", o->Width, "image width")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", o->Height, "image height")->check(CLI::Range(1, 4096));
  cmd->add_option("--spp", o->Spp, "samples per pixel per timed frame")->check(CLI::Range(1, 1024));
  cmd->add_option("--repeats", o->Repeats, "timed frames per strategy (median)")->check(CLI::Range(1, 1000));
  cmd->add_option("--strategies", o->Strategies, "strategies to measure (default: all five)")->delimiter(',');
  cmd->add_flag("!--no-cell-modes", o->CellModes,
    "skip the variants of the grid strategies (stochastic cell without the direction table, trilinear cells)");
  cmd->add_flag("--quick", o->Quick, "64 x 64, 1 spp, 1 frame (seconds; for tests)");
  cmd->add_option("--shadow-rays", o->ShadowRays, "shadow rays per scatter point (splitting; default: the scene's render.shadow_rays)")->check(CLI::Range(1, 64));
  cmd->add_option("--sampler", o->Sampler,
       "pixel jitter and light directions: independent or sobol (the per-sample variance it reports does not "
       "show the Sobol sampler's gain, which is in the error of the mean: bench convergence)")
    ->check(CLI::IsMember(vs::KernelOptionWords(vs::KernelOptionId::Sampler)));
  cmd->add_option("--control", o->Control,
       "control extinction: none, shadow (residual ratio tracking), camera (decomposition tracking) or both")
    ->check(CLI::IsMember(vs::KernelOptionWords(vs::KernelOptionId::ControlExtinction)));
  cmd->add_option("--transmittance", o->Transmittance,
       "the shadow rays' transmittance estimator: ratio-tracking (residual with --control shadow or both) or "
       "ray-marching (Kettunen et al. 2021's unbiased ray marching)")
    ->check(CLI::IsMember(vs::KernelOptionWords(vs::KernelOptionId::Transmittance)));
  cmd->add_option("--max-scattering-events", o->MaxEvents,
       "the most scattering events a path may have (default: the scene's render.max_scattering_events)")
    ->check(CLI::Range(1, 100000));
  cmd->add_option("--roulette-depth", o->RouletteDepth, "the event from which Russian roulette may end a path")
    ->check(CLI::Range(1, 65535));
  cmd->add_option("--light-events", o->LightEvents,
    "LO:HI: next-event estimation alone, scored at scattering events LO to HI only (e.g. 1:1, 2:2, 3:4, 5:1024): "
    "the variance of the light sample at that depth, per strategy");
  cmd->add_option("--camera", o->Camera, "camera estimator: collision (delta tracking) or reservoir")
    ->check(CLI::IsMember(vs::KernelOptionWords(vs::KernelOptionId::CameraEstimator)));
  cmd->add_option("--defensive", o->Defensive, "TwoStep's defensive weights to measure (default 0 = plain TwoStep)")
    ->delimiter(',')
    ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--json", o->Json, "write the figures as JSON");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
