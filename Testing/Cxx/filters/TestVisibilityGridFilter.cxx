// vtkVisibilityGridFilter: the grid as a VTK pipeline product — geometry aligned
// with the input, arrays and field data, progress, recomputation only when
// something that changes extinction changes, and errors that name the cause.
#include "vtkVisibilityGridFilter.h"

#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsEnvironmentMap.h"
#include "vsLightVolume.h"
#include "vsVisibilityGrid.h"
#include "vsVolumeScene.h"

#include "vtkCallbackCommand.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkMath.h"
#include "vtkExecutive.h"
#include "vtkColorTransferFunction.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
vtkSmartPointer<vtkImageData> Box(int n, double value, double spacing = 0.5)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(spacing, spacing, spacing);
  image->SetOrigin(10.0, -3.0, 2.0);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(vtkIdType(n) * n * n);
  a->Fill(value);
  image->GetPointData()->SetScalars(a);
  return image;
}

vtkSmartPointer<vtkVolumeProperty> Property(double alpha)
{
  auto p = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> o;
  o->AddPoint(0.0, 0.0);
  o->AddPoint(1.0, alpha);
  vtkNew<vtkColorTransferFunction> c;
  c->AddRGBPoint(0.0, 1, 1, 1);
  c->AddRGBPoint(1.0, 1, 1, 1);
  p->SetScalarOpacity(o);
  p->SetColor(c);
  return p;
}

struct Counter
{
  int Errors = 0, Progress = 0;
};
}

TEST(VisibilityGridFilter, OutputAlignedWithInputAndAnalytic)
{
  auto image = Box(17, 1.0, 0.5);
  auto property = Property(0.3);
  vtkNew<vtkVisibilityGridFilter> f;
  f->SetInputData(image);
  f->SetVolumeProperty(property);
  f->SetStorageFormat(vtkVisibilityGridFilter::Float32);
  f->FilteringOff();
  f->SetMethodToBruteForce();
  Counter counter;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetClientData(&counter);
  cb->SetCallback([](vtkObject*, unsigned long, void* client, void*) { ++static_cast<Counter*>(client)->Progress; });
  f->AddObserver(vtkCommand::ProgressEvent, cb);
  f->Update();
  vtkImageData* out = f->GetOutput();
  int dims[3];
  out->GetDimensions(dims);
  EXPECT_EQ(dims[0], 4); // 16 voxel units / 4 per cell
  double* origin = out->GetOrigin();
  double* spacing = out->GetSpacing();
  EXPECT_NEAR(origin[0], 10.0 + 0.5 * 2.0, 1e-9); // first cell centre: 2 voxels in
  EXPECT_NEAR(origin[1], -3.0 + 1.0, 1e-9);
  EXPECT_NEAR(spacing[2], 2.0, 1e-9);
  vtkDataArray* vis = out->GetPointData()->GetArray("Visibility");
  ASSERT_NE(vis, nullptr);
  EXPECT_EQ(vis->GetNumberOfComponents(), 64);
  ASSERT_NE(out->GetPointData()->GetArray("MeanVisibility"), nullptr);
  vtkDataArray* dirs = out->GetFieldData()->GetArray("Directions");
  ASSERT_NE(dirs, nullptr);
  EXPECT_GT(counter.Progress, 2);
  // Analytic at every cell and direction: sigma_t = -ln(0.7) per world unit.
  const double sigma = -std::log(0.7);
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    for (int d = 0; d < 64; ++d)
    {
      double w[3];
      dirs->GetTuple(d, w);
      double t = 1e300;
      double lo[3] = { 10.0, -3.0, 2.0 };
      for (int k = 0; k < 3; ++k)
      {
        double hi = lo[k] + 8.0;
        if (w[k] > 0)
          t = std::min(t, (hi - p[k]) / w[k]);
        else if (w[k] < 0)
          t = std::min(t, (lo[k] - p[k]) / w[k]);
      }
      worst = std::max(worst, std::abs(vis->GetComponent(i, d) - std::exp(-sigma * t)));
    }
  }
  EXPECT_LT(worst, 1e-4);
}

