#include "vsBenchConvergence.h"
#include "vsBenchOutput.h"
#include "vsToolCommand.h"
#include "vsImageOutput.h"
#include "vsRenderCommand.h"
#include "vsSceneFile.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <CLI/CLI.hpp>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace vstool
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The references' default cache: a user cache folder ($XDG_CACHE_HOME/vissweep/references, else
// ~/.cache/vissweep/references), never the data folder: in the build tree that is a link into the
// source tree, where the references were written (issue 35, class 7).
std::string DefaultReferenceDir()
{
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  const fs::path base = xdg && *xdg ? fs::path(xdg) : home && *home ? fs::path(home) / ".cache" : fs::temp_directory_path();
  return (base / "vissweep" / "references").string();
}

struct Options
{
  std::string Scene, Reference, Json, Csv, Plot;
  std::string ReferenceDir = DefaultReferenceDir();
  std::string ReferenceStrategy = "two-step";
  int ReferenceSpp = 4096;
  int Width = 128, Height = 128, Repeats = 2;
  std::vector<std::string> Strategies{ "uniform", "environment", "visibility", "combined", "two-step", "auto" };
  std::vector<double> Budgets{ 1, 2, 4, 8, 16 };
  std::vector<int> SppList;
  bool Quick = false;
  double MaxFrameSeconds = 0.25; // equal time: a frame's samples at most this long, as in a window
  bool Blocking = false; // equal time: sweep the whole grid before the first sample (no progressive fill-in)
};

// Linear RGB, VTK row order (bottom-up), 3 floats per pixel.
using Rgb = std::vector<float>;

Rgb Radiance(vtkVisibilitySweepVolumeMapper* mapper)
{
  vtkDataArray* a = mapper->GetRadiance()->GetPointData()->GetArray("Radiance");
  Rgb out(size_t(a->GetNumberOfTuples()) * 3);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      out[size_t(i) * 3 + c] = float(a->GetComponent(i, c));
  return out;
}

Rgb ReadExr(const std::string& path, int w, int h)
{
  Imf::InputFile file(path.c_str());
  const auto dw = file.header().dataWindow();
  if (dw.max.x - dw.min.x + 1 != w || dw.max.y - dw.min.y + 1 != h)
  {
    throw std::runtime_error("reference '" + path + "' is not " + std::to_string(w) + " x " + std::to_string(h));
  }
  std::vector<float> rgba(size_t(w) * h * 3);
  Imf::FrameBuffer frame;
  const char* names[3] = { "R", "G", "B" };
  for (int c = 0; c < 3; ++c)
  {
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c), sizeof(float) * 3,
                             sizeof(float) * 3 * w));
  }
  file.setFrameBuffer(frame);
  file.readPixels(dw.min.y, dw.max.y);
  Rgb out(rgba.size());
  for (int y = 0; y < h; ++y) // EXR rows top-down -> VTK bottom-up
    std::copy_n(rgba.begin() + size_t(h - 1 - y) * w * 3, w * 3, out.begin() + size_t(y) * w * 3);
  return out;
}

struct Error
{
  double Mse = 0.0, RelMse = 0.0;
  double BlockRelRmse = 0.0; // the RMSE of 8 x 8 pixel blocks' means over the reference's mean
};

// The error a viewer sees at a coarser scale: the image and the reference averaged over 8 x 8
// pixel blocks (whole blocks only), per channel, the RMSE of the differences relative to the
// reference's mean (issue 34's "time to 1% relative RMSE, 8 x 8 blocks").
double BlockRelativeRmse(const Rgb& image, const Rgb& reference, int width, double mean)
{
  constexpr int kBlock = 8;
  const int height = width > 0 ? int(reference.size() / 3 / size_t(width)) : 0;
  double se = 0.0;
  size_t blocks = 0;
  for (int by = 0; by + kBlock <= height; by += kBlock)
  {
    for (int bx = 0; bx + kBlock <= width; bx += kBlock)
    {
      for (int c = 0; c < 3; ++c)
      {
        double d = 0.0;
        for (int y = by; y < by + kBlock; ++y)
        {
          for (int x = bx; x < bx + kBlock; ++x)
          {
            const size_t i = (size_t(y) * width + x) * 3 + c;
            d += double(image[i]) - reference[i];
          }
        }
        d /= kBlock * kBlock;
        se += d * d;
        ++blocks;
      }
    }
  }
  return blocks > 0 && mean > 0.0 ? std::sqrt(se / double(blocks)) / mean : 0.0;
}

