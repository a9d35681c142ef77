// vsRenderCommand.h — `vissweep render SCENE.json -o OUT.(exr|png) ...`: renders the VTK
// pipeline of a scene file (vsSceneFile.h, built by vsSceneBuild.h) progressively offscreen with
// vtkVisibilitySweepVolumeMapper, writing linear EXR (with what made it in its header) and/or
// tone-mapped PNG or JPEG, and stats.
#ifndef vsRenderCommand_h
#define vsRenderCommand_h

#include "vsPendingFile.h"
#include "vsSceneBuild.h"
#include "vsSceneFile.h"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CLI
{
class App;
}

namespace vstool
{
struct ImageProvenance;

/** The options of `vissweep render`. */
struct RenderOptions
{
  std::string SceneFile;
  std::vector<std::string> Outputs;
  int Width = 0;
  int Height = 0;
  int Spp = 0;
  double TimeBudget = 0.0;
  std::string Strategy;
  std::string Mode; // the render mode (overrides render.mode)
  int MaxScatteringEvents = 0;  // 0: the scene's render.max_scattering_events
  std::optional<double> Anisotropy; // the scene's render.anisotropy when absent
  std::optional<double> ScatteringBlending; // issue 38: the scene's render.volumetric_scattering_blending when absent
  bool NoLights = false; // issue 38: --no-lights renders without the scene's lights
  bool Shade = false; // issue 38: --shade turns the property's shading on (transfer_function.shade)
  bool Denoise = false; // issue 39: --denoise, the PNG/JPEG shows the estimate through the display filter
  int Seed = -1;
  double Exposure = -1.0; // the PNG's exposure (overrides render.exposure); < 0: the scene's
  int SamplesPerFrame = 0; // 0: frames of about AutoFrameSeconds
  std::string Json;
  bool Quiet = false;
  std::string Frames; // "A:B": a time range of a volume sequence (vsRenderFrames.h)
  // The camera, each overriding the scene's (or the framing of a scene without one) when given:
  // three numbers "X,Y,Z" (world coordinates; the view up a direction).
  std::vector<double> CameraPosition;
  std::vector<double> FocalPoint;
  std::vector<double> ViewUp;
};

/** What a progressive render did. */
struct ProgressiveResult
{
  int Frames = 0;               // Render() calls
  int Spp = 0;                  // samples per pixel reached
  double Seconds = 0.0;         // wall time of the loop (the first frame's update included)
  double FirstFrameSeconds = 0.0;
  double UpdateSeconds = 0.0;   // the first frame's upload, majorants and sweeps (host wall time)
  int DirectionsUpdated = 0;    // directions swept by the first frame
  double DeviceSeconds = 0.0;   // render passes on the device
  double SweepSeconds = 0.0;    // sweeps on the device
  // The first frame's host time by phase (the mapper's GetLastFramePhaseName), in the order they ran.
  std::vector<std::pair<std::string, double>> FirstFramePhases;
  // Every frame of the loop (--json's "frames_log"): where the time outside the render passes goes.
  struct Frame
  {
    double Seconds = 0.0;       // the Render() call's wall time
    int Samples = 0;            // samples it added
    double DeviceSeconds = 0.0; // its render passes on the device
    double SweepSeconds = 0.0;  // its sweeps on the device
    double UpdateSeconds = 0.0; // its scene update (upload, majorants) on the host
    int DirectionsSwept = 0;
    std::string Strategy;       // what it sampled with
    std::vector<std::pair<std::string, double>> Phases; // its host time by phase (GetLastFramePhaseName)
  };
  std::vector<Frame> FrameLog;
};

/** The Vulkan device the renders run on (name, type, driver, Vulkan version), for --json. */
nlohmann::json DeviceJson();
/** Reads the scene file and applies the command line's overrides (size, spp, strategy, seed). */
Scene LoadScene(const RenderOptions& options);
/** Sets the command line's camera (--camera-position, --focal-point, --view-up) on the built scene's
 *  camera, after the scene's own or its framing; throws std::runtime_error naming the option when the
 *  position is the focal point or the view up is zero or along the view direction. */
void ApplyCameraOptions(SceneObjects& objects, const RenderOptions& options);
/** The length of an automatic progressive frame (about two progress-bar updates a second). */
constexpr double AutoFrameSeconds = 0.5;
/** Renders until `target` spp (or `timeBudget` seconds when > 0), `samplesPerFrame` per frame, or
 *  with 0 as many as take about AutoFrameSeconds (the first frame one); throws
 *  std::runtime_error on a render error or when no samples accumulate. */
ProgressiveResult RenderProgressively(
  SceneObjects& objects, int target, int samplesPerFrame, double timeBudget, bool progressBar);
/** What made the image, for the EXR's header: the scene file, the loop's result, the camera rendered
 *  with; `timeStep` >= 0 for a step of --frames. */
ImageProvenance Provenance(SceneObjects& objects, const Scene& scene, const std::string& sceneFile,
  const ProgressiveResult& loop, int timeStep = -1);
/** Writes the outputs (.exr: the radiance with `provenance` in its header, .png/.jpg: the window)
 *  under temporary names; commit them. */
std::vector<std::unique_ptr<PendingFile>> WriteOutputs(SceneObjects& objects, const Scene& scene,
  const std::vector<std::string>& outputs, const ImageProvenance& provenance);

/** Registers `render` on the tool's top-level app. */
void AddRender(CLI::App& app);
}

#endif
