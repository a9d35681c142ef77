#include "vsRenderTestUtilities.h"

#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageShrink3D.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkWindowToImageFilter.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace vstest
{
namespace
{
int failures = 0;
}

void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

int Failures()
{
  return failures;
}

int ExitCode()
{
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

std::string Argument(int argc, char* argv[], const char* flag)
{
  for (int i = 0; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], flag) == 0)
    {
      return argv[i + 1];
    }
  }
  return std::string();
}

vtkSmartPointer<vtkImageData> FloatVolume(int n, const std::function<float(int x, int y, int z)>& value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(vtkIdType(n) * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        a->SetValue((vtkIdType(z) * n + y) * n + x, value(x, y, z));
  image->GetPointData()->SetScalars(a);
  return image;
}

vtkSmartPointer<vtkImageData> Ball(int n)
{
  const double c = 0.5 * (n - 1);
  return FloatVolume(n, [c](int x, int y, int z) {
    const double r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
    return float(std::max(0.0, 1.0 - r / c));
  });
}

std::vector<int> WindowPixels(vtkRenderWindow* win, int scale)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(win);
  grab->SetScale(scale);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  if (scale == 1)
  {
    grab->ShouldRerenderOff();
  }
  grab->Update();
  vtkDataArray* a = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<int> out;
  out.reserve(size_t(a->GetNumberOfTuples()) * 3);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.push_back(int(a->GetComponent(i, c)));
    }
  }
  return out;
}

double MeanAbsoluteDifference(const std::vector<int>& a, const std::vector<int>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return 1e9;
  }
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    sum += std::abs(a[i] - b[i]);
  }
  return sum / double(a.size());
}

int MaxAbsoluteDifference(const std::vector<int>& a, const std::vector<int>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return 1000000000;
  }
  int d = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    d = std::max(d, std::abs(a[i] - b[i]));
  }
  return d;
}

vtkSmartPointer<vtkImageData> ReadBrain(const std::string& path)
{
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  return image;
}

vtkSmartPointer<vtkImageData> ShrunkBrain(const std::string& path, int factor)
{
  vtkNew<vtkImageShrink3D> shrink;
  shrink->SetInputData(ReadBrain(path));
  shrink->SetShrinkFactors(factor, factor, factor);
  shrink->AveragingOn();
  shrink->Update();
  vtkSmartPointer<vtkImageData> image = shrink->GetOutput();
  return image;
}

vtkSmartPointer<vtkEnvironmentMapReader> SunriseEnvironment()
{
  auto env = vtkSmartPointer<vtkEnvironmentMapReader>::New();
  env->SetFileName((std::string(VISSWEEP_DATA) + "/envmaps/sunrise.exr").c_str());
  env->SetOctahedralSize(128);
  return env;
}

vtkSmartPointer<vtkVolumeProperty> BrainProperty()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(90, 0.05);
  opacity->AddPoint(255, 0.3);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(90, 0.9, 0.6, 0.5);
  color->AddRGBPoint(255, 1.0, 1.0, 0.9);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(1.0);
  property->SetInterpolationTypeToLinear(); // the baselines' trilinear reconstruction (VTK's default is nearest)
  return property;
}

void ErrorRecorder::Execute(vtkObject*, unsigned long event, void* data)
{
  std::string msg = data ? static_cast<const char*>(data) : "";
  (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(msg);
}

void ErrorRecorder::Watch(vtkObject* o)
{
  o->AddObserver(vtkCommand::ErrorEvent, this);
  o->AddObserver(vtkCommand::WarningEvent, this);
}

bool ErrorRecorder::Saw(const std::string& substring) const
{
  for (const auto& e : this->Errors)
  {
    if (e.find(substring) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}
}