Error Compare(const Rgb& image, const Rgb& reference, int width)
{
  double se = 0.0, mean = 0.0;
  for (size_t i = 0; i < image.size(); ++i)
  {
    const double d = double(image[i]) - reference[i];
    se += d * d;
    mean += reference[i];
  }
  mean /= double(reference.size());
  Error e;
  e.Mse = se / double(image.size());
  e.RelMse = mean > 0.0 ? e.Mse / (mean * mean) : 0.0;
  e.BlockRelRmse = BlockRelativeRmse(image, reference, width, mean);
  return e;
}

// Bumped whenever the renderer's image of a scene changes by definition (not by noise), so that
// references cached by an older build are not compared with new images:
//   2: the visible background is bilinear between environment texels (was the nearest texel).
//   3: full light transport by default (MaximumScatteringEvents 1024; was single scattering).
constexpr int ImageDefinition = 3;

// The cache key of a reference: what determines it.
std::string ReferenceKey(const Options& o)
{
  std::ifstream in(o.Scene, std::ios::binary);
  std::stringstream content;
  content << in.rdbuf();
  std::ostringstream key;
  key << content.str() << '|' << o.Width << 'x' << o.Height << '|' << o.ReferenceSpp << '|' << o.ReferenceStrategy
      << "|image definition " << ImageDefinition;
  std::ostringstream hex;
  hex << std::hex << std::hash<std::string>()(key.str());
  return fs::path(o.Scene).stem().string() + "_" + std::to_string(o.Width) + "x" + std::to_string(o.Height) + "_" +
    std::to_string(o.ReferenceSpp) + "spp_" + hex.str();
}

struct Point
{
  double Budget = 0.0; // seconds (equal time) or spp (equal spp)
  std::vector<double> Seconds, Spp, Mse, RelMse, BlockRelRmse; // one per repeat
  std::vector<double> SweepSeconds, Swept;         // device seconds of sweeps and directions swept so far
  std::vector<std::string> Effective;              // the strategy of the last frame (Auto chooses)
};

double Mean(const std::vector<double>& v)
{
  double s = 0.0;
  for (double x : v)
    s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}

double Spread(const std::vector<double>& v)
{
  if (v.size() < 2)
    return 0.0;
  const double m = Mean(v);
  double s = 0.0;
  for (double x : v)
    s += (x - m) * (x - m);
  return std::sqrt(s / double(v.size() - 1));
}

class Runner
{
public:
  Runner(const Options& o, const Scene& scene)
    : O(o)
    , Objects(BuildScene(scene))
  {
    this->M = this->Objects.Mapper;
    this->M->SetInteractiveUpdateRate(0.0);
    this->M->SetMaximumSamples(1 << 30);
  }

  vtkVisibilitySweepVolumeMapper* Mapper() { return this->M; }

  void Render()
  {
    this->Objects.Window->Render();
    const char* error = this->M->GetLastError();
    if (error && *error)
    {
      throw std::runtime_error(std::string("render failed: ") + error);
    }
  }

