// vsStressScene.h — the small scene every stress case perturbs: a volume, a transfer
// function, an environment, the mapper in a 16 x 16 window; and the checks every case
// makes of the result: no error (unless expected), no NaN/Inf radiance, and radiance
// within physical bounds.
#ifndef vsStressScene_h
#define vsStressScene_h

#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

// VS_STRESS_ASAN: built with AddressSanitizer (scripts/sanitize.sh); gcc defines
// __SANITIZE_ADDRESS__, clang has __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define VS_STRESS_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VS_STRESS_ASAN 1
#endif
#endif
#ifndef VS_STRESS_ASAN
#define VS_STRESS_ASAN 0
#endif

namespace vsstress
{
/** A volume of dims voxels with values f(x, y, z) (index coordinates). */
vtkSmartPointer<vtkImageData> MakeVolume(int nx, int ny, int nz, const std::function<float(int, int, int)>& f,
  double spacing[3] = nullptr);

/** A soft ball of values in [0, 1], densest in the middle. */
float Ball(int x, int y, int z, int nx, int ny, int nz);

/** An environment map image (the vtkEnvironmentMapAlgorithm layout) of size x size texels. */
vtkSmartPointer<vtkImageData> MakeEnvironment(int size, const std::function<void(int, int, float rgb[3])>& texel);

struct Result
{
  std::string Error;
  int Samples = 0;
  int NonFinite = 0;     // radiance or variance values that are NaN or infinite
  double MaxMean = 0.0;  // largest per-pixel mean radiance (any channel)
  double MaxExcess = 0.0; // largest (mean - bound) / standard error over pixels and channels
  double Mean = 0.0;     // mean over pixels and channels
  double Coverage = 0.0; // mean alpha: the fraction of the image the volume covers
  // Per pixel: mean (r, g, b, alpha) and the variance of one sample of each (4 values a pixel).
  std::vector<double> PixelMean, PixelVariance;
};

class Scene
{
public:
  Scene(vtkImageData* volume, int size = 16);
  ~Scene();

  vtkVisibilitySweepVolumeMapper* Mapper() { return this->M; }
  vtkVolumeProperty* Property() { return this->P; }
  vtkPiecewiseFunction* Opacity() { return this->Op; }
  vtkColorTransferFunction* Color() { return this->Col; }
  vtkEnvironmentMapSource* Sky() { return this->Env; }
  vtkRenderer* Renderer() { return this->Ren; }
  vtkRenderWindow* Window() { return this->Win; }

  /** Renders until `spp` samples per pixel and checks radiance against `bound` (the
   *  largest environment radiance times the intensity: a single-scattering pixel cannot
   *  exceed it once converged; judged per pixel with 6 standard errors of slack). */
  Result Render(int spp, double bound);

private:
  vtkNew<vtkVisibilitySweepVolumeMapper> M;
  vtkNew<vtkVolumeProperty> P;
  vtkNew<vtkPiecewiseFunction> Op;
  vtkNew<vtkColorTransferFunction> Col;
  vtkNew<vtkEnvironmentMapSource> Env;
  vtkNew<vtkVolume> Vol;
  vtkNew<vtkRenderer> Ren;
  vtkNew<vtkRenderWindow> Win;
};

/** The checks every case makes: no error, no non-finite values, within the bound. */
void ExpectSane(const Result& r, const std::string& what);
}

#endif
