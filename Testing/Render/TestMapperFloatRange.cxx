// Numbers outside float range (issue 13, item 5): finite doubles the device's float cannot hold
// used to become infinities or zeros there (an intensity of 1e39: an all-NaN image; a
// transfer-function point at 1e39: an empty table; a clip-plane normal of 1e300: an ignored
// plane). The mapper's setters refuse them (an error, the setting kept); what the mapper reads
// from VTK objects at Render() (transfer-function points, unit distance, camera, clipping planes)
// is an error once per change naming the value and the limit, and nothing is drawn. A huge
// clip-plane normal is a direction: normalised in double, it clips as its unit normal does.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <vector>

using vstest::Check;

namespace
{
vtkSmartPointer<vtkImageData> Ball()
{
  const int n = 12;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(vtkIdType(n) * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
      {
        const double dx = x - 5.5, dy = y - 5.5, dz = z - 5.5;
        a->SetValue((vtkIdType(z) * n + y) * n + x, float(std::max(0.0, 1.0 - std::sqrt(dx * dx + dy * dy + dz * dz) / 6.0)));
      }
  image->GetPointData()->SetScalars(a);
  return image;
}

struct Scene
{
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vstest::ErrorRecorder> Recorder;

  explicit Scene(vtkImageData* image)
  {
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, 0.9);
    this->Color->AddRGBPoint(0.0, 0.8, 0.8, 0.8);
    this->Color->AddRGBPoint(1.0, 0.8, 0.8, 0.8);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Property->SetInterpolationTypeToLinear();
    this->Mapper->SetInputData(image);
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Mapper->SetMaximumSamples(4);
    this->Mapper->SetSamplesPerFrame(4);
    this->Recorder->Watch(this->Mapper);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetBackground(0.2, 0.4, 0.6);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(24, 24);
    this->Renderer->ResetCamera();
  }

  bool OnlyBackground()
  {
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetPixelData(0, 0, 23, 23, 0, pixels);
    for (vtkIdType i = 0; i < 24 * 24; ++i)
    {
      if (pixels->GetValue(3 * i) != 51 || pixels->GetValue(3 * i + 1) != 102 || pixels->GetValue(3 * i + 2) != 153)
      {
        return false;
      }
    }
    return true;
  }

  std::vector<float> Radiance()
  {
    std::vector<float> v;
    vtkImageData* r = this->Mapper->GetRadiance();
    if (!r)
    {
      return v;
    }
    vtkDataArray* a = r->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c)
        v.push_back(float(a->GetComponent(i, c)));
    return v;
  }
};

// A case for Render(): `edit` breaks the scene, two renders give exactly one error containing
// `expected` and draw nothing; `repair` undoes it and the next render draws again without error.
void RenderCase(const char* name, const std::function<void(Scene&)>& edit, const std::string& expected)
{
  auto image = Ball();
  Scene s(image);
  edit(s);
  s.Window->Render();
  s.Window->Render();
  const bool once = s.Recorder->Errors.size() == 1;
  Check(once, std::string(name) + ": exactly one error for two renders of the same input (got " +
      std::to_string(s.Recorder->Errors.size()) + ")");
  Check(s.Recorder->Saw(expected), std::string(name) + ": an error containing '" + expected + "'");
  Check(s.OnlyBackground(), std::string(name) + ": nothing drawn");
  Check(std::string(s.Mapper->GetLastError()).find(expected) != std::string::npos,
    std::string(name) + ": GetLastError() holds it");
  Check(s.Mapper->GetRadiance() == nullptr, std::string(name) + ": no radiance after the error");
  std::cout << name << ": " << (s.Recorder->Errors.empty() ? "(no error)" : s.Recorder->Errors.front()) << "\n";
}
}