  /** Brings the device up to date (volume, environment, every kernel a run may use compiled)
   *  without sweeping the run's grid: one frame of TwoStep, whose new grid sweeps nothing in its
   *  first frame (it renders as Environment sampling); one of TwoStep over a coarse grid swept
   *  whole, which makes TwoStep's own kernel, its direction table's and the sweeps' pipelines
   *  (before, Auto's runs made TwoStep's kernel inside their clock, ~0.3 s of a core in their
   *  first second, while Environment sampling's was made here); and one of Environment sampling.
   *  Then sets the strategy and seed of the run; its first frame starts a fresh accumulation, and
   *  its grid (if any) starts empty (the coarse grid's cells differ), so every sweep of the run
   *  happens inside the run's own time. progressive: the grid fills in between frames (else it is
   *  swept whole in the run's first frame). */
  void Start(const std::string& strategy, int seed, bool progressive)
  {
    this->M->SetSamplesPerFrame(1);
    this->M->SetSeed(seed == 99991 ? 99992 : 99991); // not the run's: its first frame restarts accumulation
    this->M->SetProgressiveVisibility(true);
    this->M->SetSamplingStrategy(vtkVisibilitySweepVolumeMapper::TwoStep);
    this->Render();
    const double cells = this->M->GetVoxelsPerCell();
    this->M->SetVoxelsPerCell(cells == 32.0 ? 64.0 : 32.0);
    this->M->SetProgressiveVisibility(false);
    this->Render();
    this->M->SetVoxelsPerCell(cells);
    this->M->SetSamplingStrategy(vtkVisibilitySweepVolumeMapper::Environment);
    this->Render();
    this->M->SetProgressiveVisibility(progressive);
    this->M->SetSamplingStrategy(StrategyIndex(strategy, "--strategies"));
    this->M->SetSeed(seed);
  }


private:
  const Options& O;
  SceneObjects Objects;
  vtkVisibilitySweepVolumeMapper* M = nullptr;
};

