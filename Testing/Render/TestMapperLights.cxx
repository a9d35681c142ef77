// Issue 38: the renderer's vtkLights in the Monte Carlo mode (vsSceneLights.h):
//  - VTK's automatic headlight is no light of the estimate: the default renderer renders the image of a
//    renderer without lights, bit for bit;
//  - a vtkLight added (a key light) changes the image; switched off, the image is that without it, bit
//    for bit; moved, the accumulation restarts;
//  - a headlight the user set up (intensity 1.5) lights the volume.
#include "vsLitBallScene.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>
#include <string>
#include <vector>

using vstest::Check;
using vstest::Mean;

namespace
{
constexpr int kSamples = 8;

// The lit ball in the Monte Carlo mode (the environment strategy), with or without VTK's automatic light.
struct Scene : vstest::LitBallScene
{
  explicit Scene(bool automaticLight)
  {
    this->Mapper->SetMaximumSamples(kSamples);
    this->Mapper->SetSamplesPerFrame(kSamples);
    this->Mapper->SetSamplingStrategyToEnvironment();
    this->Renderer->SetAutomaticLightCreation(automaticLight);
  }

  // Renders until converged; the radiance's rgb.
  std::vector<float> Radiance()
  {
    for (int i = 0; i < 4 && !this->Mapper->IsConverged(); ++i)
      this->Window->Render();
    this->Window->Render();
    return this->LastRadiance();
  }
};
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
  vtkSmartPointer<vtkLight> key = vstest::KeyLight();
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
