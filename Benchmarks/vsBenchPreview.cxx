#include "vsBenchPreview.h"
#include "vsBenchOutput.h"
#include "vsBenchScene.h"
#include "vsToolCommand.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace vstool
{
namespace
{
struct PreviewOptions
{
  std::string SceneFile;
  int Size = 512;
  int ReferenceSpp = 1024;
  int Repeats = 3;
  double SampleDistance = 0.0;
  std::vector<int> PreviewOrders; // the preview again at each of these PreviewScatteringOrders
  std::string Json, ContactSheet, Plot;
};

// The volume's radiance of the last render (rgb per pixel), empty without one.
std::vector<double> Radiance(vtkVisibilitySweepVolumeMapper* mapper)
{
  return ImageRgb(mapper->GetRadiance());
}

// sum (x - ref)^2 / sum ref^2 over the pixels' rgb; NaN when they do not compare.
double RelativeMSE(const std::vector<double>& x, const std::vector<double>& ref)
{
  if (x.size() != ref.size() || ref.empty())
  {
    return std::nan("");
  }
  double num = 0.0, den = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    num += (x[i] - ref[i]) * (x[i] - ref[i]);
    den += ref[i] * ref[i];
  }
  return den > 0.0 ? num / den : std::nan("");
}

// The window as shown (rgb, rows bottom-up), without rendering it again.
std::vector<unsigned char> WindowImage(vtkRenderWindow* win)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(win);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkDataArray* a = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<unsigned char> out(size_t(a->GetNumberOfTuples()) * 3);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      out[3 * size_t(i) + c] = static_cast<unsigned char>(a->GetComponent(i, c));
    }
  }
  return out;
}

