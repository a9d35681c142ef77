// vsRenderCommand.cxx — `vissweep render` (vsRenderCommand.h): its options, loading the scene
// with the command line's overrides, the progressive render loop with its progress bar, the
// outputs and the statistics. BuildScene (vsSceneBuild.cxx) makes the pipeline it renders.
#include "vsRenderCommand.h"
#include "vsImageOutput.h"
#include "vsOutputChecks.h"
#include "vsPendingFile.h"
#include "vsRenderFrames.h"
#include "vsToolCommand.h"
#include "vsContext.h"

#include "vtkImageData.h"
#include "vtkRenderWindow.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>

namespace vstool
{
namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

void Progress(int spp, int target, double elapsed, double budget, bool done)
{
  const int width = 30;
  const double f = budget > 0.0 ? std::min(1.0, elapsed / budget) : std::min(1.0, double(spp) / std::max(target, 1));
  const int filled = int(std::round(f * width));
  std::string bar(size_t(filled), '#');
  bar += std::string(size_t(width - filled), '.');
  if (budget > 0.0)
  {
    std::fprintf(stderr, "\r[%s] %6d spp  %6.1f / %.1f s", bar.c_str(), spp, elapsed, budget);
  }
  else
  {
    std::fprintf(stderr, "\r[%s] %6d / %d spp  %6.1f s", bar.c_str(), spp, target, elapsed);
  }
  if (done)
  {
    std::fprintf(stderr, "\n");
  }
  std::fflush(stderr);
}

int Run(const RenderOptions& o)
{
  if (!o.Frames.empty())
  {
    return RunFrames(o);
  }
  const auto start = Clock::now();
  // Everything that can be checked before the (slow) render is checked first.
  CheckOutputs(o.Outputs, o.Json);
  Scene scene = LoadScene(o);
  CheckOutputsForMode(o.Outputs, scene.Render.Mode);
  const bool timed = o.TimeBudget > 0.0;
  const int target = timed ? (1 << 30) : scene.Render.Spp;

  SceneObjects objects = BuildScene(scene);
  CheckVolumeInView(objects);
  auto* mapper = objects.Mapper.Get();
  const double setupSeconds = Seconds(start, Clock::now());

  const bool bar = !o.Quiet && ::isatty(STDERR_FILENO);
  const ProgressiveResult loop = RenderProgressively(objects, target, o.SamplesPerFrame, o.TimeBudget, bar);
  const int frames = loop.Frames, reached = loop.Spp;
  const double deviceSeconds = loop.DeviceSeconds, sweepSeconds = loop.SweepSeconds;
  const double firstFrameSeconds = loop.FirstFrameSeconds;
  const double renderSeconds = loop.Seconds;

  // Outputs: temporary names first, renamed only when all are written.
  std::vector<std::unique_ptr<PendingFile>> pending = WriteOutputs(objects, scene, o.Outputs);

  const double pixels = double(scene.Render.Width) * scene.Render.Height;
  nlohmann::json stats;
  stats["version"] = VISSWEEP_VERSION;
  stats["device"] = DeviceJson();
  stats["scene"] = o.SceneFile;
  stats["outputs"] = o.Outputs;
  stats["width"] = scene.Render.Width;
  stats["height"] = scene.Render.Height;
  stats["mode"] = scene.Render.Mode;
  stats["strategy"] = scene.Render.Strategy;
  // What the last frame sampled with (Auto chooses per frame), and the grid's state.
  stats["effective_strategy"] = mapper->GetEffectiveStrategyAsString();
  stats["directions_swept"] = mapper->GetDirectionsUpdatedTotal();
  stats["pending_directions"] = mapper->GetPendingDirections();
  stats["seed"] = scene.Render.Seed;
  stats["shadow_rays"] = mapper->GetShadowRays();
  stats["max_scattering_events"] = mapper->GetMaximumScatteringEvents();
  stats["anisotropy"] = mapper->GetScatteringAnisotropy();
  stats["mean_scattering_events_per_path"] = mapper->GetMeanScatteringEvents();
  stats["spp"] = reached;
  if (timed)
  {
    stats["time_budget_seconds"] = o.TimeBudget;
  }
  else
  {
    stats["spp_requested"] = scene.Render.Spp;
  }
  stats["frames"] = frames;
  stats["samples_per_frame"] = mapper->GetSamplesPerFrame();
  stats["setup_seconds"] = setupSeconds;       // reading the volume and the environment
  stats["render_seconds"] = renderSeconds;     // the progressive loop, first frame's sweeps included
  stats["first_frame_seconds"] = firstFrameSeconds;
  // The product of visibility and light is made once per grid state (the direction table, whose
  // builds are part of "render": direction_table_seconds below) or per scatter event inside the
  // render kernel (trilinear cells); bench overhead separates the variants per strategy.
  stats["device_seconds"] = { { "majorants", mapper->GetLastMajorantSeconds() }, { "sweeps", sweepSeconds },
    { "render", deviceSeconds } };
  stats["paths_per_second"] = renderSeconds > 0.0 ? pixels * reached / renderSeconds : 0.0;
  stats["paths_per_device_second"] = deviceSeconds > 0.0 ? pixels * reached / deviceSeconds : 0.0;
  stats["visibility_updates"] = mapper->GetVisibilityUpdateCount();
  stats["direction_table_builds"] = mapper->GetDirectionTableBuildCount();
  stats["direction_table_seconds"] = mapper->GetLastDirectionTableSeconds(); // device, the last build
  stats["directions_swept"] = mapper->GetDirectionsUpdatedTotal();
  stats["unlit_directions"] = mapper->GetUnlitDirections(); // not swept: no environment light there
  stats["accumulation_resets"] = mapper->GetAccumulationResetCount();

  std::unique_ptr<PendingFile> jsonFile;
  if (!o.Json.empty() && o.Json != "-")
  {
    jsonFile = std::make_unique<PendingFile>(o.Json);
    std::ofstream out(jsonFile->Path());
    out << stats.dump(2) << "\n";
    if (!out)
    {
      throw std::runtime_error("--json " + o.Json + ": cannot write");
    }
  }
  // All outputs (images and statistics) together or none.
  std::vector<PendingFile*> group;
  for (auto& p : pending)
  {
    group.push_back(p.get());
  }
  if (jsonFile)
  {
    group.push_back(jsonFile.get());
  }
  CommitAll(group);
  stats["wall_seconds"] = Seconds(start, Clock::now());
  if (o.Json == "-")
  {
    std::cout << stats.dump(2) << std::endl;
  }
  else if (scene.Render.Mode != "monte-carlo")
  {
    // A deterministic mode renders one frame: no samples, no paths, no strategy to report.
    std::printf("%d x %d, %s, one frame in %.2f s (setup %.2f s; device: majorants %.3f s, sweeps %.3f s, render %.3f s)\n",
      scene.Render.Width, scene.Render.Height, scene.Render.Mode.c_str(), renderSeconds, setupSeconds,
      mapper->GetLastMajorantSeconds(), sweepSeconds, deviceSeconds);
    for (const auto& out : o.Outputs)
    {
      std::printf("wrote %s\n", out.c_str());
    }
  }
  else
  {
    std::printf("%d x %d, %s, %d spp in %.2f s (setup %.2f s; device: majorants %.3f s, sweeps %.3f s, render %.3f s): "
                "%.3g paths/s\n",
      scene.Render.Width, scene.Render.Height, scene.Render.Strategy.c_str(), reached, renderSeconds, setupSeconds,
      mapper->GetLastMajorantSeconds(), sweepSeconds, deviceSeconds, stats["paths_per_second"].get<double>());
    if (scene.Render.Mode == "monte-carlo")
    {
      std::printf("light transport: %s, %.2f scattering events per path, anisotropy %g\n",
        mapper->GetMaximumScatteringEvents() > 1
          ? ("up to " + std::to_string(mapper->GetMaximumScatteringEvents()) + " events").c_str()
          : "single scattering",
        mapper->GetMeanScatteringEvents(), mapper->GetScatteringAnisotropy());
    }
    for (const auto& out : o.Outputs)
    {
      std::printf("wrote %s\n", out.c_str());
    }
  }
  return 0;
}
}

