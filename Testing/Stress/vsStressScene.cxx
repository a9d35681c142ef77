#include "vsStressScene.h"

#include "vtkPointData.h"

#include <algorithm>
#include <cmath>

#if VS_STRESS_ASAN
#include <dlfcn.h>
#include <link.h>

#include <cstring>
#include <vector>
#endif

namespace vsstress
{
namespace
{
#if VS_STRESS_ASAN
// Sanitizer builds only: keep Mesa's OpenGL driver (swrast_dri.so, llvmpipe behind the
// Xvfb window) loaded until exit. Mesa's GLX dlcloses the driver when a window's display
// closes, and the driver's data segment goes with it; LeakSanitizer no longer scans that
// memory at exit, so the driver's own allocations that were still referenced from it are
// reported as leaks "allocated from <unknown module>" (a u_mm heap the driver creates on the
// first draw, 2 x 56 bytes per window). With the library pinned (RTLD_NODELETE on the very
// object GLX loaded, found by path) its globals stay mapped and scanned, the false reports
// go away, and any real leak in it would be attributed to swrast_dri.so by name.
// See scripts/sanitizers/lsan.supp.
void KeepGLDriverLoaded()
{
  static bool done = false;
  if (done)
  {
    return;
  }
  std::vector<std::string> drivers;
  dl_iterate_phdr(
    [](dl_phdr_info* info, size_t, void* out) {
      const char* slash = info->dlpi_name ? std::strrchr(info->dlpi_name, '/') : nullptr;
      if (slash && std::strcmp(slash + 1, "swrast_dri.so") == 0)
      {
        static_cast<std::vector<std::string>*>(out)->push_back(info->dlpi_name);
      }
      return 0;
    },
    &drivers);
  for (const std::string& path : drivers)
  {
    // RTLD_NOLOAD: only the object already loaded; RTLD_NODELETE: never unmapped.
    if (dlopen(path.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE))
    {
      done = true;
    }
  }
}
#else
void KeepGLDriverLoaded() {}
#endif
}

vtkSmartPointer<vtkImageData> MakeVolume(
  int nx, int ny, int nz, const std::function<float(int, int, int)>& f, double spacing[3])
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  if (spacing)
  {
    image->SetSpacing(spacing);
  }
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(vtkIdType(nx) * ny * nz);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        values->SetValue((vtkIdType(z) * ny + y) * nx + x, f(x, y, z));
  image->GetPointData()->SetScalars(values);
  return image;
}

float Ball(int x, int y, int z, int nx, int ny, int nz)
{
  auto c = [](int i, int n) { return n > 1 ? (i - 0.5 * (n - 1)) / (0.5 * n) : 0.0; };
  double r = std::sqrt(c(x, nx) * c(x, nx) + c(y, ny) * c(y, ny) + c(z, nz) * c(z, nz));
  return float(std::max(0.0, 1.0 - r));
}

vtkSmartPointer<vtkImageData> MakeEnvironment(int size, const std::function<void(int, int, float rgb[3])>& texel)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size, size, 1);
  image->SetOrigin(0.5 / size, 0.5 / size, 0.0);
  image->SetSpacing(1.0 / size, 1.0 / size, 1.0);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(vtkIdType(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
    {
      float rgb[3] = { 0, 0, 0 };
      texel(x, y, rgb);
      radiance->SetTypedTuple(vtkIdType(y) * size + x, rgb);
    }
  image->GetPointData()->SetScalars(radiance);
  return image;
}

Scene::Scene(vtkImageData* volume, int size)
{
  this->Op->AddPoint(0.0, 0.0);
  this->Op->AddPoint(1.0, 0.8);
  this->Col->AddRGBPoint(0.0, 0.9, 0.9, 0.9);
  this->Col->AddRGBPoint(1.0, 0.8, 0.6, 0.5);
  this->P->SetScalarOpacity(this->Op);
  this->P->SetColor(this->Col);
  this->Env->SetTypeToSunDisk();
  this->Env->SetSunAngularRadius(5.0);
  this->Env->SetOctahedralSize(32);
  this->M->SetInputData(volume);
  this->M->SetEnvironmentConnection(this->Env->GetOutputPort());
  this->M->SetInteractiveUpdateRate(0.0);
  this->Vol->SetMapper(this->M);
  this->Vol->SetProperty(this->P);
  this->Ren->AddVolume(this->Vol);
  this->Win->SetMultiSamples(0);
  this->Win->AddRenderer(this->Ren);
  this->Win->SetSize(size, size);
  this->Ren->ResetCamera();
}

Scene::~Scene()
{
  // The window (and with it the display and GLX's reference to the driver) goes after this.
  KeepGLDriverLoaded();
}

Result Scene::Render(int spp, double bound)
{
  Result r;
  this->M->SetMaximumSamples(spp);
  this->M->SetSamplesPerFrame(std::min(spp, 64));
  for (int frame = 0; frame < 1 + spp / 64 + 1; ++frame)
  {
    this->Win->Render();
    r.Error = this->M->GetLastError();
    if (!r.Error.empty() || this->M->GetAccumulatedSamples() >= spp)
    {
      break;
    }
  }
  r.Samples = this->M->GetAccumulatedSamples();
  vtkImageData* radiance = this->M->GetRadiance(true);
  if (!radiance)
  {
    return r;
  }
  auto* mean = vtkFloatArray::SafeDownCast(radiance->GetPointData()->GetArray("Radiance"));
  vtkDataArray* var = radiance->GetPointData()->GetArray("Variance");
  const vtkIdType n = mean->GetNumberOfTuples();
  vtkDataArray* alpha = radiance->GetPointData()->GetArray("Alpha");
  r.PixelMean.resize(4 * n);
  r.PixelVariance.resize(4 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    r.Coverage += alpha->GetComponent(i, 0) / double(n);
    for (int c = 0; c < 4; ++c)
    {
      r.PixelMean[4 * i + c] = c < 3 ? mean->GetComponent(i, c) : alpha->GetComponent(i, 0);
      r.PixelVariance[4 * i + c] = var->GetComponent(i, c);
    }
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double m = mean->GetComponent(i, c), v = var->GetComponent(i, c);
      if (!std::isfinite(m) || !std::isfinite(v))
      {
        ++r.NonFinite;
        continue;
      }
      r.MaxMean = std::max(r.MaxMean, m);
      r.Mean += m / (3.0 * n);
      const double se = std::sqrt(v / std::max(1, r.Samples));
      if (m > bound)
      {
        r.MaxExcess = std::max(r.MaxExcess, se > 0.0 ? (m - bound) / se : 1e30);
      }
    }
  }
  return r;
}

void ExpectSane(const Result& r, const std::string& what)
{
  EXPECT_EQ(r.Error, "") << what;
  EXPECT_GT(r.Samples, 0) << what;
  EXPECT_EQ(r.NonFinite, 0) << what << ": NaN or infinite radiance";
  EXPECT_LE(r.MaxExcess, 6.0) << what << ": a pixel's radiance exceeds the brightest light by " << r.MaxExcess
                              << " standard errors (max mean " << r.MaxMean << ")";
}
}
