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
#include "vsFrameTimePredictor.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <system_error>

namespace vstool
{
namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

// The progress display on stderr. On a terminal one line redrawn in place ('\r'); otherwise (a
// log, a pipe) whole lines, one each time a further tenth of the way is done and one at the end,
// so that a log reads line by line instead of one run-together line.
struct ProgressDisplay
{
  bool Terminal = ::isatty(STDERR_FILENO) != 0;
  int LastTenth = -1; // whole lines: the last tenth written

  void Show(int spp, int target, double elapsed, double budget, bool done)
  {
    const int width = 30;
    const double f = budget > 0.0 ? std::min(1.0, elapsed / budget) : std::min(1.0, double(spp) / std::max(target, 1));
    if (!Terminal)
    {
      const int tenth = int(std::floor(f * 10.0));
      if (!done && tenth <= LastTenth)
      {
        return;
      }
      LastTenth = tenth;
    }
    const int filled = int(std::round(f * width));
    std::string bar(size_t(filled), '#');
    bar += std::string(size_t(width - filled), '.');
    const char* start = Terminal ? "\r" : "";
    if (budget > 0.0)
    {
      std::fprintf(stderr, "%s[%s] %6d spp  %6.1f / %.1f s", start, bar.c_str(), spp, elapsed, budget);
    }
    else
    {
      std::fprintf(stderr, "%s[%s] %6d / %d spp  %6.1f s", start, bar.c_str(), spp, target, elapsed);
    }
    if (done || !Terminal)
    {
      std::fprintf(stderr, "\n");
    }
    std::fflush(stderr);
  }
};

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
  ApplyCameraOptions(objects, o);
  CheckVolumeInView(objects);
  auto* mapper = objects.Mapper.Get();
  mapper->SetDisplayDenoise(o.Denoise); // the window's image (PNG, JPEG) only: the EXR is the estimate
  const double setupSeconds = Seconds(start, Clock::now());

  const ProgressiveResult loop = RenderProgressively(objects, target, o.SamplesPerFrame, o.TimeBudget, !o.Quiet);
  const int frames = loop.Frames, reached = loop.Spp;
  const double deviceSeconds = loop.DeviceSeconds, sweepSeconds = loop.SweepSeconds;
  const double firstFrameSeconds = loop.FirstFrameSeconds;
  const double renderSeconds = loop.Seconds;