// The reference's own error: the mean variance of its pixels' means, an MSE floor that every
// measured MSE contains (measured = true + floor, the two being independent).
double NoiseFloor(vtkVisibilitySweepVolumeMapper* m)
{
  vtkDataArray* var = m->GetRadiance(true)->GetPointData()->GetArray("Variance");
  double sum = 0.0;
  for (vtkIdType i = 0; i < var->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      sum += var->GetComponent(i, c);
  return sum / (3.0 * double(var->GetNumberOfTuples()) * std::max(1, m->GetAccumulatedSamples()));
}

Rgb MakeReference(Runner& runner, const Options& o)
{
  std::fprintf(stderr, "rendering the reference: %s, %d spp, %d x %d ...\n", o.ReferenceStrategy.c_str(),
    o.ReferenceSpp, o.Width, o.Height);
  runner.Start(o.ReferenceStrategy, 100003, true); // a seed no measured run uses
  auto* m = runner.Mapper();
  m->SetSamplesPerFrame(std::min(o.ReferenceSpp, 64));
  m->SetMaximumSamples(o.ReferenceSpp);
  while (m->GetAccumulatedSamples() < o.ReferenceSpp)
  {
    runner.Render();
  }
  m->SetMaximumSamples(1 << 30);
  return Radiance(m);
}

int Run(const Options& given)
{
  CheckBenchOutputs({ { "--json", given.Json }, { "--csv", given.Csv }, { "--plot", given.Plot } });
  Options o = given;
  if (o.Quick)
  {
    o.Width = std::min(o.Width, 32);
    o.Height = std::min(o.Height, 32);
    o.Budgets = { 0.5, 1.0 };
    o.Repeats = 1;
    o.ReferenceSpp = std::min(o.ReferenceSpp, 64);
    if (!o.SppList.empty())
    {
      o.SppList = { 1, 4 };
    }
  }
  Scene scene = ReadSceneFile(o.Scene);
  scene.Render.Width = o.Width;
  scene.Render.Height = o.Height;
  Runner runner(o, scene);

  // The reference: given, cached, or rendered now (and cached).
  Rgb reference;
  std::string referencePath = o.Reference;
  double noiseFloor = -1.0; // unknown for a given reference
  bool rendered = false;
  if (referencePath.empty())
  {
    fs::path dir = o.ReferenceDir;
    referencePath = (dir / (ReferenceKey(o) + ".exr")).string();
    const std::string sidecar = (dir / (ReferenceKey(o) + ".json")).string();
    if (!fs::exists(referencePath) || !fs::exists(sidecar))
    {
      reference = MakeReference(runner, o);
      noiseFloor = NoiseFloor(runner.Mapper());
      fs::create_directories(dir);
      WriteExr(runner.Mapper()->GetRadiance(), referencePath);
      nlohmann::json meta = { { "scene", fs::path(o.Scene).filename().string() }, { "spp", o.ReferenceSpp },
        { "strategy", o.ReferenceStrategy }, { "width", o.Width }, { "height", o.Height },
        { "noise_floor_mse", noiseFloor } };
      WriteBenchText("--reference-dir", sidecar, meta.dump(2) + "\n");
      rendered = true;
    }
    else
    {
      std::ifstream in(sidecar);
      noiseFloor = nlohmann::json::parse(in).value("noise_floor_mse", -1.0);
    }
  }
  if (!rendered)
  {
    reference = ReadExr(referencePath, o.Width, o.Height);
  }
  std::fprintf(stderr, "reference: %s\n", referencePath.c_str());

  const bool equalSpp = !o.SppList.empty();
  std::map<std::string, std::vector<Point>> results;
  for (const auto& strategy : o.Strategies)
  {
    std::vector<Point>& points = results[strategy];
    if (equalSpp)
      for (int spp : o.SppList)
        points.push_back({ double(spp) });
    else
      for (double b : o.Budgets)
        points.push_back({ b });
  }
  // Repeat by repeat, every strategy in turn: this machine's speed drifts by 10-20% over minutes
  // (Environment sampling's samples in 4 s on mri_sunrise: 376 in one run, 292 in the next), so
  // running all repeats of one strategy before the next would charge the drift to the strategies.
  for (int r = 0; r < o.Repeats; ++r)
  {
    for (const auto& strategy : o.Strategies)
    {
      std::vector<Point>& points = results[strategy];
      // One progressive run per repeat on a fresh mapper, its error read at every budget. The
      // sweeps happen inside the run's clock: progressively between frames (the default), or all
      // in the first frame (--blocking, and equal-spp mode, which compares the estimators with a
      // complete grid).
      Runner run(o, scene);
      run.Start(strategy, 1 + r, !o.Blocking && !equalSpp);
      auto* m = run.Mapper();
      const int sweptBefore = m->GetDirectionsUpdatedTotal(); // the warm-up's coarse grid
      double sweepSeconds = 0.0;
      const auto t0 = Clock::now();
      auto elapsed = [&]() { return std::chrono::duration<double>(Clock::now() - t0).count(); };
      int frames = 0;
      double deadline = 0.0; // the run's last budget
      for (const Point& p : points)
        deadline = std::max(deadline, p.Budget);
      auto frame = [&]() {
        ++frames;
        run.Render();
        sweepSeconds += m->GetLastFrameSweepSeconds();
      };
      for (auto& p : points)
      {
        if (equalSpp)
        {
          while (m->GetAccumulatedSamples() < int(p.Budget))
          {
            m->SetSamplesPerFrame(int(p.Budget) - m->GetAccumulatedSamples());
            frame();
          }
        }
        else
        {
          // Frames of a size that lands close to the budget, and no longer than MaxFrameSeconds:
          // a user's window adds a sample or a few per frame, and the progressive sweeps and
          // Auto's choices happen between frames (frames of up to 64 samples, 2.8 s each at 256²,
          // left Auto a handful of frames to sweep and choose in over 16 s).
          while (elapsed() < p.Budget)
          {
            // The run's deadline is its last budget (the earlier ones are read on the way), as
            // `vissweep render --time-budget` tells Auto its own.
            m->SetRemainingTimeBudget(std::max(1e-3, deadline - elapsed()));
            // The run's first frame is one sample: its time is the first estimate of a sample's
            // cost (before it, the sample count is still the warm-up's).
            const int acc = frames == 0 ? 0 : m->GetAccumulatedSamples();
            const double perSample = std::max(elapsed() / std::max(1, acc), 1e-6);
            const int left = int((p.Budget - elapsed()) / perSample);
            const int cap = std::max(1, int(o.MaxFrameSeconds / perSample));
            m->SetSamplesPerFrame(acc == 0 ? 1 : std::clamp(left / 2, 1, std::min(64, cap)));
            frame();
          }
        }
        Error e = Compare(Radiance(m), reference, o.Width);
        p.Seconds.push_back(elapsed());
        p.Spp.push_back(m->GetAccumulatedSamples());
        p.Mse.push_back(e.Mse);
        p.RelMse.push_back(e.RelMse);
        p.BlockRelRmse.push_back(e.BlockRelRmse);
        p.SweepSeconds.push_back(sweepSeconds);
        const int swept = m->GetDirectionsUpdatedTotal() - sweptBefore;
        p.Swept.push_back(swept);
        p.Effective.push_back(m->GetEffectiveStrategyAsString());
        std::fprintf(stderr, "  %-12s repeat %d: %s %g -> %d spp, %.2f s (sweeps %.2f s, %d directions), MSE %.4g, last "
                             "frame %s\n",
          strategy.c_str(), r, equalSpp ? "spp" : "budget", p.Budget, m->GetAccumulatedSamples(), elapsed(),
          sweepSeconds, swept, e.Mse, m->GetEffectiveStrategyAsString());
      }
    }
  }

  // Report.
  double refMean = 0.0;
  for (float v : reference)
    refMean += v;
  refMean /= double(reference.size());
  nlohmann::json report;
  report["scene"] = o.Scene;
  report["width"] = o.Width;
  report["height"] = o.Height;
  report["mode"] = equalSpp ? "equal-spp" : "equal-time";
  report["max_frame_seconds"] = o.MaxFrameSeconds;
  report["repeats"] = o.Repeats;
  report["reference"] = { { "file", referencePath }, { "spp", o.ReferenceSpp }, { "strategy", o.ReferenceStrategy },
    { "mean", refMean }, { "noise_floor_mse", noiseFloor } };
  std::printf("%s, %d x %d, %s, %d repeat(s); reference %s (%d spp, %s)\n", o.Scene.c_str(), o.Width, o.Height,
    equalSpp ? "equal spp" : "equal time (sweeps included)", o.Repeats, referencePath.c_str(), o.ReferenceSpp,
    o.ReferenceStrategy.c_str());
  if (noiseFloor >= 0.0)
  {
    std::printf("the reference's own noise: MSE floor %.3g (every MSE below includes it)\n", noiseFloor);
  }
  std::printf("%-12s %8s %9s %8s %12s %12s %10s %10s\n", "strategy", equalSpp ? "spp" : "budget", "seconds", "spp",
    "MSE", "(spread)", "relMSE", "relRMSE8");
  std::ostringstream csv;
  csv << "strategy,mode,budget,seconds,spp,mse,mse_spread,relmse,block8_relative_rmse\n";
  for (const auto& strategy : o.Strategies)
  {
    nlohmann::json js;
    for (const auto& p : results[strategy])
    {
      js["sweep_seconds"].push_back(Mean(p.SweepSeconds));
      js["directions_swept"].push_back(Mean(p.Swept));
      js["effective_strategy"].push_back(p.Effective);
      std::printf("%-12s %8g %9.2f %8.0f %12.4g %12.2g %10.4g %10.4g\n", strategy.c_str(), p.Budget, Mean(p.Seconds),
        Mean(p.Spp), Mean(p.Mse), Spread(p.Mse), Mean(p.RelMse), Mean(p.BlockRelRmse));
      csv << strategy << ',' << (equalSpp ? "spp" : "time") << ',' << p.Budget << ',' << Mean(p.Seconds) << ','
          << Mean(p.Spp) << ',' << Mean(p.Mse) << ',' << Spread(p.Mse) << ',' << Mean(p.RelMse) << ','
          << Mean(p.BlockRelRmse) << '\n';
      js["budgets"].push_back(p.Budget);
      js["seconds"].push_back(Mean(p.Seconds));
      js["spp"].push_back(Mean(p.Spp));
      js["mse"].push_back(Mean(p.Mse));
      js["mse_spread"].push_back(Spread(p.Mse));
      js["relmse"].push_back(Mean(p.RelMse));
      js["block8_relative_rmse"].push_back(Mean(p.BlockRelRmse));
      js["mse_per_repeat"].push_back(p.Mse);
    }
    report["strategies"][strategy] = js;
  }
  if (!o.Json.empty())
    WriteBenchText("--json", o.Json, report.dump(2) + "\n");
  if (!o.Csv.empty())
    WriteBenchText("--csv", o.Csv, csv.str());
  if (!o.Plot.empty())
  {
    // matplotlib (python3-matplotlib) draws it from the JSON.
    std::string json = o.Json.empty() ? o.Plot + ".json" : o.Json;
    if (o.Json.empty())
      WriteBenchText("--plot", json, report.dump(2) + "\n");
    const std::string script = (fs::path(BenchmarksDir()) / "plot_convergence.py").string();
    RunBenchPlot(script, json, o.Plot);
  }
  return 0;
}
}