TEST(VisibilityGridFilter, RecomputesOnlyForExtinctionChanges)
{
  auto image = Box(9, 1.0);
  auto property = Property(0.3);
  vtkNew<vtkVisibilityGridFilter> f;
  f->SetInputData(image);
  f->SetVolumeProperty(property);
  f->Update();
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 64);
  f->Update(); // nothing changed
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 64);
  property->GetScalarOpacity()->AddPoint(0.5, 0.1); // extinction changes
  f->Update();
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 128);
  vtkNew<vtkPlaneCollection> planes;
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(12, 0, 0);
  plane->SetNormal(1, 0, 0);
  planes->AddItem(plane);
  f->SetClippingPlanes(planes);
  f->Update();
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 192);
  plane->SetOrigin(13, 0, 0); // moving a plane is a change too
  f->Update();
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 256);
}

TEST(VisibilityGridFilter, ErrorsNameTheCause)
{
  vtkNew<vtkCallbackCommand> cb;
  std::string last;
  cb->SetClientData(&last);
  cb->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<std::string*>(client) += std::string(static_cast<const char*>(data)) + "\n";
  });
  auto run = [&](vtkVisibilityGridFilter* f) {
    last.clear();
    f->AddObserver(vtkCommand::ErrorEvent, cb);
    f->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, cb);
    f->Update();
    return last;
  };
  auto image = Box(9, 1.0);
  {
    vtkNew<vtkVisibilityGridFilter> f;
    f->SetInputData(image);
    EXPECT_NE(run(f).find("volume property"), std::string::npos) << last;
    EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    vtkNew<vtkVisibilityGridFilter> f;
    f->SetInputData(image);
    f->SetVolumeProperty(Property(0.5));
    f->SetDirectionResolution(6);
    EXPECT_NE(run(f).find("DirectionResolution"), std::string::npos) << last;
  }
  {
    vtkNew<vtkVisibilityGridFilter> f;
    f->SetInputData(image);
    f->SetVolumeProperty(Property(0.5));
    f->SetVoxelsPerCell(0.0);
    EXPECT_NE(run(f).find("VoxelsPerCell"), std::string::npos) << last;
  }
  {
    vtkNew<vtkImageData> empty;
    vtkNew<vtkVisibilityGridFilter> f;
    f->SetInputData(empty);
    f->SetVolumeProperty(Property(0.5));
    EXPECT_FALSE(run(f).empty());
  }
}