  // Outputs: temporary names first, renamed only when all are written.
  std::vector<std::unique_ptr<PendingFile>> pending =
    WriteOutputs(objects, scene, o.Outputs, Provenance(objects, scene, o.SceneFile, loop));

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
  stats["display_denoised"] = mapper->GetLastDisplayDenoised();
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
  // Where the first frame's host time went (the mapper's GetLastFramePhaseName; "scene.*" are parts
  // of "scene"), and the share of the loop's time the render passes took on the device.
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [name, seconds] : loop.FirstFramePhases)
  {
    phases[name] = seconds;
  }
  stats["first_frame_phases"] = phases;
  stats["render_device_share"] = renderSeconds > 0.0 ? deviceSeconds / renderSeconds : 0.0;
  // The sweeps fill the grid the samples are drawn with: the share of the loop spent on both.
  stats["sampling_device_share"] = renderSeconds > 0.0 ? (deviceSeconds + sweepSeconds) / renderSeconds : 0.0;
  nlohmann::json frameLog = nlohmann::json::array();
  for (const auto& f : loop.FrameLog)
  {
    frameLog.push_back({ { "seconds", f.Seconds }, { "samples", f.Samples }, { "device_seconds", f.DeviceSeconds },
      { "sweep_seconds", f.SweepSeconds }, { "update_seconds", f.UpdateSeconds }, { "directions_swept", f.DirectionsSwept },
      { "strategy", f.Strategy } });
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, seconds] : f.Phases)
    {
      phases[name] = seconds;
    }
    frameLog.back()["phases"] = phases;
  }
  stats["frames_log"] = frameLog;
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
    // The preview: the mean of its frames, their offsets rotated (issue 39).
    const std::string framesText = frames == 1 ? "one frame" : std::to_string(frames) + " frames averaged";
    std::printf("%d x %d, %s, %s in %.2f s (setup %.2f s; device: majorants %.3f s, sweeps %.3f s, render %.3f s)\n",
      scene.Render.Width, scene.Render.Height, scene.Render.Mode.c_str(), framesText.c_str(), renderSeconds, setupSeconds,
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
    if (o.Denoise)
    {
      std::printf("display: %s\n", mapper->GetLastDisplayDenoised()
          ? "the estimate through the filter guided by the preview (--denoise; the EXR is the estimate)"
          : "the estimate as it is (--denoise: fewer than 2 spp, or no preview to guide the filter)");
    }
    for (const auto& out : o.Outputs)
    {
      std::printf("wrote %s\n", out.c_str());
    }
  }
  // Every output is committed and the report printed: the process ends here, without tearing down
  // the device, the volume and the kernels still being made ahead for frames that will not come
  // (issue 39: ch2better's exit waited up to 0.65 s for TwoStep's kernel, compiled at the lowest
  // priority beside the frames). As compilers skip freeing their memory at exit.
  std::cout.flush();
  std::fflush(nullptr);
  std::_Exit(0);
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
  if (o.NoLights)
  {
    scene.Lights.clear();
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
  ProgressDisplay progress;
  const auto loopStart = Clock::now();
  if (mapper->GetRenderMode() != vtkVisibilitySweepVolumeMapper::MonteCarlo)
  {
    // The deterministic modes (preview, ambient occlusion, emission-absorption): one render is the image;
    // the preview's is the mean of a few frames with its offsets rotated (issue 39), until IsConverged().
    int frames = 0;
    do
    {
      objects.Window->Render();
      const char* error = mapper->GetLastError();
      if (error && *error)
      {
        throw std::runtime_error(std::string("render failed: ") + error);
      }
      ++frames;
    } while (!mapper->IsConverged() && frames < 64);
    r.Frames = frames;
    r.Seconds = r.FirstFrameSeconds = Seconds(loopStart, Clock::now());
    r.UpdateSeconds = mapper->GetLastUpdateSeconds();
    r.DirectionsUpdated = mapper->GetDirectionsUpdatedLastFrame();
    r.DeviceSeconds = mapper->GetLastDeviceSeconds();
    r.SweepSeconds = mapper->GetLastFrameSweepSeconds();
    return r; // no progress to show: one frame, no samples (the summary line says what it took)
  }
  int stalled = 0, previousSpp = 0;
  vs::FrameTimePredictor predictor;
  while (true)
  {
    const auto f0 = Clock::now();
    if (timed)
    {
      // The deadline, for Auto's sweeps (vtkVisibilitySweepVolumeMapper::SetRemainingTimeBudget).
      mapper->SetRemainingTimeBudget(std::max(1e-3, timeBudget - Seconds(loopStart, f0)));
    }
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
      for (int i = 0; i < mapper->GetNumberOfLastFramePhases(); ++i)
      {
        r.FirstFramePhases.emplace_back(mapper->GetLastFramePhaseName(i), mapper->GetLastFramePhaseSeconds(i));
      }
      r.UpdateSeconds = mapper->GetLastUpdateSeconds();
      r.DirectionsUpdated = mapper->GetDirectionsUpdatedLastFrame();
    }
    r.DeviceSeconds += mapper->GetLastDeviceSeconds();
    r.SweepSeconds += mapper->GetLastFrameSweepSeconds();
    const int acc = mapper->GetAccumulatedSamples();
    r.FrameLog.push_back({ frameSeconds, acc - r.Spp, mapper->GetLastDeviceSeconds(), mapper->GetLastFrameSweepSeconds(),
      mapper->GetLastUpdateSeconds(), mapper->GetDirectionsUpdatedLastFrame(), mapper->GetEffectiveStrategyAsString(), {} });
    for (int i = 0; i < mapper->GetNumberOfLastFramePhases(); ++i)
    {
      r.FrameLog.back().Phases.emplace_back(mapper->GetLastFramePhaseName(i), mapper->GetLastFramePhaseSeconds(i));
    }
    stalled = acc > r.Spp ? 0 : stalled + 1;
    r.Spp = acc;
    if (stalled >= 3)
    {
      throw std::runtime_error("the renderer accumulates no samples (" + std::to_string(r.Spp) + " spp after " +
        std::to_string(r.Frames) + " frames)");
    }
    // The next frame costs what this one did without the update (new data, sweeps): predicting
    // it with the update included would stop a budget right after the first frame of a new step.
    // Per sample, the longest of the last three frames (vs::FrameTimePredictor): a frame slower than the
    // one before must not run the budget over.
    // A frame's fixed part (host work, the display, the last dispatch's tail) apart: the last frame,
    // sized to what is left of the budget, has few samples and would run over by it.
    predictor.Add(std::max(0.0, frameSeconds - mapper->GetLastUpdateSeconds()), r.Spp - previousSpp);
    const double elapsed = Seconds(loopStart, Clock::now());
    int nextSamples = std::min(mapper->GetSamplesPerFrame(), std::max(target - r.Spp, 0));
    if (autoFrames && r.Spp > previousSpp && r.Spp < target)
    {
      int fit = predictor.SamplesWithin(AutoFrameSeconds);
      if (timed)
      {
        fit = std::min(fit, predictor.SamplesWithin(timeBudget - elapsed)); // the last frame ends within the budget
      }
      nextSamples = std::min(std::clamp(fit, 1, 1 << 16), target - r.Spp);
      mapper->SetSamplesPerFrame(nextSamples);
    }
    const double nextFrameSeconds = predictor.NextFrameSeconds(nextSamples);
    previousSpp = r.Spp;
    const bool done = r.Spp >= target || (timed && elapsed + nextFrameSeconds > timeBudget);
    if (bar)
    {
      progress.Show(r.Spp, target, elapsed, timed ? timeBudget : 0.0, done);
    }
    if (done)
    {
      break;
    }
  }
  r.Seconds = Seconds(loopStart, Clock::now());
  mapper->SetRemainingTimeBudget(0.0);
  return r;
}

