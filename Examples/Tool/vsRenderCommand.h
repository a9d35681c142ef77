// vsRenderCommand.h — `vissweep render SCENE.json -o OUT.(exr|png) ...`: builds the VTK
// pipeline of a scene file (vsSceneFile.h) and renders it progressively offscreen with
// vtkVisibilitySweepVolumeMapper, writing linear EXR and/or tone-mapped PNG and stats.
#ifndef vsRenderCommand_h
#define vsRenderCommand_h

#include "vsPendingFile.h"
#include "vsSceneFile.h"

#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

class vtkAlgorithm;
class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;
class vtkVisibilitySweepVolumeMapper;
class vtkVolume;
class vtkVolumeProperty;

namespace vstool
{
/** The VTK objects of a scene; keep this alive while rendering. */
struct SceneObjects
{
  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkAlgorithm> Environment; // vtkEnvironmentMapReader or vtkEnvironmentMapSource (updated)
  vtkSmartPointer<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> Window; // offscreen, scene.Render.Width x Height
};

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
  int Seed = -1;
  int SamplesPerFrame = 0; // 0: frames of about AutoFrameSeconds
  std::string Json;
  bool Quiet = false;
  std::string Frames; // "A:B": a time range of a volume sequence (vsRenderFrames.h)
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
};

/** The Vulkan device the renders run on (name, type, driver, Vulkan version), for --json. */
nlohmann::json DeviceJson();
/** Reads the scene file and applies the command line's overrides (size, spp, strategy, seed). */
Scene LoadScene(const RenderOptions& options);
/** The length of an automatic progressive frame (about two progress-bar updates a second). */
constexpr double AutoFrameSeconds = 0.5;
/** Renders until `target` spp (or `timeBudget` seconds when > 0), `samplesPerFrame` per frame, or
 *  with 0 as many as take about AutoFrameSeconds (the first frame one); throws
 *  std::runtime_error on a render error or when no samples accumulate. */
ProgressiveResult RenderProgressively(
  SceneObjects& objects, int target, int samplesPerFrame, double timeBudget, bool progressBar);
/** Writes the outputs (.exr: the radiance, .png: the window) under temporary names; commit them. */
std::vector<std::unique_ptr<PendingFile>> WriteOutputs(
  SceneObjects& objects, const Scene& scene, const std::vector<std::string>& outputs);

/** The transfer functions and unit distance of the scene. */
vtkSmartPointer<vtkVolumeProperty> MakeVolumeProperty(const Scene& scene);
/** The environment (reader or procedural source), updated; throws std::runtime_error with the reason. */
vtkSmartPointer<vtkAlgorithm> MakeEnvironment(const Scene& scene);
/** Monte Carlo mode, strategy, seed, spp (MaximumSamples = scene spp), density, environment
 *  intensity/visibility, exposure, update scheme, visibility-grid parameters and clipping planes. */
void ConfigureMapper(vtkVisibilitySweepVolumeMapper* mapper, const Scene& scene);
/** Reads the volume, builds everything, sets the camera; the window is offscreen. Throws std::runtime_error. */
SceneObjects BuildScene(const Scene& scene);

/** Registers `render` on the tool's top-level app. */
void AddRender(CLI::App& app);
}

#endif
