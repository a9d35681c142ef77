// vsBenchScene.h — what the benchmarks that compare a render's radiance with a converged Monte Carlo
// render (bench preview, bench denoise) share: the scene built for the volume's own radiance, the check
// after each render, an image's rgb per pixel and the stopwatch.
#ifndef vsBenchScene_h
#define vsBenchScene_h

#include "vsSceneBuild.h"
#include "vsSceneFile.h"

#include <chrono>
#include <string>
#include <vector>

class vtkImageData;
class vtkVisibilitySweepVolumeMapper;

namespace vstool
{
/** The scene file read into `scene`, at size x size, with the environment not visible beside the volume,
 *  built. The volume's own radiance is what these benchmarks compare: the environment seen beside and
 *  through the volume is exact in the preview and in every Monte Carlo image alike, and would dominate
 *  (or dilute) the norm. Throws std::runtime_error as ReadSceneFile and BuildScene do. */
SceneObjects BuildRadianceScene(const std::string& sceneFile, int size, Scene& scene);

/** Throws std::runtime_error ("render failed: ...") when the mapper's last render failed. */
void CheckRender(vtkVisibilitySweepVolumeMapper* mapper);

/** The rgb per pixel of the image's `array` ("Radiance", or "Variance"); empty without image or array. */
std::vector<double> ImageRgb(vtkImageData* image, const char* array = "Radiance");

/** Seconds since `start` on the steady clock. */
double SecondsSince(std::chrono::steady_clock::time_point start);
}

#endif