ImageProvenance Provenance(SceneObjects& objects, const Scene& scene, const std::string& sceneFile,
  const ProgressiveResult& loop, int timeStep)
{
  ImageProvenance p;
  p.Version = VISSWEEP_VERSION;
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(sceneFile, ec);
  p.SceneFile = ec ? sceneFile : absolute.lexically_normal().string();
  p.TimeStep = timeStep;
  p.Mode = scene.Render.Mode;
  p.Strategy = scene.Render.Strategy;
  p.EffectiveStrategy = objects.Mapper->GetEffectiveStrategyAsString();
  p.Spp = loop.Spp;
  p.Seconds = loop.Seconds;
  p.Seed = scene.Render.Seed;
  vtkCamera* camera = objects.Renderer->GetActiveCamera();
  camera->GetPosition(p.CameraPosition.data());
  camera->GetFocalPoint(p.FocalPoint.data());
  camera->GetViewUp(p.ViewUp.data());
  p.ViewAngle = camera->GetViewAngle();
  p.Device = vs::Context::Default()->Info().Name;
  return p;
}

void ApplyCameraOptions(SceneObjects& objects, const RenderOptions& o)
{
  if (o.CameraPosition.empty() && o.FocalPoint.empty() && o.ViewUp.empty())
  {
    return;
  }
  vtkCamera* camera = objects.Renderer->GetActiveCamera();
  if (!o.CameraPosition.empty())
  {
    camera->SetPosition(o.CameraPosition.data());
  }
  if (!o.FocalPoint.empty())
  {
    camera->SetFocalPoint(o.FocalPoint.data());
  }
  Vec3 position, focal, up;
  camera->GetPosition(position.data());
  camera->GetFocalPoint(focal.data());
  camera->GetViewUp(up.data());
  if (!o.ViewUp.empty())
  {
    up = { o.ViewUp[0], o.ViewUp[1], o.ViewUp[2] };
  }
  const char* which = !o.CameraPosition.empty() ? "--camera-position" : "--focal-point";
  const Vec3 d = Normalized({ focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] });
  if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
  {
    throw std::runtime_error(std::string(which) + ": the camera's position and focal point are the same point");
  }
  const Vec3 u = Normalized(up);
  const double along = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
  if ((u[0] == 0.0 && u[1] == 0.0 && u[2] == 0.0) || std::abs(along) > 0.999)
  {
    throw std::runtime_error(std::string(o.ViewUp.empty() ? which : "--view-up") +
      ": the view up is zero or along the view direction; give --view-up across it");
  }
  camera->SetViewUp(u.data());
  camera->OrthogonalizeViewUp();
  objects.Renderer->ResetCameraClippingRange();
}

