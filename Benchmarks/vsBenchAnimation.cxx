#include "vsBenchAnimation.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"
#include "vsPendingFile.h"
#include "vsRenderCommand.h"
#include "vsRenderFrames.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace vstool
{
namespace
{
struct AnimationOptions
{
  std::string SceneFile;
  std::string Frames;
  double Budget = 2.0;
  int ReferenceSpp = 1024;
  int Repeats = 1;
  int Width = 0;
  int Height = 0;
  std::string Json;
  std::string Plot;
};

struct Method
{
  std::string Name;
  std::string Scheme;
  std::string Strategy;
};

const std::vector<Method>& Methods()
{
  static const std::vector<Method> methods{ { "full", "full", "two-step" }, { "round-robin", "round-robin", "two-step" },
    { "environment-guided", "environment-guided", "two-step" }, { "static", "static", "two-step" },
    { "environment (no sweeps)", "full", "environment" }, { "auto (round-robin)", "round-robin", "auto" } };
  return methods;
}

std::vector<double> RadianceOf(vtkVisibilitySweepVolumeMapper* mapper)
{
  vtkImageData* r = mapper->GetRadiance();
  vtkDataArray* rgb = r ? r->GetPointData()->GetArray("Radiance") : nullptr;
  if (!rgb)
  {
    throw std::runtime_error("the renderer produced no radiance image");
  }
  std::vector<double> out(size_t(rgb->GetNumberOfTuples()) * 3);
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      out[size_t(i) * 3 + c] = rgb->GetComponent(i, c);
  return out;
}

double Mse(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    sum += (a[i] - b[i]) * (a[i] - b[i]);
  return sum / double(std::max<size_t>(1, a.size()));
}

double MeanOf(const std::vector<double>& v, size_t first, size_t count)
{
  double sum = 0.0;
  for (size_t i = first; i < first + count; ++i)
    sum += v[i];
  return count ? sum / double(count) : 0.0;
}

// The per-frame references of the timed steps (after the first): TwoStep with a fresh grid
// every step, many samples, its own seed.
std::vector<std::vector<double>> References(Scene scene, FrameRange range, int spp)
{
  scene.Render.Strategy = "two-step";
  scene.Render.UpdateScheme = "full";
  scene.Render.Seed = 1000003;
  scene.Volume.TimeStep = range.First + 1;
  SceneObjects objects = BuildScene(scene);
  std::vector<std::vector<double>> refs;
  for (int step = range.First + 1; step <= range.Last; ++step)
  {
    if (step != range.First + 1)
    {
      ShowTimeStep(objects, scene, step);
    }
    const ProgressiveResult r = RenderProgressively(objects, spp, 16, 0.0, false);
    std::printf("reference of step %d: %d spp in %.1f s\n", step, r.Spp, r.Seconds);
    std::fflush(stdout);
    refs.push_back(RadianceOf(objects.Mapper));
  }
  return refs;
}

// One method over the range at `budget` seconds per frame (update + render). The first step is
// rendered once untimed: it computes every direction for every method (and creates the
// pipelines), so the timed steps all start from a complete grid of the step before.
nlohmann::json RunMethod(Scene scene, const Method& m, FrameRange range, double budget,
  const std::vector<std::vector<double>>& refs, int repeat)
{
  scene.Render.Seed = scene.Render.Seed + repeat;
  scene.Render.Strategy = m.Strategy;
  scene.Render.UpdateScheme = m.Scheme;
  scene.Volume.TimeStep = range.First;
  SceneObjects objects = BuildScene(scene);
  RenderProgressively(objects, 1, 1, 0.0, false);
  std::vector<double> mse, update, spp;
  nlohmann::json frames = nlohmann::json::array();
  for (int step = range.First + 1; step <= range.Last; ++step)
  {
    ShowTimeStep(objects, scene, step);
    const ProgressiveResult r = RenderProgressively(objects, 1 << 30, 1, budget, false);
    mse.push_back(Mse(RadianceOf(objects.Mapper), refs[size_t(step - range.First - 1)]));
    update.push_back(r.UpdateSeconds);
    spp.push_back(r.Spp);
    frames.push_back({ { "time_step", step }, { "mse", mse.back() }, { "update_seconds", r.UpdateSeconds },
      { "directions_updated", r.DirectionsUpdated }, { "spp", r.Spp }, { "seconds", r.Seconds } });
  }
  const size_t n = mse.size(), k = std::min<size_t>(20, n);
  nlohmann::json out;
  out["method"] = m.Name;
  out["update_scheme"] = m.Scheme;
  out["strategy"] = m.Strategy;
  out["frames"] = frames;
  out["mean_mse"] = MeanOf(mse, 0, n);
  out["mean_mse_first"] = MeanOf(mse, 0, k);
  out["mean_mse_last"] = MeanOf(mse, n - k, k);
  out["edge_frames"] = k;
  out["mean_update_seconds"] = MeanOf(update, 0, n);
  out["mean_spp"] = MeanOf(spp, 0, n);
  return out;
}

void PrintTable(const nlohmann::json& methods, size_t frames)
{
  std::printf("\n%-24s %12s %10s %12s %12s %14s %9s\n", "method", "mean MSE", "(spread)", "first MSE", "last MSE",
    "update s/frame", "mean spp");
  for (const auto& m : methods)
  {
    std::printf("%-24s %12.4g %10.2g %12.4g %12.4g %14.4f %9.1f\n", m["method"].get<std::string>().c_str(),
      m["mean_mse"].get<double>(), m["mean_mse_spread"].get<double>(), m["mean_mse_first"].get<double>(),
      m["mean_mse_last"].get<double>(), m["mean_update_seconds"].get<double>(), m["mean_spp"].get<double>());
  }
  std::printf("(timed steps after the first, which computes the full grid untimed; first/last: the first and "
              "last %zu of %zu timed steps)\n",
    std::min<size_t>(20, frames), frames);
  const double fullMse = methods[0]["mean_mse"], rrMse = methods[1]["mean_mse"];
  const double fullUpdate = methods[0]["mean_update_seconds"];
  const double rrUpdate = methods[1]["mean_update_seconds"];
  if (fullMse > 0.0 && fullUpdate > 0.0)
  {
    std::printf("round-robin / full: MSE x%.3f at x%.3f of the update cost\n", rrMse / fullMse, rrUpdate / fullUpdate);
  }
}

int Run(const AnimationOptions& o)
{
  CheckBenchOutputs({ { "--json", o.Json }, { "--plot", o.Plot } });
  RenderOptions ro;
  ro.SceneFile = o.SceneFile;
  ro.Width = o.Width;
  ro.Height = o.Height;
  Scene scene = LoadScene(ro);
  if (scene.Volume.Files.empty())
  {
    throw std::runtime_error("bench animation needs a volume sequence: give volume.files in the scene");
  }
  const int steps = int(scene.Volume.Files.size());
  const FrameRange range = ParseFrameRange(o.Frames.empty() ? "0:" + std::to_string(steps - 1) : o.Frames, steps);
  if (range.Last == range.First)
  {
    throw std::runtime_error("--frames '" + o.Frames + "': the benchmark needs at least two time steps");
  }
  std::printf("%s: steps %d..%d, %dx%d, %.2f s per frame (update + render), references %d spp\n",
    o.SceneFile.c_str(), range.First, range.Last, scene.Render.Width, scene.Render.Height, o.Budget, o.ReferenceSpp);
  const auto refs = References(scene, range, o.ReferenceSpp);
  // Repeat by repeat (each with its own seed), every method in turn: this machine's speed drifts
  // over minutes, and running all repeats of one method before the next would charge the drift
  // to the methods. A method's figures are the means over its repeats (spread: their standard
  // deviation); its per-frame figures are those of the first repeat.
  std::vector<std::vector<nlohmann::json>> runs(Methods().size());
  for (int r = 0; r < o.Repeats; ++r)
  {
    for (size_t i = 0; i < Methods().size(); ++i)
    {
      const Method& m = Methods()[i];
      runs[i].push_back(RunMethod(scene, m, range, o.Budget, refs, r));
      std::printf("%s, repeat %d: mean MSE %.4g\n", m.Name.c_str(), r, runs[i].back()["mean_mse"].get<double>());
      std::fflush(stdout);
    }
  }
  nlohmann::json methods = nlohmann::json::array();
  for (const auto& repeats : runs)
  {
    nlohmann::json m = repeats.front();
    for (const char* key : { "mean_mse", "mean_mse_first", "mean_mse_last", "mean_update_seconds", "mean_spp" })
    {
      std::vector<double> v;
      for (const auto& run : repeats)
      {
        v.push_back(run[key].get<double>());
      }
      const double mean = MeanOf(v, 0, v.size());
      double var = 0.0;
      for (double x : v)
      {
        var += (x - mean) * (x - mean);
      }
      m[key] = mean;
      m[std::string(key) + "_repeats"] = v;
      if (std::string(key) == "mean_mse")
      {
        m["mean_mse_spread"] = v.size() > 1 ? std::sqrt(var / double(v.size() - 1)) : 0.0;
      }
    }
    m["repeats"] = repeats.size();
    methods.push_back(m);
  }
  PrintTable(methods, size_t(range.Last - range.First));
  if (!o.Json.empty() || !o.Plot.empty())
  {
    nlohmann::json j = { { "scene", o.SceneFile }, { "first_step", range.First }, { "last_step", range.Last },
      { "width", scene.Render.Width }, { "height", scene.Render.Height }, { "budget_per_frame_seconds", o.Budget },
      { "reference_spp", o.ReferenceSpp }, { "directions_per_frame", scene.Render.DirectionsPerFrame },
      { "static_interval", scene.Render.StaticInterval }, { "methods", methods } };
    const std::string json = o.Json.empty() ? o.Plot + ".json" : o.Json;
    WriteBenchText(o.Json.empty() ? "--plot" : "--json", json, j.dump(2) + "\n");
    if (!o.Plot.empty())
    {
      // matplotlib (python3-matplotlib) draws it from the JSON.
      RunBenchPlot(BenchmarksDir() + "/plot_animation.py", json, o.Plot);
    }
  }
  return 0;
}
}

void AddBenchAnimation(CLI::App& bench)
{
  auto o = std::make_shared<AnimationOptions>();
  auto* cmd = bench.add_subcommand("animation", "lazy visibility updates at equal time per frame (von Radziewsky et al. 2017, Sec. 9)");
  cmd->add_option("scene", o->SceneFile, "a scene with a volume 'files' sequence")->required();
  cmd->add_option("--frames", o->Frames, "time steps A:B (default: all)");
  cmd->add_option("--budget-per-frame", o->Budget, "seconds per frame, update + render (default 2)")
    ->check(FiniteNumber())
    ->check(CLI::PositiveNumber);
  cmd->add_option("--reference-spp", o->ReferenceSpp, "samples per pixel of the per-frame references (default 1024)")
    ->check(CLI::Range(1, 1 << 24));
  cmd->add_option("--repeats", o->Repeats, "runs of every method, each with its own seed, interleaved (default 1)")
    ->check(CLI::Range(1, 100));
  cmd->add_option("--width", o->Width, "image width (overrides the scene)")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", o->Height, "image height (overrides the scene)")->check(CLI::Range(1, 16384));
  cmd->add_option("--json", o->Json, "write per-frame and summary figures as JSON");
  cmd->add_option("--plot", o->Plot, "draw per-frame MSE and update time to this PNG (matplotlib)");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
