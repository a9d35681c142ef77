// vsSceneBuild.h — the VTK pipeline of a scene file's Scene (vsSceneFile.h): the volume,
// its property, the environment map, vtkVisibilitySweepVolumeMapper configured from the scene,
// the camera and an offscreen window. `vissweep render`, its --frames and the benchmarks
// render what BuildScene returns.
#ifndef vsSceneBuild_h
#define vsSceneBuild_h

#include "vsSceneFile.h"

#include "vtkSmartPointer.h"

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
  vtkSmartPointer<vtkRenderWindow> Window; // scene.Render.Width x Height: headless, or offscreen OpenGL
};

/** The transfer functions and unit distance of the scene. */
vtkSmartPointer<vtkVolumeProperty> MakeVolumeProperty(const Scene& scene);
/** The environment (reader or procedural source), updated; throws std::runtime_error with the reason. */
vtkSmartPointer<vtkAlgorithm> MakeEnvironment(const Scene& scene);
/** Monte Carlo mode, strategy, seed, spp (MaximumSamples = scene spp), density, environment
 *  intensity/visibility, exposure, update scheme, visibility-grid parameters and clipping planes. */
void ConfigureMapper(vtkVisibilitySweepVolumeMapper* mapper, const Scene& scene);
/** Reads the volume, builds everything, sets the camera. The window is a vtkVisSweepHeadlessWindow
 *  (no X display, the same pixels), or with `openGLWindow` VTK's offscreen OpenGL window on the X
 *  display (for what measures a window: bench frames; vs::RequireDisplay() says when there is none).
 *  Throws std::runtime_error. */
SceneObjects BuildScene(const Scene& scene, bool openGLWindow = false);
}

#endif
