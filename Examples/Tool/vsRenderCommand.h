// vsRenderCommand.h — `vissweep render SCENE.json -o OUT.(exr|png) ...`: builds the VTK
// pipeline of a scene file (vsSceneFile.h) and renders it progressively offscreen with
// vtkVisibilitySweepVolumeMapper, writing linear EXR and/or tone-mapped PNG and stats.
#ifndef vsRenderCommand_h
#define vsRenderCommand_h

#include "vsSceneFile.h"

#include "vtkSmartPointer.h"

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

/** The transfer functions and unit distance of the scene. */
vtkSmartPointer<vtkVolumeProperty> MakeVolumeProperty(const Scene& scene);
/** The environment (reader or procedural source), updated; throws std::runtime_error with the reason. */
vtkSmartPointer<vtkAlgorithm> MakeEnvironment(const Scene& scene);
/** Monte Carlo mode, strategy, seed, spp (MaximumSamples = scene spp), density, environment
 *  intensity/visibility, exposure, visibility-grid parameters and clipping planes. */
void ConfigureMapper(vtkVisibilitySweepVolumeMapper* mapper, const Scene& scene);
/** Reads the volume, builds everything, sets the camera; the window is offscreen. Throws std::runtime_error. */
SceneObjects BuildScene(const Scene& scene);

/** Writes the mapper's radiance image (GetRadiance()) as linear float RGBA EXR; throws std::runtime_error. */
void WriteExr(vtkImageData* radiance, const std::string& path);

/** Registers `render` on the tool's top-level app. */
void AddRender(CLI::App& app);
}

#endif
