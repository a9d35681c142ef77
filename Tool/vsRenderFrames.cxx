#include "vsRenderFrames.h"
#include "vsImageOutput.h"
#include "vsOutputChecks.h"
#include "vsRenderCommand.h"
#include "vsToolVolume.h"

#include "vtkImageData.h"
#include "vtkRenderWindow.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <nlohmann/json.hpp>


#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <regex>
#include <stdexcept>

namespace vstool
{
namespace
{
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

int ParseStep(const std::string& text, const std::string& whole)
{
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9)
  {
    throw std::runtime_error("--frames '" + whole + "': expected A:B with non-negative integers A <= B");
  }
  return std::stoi(text);
}

// Per-frame statistics, as printed and as JSON.
nlohmann::json FrameStats(int step, const ProgressiveResult& r, double readSeconds,
  const std::vector<std::string>& outputs)
{
  nlohmann::json f;
  f["time_step"] = step;
  f["outputs"] = outputs;
  f["spp"] = r.Spp;
  f["read_seconds"] = readSeconds;           // reading the .vdb step (host)
  f["update_seconds"] = r.UpdateSeconds;     // upload, majorants, sweeps (host wall time)
  f["directions_updated"] = r.DirectionsUpdated;
  f["sweep_device_seconds"] = r.SweepSeconds;
  f["render_seconds"] = r.Seconds - r.UpdateSeconds; // the progressive loop without the update
  f["render_device_seconds"] = r.DeviceSeconds;
  return f;
}

void PrintFrame(const nlohmann::json& f)
{
  std::printf("frame %d: update %.3f s (%d directions, sweeps %.3f s device), render %.3f s, %d spp\n",
    f["time_step"].get<int>(), f["update_seconds"].get<double>(), f["directions_updated"].get<int>(),
    f["sweep_device_seconds"].get<double>(), f["render_seconds"].get<double>(), f["spp"].get<int>());
  for (const auto& out : f["outputs"])
  {
    std::printf("wrote %s\n", out.get<std::string>().c_str());
  }
  std::fflush(stdout);
}

void WriteJson(const nlohmann::json& stats, const std::string& path)
{
  if (path == "-")
  {
    std::cout << stats.dump(2) << std::endl;
    return;
  }
  PendingFile file(path);
  std::ofstream out(file.Path());
  out << stats.dump(2) << "\n";
  out.close();
  if (!out)
  {
    throw std::runtime_error("--json " + path + ": cannot write");
  }
  file.Commit();
}
}

FrameRange ParseFrameRange(const std::string& text, int steps)
{
  const auto colon = text.find(':');
  FrameRange r;
  r.First = ParseStep(text.substr(0, colon), text);
  r.Last = colon == std::string::npos ? r.First : ParseStep(text.substr(colon + 1), text);
  if (r.First > r.Last)
  {
    throw std::runtime_error("--frames '" + text + "': the first step is after the last");
  }
  if (r.Last >= steps)
  {
    throw std::runtime_error("--frames '" + text + "': the sequence has " + std::to_string(steps) +
      " time steps (0.." + std::to_string(steps - 1) + ")");
  }
  return r;
}

std::string FrameOutputName(const std::string& out, int frame)
{
  char buffer[4096];
  if (out.find('%') != std::string::npos)
  {
    static const std::regex pattern("^[^%]*%0?[0-9]?d[^%]*$");
    if (!std::regex_match(out, pattern))
    {
      throw std::runtime_error("-o " + out + ": a frame pattern needs exactly one integer conversion such as %04d");
    }
    std::snprintf(buffer, sizeof(buffer), out.c_str(), frame);
    return buffer;
  }
  const std::string ext = Extension(out);
  const std::string stem = out.substr(0, out.size() - ext.size());
  std::snprintf(buffer, sizeof(buffer), "%s_%04d%s", stem.c_str(), frame, out.substr(out.size() - ext.size()).c_str());
  return buffer;
}

void ShowTimeStep(SceneObjects& objects, const Scene& scene, int step)
{
  objects.Image = ReadVolumeSequence(scene.Volume.Files, scene.Volume.Grid, step);
  objects.Mapper->SetInputData(objects.Image);
}

int RunFrames(const RenderOptions& o)
{
  Scene scene = LoadScene(o);
  if (scene.Volume.Files.empty())
  {
    throw std::runtime_error("--frames needs a volume sequence: give volume.files in the scene");
  }
  const FrameRange range = ParseFrameRange(o.Frames, int(scene.Volume.Files.size()));
  // Every output of every frame, before anything renders: a later frame's path that is a folder, in
  // a missing folder or the same as another output was found only when that frame was written.
  std::vector<std::string> allOutputs;
  for (int step = range.First; step <= range.Last; ++step)
  {
    for (const auto& out : o.Outputs)
    {
      allOutputs.push_back(FrameOutputName(out, step));
    }
  }
  CheckOutputs(allOutputs, o.Json);
  CheckOutputsForMode(allOutputs, scene.Render.Mode);
  const bool timed = o.TimeBudget > 0.0;
  const int target = timed ? (1 << 30) : scene.Render.Spp;
  const bool bar = !o.Quiet;

  scene.Volume.TimeStep = range.First;
  auto t0 = Clock::now();
  SceneObjects objects = BuildScene(scene);
  ApplyCameraOptions(objects, o);
  CheckVolumeInView(objects);
  double readSeconds = Since(t0);
  nlohmann::json frames = nlohmann::json::array();
  for (int step = range.First; step <= range.Last; ++step)
  {
    if (step != range.First)
    {
      t0 = Clock::now();
      ShowTimeStep(objects, scene, step);
      readSeconds = Since(t0);
    }
    const ProgressiveResult r = RenderProgressively(objects, target, o.SamplesPerFrame, o.TimeBudget, bar);
    std::vector<std::string> names;
    for (const auto& out : o.Outputs)
    {
      names.push_back(FrameOutputName(out, step));
    }
    {
      auto files = WriteOutputs(objects, scene, names, Provenance(objects, scene, o.SceneFile, r, step));
      std::vector<PendingFile*> group;
      for (auto& file : files)
      {
        group.push_back(file.get());
      }
      CommitAll(group); // this step's images together or none
    }
    frames.push_back(FrameStats(step, r, readSeconds, names));
    if (o.Json != "-")
    {
      PrintFrame(frames.back());
    }
  }

  nlohmann::json stats;
  stats["version"] = VISSWEEP_VERSION;
  stats["device"] = DeviceJson();
  stats["scene"] = o.SceneFile;
  stats["width"] = scene.Render.Width;
  stats["height"] = scene.Render.Height;
  stats["strategy"] = scene.Render.Strategy;
  stats["seed"] = scene.Render.Seed;
  stats["update_scheme"] = scene.Render.UpdateScheme;
  stats["directions_per_frame"] = scene.Render.DirectionsPerFrame;
  stats["static_interval"] = scene.Render.StaticInterval;
  if (timed)
  {
    stats["time_budget_seconds"] = o.TimeBudget;
  }
  else
  {
    stats["spp_requested"] = scene.Render.Spp;
  }
  stats["frames"] = frames;
  stats["visibility_updates"] = objects.Mapper->GetVisibilityUpdateCount();
  stats["directions_updated"] = objects.Mapper->GetDirectionsUpdatedTotal();
  if (!o.Json.empty())
  {
    WriteJson(stats, o.Json);
  }
  return 0;
}
}
