// One volume in two renderers (issue 14: two views of the same volume): each renderer keeps its
// own accumulator, so both converge instead of restarting every frame. Two renderers side by side
// in one window, different cameras, 4 window renders of 1 sample per pixel: the mapper restarts
// accumulation once per view (2, not 8) and converges; the right view's radiance is bit for bit
// that of a second mapper rendering the right view alone (same seed: its samples are its own). The
// views of two windows converge too, and a renderer that goes away is forgotten.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using vstest::Check;

namespace
{
vtkSmartPointer<vtkImageData> Ball(int n)
{
  const double c = 0.5 * (n - 1);
  return vstest::FloatVolume(n, [c](int x, int y, int z) {
    const double r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - 0.7 * c) * (z - 0.7 * c));
    return float(std::max(0.0, 1.0 - r / c));
  });
}

vtkSmartPointer<vtkVolumeProperty> Property()
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.8, 0.7);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  return property;
}

vtkSmartPointer<vtkVisibilitySweepVolumeMapper> Mapper(vtkImageData* data)
{
  auto m = vtkSmartPointer<vtkVisibilitySweepVolumeMapper>::New();
  m->SetInputData(data);
  m->SetSamplingStrategyToEnvironment();
  m->SetSamplesPerFrame(1);
  m->SetMaximumSamples(4);
  m->SetSeed(3);
  return m;
}

// The right view: looking along +y; the left one along -x.
void PlaceRight(vtkRenderer* ren)
{
  ren->SetViewport(0.5, 0.0, 1.0, 1.0);
  ren->GetActiveCamera()->SetPosition(0.0, -1.0, 0.0);
  ren->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  ren->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  ren->ResetCamera();
}

std::vector<float> Radiance(vtkVisibilitySweepVolumeMapper* m)
{
  std::vector<float> out;
  vtkImageData* r = m ? m->GetRadiance() : nullptr;
  if (r)
  {
    vtkDataArray* a = r->GetPointData()->GetArray("Radiance");
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      out.insert(out.end(), { float(a->GetComponent(i, 0)), float(a->GetComponent(i, 1)), float(a->GetComponent(i, 2)) });
    }
  }
  return out;
}
}

int TestMapperTwoViews(int, char*[])
{
  vtkSmartPointer<vtkImageData> data = Ball(20);
  vtkSmartPointer<vtkVolumeProperty> property = Property();
  vtkSmartPointer<vtkVisibilitySweepVolumeMapper> m = Mapper(data);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);

  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(64, 32);
  auto left = vtkSmartPointer<vtkRenderer>::New();
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  left->AddVolume(volume);
  left->GetActiveCamera()->SetPosition(-1.0, 0.0, 0.0);
  left->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  left->ResetCamera();
  vtkNew<vtkRenderer> right;
  right->AddVolume(volume);
  PlaceRight(right);
  win->AddRenderer(left);
  win->AddRenderer(right);

  for (int k = 0; k < 4; ++k)
  {
    win->Render();
  }
  Check(std::string(m->GetLastError()).empty(), std::string("renders: ") + m->GetLastError());
  std::cout << "two views, 4 window renders: " << m->GetAccumulationResetCount() << " accumulation restarts, "
            << m->GetAccumulatedSamples() << " spp\n";
  Check(m->GetAccumulationResetCount() == 2, "one accumulation start per view, no restart per frame");
  Check(m->IsConverged() && m->GetAccumulatedSamples() == 4, "the views converge");
  const std::vector<float> both = Radiance(m);

  // The right view alone, by a second mapper with the same settings.
  vtkSmartPointer<vtkVisibilitySweepVolumeMapper> alone = Mapper(data);
  vtkNew<vtkVolume> volume2;
  volume2->SetMapper(alone);
  volume2->SetProperty(property);
  vtkNew<vtkRenderWindow> win2;
  win2->SetMultiSamples(0);
  win2->SetSize(64, 32);
  vtkNew<vtkRenderer> right2;
  right2->AddVolume(volume2);
  PlaceRight(right2);
  win2->AddRenderer(right2);
  for (int k = 0; k < 4; ++k)
  {
    win2->Render();
  }
  Check(!both.empty() && Radiance(alone) == both, "the right view's image is its own samples, bit for bit");

  // Two windows showing the same volume converge as well.
  vtkNew<vtkRenderWindow> win3;
  win3->SetMultiSamples(0);
  win3->SetSize(40, 40);
  vtkNew<vtkRenderer> third;
  third->AddVolume(volume);
  third->ResetCamera();
  win3->AddRenderer(third);
  m->SetMaximumSamples(8);
  for (int k = 0; k < 8; ++k)
  {
    win->Render();
    win3->Render();
  }
  std::cout << "three views: " << m->GetAccumulationResetCount() << " accumulation starts\n";
  Check(m->GetAccumulationResetCount() == 3, "the third view started once (a second window keeps the others)");
  Check(m->GetVolumeUploadCount() == 1, "the volume is uploaded once for all views");
  Check(m->IsConverged(), "the views of two windows converge");

  // A renderer that goes away is forgotten (VTK may release the mapper's resources with it: the
  // other views then start again and converge again).
  win->RemoveRenderer(left);
  left = nullptr;
  for (int k = 0; k < 8; ++k)
  {
    win->Render();
    win3->Render();
  }
  Check(std::string(m->GetLastError()).empty(), "renders after a view went away");
  Check(m->IsConverged(), "the remaining views converge");
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