nlohmann::json DeviceJson()
{
  const vs::DeviceInfo& d = vs::Context::Default()->Info();
  return { { "name", d.Name }, { "type", d.Type }, { "driver", d.Driver }, { "vulkan", d.ApiVersion } };
}

Scene LoadScene(const RenderOptions& o)
{
  Scene scene = ReadSceneFile(o.SceneFile);
  if (o.Width > 0)
  {
    scene.Render.Width = o.Width;
  }
  if (o.Height > 0)
  {
    scene.Render.Height = o.Height;
  }
  if (o.Spp > 0)
  {
    scene.Render.Spp = o.Spp;
  }
  if (!o.Strategy.empty())
  {
    scene.Render.Strategy = SceneStrategies()[StrategyIndex(o.Strategy, "--strategy")];
  }
  if (o.Seed >= 0)
  {
    scene.Render.Seed = o.Seed;
  }
  if (o.Exposure >= 0.0)
  {
    scene.Render.Exposure = o.Exposure;
  }
  if (!o.Mode.empty())
  {
    scene.Render.Mode = SceneRenderModes()[RenderModeIndex(o.Mode, "--mode")];
  }
  if (o.MaxScatteringEvents > 0)
  {
    scene.Render.MaxScatteringEvents = o.MaxScatteringEvents;
  }
  if (o.Anisotropy)
  {
    if (!(*o.Anisotropy > -1.0 && *o.Anisotropy < 1.0))
    {
      throw std::runtime_error("--anisotropy must be in (-1, 1), got " + std::to_string(*o.Anisotropy));
    }
    scene.Render.Anisotropy = *o.Anisotropy;
  }
  // issue 38: hybrid scattering.
  if (o.ScatteringBlending)
  {
    if (!(*o.ScatteringBlending >= 0.0 && *o.ScatteringBlending <= 2.0))
    {
      throw std::runtime_error(
        "--volumetric-scattering-blending must be in [0, 2], got " + std::to_string(*o.ScatteringBlending));
    }
    scene.Render.VolumetricScatteringBlending = *o.ScatteringBlending;
  }
  if (o.Shade)
  {
    scene.TransferFunction.Shade = true;
  }
  return scene;
}

