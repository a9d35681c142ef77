#include "vsRenderCommand.h"
#include "vsDisplayCheck.h"
#include "vsImageOutput.h"
#include "vsPendingFile.h"
#include "vsRenderFrames.h"
#include "vsRenderTargetLimits.h"
#include "vsToolCommand.h"
#include "vsToolVolume.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsError.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

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
namespace fs = std::filesystem;

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

// Turns an algorithm's vtkErrorMacro messages into the text of an exception.
class ErrorCollector
{
public:
  explicit ErrorCollector(vtkObject* object)
    : Object(object)
  {
    this->Observer->SetCallback(&ErrorCollector::Collect);
    this->Observer->SetClientData(&this->Messages);
    this->Tag = object->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  ~ErrorCollector() { this->Object->RemoveObserver(this->Tag); }
  const std::string& Text() const { return this->Messages; }

private:
  static void Collect(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* messages = static_cast<std::string*>(clientData);
    if (!callData)
    {
      return;
    }
    std::string m(static_cast<const char*>(callData));
    const auto colon = m.find("): ");
    if (colon != std::string::npos)
    {
      m = m.substr(colon + 3);
    }
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
    {
      m.pop_back();
    }
    *messages += (messages->empty() ? "" : "; ") + m;
  }

  vtkObject* Object;
  vtkNew<vtkCallbackCommand> Observer;
  std::string Messages;
  unsigned long Tag = 0;
};


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
  for (const auto& out : o.Outputs)
  {
    CheckOutputPath(out);
  }
  if (!o.Json.empty() && o.Json != "-")
  {
    CheckWritable("--json", o.Json);
  }
  Scene scene = LoadScene(o);
  const bool timed = o.TimeBudget > 0.0;
  const int target = timed ? (1 << 30) : scene.Render.Spp;

