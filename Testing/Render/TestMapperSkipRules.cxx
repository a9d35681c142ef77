// The skip rules (README, "How it works"), through the counters of the mapper: each change does the work it
// needs and no more (camera/colour: restart accumulation only; opacity, data, unit distance,
// density scale, clipping: recompute majorants and visibility; environment: the light's pdf
// only, unless its light moved inside a direction texel: the grid is swept towards each
// texel's light), and a volume empty under the transfer function skips the sweeps entirely.
// The grid is swept whole in the frame that needs it here (progressive fill-in off; the
// progressive path has its own counters in TestMapperProgressive).
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsRenderTestUtilities.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <iostream>

namespace
{
using vstest::Check;
}

int TestMapperSkipRules(int, char*[])
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(20, 18, 16);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfTuples(20 * 18 * 16);
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    values->SetValue(i, float(i % 7) / 6.0f);
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.3);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1, 1, 1);
  color->AddRGBPoint(1.0, 1, 0.5, 0.2);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  vtkNew<vtkEnvironmentMapSource> env;
  env->SetOctahedralSize(16);

  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(image);
  m->SetEnvironmentConnection(env->GetOutputPort());
  m->SetSamplingStrategyToTwoStep();
  m->SetProgressiveVisibility(false);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->AddRenderer(ren);
  win->SetSize(24, 24);
  ren->ResetCamera();

  win->Render();
  Check(std::string(m->GetLastError()).empty(), m->GetLastError());
  Check(m->GetVisibilityUpdateCount() == 1, "first render computes the visibility grid");
  Check(m->GetAccumulationResetCount() == 1, "first render starts accumulation");
  Check(m->GetEnvironmentUploadCount() == 1, "first render uploads the environment");
  const int majorants = m->GetMajorantUpdateCount();

  win->Render();
  Check(m->GetAccumulatedSamples() == 2, "an unchanged view accumulates");
  Check(m->GetAccumulationResetCount() == 1, "an unchanged view does not restart");

  ren->GetActiveCamera()->Azimuth(10);
  win->Render();
  Check(m->GetAccumulationResetCount() == 2, "a camera move restarts accumulation");
  Check(m->GetVisibilityUpdateCount() == 1, "a camera move keeps the visibility grid");

  color->AddRGBPoint(0.5, 0.2, 0.9, 0.2);
  win->Render();
  Check(m->GetAccumulationResetCount() == 3, "a colour change restarts accumulation");
  Check(m->GetVisibilityUpdateCount() == 1, "a colour change keeps the visibility grid");
  Check(m->GetMajorantUpdateCount() == majorants, "a colour change keeps the majorants");

  env->SetColor(2.0, 2.0, 2.0);
  win->Render();
  Check(m->GetEnvironmentUploadCount() == 2, "an environment change uploads the environment");
  Check(m->GetVisibilityUpdateCount() == 1, "an environment change keeps the visibility grid");
  Check(m->GetAccumulationResetCount() == 4, "an environment change restarts accumulation");

  opacity->AddPoint(0.5, 0.6);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 2, "an opacity change recomputes the visibility grid");
  Check(m->GetMajorantUpdateCount() == majorants + 1, "an opacity change recomputes the majorants");

  property->SetScalarOpacityUnitDistance(2.0);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 3, "a unit distance change recomputes the visibility grid");

  m->SetDensityScale(0.5);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 4, "a density scale change recomputes the visibility grid");

  vtkNew<vtkPlane> plane;
  plane->SetOrigin(10, 9, 8);
  plane->SetNormal(1, 0, 0);
  m->AddClippingPlane(plane);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 5, "a clipping plane recomputes the visibility grid");

  // Sampling parameters restart accumulation (they change the estimator) but keep the grid.
  int resets = m->GetAccumulationResetCount();
  m->SetSamplingStrategyToCombined();
  win->Render();
  Check(m->GetAccumulationResetCount() == resets + 1, "a strategy change restarts accumulation");
  m->SetCellModeToTrilinear();
  win->Render();
  Check(m->GetAccumulationResetCount() == resets + 2, "a cell mode change restarts accumulation");
  m->SetSamplingStrategyToTwoStep();
  m->SetCellModeToStochastic();
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 5, "sampling parameters keep the visibility grid");

  // Cropping (the subvolume) cuts the box the grid covers: the grid follows it.
  double bounds[6];
  image->GetBounds(bounds);
  m->CroppingOn();
  m->SetCroppingRegionPlanes(bounds[0], 0.5 * (bounds[0] + bounds[1]), bounds[2], bounds[3], bounds[4], bounds[5]);
  win->Render();
  Check(std::string(m->GetLastError()).empty(), m->GetLastError());
  Check(m->GetVisibilityUpdateCount() == 6, "cropping recomputes the visibility grid");
  // Other region flags are honoured (a union of boxes): a new extinction, so the grid follows.
  m->SetCroppingRegionFlagsToFence();
  win->Render();
  Check(std::string(m->GetLastError()).empty(), m->GetLastError());
  Check(m->GetVisibilityUpdateCount() == 7, "cropping regions recompute the visibility grid");
  m->SetCroppingRegionFlagsToSubVolume();
  m->SetCroppingRegionPlanes(bounds[1] + 1.0, bounds[1] + 2.0, bounds[2], bounds[3], bounds[4], bounds[5]);
  win->Render();
  Check(std::string(m->GetLastError()).empty(), m->GetLastError());
  Check(m->GetVisibilityUpdateCount() == 7, "a volume cropped away entirely skips the sweeps");
  m->CroppingOff();
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 8, "cropping off recomputes the grid for the whole box");

  values->SetValue(5, 0.9f);
  values->Modified();
  win->Render();
  Check(m->GetVolumeUploadCount() == 2, "modified data is uploaded again");
  Check(m->GetVisibilityUpdateCount() == 9, "modified data recomputes the visibility grid");

  m->SetSamplingStrategyToEnvironment();
  opacity->AddPoint(0.7, 0.1);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == 9, "strategies without visibility never sweep");

  // A volume that is empty under the transfer function: background only, no sweeps.
  vtkNew<vtkPiecewiseFunction> none;
  none->AddPoint(0.0, 0.0);
  none->AddPoint(1.0, 0.0);
  property->SetScalarOpacity(none);
  m->SetSamplingStrategyToTwoStep();
  win->Render();
  Check(std::string(m->GetLastError()).empty(), m->GetLastError());
  Check(m->GetVisibilityUpdateCount() == 9, "an empty volume skips the sweeps");

  // The grid is swept towards each texel's light: a sun that moves sweeps the grid again, an
  // environment only scaled in intensity does not; with LightWeightedDirections off neither does.
  property->SetScalarOpacity(opacity);
  env->SetTypeToSunDisk();
  env->SetSkyColor(0.2, 0.25, 0.3); // every direction lit: which directions are needed never changes
  env->SetSunDirection(0.3, 0.2, 0.9);
  win->Render();
  const int updates = m->GetVisibilityUpdateCount();
  Check(updates == 10, "a new light's directions sweep the grid again");
  double sun[3], sky[3];
  env->GetSunRadiance(sun);
  env->GetSkyColor(sky);
  env->SetSunRadiance(2 * sun[0], 2 * sun[1], 2 * sun[2]);
  env->SetSkyColor(2 * sky[0], 2 * sky[1], 2 * sky[2]);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == updates, "an environment twice as bright everywhere keeps the grid");
  env->SetSunDirection(0.5, 0.1, 0.85);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == updates + 1, "a sun that moved sweeps the grid again");
  m->LightWeightedDirectionsOff();
  win->Render();
  const int centres = m->GetVisibilityUpdateCount();
  Check(centres == updates + 2, "texel centres instead of the light's directions: a new grid");
  env->SetSunDirection(0.3, 0.2, 0.9);
  win->Render();
  Check(m->GetVisibilityUpdateCount() == centres, "texel centres: a moved sun keeps the grid");
  Check(std::string(m->GetLastError()).empty(), m->GetLastError());
  return vstest::ExitCode();
}