ProgressiveResult RenderProgressively(
  SceneObjects& objects, int target, int samplesPerFrame, double timeBudget, bool bar)
{
  auto* mapper = objects.Mapper.Get();
  mapper->SetMaximumSamples(target);
  // Automatic frames: one sample first (its time is the first estimate of a sample's), then as
  // many as take about AutoFrameSeconds. One sample per frame cost the MRI at 256^2 30-45% more
  // time for the same image (a fixed seed gives the same image for any frame split): each frame
  // waits for its slowest path and reads the image back for the window.
  const bool autoFrames = samplesPerFrame <= 0;
  mapper->SetSamplesPerFrame(autoFrames ? 1 : std::min(samplesPerFrame, target));
  const bool timed = timeBudget > 0.0;
  ProgressiveResult r;
  const auto loopStart = Clock::now();
  if (mapper->GetRenderMode() != vtkVisibilitySweepVolumeMapper::MonteCarlo)
  {
    // The deterministic modes (preview, ambient occlusion, emission-absorption): one render is the image.
    objects.Window->Render();
    const char* error = mapper->GetLastError();
    if (error && *error)
    {
      throw std::runtime_error(std::string("render failed: ") + error);
    }
    r.Frames = 1;
    r.Seconds = r.FirstFrameSeconds = Seconds(loopStart, Clock::now());
    r.UpdateSeconds = mapper->GetLastUpdateSeconds();
    r.DirectionsUpdated = mapper->GetDirectionsUpdatedLastFrame();
    r.DeviceSeconds = mapper->GetLastDeviceSeconds();
    r.SweepSeconds = mapper->GetLastFrameSweepSeconds();
    if (bar)
    {
      Progress(target, target, r.Seconds, 0.0, true);
    }
    return r;
  }
  int stalled = 0, previousSpp = 0;
  while (true)
  {
    const auto f0 = Clock::now();
    objects.Window->Render();
    const double frameSeconds = Seconds(f0, Clock::now());
    ++r.Frames;
    const char* error = mapper->GetLastError();
    if (error && *error)
    {
      throw std::runtime_error(std::string("render failed: ") + error);
    }
    if (r.Frames == 1)
    {
      r.FirstFrameSeconds = frameSeconds;
      r.UpdateSeconds = mapper->GetLastUpdateSeconds();
      r.DirectionsUpdated = mapper->GetDirectionsUpdatedLastFrame();
    }
    r.DeviceSeconds += mapper->GetLastDeviceSeconds();
    r.SweepSeconds += mapper->GetLastFrameSweepSeconds();
    const int acc = mapper->GetAccumulatedSamples();
    stalled = acc > r.Spp ? 0 : stalled + 1;
    r.Spp = acc;
    if (stalled >= 3)
    {
      throw std::runtime_error("the renderer accumulates no samples (" + std::to_string(r.Spp) + " spp after " +
        std::to_string(r.Frames) + " frames)");
    }
    // The next frame costs what this one did without the update (new data, sweeps): predicting
    // it with the update included would stop a budget right after the first frame of a new step.
    double nextFrameSeconds = std::max(0.0, frameSeconds - mapper->GetLastUpdateSeconds());
    const double elapsed = Seconds(loopStart, Clock::now());
    if (autoFrames && r.Spp > previousSpp && r.Spp < target)
    {
      const double perSample = std::max(nextFrameSeconds / double(r.Spp - previousSpp), 1e-6);
      double fit = AutoFrameSeconds / perSample;
      if (timed)
      {
        fit = std::min(fit, (timeBudget - elapsed) / perSample); // the last frame ends within the budget
      }
      const int next = std::min(int(std::clamp(fit, 1.0, double(1 << 16))), target - r.Spp);
      mapper->SetSamplesPerFrame(next);
      nextFrameSeconds = perSample * double(next);
    }
    previousSpp = r.Spp;
    const bool done = r.Spp >= target || (timed && elapsed + nextFrameSeconds > timeBudget);
    if (bar)
    {
      Progress(r.Spp, target, elapsed, timed ? timeBudget : 0.0, done);
    }
    if (done)
    {
      break;
    }
  }
  r.Seconds = Seconds(loopStart, Clock::now());
  return r;
}