  SceneObjects objects = BuildScene(scene);
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
  stats["strategy"] = scene.Render.Strategy;
  // What the last frame sampled with (Auto chooses per frame), and the grid's state.
  stats["effective_strategy"] = mapper->GetEffectiveStrategyAsString();
  stats["directions_swept"] = mapper->GetDirectionsUpdatedTotal();
  stats["pending_directions"] = mapper->GetPendingDirections();
  stats["seed"] = scene.Render.Seed;
  stats["shadow_rays"] = mapper->GetShadowRays();
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
  else
  {
    std::printf("%d x %d, %s, %d spp in %.2f s (setup %.2f s; device: majorants %.3f s, sweeps %.3f s, render %.3f s): "
                "%.3g paths/s\n",
      scene.Render.Width, scene.Render.Height, scene.Render.Strategy.c_str(), reached, renderSeconds, setupSeconds,
      mapper->GetLastMajorantSeconds(), sweepSeconds, deviceSeconds, stats["paths_per_second"].get<double>());
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

vtkSmartPointer<vtkVolumeProperty> MakeVolumeProperty(const Scene& scene)
{
  const auto& tf = scene.TransferFunction;
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  for (const auto& p : tf.Opacity)
  {
    opacity->AddPoint(p[0], p[1]);
  }
  vtkNew<vtkColorTransferFunction> color;
  if (tf.Color.empty())
  {
    color->AddRGBPoint(tf.Opacity.empty() ? 0.0 : tf.Opacity.front()[0], 1.0, 1.0, 1.0);
  }
  for (const auto& p : tf.Color)
  {
    color->AddRGBPoint(p[0], p[1], p[2], p[3]);
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(tf.UnitDistance);
  if (!tf.GradientOpacity.empty())
  {
    vtkNew<vtkPiecewiseFunction> gradient; // opacity x gradient-opacity(|grad s|), as VTK
    for (const auto& p : tf.GradientOpacity)
    {
      gradient->AddPoint(p[0], p[1]);
    }
    property->SetGradientOpacity(gradient);
  }
  if (tf.Nearest)
  {
    property->SetInterpolationTypeToNearest(); // label maps: no blended labels between regions
  }
  else
  {
    property->SetInterpolationTypeToLinear();
  }
  property->ShadeOff();
  return property;
}

vtkSmartPointer<vtkAlgorithm> MakeEnvironment(const Scene& scene)
{
  const auto& e = scene.Environment;
  using Kind = Scene::EnvironmentSection::Kind;
  vtkSmartPointer<vtkAlgorithm> algorithm;
  std::string what;
  if (e.Type == Kind::File)
  {
    auto reader = vtkSmartPointer<vtkEnvironmentMapReader>::New();
    reader->SetFileName(e.File.c_str());
    reader->SetRotationDegrees(e.RotationDeg);
    reader->SetOctahedralSize(e.OctahedralSize);
    algorithm = reader;
    what = "environment.file '" + e.File + "'";
  }
  else
  {
    auto source = vtkSmartPointer<vtkEnvironmentMapSource>::New();
    switch (e.Type)
    {
      case Kind::Constant:
        source->SetTypeToConstant();
        source->SetColor(e.Constant.data());
        break;
      case Kind::Sun:
        source->SetTypeToSunDisk();
        source->SetSunDirection(Normalized(e.SunDirection).data()); // (1e300, 0, 0) is +X, not inf
        source->SetSunAngularRadius(e.SunRadiusDeg);
        source->SetSunRadiance(e.SunRadiance.data());
        source->SetSkyColor(e.SunSky.data());
        break;
      default:
        source->SetTypeToTwoToneSky();
        source->SetUpperColor(e.Upper.data());
        source->SetLowerColor(e.Lower.data());
        break;
    }
    if (e.OctahedralSize > 0)
    {
      source->SetOctahedralSize(e.OctahedralSize);
    }
    algorithm = source;
    what = "environment";
  }
  ErrorCollector errors(algorithm);
  ErrorCollector executiveErrors(algorithm->GetExecutive());
  algorithm->Update();
  auto* image = vtkImageData::SafeDownCast(algorithm->GetOutputDataObject(0));
  if (!errors.Text().empty() || !executiveErrors.Text().empty() || !image || image->GetNumberOfPoints() == 0)
  {
    std::string reason = errors.Text().empty() ? executiveErrors.Text() : errors.Text();
    throw std::runtime_error(what + ": cannot build the environment map" + (reason.empty() ? "" : ": " + reason));
  }
  return algorithm;
}

void ConfigureMapper(vtkVisibilitySweepVolumeMapper* mapper, const Scene& scene)
{
  mapper->SetRenderModeToMonteCarlo();
  mapper->SetSamplingStrategy(StrategyIndex(scene.Render.Strategy));
  mapper->SetSeed(scene.Render.Seed);
  mapper->SetMaximumSamples(scene.Render.Spp);
  mapper->SetDensityScale(scene.TransferFunction.DensityScale);
  mapper->SetEnvironmentIntensity(scene.Environment.Intensity);
  mapper->SetEnvironmentVisible(scene.Environment.VisibleBackground);
  // The tool's window holds the volume alone: its PNG is the display transform of the radiance, the
  // environment included, as the volume paints it (not the 8-bit lat-long image of a skybox).
  mapper->SetEnvironmentAsBackground(false);
  mapper->SetExposure(scene.Render.Exposure);
  mapper->SetToneMapping(scene.Render.ToneMapping);
  mapper->SetUpdateScheme(UpdateSchemeIndex(scene.Render.UpdateScheme));
  mapper->SetControlExtinction(ControlExtinctionIndex(scene.Render.ControlExtinction));
  mapper->SetTransmittanceEstimator(TransmittanceEstimatorIndex(scene.Render.TransmittanceEstimator));
  mapper->SetSampler(SamplerIndex(scene.Render.Sampler));
  mapper->SetShadowRays(scene.Render.ShadowRays);
  mapper->SetDirectionsPerFrame(scene.Render.DirectionsPerFrame);
  mapper->SetStaticInterval(scene.Render.StaticInterval);
  const auto& v = scene.Visibility;
  if (v.DirectionResolution)
  {
    mapper->SetDirectionResolution(*v.DirectionResolution);
  }
  if (v.VoxelsPerCell)
  {
    mapper->SetVoxelsPerCell(*v.VoxelsPerCell);
  }
  if (v.KernelResolution)
  {
    mapper->SetKernelResolution(*v.KernelResolution);
  }
  if (v.ExtinctionPooling)
  {
    mapper->SetExtinctionPooling(*v.ExtinctionPooling);
  }
  if (v.Filtering)
  {
    mapper->SetFiltering(*v.Filtering);
  }
  if (v.SkipUnlitDirections)
  {
    mapper->SetSkipUnlitDirections(*v.SkipUnlitDirections);
  }
  if (v.Progressive)
  {
    mapper->SetProgressiveVisibility(*v.Progressive);
  }
  if (v.LightWeightedDirections)
  {
    mapper->SetLightWeightedDirections(*v.LightWeightedDirections);
  }
  if (v.FillUnswept)
  {
    mapper->SetFillUnsweptDirections(*v.FillUnswept);
  }
  if (v.SweepFrameFraction)
  {
    mapper->SetSweepFrameFraction(*v.SweepFrameFraction);
  }
  if (v.FilterAngleFraction)
  {
    mapper->SetFilterAngleFraction(*v.FilterAngleFraction);
  }
  if (v.Epsilon)
  {
    mapper->SetVisibilityEpsilon(*v.Epsilon);
  }
  if (v.CellMode)
  {
    mapper->SetCellMode(*v.CellMode == "trilinear" ? vtkVisibilitySweepVolumeMapper::TrilinearCells
                                                   : vtkVisibilitySweepVolumeMapper::StochasticCell);
  }
  mapper->RemoveAllClippingPlanes();
  for (const auto& p : scene.ClipPlanes)
  {
    vtkNew<vtkPlane> plane; // VTK keeps the half-space the normal points into
    plane->SetOrigin(p.Origin.data());
    plane->SetNormal(Normalized(p.Normal).data()); // normalised in double: a normal of 1e300 is no infinity
    mapper->AddClippingPlane(plane);
  }
}

namespace
{
// A volume's dimensions against the device's limits (the volume image) and the host's memory,
// before the reader allocates anything (issue 13, item 7).
std::string VolumeFits(const std::array<int, 3>& dims)
{
  try
  {
    vs::DeviceVolume::CheckFits(*vs::Context::Default(), { uint32_t(dims[0]), uint32_t(dims[1]), uint32_t(dims[2]) });
  }
  catch (const vs::Error& e)
  {
    return e.what();
  }
  // The reader's values (up to 8 bytes a voxel), their float copy and the upload's staging.
  const uint64_t voxels = uint64_t(dims[0]) * uint64_t(dims[1]) * uint64_t(dims[2]);
  const uint64_t host = voxels * 16, memory = vs::RenderTargetLimits::HostMemoryBytes();
  if (memory && host > memory / 2)
  {
    return "reading it needs about " + std::to_string(host >> 20) + " MiB of host memory (16 bytes a voxel), more "
      "than half of this host's " + std::to_string(memory >> 20) + " MiB";
  }
  return std::string();
}
}

SceneObjects BuildScene(const Scene& scene)
{
  SceneObjects o;
  // The image size against the device's limits and the host's memory before anything is read or
  // allocated (issue 13, item 7): a 16384 x 16384 window alone is gigabytes of host memory.
  vs::RenderTargetLimits::Check(*vs::Context::Default(), uint32_t(scene.Render.Width), uint32_t(scene.Render.Height));
  try
  {
    o.Image = scene.Volume.Files.empty()
      ? ReadVolume(scene.Volume.File, scene.Volume.Grid, vtkIdType(1) << 31, VolumeFits)
      : ReadVolumeSequence(scene.Volume.Files, scene.Volume.Grid, scene.Volume.TimeStep);
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error(std::string(scene.Volume.Files.empty() ? "volume.file: " : "volume.files: ") + e.what());
  }
  vtkDataArray* scalars = o.Image->GetPointData()->GetScalars();
  if (scalars->GetNumberOfComponents() != 1)
  {
    throw std::runtime_error("volume: the scalars have " + std::to_string(scalars->GetNumberOfComponents()) +
      " components (expected 1)");
  }
  o.Property = MakeVolumeProperty(scene);
  o.Environment = MakeEnvironment(scene);

  o.Mapper = vtkSmartPointer<vtkVisibilitySweepVolumeMapper>::New();
  o.Mapper->SetInputData(o.Image);
  o.Mapper->SetEnvironmentConnection(o.Environment->GetOutputPort());
  ConfigureMapper(o.Mapper, scene);

  o.Volume = vtkSmartPointer<vtkVolume>::New();
  o.Volume->SetMapper(o.Mapper);
  o.Volume->SetProperty(o.Property);

  o.Renderer = vtkSmartPointer<vtkRenderer>::New();
  const auto& bg = scene.Environment.Background;
  o.Renderer->SetBackground(bg[0], bg[1], bg[2]);
  o.Renderer->AddVolume(o.Volume);
  vtkCamera* camera = o.Renderer->GetActiveCamera();
  camera->SetPosition(scene.Camera.Position.data());
  camera->SetFocalPoint(scene.Camera.FocalPoint.data());
  camera->SetViewUp(Normalized(scene.Camera.ViewUp).data());
  camera->SetViewAngle(scene.Camera.ViewAngle);
  if (scene.Camera.ParallelScale)
  {
    camera->ParallelProjectionOn();
    camera->SetParallelScale(*scene.Camera.ParallelScale);
  }
  camera->OrthogonalizeViewUp();
  if (scene.Camera.Reset)
  {
    o.Renderer->ResetCamera(); // keeps the default direction (+Y, +Z up), frames the volume's bounds
  }
  o.Renderer->ResetCameraClippingRange();

  vs::RequireDisplay();
  o.Window = vtkSmartPointer<vtkRenderWindow>::New();
  o.Window->SetOffScreenRendering(1);
  o.Window->SetMultiSamples(0);
  o.Window->SetSize(scene.Render.Width, scene.Render.Height);
  o.Window->AddRenderer(o.Renderer);
  return o;
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
  // CLI::NonNegativeNumber printed its bound as a 309-digit double ("not in range 0.000000 to 17976...").
  cmd->add_option("--seed", o->Seed, "random seed, 0 to 2147483647 (overrides the scene)")
    ->check(CLI::Range(0, std::numeric_limits<int>::max()));
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
