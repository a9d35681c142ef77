// Every public class without a Vulkan device (issue 13 item 1): ctest runs these tests twice,
// with VK_ICD_FILENAMES pointing at no driver and with VISSWEEP_DEVICE naming a device that does
// not exist. Each entry point must report a vtkErrorMacro and fail its request (or answer
// "unavailable"); none may end the process (an exception escaping a VTK pipeline call ended in
// std::terminate). Classes that need no device must work as usual.
#include "vtkEnvironmentMapReader.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkOpenVDBVolumeReader.h"
#include "vtkVisSweepDevice.h"
#include "vtkVisibilityGridFilter.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// The ErrorEvents of an object (and of an algorithm's executive), as text.
class Errors
{
public:
  Errors()
  {
    this->Observer->SetCallback(&Errors::Collect);
    this->Observer->SetClientData(&this->Messages);
  }
  void Watch(vtkObject* o)
  {
    o->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    if (auto* a = vtkAlgorithm::SafeDownCast(o))
    {
      a->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    }
  }
  bool Saw(const std::string& part) const
  {
    for (const auto& m : this->Messages)
    {
      if (m.find(part) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  std::string All() const
  {
    std::string s;
    for (const auto& m : this->Messages)
    {
      s += "[" + m + "] ";
    }
    return s;
  }
  std::vector<std::string> Messages;

private:
  static void Collect(vtkObject*, unsigned long, void* list, void* text)
  {
    static_cast<std::vector<std::string>*>(list)->push_back(text ? static_cast<const char*>(text) : "");
  }
  vtkNew<vtkCallbackCommand> Observer;
};

vtkSmartPointer<vtkImageData> Ball()
{
  const int n = 8;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(n * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
      {
        const double dx = x - 3.5, dy = y - 3.5, dz = z - 3.5;
        a->SetValue((z * n + y) * n + x, float(dx * dx + dy * dy + dz * dz < 9.0));
      }
  image->GetPointData()->SetScalars(a);
  return image;
}

vtkSmartPointer<vtkVolumeProperty> Property()
{
  auto p = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  color->AddRGBPoint(1.0, 1.0, 1.0, 1.0);
  p->SetScalarOpacity(opacity);
  p->SetColor(color);
  return p;
}

// The words the core uses for a missing driver or device.
bool NamesTheDevice(const std::string& text)
{
  return text.find("Vulkan") != std::string::npos || text.find("device") != std::string::npos ||
    text.find("driver") != std::string::npos;
}
}

TEST(NoDevice, DeviceQueryReportsUnavailable)
{
  vtkNew<vtkVisSweepDevice> d;
  EXPECT_FALSE(d->IsAvailable());
  const std::string why = d->GetErrorMessage();
  EXPECT_TRUE(NamesTheDevice(why)) << why;
  EXPECT_STREQ(d->GetDescription(), "");
  EXPECT_STREQ(d->GetDeviceName(), "");
  EXPECT_EQ(d->GetMaxImageDimension3D(), 0u);
  EXPECT_EQ(d->GetMemoryHeapBytes(), 0.0);
  EXPECT_EQ(d->GetValidationMessageCount(), 0.0);
  std::ostringstream os;
  d->PrintSelf(os, vtkIndent());
  EXPECT_NE(os.str().find("Unavailable"), std::string::npos) << os.str();
}

// vtkVisibilityGridFilter::Update() used to end in std::terminate (RequestInformation).
TEST(NoDevice, VisibilityGridFilterFailsItsRequest)
{
  vtkNew<vtkVisibilityGridFilter> filter;
  Errors errors;
  errors.Watch(filter);
  filter->SetInputData(Ball());
  filter->SetVolumeProperty(Property());
  filter->UpdateInformation();
  EXPECT_TRUE(errors.Saw("cannot compute the visibility grid")) << errors.All();
  EXPECT_EQ(static_cast<vtkAlgorithm*>(filter.Get())->Update(0, nullptr), 0) << "the request must fail";
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetNumberOfComputedDirections(), 0.0);
  EXPECT_TRUE(NamesTheDevice(errors.All())) << errors.All();
  filter->Modified();
  EXPECT_EQ(static_cast<vtkAlgorithm*>(filter.Get())->Update(0, nullptr), 0) << "a second update must fail the same way";
  std::ostringstream os;
  filter->PrintSelf(os, vtkIndent());
}

// The readers and sources need no device: they work as usual.
TEST(NoDevice, ReadersAndSourcesWork)
{
  vtkNew<vtkEnvironmentMapSource> sky;
  sky->SetTypeToSunDisk();
  sky->SetOctahedralSize(16);
  Errors errors;
  errors.Watch(sky);
  sky->Update();
  EXPECT_GT(sky->GetOutput()->GetNumberOfPoints(), 0) << errors.All();

  vtkNew<vtkEnvironmentMapReader> env;
  errors.Watch(env);
  env->SetFileName(VISSWEEP_DATA "/envmaps/courtyard.exr");
  env->SetOctahedralSize(32);
  env->Update();
  EXPECT_GT(env->GetOutput()->GetNumberOfPoints(), 0) << errors.All();

  vtkNew<vtkOpenVDBVolumeReader> vdb;
  errors.Watch(vdb);
  vdb->SetFileName(VISSWEEP_DATA "/smoke/smoke_0004.vdb");
  vdb->Update();
  EXPECT_GT(vdb->GetOutput()->GetNumberOfPoints(), 0) << errors.All();
  EXPECT_TRUE(errors.Messages.empty()) << errors.All();
}

// The mapper in a window, both render modes: an error naming the device, once (not at every
// Render()), nothing drawn, no radiance or grid to return. Needs a display (xvfb-run).
TEST(NoDevice, MapperReportsOnceAndDrawsNothing)
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    GTEST_SKIP() << "no display (run under xvfb-run)";
  }
  for (int mode : { vtkVisibilitySweepVolumeMapper::MonteCarlo, vtkVisibilitySweepVolumeMapper::EmissionAbsorption })
  {
    vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
    Errors errors;
    errors.Watch(mapper);
    mapper->SetInputData(Ball());
    mapper->SetRenderMode(mode);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(Property());
    vtkNew<vtkRenderer> ren;
    ren->AddVolume(volume);
    vtkNew<vtkRenderWindow> win;
    win->SetOffScreenRendering(1);
    win->AddRenderer(ren);
    win->SetSize(16, 16);
    ren->ResetCamera();
    for (int i = 0; i < 3; ++i)
    {
      win->Render();
    }
    const std::string last = mapper->GetLastError();
    EXPECT_TRUE(NamesTheDevice(last)) << "mode " << mode << ": " << last;
    EXPECT_EQ(errors.Messages.size(), 1u) << "mode " << mode << ": one report for three renders of the same input: "
                                          << errors.All();
    EXPECT_EQ(mapper->GetAccumulatedSamples(), 0);
    EXPECT_EQ(mapper->GetRadiance(), nullptr);
    EXPECT_EQ(mapper->GetRadiance(true), nullptr);
    EXPECT_EQ(mapper->GetVisibilityGrid(), nullptr);
    // A change is news: the error is reported again.
    mapper->SetDensityScale(2.0);
    win->Render();
    EXPECT_EQ(errors.Messages.size(), 2u) << "mode " << mode << ": " << errors.All();
    std::ostringstream os;
    mapper->PrintSelf(os, vtkIndent());
  }
}
