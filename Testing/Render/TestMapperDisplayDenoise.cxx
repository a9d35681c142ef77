// DisplayDenoise (issue 39): the window shows the estimate through the filter guided by the preview,
// while GetRadiance() stays the estimate bit for bit (radiance, alpha and variance): two mappers of one
// seed, the filter on in one, render the same samples. The filtered image shown (GetDisplayedRadiance) is
// closer to a render of many more samples than the estimate it was made from; without the filter the
// image shown is the estimate itself. A drag and the hand-over keep the filter's behaviour: no filter
// while dragging, the hand-over's preview as its guide afterwards.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

using vstest::Check;

namespace
{
struct View
{
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  View(vtkImageData* brain, vtkEnvironmentMapReader* env, bool denoise, int spp)
  {
    Mapper->SetInputData(brain);
    Mapper->SetEnvironmentConnection(env->GetOutputPort());
    Mapper->SetSamplingStrategyToEnvironment();
    Mapper->SetSamplesPerFrame(4);
    Mapper->SetMaximumSamples(spp);
    Mapper->SetEnvironmentVisible(false); // the volume's own radiance
    Mapper->SetDisplayDenoise(denoise);
    Volume->SetMapper(Mapper);
    Volume->SetProperty(vstest::BrainProperty());
    Renderer->AddVolume(Volume);
    Window->SetMultiSamples(0);
    Window->SetOffScreenRendering(1);
    Window->AddRenderer(Renderer);
    Window->SetSize(48, 48);
    vtkCamera* cam = Renderer->GetActiveCamera();
    cam->SetViewUp(0, 0, 1);
    cam->SetFocalPoint(90, 108, 90);
    cam->SetPosition(90 + 300, 108 + 420, 90 + 120);
    Renderer->ResetCamera();
    Window->SetDesiredUpdateRate(0.0001);
  }
  void RenderTo(int spp)
  {
    while (Mapper->GetAccumulatedSamples() < spp && !Mapper->IsConverged())
    {
      Window->Render();
      if (*Mapper->GetLastError())
        break;
    }
  }
};

std::vector<double> Values(vtkImageData* image, const char* name)
{
  std::vector<double> v;
  vtkDataArray* a = image ? image->GetPointData()->GetArray(name) : nullptr;
  if (!a)
    return v;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
      v.push_back(a->GetComponent(i, c));
  return v;
}

double SquaredError(const std::vector<double>& x, const std::vector<double>& ref)
{
  if (x.size() != ref.size() || x.empty())
    return 1e30;
  double e = 0.0;
  for (size_t i = 0; i < x.size(); ++i)
    e += (x[i] - ref[i]) * (x[i] - ref[i]);
  return e;
}
}

int TestMapperDisplayDenoise(int argc, char* argv[])
{
  auto brain = vstest::ShrunkBrain(vstest::Argument(argc, argv, "-D"), 4);
  auto env = vstest::SunriseEnvironment();
  const int spp = 16;
  View plain(brain, env, false, 1 << 20), filtered(brain, env, true, 1 << 20);
  Check(!plain.Mapper->GetDisplayDenoise() && filtered.Mapper->GetDisplayDenoise(), "the setting");
  plain.RenderTo(spp);
  filtered.RenderTo(spp);
  Check(std::string(filtered.Mapper->GetLastError()).empty(), std::string("renders: ") + filtered.Mapper->GetLastError());
  Check(plain.Mapper->GetAccumulatedSamples() == filtered.Mapper->GetAccumulatedSamples(), "the same samples");
  Check(filtered.Mapper->GetLastDisplayDenoised() && !plain.Mapper->GetLastDisplayDenoised(),
    "the filter shows its image (and only where it is on)");
  Check(filtered.Mapper->GetLastDenoiseSeconds() > 0.0, "the filter's device time is reported");
  // GetRadiance() is the estimate, bit for bit, the variance included.
  for (const char* name : { "Radiance", "Alpha" })
  {
    const std::vector<double> a = Values(plain.Mapper->GetRadiance(), name), b = Values(filtered.Mapper->GetRadiance(), name);
    Check(!a.empty() && a == b, std::string("GetRadiance()'s ") + name + " is the same with the filter on");
  }
  {
    const std::vector<double> a = Values(plain.Mapper->GetRadiance(true), "Variance"),
                              b = Values(filtered.Mapper->GetRadiance(true), "Variance");
    Check(!a.empty() && a == b, "GetRadiance(true)'s Variance is the same with the filter on");
  }
  // What the windows show: the estimate itself without the filter, another image with it.
  const std::vector<double> estimate = Values(plain.Mapper->GetRadiance(), "Radiance");
  const std::vector<double> shownPlain = Values(plain.Mapper->GetDisplayedRadiance(), "Radiance");
  const std::vector<double> shownFiltered = Values(filtered.Mapper->GetDisplayedRadiance(), "Radiance");
  Check(shownPlain == estimate, "without the filter the image shown is the estimate");
  Check(shownFiltered.size() == estimate.size() && shownFiltered != estimate, "with it, another image");
  const std::vector<int> windowPlain = vstest::WindowPixels(plain.Window), windowFiltered = vstest::WindowPixels(filtered.Window);
  Check(vstest::MeanAbsoluteDifference(windowPlain, windowFiltered) > 0.0, "the window shows the filtered image");

  // Closer to a render of 16 times the samples (another seed) than the estimate.
  View reference(brain, env, false, 16 * spp);
  reference.Mapper->SetSeed(977);
  reference.Mapper->SetSamplesPerFrame(32);
  reference.RenderTo(16 * spp);
  const std::vector<double> ref = Values(reference.Mapper->GetRadiance(), "Radiance");
  const double before = SquaredError(estimate, ref), after = SquaredError(shownFiltered, ref);
  std::cout << "squared error against " << reference.Mapper->GetAccumulatedSamples() << " spp: the estimate (" << spp
            << " spp) " << before << ", filtered " << after << " (" << after / before << "x)\n";
  Check(after < 0.6 * before, "the filtered image is closer to the converged one than the estimate");

  // A drag: no filter while dragging (the preview is shown); once still, the hand-over's preview guides it.
  filtered.Window->SetDesiredUpdateRate(15.0);
  filtered.Renderer->GetActiveCamera()->Azimuth(10.0);
  filtered.Window->Render();
  Check(!filtered.Mapper->GetLastDisplayDenoised() && filtered.Mapper->GetLastPreviewShare() == 1.0,
    "a drag frame is the preview, unfiltered");
  filtered.Window->SetDesiredUpdateRate(0.0001);
  filtered.Window->Render(); // the first still frame: its samples restart
  filtered.Window->Render();
  Check(filtered.Mapper->GetLastDisplayDenoised(),
    "the still frames after a drag are filtered (the hand-over's preview guides; share " +
      std::to_string(filtered.Mapper->GetLastPreviewShare()) + ")");
  return vstest::ExitCode();
}
