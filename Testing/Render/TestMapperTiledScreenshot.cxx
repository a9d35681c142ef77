// Tiled screenshots (issue 14): vtkWindowToImageFilter with Scale 2 renders 4 tiles, each with the
// camera of its quarter. The view's accumulator used to restart for every tile (1 frame of samples
// each) and once more afterwards. Now: a converged 40x40 view (16 spp) keeps its accumulator
// through the screenshot (no restart, 16 samples, converged; the next Render() restarts nothing),
// the 4 tiles have 16 spp each, and the 80x80 screenshot agrees with an 80x80 render of 16 spp
// as well as a second 80x80 render of another seed does (mean absolute difference of the 8-bit
// images within 1.25x of theirs: tiles of 2 spp, the old behaviour, are about 2x).
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
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

struct Scene
{
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(vtkImageData* data, int size, int seed)
  {
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, 0.8);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.9, 0.8, 0.7);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    property->SetInterpolationTypeToLinear();
    this->Mapper->SetInputData(data);
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Mapper->SetSamplesPerFrame(2);
    this->Mapper->SetMaximumSamples(16);
    this->Mapper->SetSeed(seed);
    this->Mapper->SetExposure(0.5);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, -1.0, 0.3);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Renderer->ResetCamera();
  }

  void Converge()
  {
    for (int i = 0; i < 32 && !this->Mapper->IsConverged(); ++i)
    {
      this->Window->Render();
    }
  }
};


}

int TestMapperTiledScreenshot(int, char*[])
{
  vtkSmartPointer<vtkImageData> data = Ball(20);
  Scene view(data, 40, 3);
  view.Converge();
  const int resets = view.Mapper->GetAccumulationResetCount();
  Check(view.Mapper->GetAccumulatedSamples() == 16 && resets == 1, "the 40x40 view converged (16 spp, 1 start)");

  const std::vector<int> tiled = vstest::WindowPixels(view.Window, 2);
  std::cout << "after the screenshot: " << view.Mapper->GetAccumulationResetCount() << " starts, "
            << view.Mapper->GetAccumulatedSamples() << " spp, " << view.Mapper->GetTileRenderCount() << " tiles\n";
  Check(view.Mapper->GetTileRenderCount() == 4, "the screenshot rendered 4 tiles");
  Check(view.Mapper->GetAccumulationResetCount() == resets, "the tiles did not restart the view's accumulation");
  Check(view.Mapper->GetAccumulatedSamples() == 16 && view.Mapper->IsConverged(), "the view is still converged");
  view.Window->Render();
  Check(view.Mapper->GetAccumulationResetCount() == resets, "the next Render() after the screenshot restarts nothing");
  vtkImageData* radiance = view.Mapper->GetRadiance();
  Check(radiance && radiance->GetDimensions()[0] == 40, "GetRadiance() is still the view's 40x40 image");

  // The reference: the same view rendered at 80x80 with 16 spp, and once more with another seed.
  Scene big(data, 80, 3), other(data, 80, 4);
  big.Converge();
  other.Converge();
  const std::vector<int> reference = vstest::WindowPixels(big.Window), second = vstest::WindowPixels(other.Window);
  const double tiledError = vstest::MeanAbsoluteDifference(tiled, reference);
  const double noise = vstest::MeanAbsoluteDifference(second, reference);
  std::cout << "mean |tiled - 80x80 render| = " << tiledError << ", mean |80x80 seed 4 - seed 3| = " << noise << "\n";
  Check(tiled.size() == size_t(80 * 80 * 3), "the screenshot is 80x80");
  Check(noise > 0.0 && tiledError <= 1.25 * noise + 0.05,
    "the tiled screenshot is no noisier than a 16 spp render of its size");
  return vstest::ExitCode();
}
