// The scene of the lights tests (TestMapperLights, TestMapperPreviewLights): the tests' ball (24^3) of grey
// albedo under the default sky, the environment not visible (the images' means are the volume's), at
// 32 x 32; and the key light they add. Each test sets its mode and sampling on top (TestMapperPreviewAnisotropy
// its own environment and a thinner ball).
#ifndef vsLitBallScene_h
#define vsLitBallScene_h

#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <vector>

namespace vstest
{
struct LitBallScene
{
  static constexpr int Size = 32;

  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolumeProperty> Property;

  explicit LitBallScene(double peakOpacity = 0.6)
  {
    this->Mapper->SetInputData(Ball(24));
    this->Mapper->SetMaximumScatteringEvents(4);
    this->Mapper->EnvironmentVisibleOff(); // the images' means are the volume's (lit by the sky still)
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, peakOpacity);
    this->Color->AddRGBPoint(0.0, 0.8, 0.8, 0.8);
    this->Color->AddRGBPoint(1.0, 0.8, 0.8, 0.8);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Property->SetInterpolationTypeToLinear();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(Size, Size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }

  /** The last render's radiance, rgb per pixel (empty before one). */
  std::vector<float> LastRadiance()
  {
    std::vector<float> out;
    vtkImageData* r = this->Mapper->GetRadiance();
    vtkDataArray* a = r ? r->GetPointData()->GetArray("Radiance") : nullptr;
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c)
        out.push_back(float(a->GetComponent(i, c)));
    return out;
  }

  /** A render in the preview mode (the mode the preview tests set), its radiance. */
  std::vector<float> Preview()
  {
    this->Window->Render();
    return this->LastRadiance();
  }

  /** The Monte Carlo estimate until converged at `samples` spp, its radiance; back to the preview mode. */
  std::vector<float> Estimate(int samples)
  {
    this->Mapper->SetRenderModeToMonteCarlo();
    this->Mapper->SetMaximumSamples(samples);
    this->Mapper->SetSamplesPerFrame(samples);
    for (int i = 0; i < 4 && !this->Mapper->IsConverged(); ++i)
      this->Window->Render();
    this->Window->Render();
    std::vector<float> out = this->LastRadiance();
    this->Mapper->SetRenderModeToPreview();
    return out;
  }
};

/** The key light both tests add: a directional scene light from the side (intensity 4, warm white). */
inline vtkSmartPointer<vtkLight> KeyLight()
{
  auto key = vtkSmartPointer<vtkLight>::New();
  key->SetLightTypeToSceneLight();
  key->SetPositional(false);
  key->SetPosition(100.0, 40.0, 60.0);
  key->SetFocalPoint(12.0, 12.0, 12.0);
  key->SetIntensity(4.0);
  key->SetColor(1.0, 0.9, 0.8);
  return key;
}

/** The mean of the values. */
inline double Mean(const std::vector<float>& v)
{
  double s = 0.0;
  for (float x : v)
    s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}
}

#endif
