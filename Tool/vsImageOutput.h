// vsImageOutput.h — the images `vissweep render` writes: linear EXR from the mapper's radiance
// (with what made it in its header), tone-mapped PNG or JPEG from the window, and the checks of
// output names made before rendering.
#ifndef vsImageOutput_h
#define vsImageOutput_h

#include <array>
#include <string>

class vtkImageData;
class vtkRenderWindow;

namespace vstool
{
/** The lower-case extension of a path, with the dot (".exr"). */
std::string Extension(const std::string& path);
/** Throws std::runtime_error naming the option when an output is not .exr/.png/.jpg/.jpeg or its
 *  folder is missing. */
void CheckOutputPath(const std::string& path);

/** What made an image: written into the EXR's header as attributes named "vissweep.<name>"
 *  (docs/reference.md, "EXR output"), so an image found later says how to make it again. */
struct ImageProvenance
{
  std::string Version;           // vissweep.version
  std::string SceneFile;         // vissweep.scene: the scene file, absolute
  int TimeStep = -1;             // vissweep.timeStep: --frames' index into volume.files (-1: not written)
  std::string Mode;              // vissweep.mode: monte-carlo, preview, ...
  std::string Strategy;          // vissweep.strategy: as asked (auto, two-step, ...)
  std::string EffectiveStrategy; // vissweep.effectiveStrategy: what the last frame sampled with
  int Spp = 0;                   // vissweep.spp: samples per pixel reached (0: a deterministic mode)
  double Seconds = 0.0;          // vissweep.seconds: the render's wall time (setup not included)
  int Seed = 0;                  // vissweep.seed
  std::array<double, 3> CameraPosition{ 0, 0, 0 }; // vissweep.cameraPosition, .focalPoint, .viewUp:
  std::array<double, 3> FocalPoint{ 0, 0, 0 };     // the camera rendered with (after any reset or
  std::array<double, 3> ViewUp{ 0, 0, 1 };         // command-line override), world coordinates
  double ViewAngle = 30.0;       // vissweep.viewAngle, degrees
  std::string Device;            // vissweep.device: the Vulkan device's name
};

/** The radiance image (arrays "Radiance", optional "Alpha") as a float RGBA EXR, rows top-down;
 *  with `provenance`, its fields as header attributes. */
void WriteExr(vtkImageData* radiance, const std::string& path, const ImageProvenance* provenance = nullptr);
/** The window as shown (tone mapped), without re-rendering (a re-render would add samples): PNG, or
 *  JPEG (quality 95) for a .jpg/.jpeg path. */
void WriteWindowImage(vtkRenderWindow* window, const std::string& path);
}

#endif
