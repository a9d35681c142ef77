#include "vsBenchLightVolume.h"
#include "vsBenchOutput.h"
#include "vsSceneBuild.h"
#include "vsSceneFile.h"
#include "vsToolCommand.h"
#include "vsToolVolume.h"

#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsEnvironmentMap.h"
#include "vsLightDirections.h"
#include "vsLightVolume.h"
#include "vsSweepPlan.h"
#include "vsVisibilityGrid.h"
#include "vsVolumeScene.h"
#include "sampling/interpolation.h"

#include "vtkDataArray.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace vstool
{
namespace
{
struct LightVolumeOptions
{
  std::string SceneFile;
  int Repeats = 7;
  double StepDeg = 15.0;
  std::string Json;
  double Anisotropy = 0.0; // != 0: also the build with the band-1 moment (issue 39), alternated with g = 0
};

struct Spread
{
  double Median = 0.0, Min = 0.0, Max = 0.0;
};

Spread SpreadOf(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? Spread() : Spread{ v[v.size() / 2], v.front(), v.back() };
}

double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int Run(const LightVolumeOptions& o)
{
  CheckBenchOutputs({ { "--json", o.Json } });
  const Scene scene = ReadSceneFile(o.SceneFile);
  if (scene.Environment.Type != Scene::EnvironmentSection::Kind::File || !scene.Volume.Files.empty())
  {
    throw std::runtime_error("the scene needs one volume file and an environment file (a rotation turns it)");
  }
  auto ctx = vs::Context::Default();
  vtkSmartPointer<vtkImageData> image = ReadVolume(scene.Volume.File, scene.Volume.Grid);
  vtkSmartPointer<vtkVolumeProperty> property = MakeVolumeProperty(scene);
  vtkSmartPointer<vtkAlgorithm> algorithm = MakeEnvironment(scene);
  auto* reader = vtkEnvironmentMapReader::SafeDownCast(algorithm);
  if (!reader)
  {
    throw std::runtime_error("the scene's environment is not read from a file");
  }
  vs::VolumeScene volume(ctx);
  volume.Update(image, image->GetPointData()->GetScalars(), property, nullptr, scene.TransferFunction.DensityScale);

  // The renderer's default grid (the mapper's defaults, vsGridSchedule.cxx): 8 x 8 directions swept
  // towards where each texel's light comes from, automatic cells and kernel, filtering on.
  const int side = 8;
  vs::VisibilityGridParameters p;
  p.DirectionResolution = side;
  p.VoxelsPerCell = vs::SweepPlan::AutomaticVoxelsPerCell(volume.Geometry());
  p.AutoKernelRaysPerCell = vs::RendererKernelRaysPerCell;
  p.NearestInterpolation = volume.Interpolation() == vs::shared::VS_INTERPOLATION_NEAREST;
  p.Directions = vs::LightWeightedDirections(*reader->GetEnvironmentMap(), side);
  vs::VisibilityGrid grid(ctx);
  grid.Compute(volume.Volume(), volume.TF(), volume.Majorants(), volume.Geometry(), {}, p);
  const auto cells = grid.Cells();
  std::printf("scene %s: %u x %u x %u voxels, grid %u x %u x %u cells x %u directions (%.1f s of sweeps); device '%s'\n",
    o.SceneFile.c_str(), volume.Geometry().Dims[0], volume.Geometry().Dims[1], volume.Geometry().Dims[2], cells[0],
    cells[1], cells[2], side * side, grid.LastSeconds(), ctx->Info().Name.c_str());

  // The first build compiles the pipeline: not timed.
  auto env = std::make_unique<vs::DeviceEnvironment>(ctx, *reader->GetEnvironmentMap(), side);
  vs::LightVolume light(ctx);
  light.Update(grid, *env, scene.Environment.Intensity);
  // With --anisotropy: a second light volume built with the band-1 moment (single scattering, as `light`).
  const bool phased = o.Anisotropy != 0.0;
  vs::LightVolume moment(ctx);
  vs::LightVolume::MultipleScattering withMoment;
  withMoment.Orders = 1;
  withMoment.Anisotropy = float(o.Anisotropy);
  if (phased)
  {
    moment.Update(grid, *env, scene.Environment.Intensity, withMoment);
  }
  std::vector<double> momentWall, momentDevice;

  // Each repeat turns the environment by another step: the reader converts the lat-long again, the
  // map goes to the device (a new serial), and the light volume is rebuilt from the same grid.
  std::vector<double> convert, upload, lightWall, lightDevice;
  for (int r = 0; r < o.Repeats; ++r)
  {
    const double rotation = scene.Environment.RotationDeg + (r + 1) * o.StepDeg;
    auto start = std::chrono::steady_clock::now();
    reader->SetRotationDegrees(rotation);
    reader->Update();
    convert.push_back(SecondsSince(start));
    start = std::chrono::steady_clock::now();
    env.reset();
    env = std::make_unique<vs::DeviceEnvironment>(ctx, *reader->GetEnvironmentMap(), side);
    upload.push_back(SecondsSince(start));
    const uint64_t builds = light.Builds();
    // With the moment too: the two builds alternate which goes first.
    if (phased && r % 2 == 1)
    {
      moment.Update(grid, *env, scene.Environment.Intensity, withMoment);
    }
    light.Update(grid, *env, scene.Environment.Intensity);
    if (phased && r % 2 == 0)
    {
      moment.Update(grid, *env, scene.Environment.Intensity, withMoment);
    }
    if (light.Builds() != builds + 1)
    {
      throw std::runtime_error("the light volume was not rebuilt after a rotation");
    }
    lightWall.push_back(light.LastWallSeconds());
    lightDevice.push_back(light.LastSeconds());
    if (phased)
    {
      momentWall.push_back(moment.LastWallSeconds());
      momentDevice.push_back(moment.LastSeconds());
      std::printf("  with the band-1 moment (g %g): %.1f ms (device %.1f ms)\n", o.Anisotropy, 1e3 * momentWall.back(),
        1e3 * momentDevice.back());
    }
    std::printf("  rotation %6.1f deg: environment %.1f ms, upload %.1f ms, light volume %.1f ms (device %.1f ms)\n",
      rotation, 1e3 * convert.back(), 1e3 * upload.back(), 1e3 * lightWall.back(), 1e3 * lightDevice.back());
  }
  nlohmann::json report;
  report["scene"] = o.SceneFile;
  report["cells"] = { cells[0], cells[1], cells[2] };
  report["directions"] = side * side;
  auto line = [&](const char* name, const char* key, const std::vector<double>& v) {
    const Spread s = SpreadOf(v);
    std::printf("%-38s median %7.1f ms (min %.1f, max %.1f over %zu)\n", name, 1e3 * s.Median, 1e3 * s.Min,
      1e3 * s.Max, v.size());
    report[key] = v;
  };
  std::printf("\nafter an environment rotation (%d repeats, %.0f degrees apart):\n", o.Repeats, o.StepDeg);
  line("light volume rebuild (wall)", "light_volume_wall_seconds", lightWall);
  line("light volume rebuild (device)", "light_volume_device_seconds", lightDevice);
  if (phased)
  {
    line("with the band-1 moment (wall)", "light_volume_moment_wall_seconds", momentWall);
    line("with the band-1 moment (device)", "light_volume_moment_device_seconds", momentDevice);
    std::vector<double> ratio;
    for (size_t i = 0; i < momentDevice.size(); ++i)
    {
      ratio.push_back(lightDevice[i] > 0.0 ? momentDevice[i] / lightDevice[i] : 0.0);
    }
    const Spread r = SpreadOf(ratio);
    std::printf("%-38s median %7.2fx (min %.2f, max %.2f)\n", "moment / isotropic (device)", r.Median, r.Min, r.Max);
    report["anisotropy"] = o.Anisotropy;
    report["moment_over_isotropic_device"] = ratio;
  }
  line("environment map conversion (reader)", "environment_seconds", convert);
  line("environment upload", "upload_seconds", upload);
  if (!o.Json.empty())
  {
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}
}

void AddBenchLightVolume(CLI::App& bench)
{
  auto o = std::make_shared<LightVolumeOptions>();
  auto* cmd = bench.add_subcommand("lightvolume",
    "the light volume (environment light per visibility cell) rebuilt after environment rotations, at the default grid");
  cmd->add_option("scene", o->SceneFile, "a scene with a volume file and an environment file")->required();
  cmd->add_option("--repeats", o->Repeats, "rotations timed (default 7)")->check(CLI::Range(1, 1000));
  cmd->add_option("--step-deg", o->StepDeg, "degrees between rotations (default 15)")->check(FiniteNumber());
  cmd->add_option("--json", o->Json, "write the times as JSON");
  cmd->add_option("--anisotropy", o->Anisotropy,
       "also time the build with the band-1 moment the preview's phase g != 0 needs (issue 39), alternated with g = 0")
    ->check(CLI::Range(-0.999, 0.999));
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