// With an environment (input port 1), "Irradiance" beside "MeanVisibility": 3 components, the light
// volume of vs::LightVolume built from the same grid and map; a new environment or intensity rebuilds
// only it, never the grid.
TEST(VisibilityGridFilter, IrradianceIsTheLightVolume)
{
  auto image = Box(17, 1.0, 0.5);
  auto property = Property(0.3);
  vtkNew<vtkEnvironmentMapSource> sky;
  sky->SetTypeToTwoToneSky();
  sky->SetOctahedralSize(32);
  sky->SetUpperColor(1.0, 0.8, 0.6);
  sky->SetLowerColor(0.1, 0.2, 0.3);
  vtkNew<vtkVisibilityGridFilter> f;
  f->SetInputData(image);
  f->SetVolumeProperty(property);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetPointData()->GetArray("Irradiance"), nullptr); // no environment, no light
  f->SetEnvironmentConnection(sky->GetOutputPort());
  f->SetEnvironmentIntensity(1.5);
  f->Update();
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 64); // the environment did not recompute the grid
  EXPECT_EQ(f->GetNumberOfIrradianceBuilds(), 1);
  vtkImageData* out = f->GetOutput();
  ASSERT_NE(out->GetPointData()->GetArray("Irradiance"), nullptr);
  vtkNew<vtkFloatArray> irradiance; // a copy: the next run replaces the output's arrays
  irradiance->DeepCopy(out->GetPointData()->GetArray("Irradiance"));
  EXPECT_EQ(irradiance->GetNumberOfComponents(), 3);
  ASSERT_EQ(irradiance->GetNumberOfTuples(), out->GetNumberOfPoints());
  ASSERT_NE(out->GetPointData()->GetArray("MeanVisibility"), nullptr);
  EXPECT_EQ(std::string(out->GetPointData()->GetScalars()->GetName()), "MeanVisibility");

  // The same grid and map through the core classes.
  auto ctx = vs::Context::Default();
  vs::VolumeScene scene(ctx);
  scene.Update(image, image->GetPointData()->GetScalars(), property, nullptr, 1.0);
  vs::VisibilityGridParameters p;
  p.NearestInterpolation = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION;
  vs::VisibilityGrid grid(ctx);
  grid.Compute(scene.Volume(), scene.TF(), scene.Majorants(), scene.Geometry(), {}, p);
  const vs::DeviceEnvironment env(ctx, *sky->GetEnvironmentMap(), 8);
  vs::LightVolume light(ctx);
  light.Update(grid, env, 1.5);
  const std::vector<float> rgba = light.Download();
  ASSERT_EQ(rgba.size(), 4 * size_t(out->GetNumberOfPoints()));
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(irradiance->GetComponent(i, c) - rgba[4 * size_t(i) + c]));
  EXPECT_EQ(worst, 0.0);
  // Bounded by the unoccluded sphere, 1.5 x 2 pi (upper + lower), and darker inside the box.
  EXPECT_LT(irradiance->GetComponent(0, 0), 1.5 * 2.0 * vtkMath::Pi() * 1.1 + 1e-6);
  EXPECT_GT(irradiance->GetComponent(0, 0), 0.0);

  // A new intensity or environment: the light volume again, the grid kept.
  f->SetEnvironmentIntensity(3.0);
  f->Update();
  EXPECT_EQ(f->GetNumberOfIrradianceBuilds(), 2);
  EXPECT_NEAR(f->GetOutput()->GetPointData()->GetArray("Irradiance")->GetComponent(5, 1),
    2.0 * irradiance->GetComponent(5, 1), 1e-5 * irradiance->GetComponent(5, 1));
  sky->SetUpperColor(2.0, 0.8, 0.6);
  f->Update();
  EXPECT_EQ(f->GetNumberOfIrradianceBuilds(), 3);
  f->Update(); // nothing changed
  EXPECT_EQ(f->GetNumberOfIrradianceBuilds(), 3);
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 64);
  // New extinction: the grid and the light volume.
  property->GetScalarOpacity()->AddPoint(0.5, 0.1);
  f->Update();
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 128);
  EXPECT_EQ(f->GetNumberOfIrradianceBuilds(), 4);
  // Disconnected: no light.
  f->SetEnvironmentConnection(nullptr);
  f->Update();
  EXPECT_EQ(f->GetOutput()->GetPointData()->GetArray("Irradiance"), nullptr);
  EXPECT_EQ(f->GetNumberOfComputedDirections(), 128);
}

TEST(VisibilityGridFilter, BadEnvironmentIsAnError)
{
  vtkNew<vtkCallbackCommand> cb;
  std::string last;
  cb->SetClientData(&last);
  cb->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<std::string*>(client) += std::string(static_cast<const char*>(data)) + "\n";
  });
  auto image = Box(9, 1.0);
  auto notAMap = Box(5, 1.0); // no "Radiance", not Size x Size x 1
  vtkNew<vtkVisibilityGridFilter> f;
  f->SetInputData(image);
  f->SetVolumeProperty(Property(0.5));
  f->SetEnvironmentData(notAMap);
  f->AddObserver(vtkCommand::ErrorEvent, cb);
  f->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, cb);
  f->Update();
  EXPECT_NE(last.find("environment"), std::string::npos) << last;
  EXPECT_EQ(f->GetOutput()->GetNumberOfPoints(), 0);
  // NaN intensity: refused with a message, no crash.
  vtkNew<vtkEnvironmentMapSource> sky;
  f->SetEnvironmentConnection(sky->GetOutputPort());
  f->SetEnvironmentIntensity(std::nan(""));
  last.clear();
  f->Update();
  EXPECT_NE(last.find("intensity"), std::string::npos) << last;
  f->SetEnvironmentIntensity(1.0);
  last.clear();
  f->Update();
  EXPECT_TRUE(last.empty()) << last;
  EXPECT_NE(f->GetOutput()->GetPointData()->GetArray("Irradiance"), nullptr);
}