int TestMapperFloatRange(int, char*[])
{
  // Setters: refused with an error, the setting kept.
  {
    vtkNew<vtkVisibilitySweepVolumeMapper> m;
    vtkNew<vstest::ErrorRecorder> recorder;
    recorder->Watch(m);
    struct Setter
    {
      const char* name;
      std::function<void(double)> set;
      std::function<double()> get;
      double keep;
    };
    const Setter setters[] = {
      { "EnvironmentIntensity", [&](double v) { m->SetEnvironmentIntensity(v); },
        [&] { return m->GetEnvironmentIntensity(); }, 2.0 },
      { "DensityScale", [&](double v) { m->SetDensityScale(v); }, [&] { return m->GetDensityScale(); }, 3.0 },
      { "Exposure", [&](double v) { m->SetExposure(v); }, [&] { return m->GetExposure(); }, 0.5 },
      { "SampleDistance", [&](double v) { m->SetSampleDistance(v); }, [&] { return m->GetSampleDistance(); }, 0.25 },
    };
    for (const Setter& s : setters)
    {
      s.set(s.keep);
      for (double bad : { 1e39, -1e300, std::numeric_limits<double>::infinity(), std::nan("") })
      {
        const size_t before = recorder->Errors.size();
        s.set(bad);
        Check(recorder->Errors.size() == before + 1, std::string(s.name) + " " + std::to_string(bad) + ": one error");
        Check(s.get() == s.keep, std::string(s.name) + " " + std::to_string(bad) + ": the setting is kept");
      }
      Check(recorder->Saw(std::string(s.name) + " 1e+39 is refused: outside the range of float"),
        std::string(s.name) + ": the error names the value and the limit");
      s.set(3.4e38);
      Check(s.get() == 3.4e38, std::string(s.name) + ": 3.4e38 fits a float and is accepted");
      s.set(-1.0);
      Check(s.get() == 0.0, std::string(s.name) + ": negative values are clamped to 0 as before");
    }
  }

  // Render(): what the mapper reads from VTK's objects.
  RenderCase("opacity point at 1e39", [](Scene& s) { s.Opacity->AddPoint(1e39, 1.0); },
    "the scalar opacity transfer function's point 2 at scalar 1e+39: outside the range of float");
  RenderCase("colour point at -1e39", [](Scene& s) { s.Color->AddRGBPoint(-1e39, 1, 1, 1); },
    "the colour transfer function's point 0 at scalar -1e+39: outside the range of float");
  RenderCase("unit distance 1e-40", [](Scene& s) { s.Property->SetScalarOpacityUnitDistance(1e-40); },
    "the scalar opacity unit distance 1e-40 is outside the range of float");
  RenderCase("unit distance 1e39", [](Scene& s) { s.Property->SetScalarOpacityUnitDistance(1e39); },
    "the scalar opacity unit distance 1e+39 is outside the range of float");
  // A camera looking at the ball from 30 voxels away towards a focal point beyond float's range (a
  // camera itself 1e39 away is culled by VTK before the mapper runs: the ball covers no pixel).
  RenderCase("camera focal point 1e39",
    [](Scene& s) {
      s.Renderer->GetActiveCamera()->SetPosition(5.5, 5.5, -30.0);
      s.Renderer->GetActiveCamera()->SetFocalPoint(5.5, 5.5, 1e39);
      s.Renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
    },
    "the camera's focal point (z = 1e+39) is outside the range of float");
  RenderCase("parallel scale 1e-39",
    [](Scene& s) {
      s.Renderer->GetActiveCamera()->ParallelProjectionOn();
      s.Renderer->GetActiveCamera()->SetParallelScale(1e-39);
    },
    "the camera's parallel scale 1e-39 is outside the range of float");
  RenderCase("clip-plane origin 1e39",
    [](Scene& s) {
      vtkNew<vtkPlane> p;
      p->SetOrigin(0, 1e39, 0);
      p->SetNormal(0, 1, 0);
      s.Mapper->AddClippingPlane(p);
    },
    "clipping plane 0's origin (y = 1e+39) is outside the range of float");
  RenderCase("clip-plane normal zero",
    [](Scene& s) {
      vtkNew<vtkPlane> p;
      p->SetOrigin(5.5, 5.5, 5.5);
      p->SetNormal(0, 0, 0);
      s.Mapper->AddClippingPlane(p);
    },
    "clipping plane 0 has a zero or non-finite normal");

  // A clip-plane normal of 1e300 is the direction +X: it clips exactly as (1, 0, 0) does (it used
  // to be an infinity in float, and the plane was ignored).
  {
    auto image = Ball();
    std::vector<float> images[3];
    const double normals[3][3] = { { 1, 0, 0 }, { 1e300, 0, 0 }, { 0, 0, 0 } };
    for (int k = 0; k < 3; ++k)
    {
      Scene s(image);
      if (k < 2)
      {
        vtkNew<vtkPlane> p;
        p->SetOrigin(5.5, 5.5, 5.5);
        p->SetNormal(normals[k][0], normals[k][1], normals[k][2]);
        s.Mapper->AddClippingPlane(p);
      }
      s.Window->Render();
      Check(s.Recorder->Errors.empty(), "clip-plane normal case " + std::to_string(k) + ": no error");
      images[k] = s.Radiance();
    }
    Check(!images[0].empty() && images[0] == images[1], "a normal of 1e300 clips exactly as a unit normal");
    Check(images[0] != images[2], "the plane clips (the image differs from the unclipped one)");
  }
  return vstest::ExitCode();
}