void AddBenchConvergence(CLI::App& bench)
{
  auto o = std::make_shared<Options>();
  auto* cmd = bench.add_subcommand("convergence", "error against time (and spp) per strategy, against a reference");
  cmd->add_option("scene", o->Scene, "scene file (Benchmarks/scenes/*.json)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--reference", o->Reference, "reference EXR (default: rendered once, cached in Benchmarks/references)")
    ->check(CLI::ExistingFile);
  cmd->add_option("--reference-dir", o->ReferenceDir, "where rendered references are cached (default $XDG_CACHE_HOME/vissweep/references, else "
    "~/.cache/vissweep/references)");
  cmd->add_option("--reference-spp", o->ReferenceSpp, "samples per pixel of a rendered reference")
    ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--reference-strategy", o->ReferenceStrategy, "strategy of a rendered reference");
  cmd->add_option("--strategies", o->Strategies, "strategies to compare (default: all six)")->delimiter(',');
  cmd->add_option("--budgets", o->Budgets, "wall-clock budgets in seconds, sweeps included (default 1,2,4,8,16)")
    ->delimiter(',')
    ->check(FiniteNumber())
    ->check(CLI::PositiveNumber);
  cmd->add_option("--spp-list", o->SppList, "equal-spp mode: these samples per pixel instead of time budgets")
    ->delimiter(',');
  cmd->add_option("--repeats", o->Repeats, "runs per strategy with different seeds")->check(CLI::Range(1, 100));
  cmd->add_option("--width", o->Width, "image width")->check(CLI::Range(1, 4096));
  cmd->add_option("--height", o->Height, "image height")->check(CLI::Range(1, 4096));
  cmd->add_option("--json", o->Json, "write the figures as JSON");
  cmd->add_option("--csv", o->Csv, "write the figures as CSV");
  cmd->add_option("--plot", o->Plot, "draw error against time (log-log) to this PNG (matplotlib)");
  cmd->add_option("--max-frame-seconds", o->MaxFrameSeconds,
      "equal time: the longest a frame's samples may take (default 0.25 s, as in a window)")
    ->check(CLI::PositiveNumber)
    ->check(FiniteNumber());
  cmd->add_flag("--blocking", o->Blocking,
    "equal time: sweep the whole grid in each run's first frame instead of progressively between frames");
  cmd->add_flag("--quick", o->Quick, "32 x 32, budgets 0.5 and 1 s, one repeat, a 64-spp reference (for tests)");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
