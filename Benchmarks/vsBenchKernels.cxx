#include "vsBenchKernels.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"

#include "vsContext.h"
#include "vsMonteCarloPass.h"
#include "vsSceneLightParams.h"
#include "vsSurfaceScattering.h"
#include "sampling/mc_params.h"
#include "sampling/strategies.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vstool
{
namespace
{
using namespace vs::shared;

struct KernelsOptions
{
  int Repeats = 5;
  std::string Json;
};

// A kernel the mapper makes, from its default settings (Sobol pixels, residual ratio tracking on the
// shadow rays, 1024 events, an 8-bit volume read through its quads) changed by Set.
struct Kernel
{
  const char* Name;
  bool Table;
  std::function<void(VsMonteCarloParams&)> Set;
};

VsMonteCarloParams MapperDefaults()
{
  VsMonteCarloParams p{};
  p.strategy = VS_STRATEGY_ENVIRONMENT;
  p.cellMode = VS_CELL_STOCHASTIC;
  p.cameraEstimator = VS_CAMERA_COLLISION;
  p.pixelSampler = VS_SAMPLER_SOBOL;
  p.controlExtinction = VS_CONTROL_SHADOW;
  p.transmittance = VS_TRANSMITTANCE_RATIO_TRACKING;
  p.maxEvents = VS_DEFAULT_SCATTERING_EVENTS;
  p.volume.interpolation = VS_INTERPOLATION_LINEAR;
  p.shadowRays = 1;
  return p;
}

const std::vector<Kernel>& Kernels()
{
  static const std::vector<Kernel> kernels = {
    { "first frame: environment, full transport", false, [](VsMonteCarloParams&) {} },
    { "two-step, full transport, direction table", true,
      [](VsMonteCarloParams& p) { p.strategy = VS_STRATEGY_TWO_STEP; } },
    { "environment, single scattering", false, [](VsMonteCarloParams& p) { p.maxEvents = 1; } },
    { "environment, full transport, surface lobe, 1 light", false,
      [](VsMonteCarloParams& p) {
        vs::SurfaceScattering::Settings s;
        s.Shade = true;
        s.Blending = 1.0;
        s.Diffuse = 0.8;
        s.Specular = 0.3;
        s.SpecularPower = 20.0;
        vs::SurfaceScattering::Set(p, s, 1.0, 1.0, 1.0, 1.0);
        p.lightCount = 1;
        vs::SceneLightParams::Make(p.lights[0], false, glm::dvec3(0.3, 0.2, -1.0), glm::dvec3(0.0), 1.0,
          glm::dvec3(1.0), 30.0, 1.0, glm::dvec3(1, 0, 0));
      } },
  };
  return kernels;
}

struct Spread
{
  double Median = 0.0, Min = 0.0, Max = 0.0;
};

Spread SpreadOf(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? Spread() : Spread{ v[v.size() / 2], v.front(), v.back() };
}

// Seconds to make `kernel`'s pipeline on a new context (its cache empty) that folds or does not.
double MakeSeconds(const Kernel& kernel, bool fold)
{
  vs::ContextOptions options;
  options.SpecializeModules = fold ? 1 : 0;
  auto context = vs::Context::Create(options);
  vs::MonteCarloPass pass(context);
  VsMonteCarloParams p = MapperDefaults();
  kernel.Set(p);
  const auto start = std::chrono::steady_clock::now();
  pass.Prewarm(p, kernel.Table, true, false);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int Run(const KernelsOptions& o)
{
  CheckBenchOutputs({ { "--json", o.Json } });
  std::printf("device: %s\n", vs::Context::Default()->Info().Name.c_str());
  std::printf("pipeline made on a new context, %d repeats alternated (folded first, then whole); seconds\n", o.Repeats);
  std::printf("%-52s %-26s %-26s %s\n", "kernel", "folded: median (min-max)", "whole: median (min-max)",
    "whole / folded");
  nlohmann::json report;
  report["device"] = vs::Context::Default()->Info().Name;
  report["repeats"] = o.Repeats;
  for (const Kernel& k : Kernels())
  {
    std::vector<double> folded, whole, ratio;
    for (int r = 0; r < o.Repeats; ++r)
    {
      folded.push_back(MakeSeconds(k, true));
      whole.push_back(MakeSeconds(k, false));
      ratio.push_back(whole.back() / std::max(folded.back(), 1e-9));
    }
    const Spread f = SpreadOf(folded), w = SpreadOf(whole), q = SpreadOf(ratio);
    std::printf("%-52s %.3f (%.3f-%.3f)%6s %.3f (%.3f-%.3f)%6s %.2fx (%.2f-%.2f)\n", k.Name, f.Median, f.Min, f.Max, "",
      w.Median, w.Min, w.Max, "", q.Median, q.Min, q.Max);
    report["kernels"].push_back({ { "kernel", k.Name }, { "folded_seconds", folded }, { "whole_seconds", whole },
      { "whole_over_folded", ratio } });
  }
  if (!o.Json.empty())
  {
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
    std::printf("wrote %s\n", o.Json.c_str());
  }
  return 0;
}
}

void AddBenchKernels(CLI::App& bench)
{
  auto o = std::make_shared<KernelsOptions>();
  auto* cmd = bench.add_subcommand("kernels",
    "time to make the render kernel's pipelines, its specialization constants folded into the module first and not");
  cmd->add_option("--repeats", o->Repeats, "pipelines made per kernel and way (default 5)")->check(CLI::Range(1, 100));
  cmd->add_option("--json", o->Json, "write the times as JSON");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
