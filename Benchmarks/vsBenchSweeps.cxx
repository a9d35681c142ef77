#include "vsBenchSweeps.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"
#include "vsToolVolume.h"

#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsVisibilityGrid.h"
#include "vsVolumeScene.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

namespace vstool
{
namespace
{
struct Options
{
  std::string Volume = DefaultBrainPath();
  std::string Json;
  int Repeats = 3;
  int ReferenceSamples = 16;
  bool Quick = false;
  bool Profile = false;
  std::string Only;
  int Pooling = -1;
  double StopTransmittance = -1.0;
  std::string Format;
  bool MaxPooling = false;
  std::vector<uint32_t> SubsetSizes;
  std::vector<double> Cells;
  std::vector<uint32_t> Kernels;
};

struct Diff
{
  double Mean = 0.0, Max = 0.0;
};

Diff Compare(const std::vector<float>& a, const std::vector<float>& b)
{
  Diff d;
  for (size_t i = 0; i < a.size(); ++i)
  {
    double e = std::abs(double(a[i]) - double(b[i]));
    d.Mean += e;
    d.Max = std::max(d.Max, e);
  }
  d.Mean /= double(std::max<size_t>(a.size(), 1));
  return d;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// `--profile`: where the sweep time goes, for the renderer's grid (RendererKernelRaysPerCell) and the
// filters' accurate one, per stage (march, filter, project), with host wall time and dispatches, and
// the cost of covering all directions in small subsets (what a progressive grid update does).
int RunProfile(const Options& o)
{
  CheckBenchOutputs({ { "--json", o.Json } });
  auto ctx = vs::Context::Default();
  auto image = ReadVolume(o.Volume);
  auto property = SkinProperty();
  vs::VolumeScene scene(ctx);
  scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  const auto dims = scene.Geometry().Dims;
  std::printf("volume %s: %u x %u x %u voxels; device '%s'; empty bricks %.1f %%\n", o.Volume.c_str(), dims[0],
    dims[1], dims[2], ctx->Info().Name.c_str(), 100.0 * scene.Majorants().EmptyFraction());
  nlohmann::json report;
  report["volume"] = o.Volume;
  report["dims"] = { dims[0], dims[1], dims[2] };
  struct Config
  {
    std::string Name;
    vs::VisibilityGridParameters P;
  };
  vs::VisibilityGridParameters renderer;
  renderer.AutoKernelRaysPerCell = vs::RendererKernelRaysPerCell;
  vs::VisibilityGridParameters accurate;
  for (auto* p : { &renderer, &accurate })
  {
    if (o.Pooling >= 0)
      p->ExtinctionPooling = uint32_t(o.Pooling);
    if (o.StopTransmittance >= 0.0)
      p->StopTransmittance = float(o.StopTransmittance);
    if (o.Format == "r16")
      p->StorageFormat = vs::VisibilityGridParameters::Format::Unorm16;
    else if (o.Format == "r32f")
      p->StorageFormat = vs::VisibilityGridParameters::Format::Float32;
    p->MaxPooling = o.MaxPooling;
  }
  std::printf("extinction pooling: %u voxels per texel (%s)\n", renderer.PoolingFactor(),
    renderer.MaxPooling ? "max" : "mean");
  const std::vector<Config> configs = { { "renderer", renderer }, { "accurate", accurate } };
  for (const Config& c : configs)
  {
    if (!o.Only.empty() && o.Only != c.Name)
      continue;
    vs::VisibilityGrid grid(ctx);
    grid.SetProfiling(true);
    std::map<std::string, std::vector<double>> stages, cpu;
    std::vector<double> total, wall;
    for (int r = 0; r < o.Repeats; ++r)
    {
      grid.Compute(scene.Volume(), scene.TF(), scene.Majorants(), scene.Geometry(), {}, c.P);
      total.push_back(grid.LastSeconds());
      wall.push_back(grid.LastWallSeconds());
      for (const auto& [name, sec] : grid.LastStageSeconds())
        stages[name].push_back(sec);
      for (const auto& [name, sec] : grid.LastStageCpuSeconds())
        cpu[name].push_back(sec);
    }
    std::sort(total.begin(), total.end());
    std::printf("\n%s grid (%u x %u x %u cells): device %.3f s (min %.3f, max %.3f over %d), wall %.3f s, %u dispatches\n",
      c.Name.c_str(), grid.Cells()[0], grid.Cells()[1], grid.Cells()[2], Median(total), total.front(), total.back(),
      o.Repeats, Median(wall), grid.LastDispatches());
    report[c.Name]["device_seconds"] = total;
    report[c.Name]["wall_seconds"] = wall;
    for (const auto& [name, secs] : stages)
    {
      std::printf("  %-10s %.3f s (%.0f %%), CPU %.3f s\n", name.c_str(), Median(secs),
        100.0 * Median(secs) / Median(total), Median(cpu[name]));
      report[c.Name]["stages"][name] = secs;
      report[c.Name]["cpu_seconds"][name] = cpu[name];
    }
    // All directions in subsets of k per call, on a grid that already has the layout.
    const uint32_t count = c.P.DirectionResolution * c.P.DirectionResolution;
    const std::vector<uint32_t> sizes = o.SubsetSizes.empty() ? std::vector<uint32_t>{ 1, 8 } : o.SubsetSizes;
    for (uint32_t k : sizes)
    {
      if (k == 0)
        continue;
      double device = 0.0, host = 0.0;
      uint32_t calls = 0;
      for (uint32_t first = 0; first < count; first += k)
      {
        std::vector<uint32_t> subset;
        for (uint32_t n = first; n < std::min(count, first + k); ++n)
          subset.push_back(n);
        grid.Compute(scene.Volume(), scene.TF(), scene.Majorants(), scene.Geometry(), {}, c.P, subset);
        device += grid.LastSeconds();
        host += grid.LastWallSeconds();
        ++calls;
      }
      std::printf("  all %u directions in %u calls of %u: device %.3f s, wall %.3f s (%.1f ms wall per call)\n", count,
        calls, k, device, host, 1e3 * host / calls);
      report[c.Name]["subsets"][std::to_string(k)] = { { "calls", calls }, { "device_seconds", device },
        { "wall_seconds", host } };
    }
  }
  if (!o.Json.empty())
  {
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}

int Run(const Options& o)
{
  if (o.Profile)
  {
    return RunProfile(o);
  }
  CheckBenchOutputs({ { "--json", o.Json } });
  auto ctx = vs::Context::Default();
  auto image = ReadVolume(o.Volume);
  auto property = SkinProperty();
  vs::VolumeScene scene(ctx);
  scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  const auto dims = scene.Geometry().Dims;
  const uint64_t volumeBytes = uint64_t(dims[0]) * dims[1] * dims[2] *
    image->GetPointData()->GetScalars()->GetDataTypeSize();
  std::printf("volume %s: %u x %u x %u voxels, %.1f MB as stored (%s); device '%s'\n", o.Volume.c_str(), dims[0],
    dims[1], dims[2], volumeBytes / 1e6, image->GetPointData()->GetScalars()->GetDataTypeAsString(),
    ctx->Info().Name.c_str());
  std::printf("empty bricks (8^3) under the skin TF: %.1f %%\n", 100.0 * scene.Majorants().EmptyFraction());

  auto compute = [&](vs::VisibilityGrid& grid, const vs::VisibilityGridParameters& p, int repeats) {
    std::vector<double> seconds;
    for (int r = 0; r < repeats; ++r)
    {
      grid.Compute(scene.Volume(), scene.TF(), scene.Majorants(), scene.Geometry(), {}, p);
      seconds.push_back(grid.LastSeconds());
    }
    return Median(seconds);
  };

  const std::vector<double> cellSizes = !o.Cells.empty() ? o.Cells
    : o.Quick                                              ? std::vector<double>{ 8 }
                                                           : std::vector<double>{ 2, 4, 8, 16 };
  const std::vector<uint32_t> kernels = !o.Kernels.empty() ? o.Kernels
    : o.Quick                                                ? std::vector<uint32_t>{ 64 }
                                                             : std::vector<uint32_t>{ 32, 64, 128, 256, 0 };
  nlohmann::json report;
  report["device"] = ctx->Info().Name;
  report["volume"] = o.Volume;
  report["dims"] = { dims[0], dims[1], dims[2] };
  report["volume_bytes"] = volumeBytes;

  std::printf("\n%-22s", "seconds (median of device timings)");
  for (double c : cellSizes)
  {
    std::printf(" | %2.0f^3 vox/cell", c);
  }
  std::printf("\n");
  std::map<double, std::vector<float>> references;
  std::map<double, double> bruteSeconds;
  std::map<double, uint64_t> gridBytes;
  std::map<double, std::array<uint32_t, 3>> gridCells;
  // Brute force: one ray per cell and direction (the cost row), and the supersampled reference.
  for (double c : cellSizes)
  {
    vs::VisibilityGridParameters p;
    p.VoxelsPerCell = c;
    p.Algorithm = vs::VisibilityGridParameters::Method::BruteForce;
    p.StorageFormat = vs::VisibilityGridParameters::Format::Float32;
    vs::VisibilityGrid grid(ctx);
    bruteSeconds[c] = compute(grid, p, 1);
    p.BruteForceSamples = uint32_t(o.ReferenceSamples);
    compute(grid, p, 1);
    references[c] = grid.Download();
    gridCells[c] = grid.Cells();
  }
  for (uint32_t k : kernels)
  {
    std::string label = k ? "sweep, " + std::to_string(k) + "^2 kernel" : "sweep, auto kernel";
    std::printf("%-22s", label.c_str());
    for (double c : cellSizes)
    {
      vs::VisibilityGridParameters p;
      p.VoxelsPerCell = c;
      p.KernelResolution = k;
      vs::VisibilityGrid grid(ctx);
      double s = compute(grid, p, o.Repeats);
      Diff d = Compare(grid.Download(), references[c]);
      gridBytes[c] = grid.Bytes();
      std::printf(" | %5.2f s (%.3f/%.2f)", s, d.Mean, d.Max);
      report["table"][label][std::to_string(int(c))] = { { "seconds", s }, { "mean_abs_error", d.Mean },
        { "max_abs_error", d.Max } };
    }
    std::printf("\n");
  }
  std::printf("%-22s", "brute force, 1 ray");
  for (double c : cellSizes)
  {
    std::printf(" | %5.2f s              ", bruteSeconds[c]);
    report["table"]["brute force"][std::to_string(int(c))] = { { "seconds", bruteSeconds[c] } };
  }
  std::printf("\n%-22s", "grid memory (8-bit)");
  for (double c : cellSizes)
  {
    std::printf(" | %8.2f MB          ", gridBytes[c] / 1e6);
  }
  std::printf("\n(errors: mean/max |V - V_ref| against the brute force with %d rays per cell and direction)\n",
    o.ReferenceSamples);

  // The defaults: 4^3 voxels per cell, auto kernel, filtering on, 8-bit storage.
  const double defaultCell = std::find(cellSizes.begin(), cellSizes.end(), 4.0) != cellSizes.end() ? 4.0 : cellSizes[0];
  vs::VisibilityGridParameters p;
  p.VoxelsPerCell = defaultCell;
  vs::VisibilityGrid sweep(ctx);
  double sweepSeconds = compute(sweep, p, o.Repeats);
  Diff d = Compare(sweep.Download(), references[defaultCell]);
  report["defaults"] = { { "voxels_per_cell", defaultCell }, { "sweep_seconds", sweepSeconds },
    { "bruteforce_seconds", bruteSeconds[defaultCell] }, { "speedup", bruteSeconds[defaultCell] / sweepSeconds },
    { "mean_abs_error", d.Mean }, { "max_abs_error", d.Max }, { "grid_bytes", sweep.Bytes() },
    { "volume_bytes", volumeBytes }, { "reference_samples", o.ReferenceSamples } };
  std::printf("\ndefaults (%.0f^3 voxels per cell, auto kernel, filtering on, 8-bit): sweep %.3f s, brute force %.3f s, "
              "speedup %.1fx, mean |dV| %.4f, max |dV| %.3f, grid %.2f MB vs volume %.2f MB\n",
    defaultCell, sweepSeconds, bruteSeconds[defaultCell], bruteSeconds[defaultCell] / sweepSeconds, d.Mean, d.Max,
    sweep.Bytes() / 1e6, volumeBytes / 1e6);

  // Storage formats: memory and the error quantisation adds (against float storage, same sweep).
  std::printf("\nstorage format at the defaults: bytes and error added by quantisation\n");
  vs::VisibilityGridParameters pf = p;
  pf.StorageFormat = vs::VisibilityGridParameters::Format::Float32;
  vs::VisibilityGrid fgrid(ctx);
  compute(fgrid, pf, 1);
  auto floats = fgrid.Download();
  for (auto f : { vs::VisibilityGridParameters::Format::Unorm8, vs::VisibilityGridParameters::Format::Unorm16,
         vs::VisibilityGridParameters::Format::Float32 })
  {
    vs::VisibilityGridParameters q = p;
    q.StorageFormat = f;
    vs::VisibilityGrid g(ctx);
    double s = compute(g, q, 1);
    Diff e = Compare(g.Download(), floats);
    const char* name = f == vs::VisibilityGridParameters::Format::Unorm8 ? "r8"
      : f == vs::VisibilityGridParameters::Format::Unorm16            ? "r16"
                                                                       : "r32f";
    std::printf("  %-5s %8.2f MB  mean %.2e  max %.2e  (%.3f s)\n", name, g.Bytes() / 1e6, e.Mean, e.Max, s);
    report["formats"][name] = { { "bytes", g.Bytes() }, { "mean_abs_error", e.Mean }, { "max_abs_error", e.Max } };
  }
  // Filtering on vs off against the reference.
  vs::VisibilityGridParameters nf = p;
  nf.Filtering = false;
  vs::VisibilityGrid unfiltered(ctx);
  double su = compute(unfiltered, nf, 1);
  Diff du = Compare(unfiltered.Download(), references[defaultCell]);
  std::printf("\nfiltering off: %.3f s, mean |dV| %.4f, max %.3f (on: %.4f, %.3f)\n", su, du.Mean, du.Max, d.Mean, d.Max);
  report["unfiltered"] = { { "seconds", su }, { "mean_abs_error", du.Mean }, { "max_abs_error", du.Max } };

  if (!o.Json.empty())
  {
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}
}

void AddBenchSweeps(CLI::App& bench)
{
  auto o = std::make_shared<Options>();
  auto* cmd = bench.add_subcommand("sweeps", "visibility sweeps against brute force (the paper's Table 1)");
  cmd->add_option("--volume", o->Volume, "volume file (default: Colin27 from mricron-data)");
  cmd->add_option("--json", o->Json, "write the figures as JSON");
  cmd->add_option("--repeats", o->Repeats, "timed runs per configuration (median)")->check(CLI::PositiveNumber);
  cmd->add_option("--reference-samples", o->ReferenceSamples, "rays per cell and direction of the reference")
    ->check(CLI::PositiveNumber);
  cmd->add_flag("--quick", o->Quick, "one configuration only (seconds)");
  cmd->add_flag("--profile", o->Profile,
    "device time per stage of the renderer's and the accurate grid, and of small-subset calls (no brute force)");
  cmd->add_option("--pooling", o->Pooling, "with --profile: ExtinctionPooling (0 auto, 1 full resolution)");
  cmd->add_option("--stop-transmittance", o->StopTransmittance,
    "with --profile: StopTransmittance (kernel rays stop marching below it)");
  cmd->add_option("--format", o->Format, "with --profile: the grid's storage format (r8, the default; r16; r32f)")
    ->check(CLI::IsMember({ "r8", "r16", "r32f" }));
  cmd->add_flag("--max-pooling", o->MaxPooling, "with --profile: pool by the max instead of the mean");
  cmd->add_option("--only", o->Only, "with --profile: only the 'renderer' or the 'accurate' grid");
  cmd->add_option("--subsets", o->SubsetSizes, "with --profile: directions per call to time (default 1,8; 0 = none)")
    ->delimiter(',');
  cmd->add_option("--cells", o->Cells, "voxels per cell to tabulate (default 2,4,8,16)")->delimiter(',');
  cmd->add_option("--kernels", o->Kernels, "kernel rays to tabulate, 0 = automatic (default 32,64,128,256,0)")
    ->delimiter(',');
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
