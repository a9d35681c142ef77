// Issue 38: the renderer's vtkLights in the Monte Carlo mode (vsSceneLights.h):
//  - VTK's automatic headlight is no light of the estimate: the default renderer renders the image of a
//    renderer without lights, bit for bit;
//  - a vtkLight added (a key light) changes the image; switched off, the image is that without it, bit
//    for bit; moved, the accumulation restarts;
//  - a headlight the user set up (intensity 1.5) lights the volume.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
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
constexpr int kSize = 32;
constexpr int kSamples = 8;

struct Scene
{
  vtkNew<vtkVisibilitySweepVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolumeProperty> Property;

  explicit Scene(bool automaticLight)
  {
    this->Mapper->SetInputData(vstest::Ball(24));
    this->Mapper->SetMaximumSamples(kSamples);
    this->Mapper->SetSamplesPerFrame(kSamples);
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Mapper->SetMaximumScatteringEvents(4);
    this->Mapper->EnvironmentVisibleOff(); // the images' means are the volume's (lit by the sky still)
    this->Opacity->AddPoint(0.0, 0.0);
    this->Opacity->AddPoint(1.0, 0.6);
    this->Color->AddRGBPoint(0.0, 0.8, 0.8, 0.8);
    this->Color->AddRGBPoint(1.0, 0.8, 0.8, 0.8);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetColor(this->Color);
    this->Property->SetInterpolationTypeToLinear();
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->SetAutomaticLightCreation(automaticLight);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(kSize, kSize);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }

  // Renders until converged; the radiance's rgb.
  std::vector<float> Radiance()
  {
    for (int i = 0; i < 4 && !this->Mapper->IsConverged(); ++i)
      this->Window->Render();
    this->Window->Render();
    std::vector<float> out;
    vtkImageData* r = this->Mapper->GetRadiance();
    vtkDataArray* a = r ? r->GetPointData()->GetArray("Radiance") : nullptr;
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
      for (int c = 0; c < 3; ++c)
        out.push_back(float(a->GetComponent(i, c)));
    return out;
  }
};

double Mean(const std::vector<float>& v)
{
  double s = 0.0;
  for (float x : v)
    s += x;
  return v.empty() ? 0.0 : s / double(v.size());
}
}

int TestMapperLights(int, char*[])
{
  Scene automatic(true), none(false);
  const std::vector<float> withAutomatic = automatic.Radiance();
  const std::vector<float> withoutLights = none.Radiance();
  std::cout << "lights of the default renderer: " << automatic.Renderer->GetLights()->GetNumberOfItems() << "\n";
  Check(!withAutomatic.empty() && withAutomatic == withoutLights,
    "VTK's automatic headlight is no light of the estimate: the image of a renderer without lights, bit for bit");

  // A key light: a directional scene light from the side.
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->SetPositional(false);
  key->SetPosition(100.0, 40.0, 60.0);
  key->SetFocalPoint(12.0, 12.0, 12.0);
  key->SetIntensity(4.0);
  key->SetColor(1.0, 0.9, 0.8);
  none.Renderer->AddLight(key);
  const int resets = none.Mapper->GetAccumulationResetCount();
  const std::vector<float> lit = none.Radiance();
  std::cout << "mean radiance without lights " << Mean(withoutLights) << ", with a key light " << Mean(lit) << "\n";
  Check(none.Mapper->GetAccumulationResetCount() > resets, "adding a light restarts the accumulation");
  Check(Mean(lit) > 1.2 * Mean(withoutLights), "a key light added to the renderer brightens the image");

  key->SwitchOff();
  const std::vector<float> off = none.Radiance();
  Check(off == withoutLights, "a light switched off is no light: the image without it, bit for bit");

  key->SwitchOn();
  none.Radiance();
  const int before = none.Mapper->GetAccumulationResetCount();
  key->SetPosition(-100.0, 40.0, 60.0);
  const std::vector<float> moved = none.Radiance();
  Check(none.Mapper->GetAccumulationResetCount() == before + 1, "a light moved restarts the accumulation once");
  Check(moved != lit, "a light moved changes the image");

  // A headlight the user set up (intensity 1.5): a light of the estimate.
  key->SwitchOff();
  vtkNew<vtkLight> head;
  head->SetLightTypeToHeadlight();
  head->SetIntensity(1.5);
  none.Renderer->AddLight(head);
  const std::vector<float> headlit = none.Radiance();
  std::cout << "mean radiance with the user's headlight " << Mean(headlit) << "\n";
  Check(Mean(headlit) > 1.1 * Mean(withoutLights), "a headlight the user made lights the volume");
  Check(std::string(none.Mapper->GetLastError()).empty(), std::string("no error: ") + none.Mapper->GetLastError());
  return vstest::ExitCode();
}