std::vector<std::unique_ptr<PendingFile>> WriteOutputs(SceneObjects& objects, const Scene& scene,
  const std::vector<std::string>& outputs, const ImageProvenance& provenance)
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
      WriteExr(radiance, pending.back()->Path(), &provenance);
    }
    else
    {
      WriteWindowImage(objects.Window, pending.back()->Path());
    }
  }
  return pending;
}


void AddRender(CLI::App& app)
{
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand("render", "render a scene file (Monte Carlo, progressive) to EXR, PNG and/or JPEG");
  cmd->add_option("scene", o->SceneFile,
       "the scene file (JSON; its format and the conventions: docs/reference.md, installed as "
       "share/doc/vissweep/reference.md)")
    ->required();
  cmd->add_option("-o,--output", o->Outputs,
       "output image: .exr (linear float RGBA, with what made it in its header), .png or .jpg (tone mapped); "
       "repeat for several")
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
  cmd->add_flag("--no-lights", o->NoLights,
    "render without the scene's lights (its \"lights\": VTK's vtkLights beside the environment)");
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
  cmd->add_option("--camera-position", o->CameraPosition,
       "the camera's position X,Y,Z in world coordinates (overrides the scene's camera.position)")
    ->expected(3)
    ->delimiter(',')
    ->check(FiniteNumber());
  cmd->add_option("--focal-point", o->FocalPoint, "the point looked at, X,Y,Z (overrides camera.focal_point)")
    ->expected(3)
    ->delimiter(',')
    ->check(FiniteNumber());
  cmd->add_option("--view-up", o->ViewUp, "the camera's up direction X,Y,Z (overrides camera.view_up)")
    ->expected(3)
    ->delimiter(',')
    ->check(FiniteNumber());
  cmd->add_option("--json", o->Json, "write the statistics as JSON to this file ('-' = stdout)");
  cmd->add_option("--frames", o->Frames,
    "render time steps A:B (inclusive; 0-based indices into the scene's volume.files) of a volume sequence, "
    "one image per step per -o: OUT with a "
    "printf pattern (frame_%04d.png) or OUT with _NNNN inserted before the extension");
  cmd->add_flag("--denoise", o->Denoise,
    "the PNG/JPEG shows the estimate through an edge-aware filter guided by the noise-free preview "
    "(DisplayDenoise; the EXR stays the unbiased estimate)");
  cmd->add_flag("-q,--quiet", o->Quiet,
    "no progress display (on stderr: a bar redrawn in place on a terminal, whole lines in a log or pipe)");
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
