#include "vsBenchFrames.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"
#include "vsRenderCommand.h"
#include "vsSceneFile.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>

namespace vstool
{
namespace
{
struct Options
{
  std::string Scene = ExampleScene("brain_sunrise.json");
  std::string Json;
  int Size = 512, Frames = 10;
};

struct FrameTimes
{
  double Median = 0.0, Max = 0.0;
};

FrameTimes Time(SceneObjects& objects, int frames, bool rotate)
{
  std::vector<double> t;
  for (int i = 0; i < frames; ++i)
  {
    if (rotate)
    {
      objects.Renderer->GetActiveCamera()->Azimuth(2.0); // what a drag does between frames
    }
    const auto a = std::chrono::steady_clock::now();
    objects.Window->Render();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count());
    const char* error = objects.Mapper->GetLastError();
    if (error && *error)
    {
      throw std::runtime_error(std::string("render failed: ") + error);
    }
  }
  std::sort(t.begin(), t.end());
  return { t[t.size() / 2], t.back() };
}

int Run(const Options& o)
{
  CheckBenchOutputs({ { "--json", o.Json } });
  Scene scene = ReadSceneFile(o.Scene);
  scene.Render.Width = scene.Render.Height = o.Size;
  SceneObjects objects = BuildScene(scene, true); // frame times in VTK's OpenGL window
  auto* mapper = objects.Mapper.Get();
  mapper->SetMaximumSamples(1 << 30);
  mapper->SetSamplesPerFrame(1);

  objects.Window->SetDesiredUpdateRate(0.0001); // still: VTK's still update rate
  // The window's own first render (its OpenGL context, VTK's shaders) without the volume, so that
  // the first frame below is VisSweep's: what a viewer that is already up waits for.
  objects.Volume->VisibilityOff();
  const auto w0 = std::chrono::steady_clock::now();
  objects.Window->Render();
  const double window = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  objects.Volume->VisibilityOn();
  const auto c0 = std::chrono::steady_clock::now();
  objects.Window->Render(); // uploads, majorants, pipelines, one sample per pixel
  const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
  FrameTimes still = Time(objects, o.Frames, false);
  // Dragging with the preview (the default): its first frame completes the grid and builds the light
  // volume, then every frame is a preview.
  objects.Window->SetDesiredUpdateRate(15.0); // what vtkRenderWindowInteractor asks while dragging
  mapper->InteractivePreviewOn();
  const FrameTimes previewFirst = Time(objects, 1, true);
  const FrameTimes preview = Time(objects, o.Frames, true);
  // Still again: the frames until the hand-over from the preview to the estimate ends.
  objects.Window->SetDesiredUpdateRate(0.0001);
  int handOverFrames = 0;
  const auto h0 = std::chrono::steady_clock::now();
  do
  {
    objects.Window->Render();
    ++handOverFrames;
  } while (mapper->GetLastPreviewShare() > 0.0 && handOverFrames < 100000);
  const double handOverSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - h0).count();
  const int handOverSpp = mapper->GetAccumulatedSamples();
  // Dragging with Monte Carlo at 1/InteractiveSubsampling resolution.
  objects.Window->SetDesiredUpdateRate(15.0);
  mapper->InteractivePreviewOff();
  Time(objects, 1, true);
  FrameTimes moving = Time(objects, o.Frames, true);
  mapper->InteractivePreviewOn();

  std::printf("%s, %d x %d window, %s\n", o.Scene.c_str(), o.Size, o.Size, scene.Render.Strategy.c_str());
  std::printf("the window's first render, without the volume:     %8.1f ms\n", 1e3 * window);
  std::printf("first frame (uploads, majorants, pipelines, 1 spp): %8.1f ms\n", 1e3 * first);
  std::printf("still: full resolution, 1 spp per frame:          %8.1f ms median, %8.1f ms max (%.1f fps)\n",
    1e3 * still.Median, 1e3 * still.Max, 1.0 / still.Median);
  std::printf("interactive: preview, first drag frame (grid, light): %8.1f ms\n", 1e3 * previewFirst.Median);
  std::printf("interactive: preview, full resolution, camera moving: %8.1f ms median, %8.1f ms max (%.1f fps)\n",
    1e3 * preview.Median, 1e3 * preview.Max, 1.0 / preview.Median);
  std::printf("still again: hand-over from the preview ended after %d frames, %d spp, %.2f s\n", handOverFrames,
    handOverSpp, handOverSeconds);
  std::printf("interactive: 1/%d resolution, 1 spp, camera moving: %8.1f ms median, %8.1f ms max (%.1f fps)\n",
    mapper->GetInteractiveSubsampling(), 1e3 * moving.Median, 1e3 * moving.Max, 1.0 / moving.Median);
  if (!o.Json.empty())
  {
    nlohmann::json j = { { "scene", o.Scene }, { "size", o.Size }, { "first_frame_seconds", first }, { "window_first_render_seconds", window },
      { "still_median_seconds", still.Median }, { "still_max_seconds", still.Max },
      { "interactive_median_seconds", moving.Median }, { "interactive_max_seconds", moving.Max },
      { "interactive_subsampling", mapper->GetInteractiveSubsampling() },
      { "preview_first_drag_seconds", previewFirst.Median }, { "preview_median_seconds", preview.Median },
      { "preview_max_seconds", preview.Max }, { "hand_over_frames", handOverFrames }, { "hand_over_spp", handOverSpp },
      { "hand_over_seconds", handOverSeconds } };
    WriteBenchText("--json", o.Json, j.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}
}

void AddBenchFrames(CLI::App& bench)
{
  auto o = std::make_shared<Options>();
  auto* cmd = bench.add_subcommand("frames", "frame times in a window: still (progressive) and while dragging");
  cmd->add_option("scene", o->Scene, "scene file (default: Examples/Scenes/brain_sunrise.json)");
  cmd->add_option("--size", o->Size, "window width and height")->check(CLI::Range(8, 4096));
  cmd->add_option("--frames", o->Frames, "frames timed per state (median)")->check(CLI::Range(1, 10000));
  cmd->add_option("--json", o->Json, "write the figures as JSON");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