// The images (each size x size rgb) side by side, left to right, as a PNG.
void WriteContactSheet(const std::string& path, const std::vector<std::vector<unsigned char>>& images, int size)
{
  vtkNew<vtkImageData> sheet;
  sheet->SetDimensions(size * int(images.size()), size, 1);
  sheet->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(sheet->GetScalarPointer());
  const size_t row = size_t(size) * images.size() * 3;
  for (size_t k = 0; k < images.size(); ++k)
  {
    for (int y = 0; y < size && images[k].size() == size_t(size) * size * 3; ++y)
    {
      std::copy_n(images[k].data() + size_t(y) * size * 3, size_t(size) * 3, out + y * row + k * size_t(size) * 3);
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(sheet);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw std::runtime_error("--contact-sheet " + path + ": cannot write");
  }
}

struct Row
{
  std::string Mode;
  double FirstSeconds = 0.0; // the first frame (grid, light volume, pipelines)
  double FrameSeconds = 0.0; // median frame after a camera move (Monte Carlo: the whole accumulation)
  double DeviceSeconds = 0.0; // the render pass's device time in that frame (deterministic modes)
  double Error = std::nan("");
};

int Run(const PreviewOptions& o)
{
  CheckBenchOutputs({ { "--json", o.Json }, { "--contact-sheet", o.ContactSheet }, { "--plot", o.Plot } });
  Scene scene;
  SceneObjects objects = BuildRadianceScene(o.SceneFile, o.Size, scene);
  vtkVisibilitySweepVolumeMapper* mapper = objects.Mapper;
  mapper->SetSampleDistance(o.SampleDistance);
  vtkCamera* camera = objects.Renderer->GetActiveCamera();
  std::vector<Row> rows;
  std::vector<std::vector<double>> images;
  std::vector<std::vector<unsigned char>> shown; // the window after each mode, for the contact sheet

  // A deterministic mode: its first frame, then the median of `Repeats` frames after small camera moves.
  // `dragging`: every frame, the image's too, at the window's interactive rate (the mapper's coarser
  // interactive step), as while the user drags.
  auto deterministic = [&](const char* name, int mode, bool shade, bool dragging = false) {
    const double stillRate = objects.Window->GetDesiredUpdateRate();
    if (dragging)
    {
      objects.Window->SetDesiredUpdateRate(std::max(15.0, mapper->GetInteractiveUpdateRate()));
    }
    mapper->SetRenderMode(mode);
    objects.Property->SetShade(shade ? 1 : 0);
    Row r;
    r.Mode = name;
    auto start = std::chrono::steady_clock::now();
    objects.Window->Render();
    r.FirstSeconds = SecondsSince(start);
    CheckRender(mapper);
    std::vector<double> frames, device;
    // A new camera every frame, as while dragging (a camera that comes back to an earlier position
    // could find device state of that frame, e.g. a driver's shader variants, and time it as free).
    for (int i = 0; i < o.Repeats; ++i)
    {
      camera->Azimuth(0.5);
      start = std::chrono::steady_clock::now();
      objects.Window->Render();
      frames.push_back(SecondsSince(start));
      device.push_back(mapper->GetLastDeviceSeconds());
      CheckRender(mapper);
    }
    camera->Azimuth(-0.5 * o.Repeats); // back where the mode started, for the image and the next mode
    objects.Window->Render();
    std::sort(frames.begin(), frames.end());
    std::sort(device.begin(), device.end());
    r.FrameSeconds = frames.empty() ? r.FirstSeconds : frames[frames.size() / 2];
    r.DeviceSeconds = device.empty() ? mapper->GetLastDeviceSeconds() : device[device.size() / 2];
    rows.push_back(r);
    images.push_back(mode == vtkVisibilitySweepVolumeMapper::Preview ? Radiance(mapper) : std::vector<double>());
    shown.push_back(WindowImage(objects.Window));
    objects.Window->SetDesiredUpdateRate(stillRate);
    std::printf("  %-28s first frame %.3f s, frame %.3f s (device %.3f s)\n", name, r.FirstSeconds, r.FrameSeconds,
      r.DeviceSeconds);
    std::fflush(stdout);
  };
  // Monte Carlo from scratch to `spp` with `seed`: the accumulation's wall time.
  auto monteCarlo = [&](int spp, int seed) {
    mapper->SetRenderModeToMonteCarlo();
    objects.Property->SetShade(0);
    mapper->SetSeed(seed);
    mapper->SetMaximumSamples(spp);
    mapper->SetSamplesPerFrame(std::min(spp, 16));
    const auto start = std::chrono::steady_clock::now();
    int frames = 0;
    do
    {
      objects.Window->Render();
      CheckRender(mapper);
    } while (++frames < 4 * spp && !mapper->IsConverged());
    if (mapper->GetAccumulatedSamples() != spp)
    {
      throw std::runtime_error("Monte Carlo reached " + std::to_string(mapper->GetAccumulatedSamples()) + " of " +
        std::to_string(spp) + " spp");
    }
    return std::make_pair(Radiance(mapper), SecondsSince(start));
  };

  std::printf("scene %s at %d x %d (the volume's radiance, environment not visible)\n", o.SceneFile.c_str(), o.Size,
    o.Size);
  const bool shaded = objects.Property->GetShade(0) != 0;
  deterministic("emission-absorption", vtkVisibilitySweepVolumeMapper::EmissionAbsorption, false);
  deterministic("emission-absorption, Phong", vtkVisibilitySweepVolumeMapper::EmissionAbsorption, true);
  deterministic("ambient occlusion", vtkVisibilitySweepVolumeMapper::AmbientOcclusion, false);
  deterministic("preview", vtkVisibilitySweepVolumeMapper::Preview, false);
  deterministic("preview while dragging", vtkVisibilitySweepVolumeMapper::Preview, false, true);
  const int defaultOrders = mapper->GetPreviewScatteringOrders();
  std::vector<std::string> orderNames;
  for (int k : o.PreviewOrders)
  {
    // The first frame builds the light volume with k orders (the grid is made already).
    mapper->SetPreviewScatteringOrders(k);
    orderNames.push_back("preview, " + std::to_string(k) + " orders");
    deterministic(orderNames.back().c_str(), vtkVisibilitySweepVolumeMapper::Preview, false);
    orderNames.push_back("preview, " + std::to_string(k) + " orders, dragging");
    deterministic(orderNames.back().c_str(), vtkVisibilitySweepVolumeMapper::Preview, false, true);
  }
  mapper->SetPreviewScatteringOrders(defaultOrders);
  monteCarlo(1, 1); // the Monte Carlo pipelines, compiled before anything is timed
  for (int spp : { 1, 4, 16, 64 })
  {
    auto mc = monteCarlo(spp, 100 + spp);
    Row r;
    r.Mode = "Monte Carlo " + std::to_string(spp) + " spp";
    r.FrameSeconds = mc.second;
    rows.push_back(r);
    images.push_back(mc.first);
    shown.push_back(WindowImage(objects.Window));
    std::printf("  %-28s %.3f s\n", r.Mode.c_str(), r.FrameSeconds);
    std::fflush(stdout);
  }
  const auto reference = monteCarlo(o.ReferenceSpp, 7919);
  shown.push_back(WindowImage(objects.Window));
  std::printf("  reference: Monte Carlo %d spp in %.1f s\n", o.ReferenceSpp, reference.second);
  objects.Property->SetShade(shaded ? 1 : 0);

  nlohmann::json report;
  report["scene"] = o.SceneFile;
  report["size"] = o.Size;
  report["reference_spp"] = o.ReferenceSpp;
  std::printf("\n%-28s %14s %12s %22s\n", "mode", "first frame s", "frame s", "relative MSE vs ref");
  for (size_t i = 0; i < rows.size(); ++i)
  {
    Row& r = rows[i];
    r.Error = RelativeMSE(images[i], reference.first);
    char error[64];
    if (std::isnan(r.Error))
    {
      std::snprintf(error, sizeof(error), "%s", "n/a (not L)");
    }
    else
    {
      std::snprintf(error, sizeof(error), "%.3e", r.Error);
    }
    char first[32] = "";
    if (r.FirstSeconds > 0.0)
    {
      std::snprintf(first, sizeof(first), "%.3f", r.FirstSeconds);
    }
    std::printf("%-28s %14s %12.3f %22s\n", r.Mode.c_str(), first, r.FrameSeconds, error);
    nlohmann::json row = { { "mode", r.Mode }, { "frame_seconds", r.FrameSeconds } };
    if (r.FirstSeconds > 0.0)
    {
      row["first_frame_seconds"] = r.FirstSeconds;
      row["device_seconds"] = r.DeviceSeconds;
    }
    if (!std::isnan(r.Error))
    {
      row["relative_mse"] = r.Error;
    }
    report["modes"].push_back(row);
  }
  std::printf("(Monte Carlo: the accumulation's wall time; emission-absorption, Phong and ambient occlusion are not "
              "estimates of the scattered radiance: no error)\n");
  const std::string json = !o.Json.empty() ? o.Json : !o.Plot.empty() ? o.Plot + ".json" : std::string();
  if (!json.empty())
  {
    WriteBenchText(o.Json.empty() ? "--plot" : "--json", json, report.dump(2) + "\n");
    std::printf("wrote %s\n", json.c_str());
  }
  if (!o.ContactSheet.empty())
  {
    WriteContactSheet(o.ContactSheet, shown, o.Size);
    std::printf("wrote %s (left to right: the modes in the table's order, then the reference)\n", o.ContactSheet.c_str());
  }
  if (!o.Plot.empty())
  {
    // matplotlib (python3-matplotlib) draws it from the JSON.
    const std::string script = (std::filesystem::path(BenchmarksDir()) / "plot_preview.py").string();
    RunBenchPlot(script, json, o.Plot);
    std::printf("wrote %s\n", o.Plot.c_str());
  }
  return 0;
}
}