std::vector<std::unique_ptr<PendingFile>> WriteOutputs(
  SceneObjects& objects, const Scene& scene, const std::vector<std::string>& outputs)
{
  std::vector<std::unique_ptr<PendingFile>> pending;
  for (const auto& out : outputs)
  {
    pending.push_back(std::make_unique<PendingFile>(out));
    if (Extension(out) == ".exr")
    {
      vtkImageData* radiance = objects.Mapper->GetRadiance();
      if (radiance)
      {
        int dims[3];
        radiance->GetDimensions(dims);
        if (dims[0] != scene.Render.Width || dims[1] != scene.Render.Height)
        {
          throw std::runtime_error("the radiance image is " + std::to_string(dims[0]) + "x" +
            std::to_string(dims[1]) + ", not the requested " + std::to_string(scene.Render.Width) + "x" +
            std::to_string(scene.Render.Height));
        }
      }
      WriteExr(radiance, pending.back()->Path());
    }
    else
    {
      WritePng(objects.Window, pending.back()->Path());
    }
  }
  return pending;
}


void AddRender(CLI::App& app)
{
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand("render", "render a scene file (Monte Carlo, progressive) to EXR and/or PNG");
  cmd->add_option("scene", o->SceneFile,
       "the scene file (JSON; its format and the conventions: docs/reference.md, installed as "
       "share/doc/vissweep/reference.md)")
    ->required();
  cmd->add_option("-o,--output", o->Outputs, "output image: .exr (linear float RGBA) or .png (tone mapped); repeat for both")
    ->required();
  cmd->add_option("--width", o->Width, "image width (overrides the scene)")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", o->Height, "image height (overrides the scene)")->check(CLI::Range(1, 16384));
  auto* spp = cmd->add_option("--spp", o->Spp, "samples per pixel (overrides the scene)")->check(CLI::Range(1, 1 << 30));
  auto* budget = cmd->add_option("--time-budget", o->TimeBudget, "render for this many seconds instead of a fixed spp")
                   ->check(FiniteNumber())
                   ->check(CLI::PositiveNumber);
  spp->excludes(budget);
  cmd->add_option("--strategy", o->Strategy,
    "auto (the default), uniform, environment, visibility, combined or two-step, or the API's spelling (TwoStep) "
    "(overrides the scene)");
  cmd->add_option("--mode", o->Mode,
    "monte-carlo (the default), preview (noise-free single scattering from the light volume), ambient-occlusion "
    "or emission-absorption (overrides the scene's render.mode)");
  cmd->add_option("--max-scattering-events", o->MaxScatteringEvents,
      "the most scattering events a path may have, 1 (single scattering) to 100000 (overrides the scene's "
      "render.max_scattering_events, default 1024)")
    ->check(CLI::Range(1, 100000));
  cmd->add_option("--anisotropy", o->Anisotropy,
    "the Henyey-Greenstein phase function's g in (-1, 1): > 0 forward, < 0 backward scattering (overrides the "
    "scene's render.anisotropy, default 0)");
  // issue 38: hybrid scattering.
  cmd->add_flag("--shade", o->Shade,
    "the volume property's shading on (transfer_function.shade): a surface lobe where the gradient is strong");
  cmd->add_option("--volumetric-scattering-blending", o->ScatteringBlending,
    "with shading: 0 a surface wherever the gradient allows, 1 where the gradient is strong and the medium opaque, 2 volumetric only (VTK 9.2's "
    "VolumetricScatteringBlending; overrides render.volumetric_scattering_blending, default 0)");
  // CLI::NonNegativeNumber printed its bound as a 309-digit double ("not in range 0.000000 to 17976...").
  cmd->add_option("--seed", o->Seed, "random seed, 0 to 2147483647 (overrides the scene)")
    ->check(CLI::Range(0, std::numeric_limits<int>::max()));
  cmd->add_option("--exposure", o->Exposure,
       "the PNG's exposure: a multiplier on the radiance before the tone curve (overrides render.exposure; "
       "the EXR is the radiance, unchanged)")
    ->check(FiniteNumber())
    ->check(CLI::PositiveNumber);
  cmd->add_option("--samples-per-frame", o->SamplesPerFrame,
      "samples per pixel added by each progressive frame (default 0: as many as take about 0.5 s)")
    ->check(CLI::Range(0, 1 << 16));
  cmd->add_option("--json", o->Json, "write the statistics as JSON to this file ('-' = stdout)");
  cmd->add_option("--frames", o->Frames,
    "render time steps A:B (inclusive) of a volume 'files' sequence, one image per step per -o: OUT with a "
    "printf pattern (frame_%04d.png) or OUT with _NNNN inserted before the extension");
  cmd->add_flag("-q,--quiet", o->Quiet, "no progress bar");
  cmd->callback([o]() {
    int status = 2;
    try
    {
      status = Run(*o);
    }
    catch (const std::exception& e)
    {
      std::cerr << (::isatty(STDERR_FILENO) ? "\n" : "") << "vissweep render: error: " << e.what() << std::endl;
      status = 2;
    }
    throw CLI::RuntimeError(status);
  });
}
}