void AddBenchPreview(CLI::App& bench)
{
  auto o = std::make_shared<PreviewOptions>();
  auto* cmd = bench.add_subcommand("preview",
    "frame time and error against converged Monte Carlo: emission-absorption, Phong, ambient occlusion, preview (still and while dragging), "
    "Monte Carlo at 1/4/16/64 spp");
  cmd->add_option("scene", o->SceneFile, "the scene file")->required();
  cmd->add_option("--size", o->Size, "image width and height (default 512)")->check(CLI::Range(1, 16384));
  cmd->add_option("--reference-spp", o->ReferenceSpp, "the converged Monte Carlo image's spp (default 1024)")
    ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--repeats", o->Repeats, "timed frames per deterministic mode (default 3)")->check(CLI::Range(1, 1000));
  cmd->add_option("--sample-distance", o->SampleDistance,
      "the deterministic modes' ray-marching step in world units (default 0: the mapper's default)")
    ->check(CLI::Range(0.0, 1e30));
  cmd->add_option("--preview-orders", o->PreviewOrders,
    "also the preview with each of these PreviewScatteringOrders (1: single scattering), still and while dragging")
    ->delimiter(',')
    ->check(CLI::Range(1, 64));
  cmd->add_option("--json", o->Json, "write the table as JSON");
  cmd->add_option("--contact-sheet", o->ContactSheet, "write the window after each mode side by side to this PNG");
  cmd->add_option("--plot", o->Plot, "draw error against frame time (log-log) to this PNG (matplotlib)");
  SetCommandRun(cmd, [o]() { return Run(*o); });
}
}
