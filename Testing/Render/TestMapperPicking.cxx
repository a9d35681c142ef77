// Picking a VisSweep volume (issue 14): vtkPropPicker (vtkRenderer::PickProp, a vtkHardwareSelector
// actor pass) picks the vtkVolume where the volume is and nothing where only the visible
// environment is, in both render modes; an actor beside it is picked as itself. A full
// vtkHardwareSelector selection returns one node per prop, every node with its prop (the radiance
// drawn in the selection passes was read as hundreds of ids without a prop); point and cell
// selections at the ball's centre return voxels of its front half. Picking touches no accumulator: no restart, no sample added, and the
// next frame accumulates on. A volume that is not pickable is not picked.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropPicker.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <string>

using vstest::Check;

namespace
{
// A ball of radius 0.4 of the box around the centre of a 20^3 volume of unit spacing.
vtkSmartPointer<vtkImageData> Ball(int n)
{
  const double c = 0.5 * (n - 1);
  return vstest::FloatVolume(n, [c, n](int x, int y, int z) {
    const double r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
    return r < 0.4 * n ? 1.0f : 0.0f;
  });
}

vtkSmartPointer<vtkVolumeProperty> Property()
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.9);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.9, 0.8, 0.7);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  return property;
}

vtkProp* Pick(vtkRenderer* ren, double x, double y)
{
  vtkNew<vtkPropPicker> picker;
  picker->Pick(x, y, 0.0, ren);
  return picker->GetViewProp();
}
}

int TestMapperPicking(int, char*[])
{
  vtkSmartPointer<vtkImageData> data = Ball(20);
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetSamplingStrategyToEnvironment();
  mapper->SetSamplesPerFrame(1);
  mapper->SetMaximumSamples(64);
  mapper->SetSeed(5);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(mapper);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(Property());

  // An opaque sphere to the right of the volume (x = 30), the volume at x in [0, 19].
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(32.0, 9.5, 9.5);
  sphere->SetRadius(5.0);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);

  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  ren->AddActor(actor);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(96, 48);
  win->AddRenderer(ren);
  vtkCamera* camera = ren->GetActiveCamera();
  camera->SetFocalPoint(19.0, 9.5, 9.5);
  camera->SetPosition(19.0, -80.0, 9.5);
  camera->SetViewUp(0.0, 0.0, 1.0);
  ren->ResetCamera();
  win->Render();
  win->Render();
  const int resets = mapper->GetAccumulationResetCount();
  const int samples = mapper->GetAccumulatedSamples();
  Check(samples == 2 && std::string(mapper->GetLastError()).empty(), "two frames accumulated without error");

  // Display positions of the volume's centre, the sphere's centre and an empty corner.
  auto display = [&](double x, double y, double z, double out[2]) {
    ren->SetWorldPoint(x, y, z, 1.0);
    ren->WorldToDisplay();
    out[0] = ren->GetDisplayPoint()[0];
    out[1] = ren->GetDisplayPoint()[1];
  };
  double vc[2], sc[2];
  display(9.5, 9.5, 9.5, vc);
  display(32.0, 9.5, 9.5, sc);
  Check(Pick(ren, vc[0], vc[1]) == volume.Get(), "vtkPropPicker picks the volume at its centre (Monte Carlo)");
  Check(Pick(ren, sc[0], sc[1]) == actor.Get(), "vtkPropPicker picks the actor beside the volume");
  Check(Pick(ren, 1.0, 1.0) == nullptr, "vtkPropPicker picks nothing in the environment (a corner)");
  Check(Pick(ren, vc[0], 46.0) == nullptr, "vtkPropPicker picks nothing above the ball");
  Check(mapper->GetSelectionRenderCount() >= 4, "the mapper drew the selection passes");
  Check(mapper->GetAccumulationResetCount() == resets && mapper->GetAccumulatedSamples() == samples,
    "picking neither restarts nor adds to the accumulation");

  // A full selection: nodes for the two props only, each with its prop.
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(ren);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  selector->SetArea(0, 0, 95, 47);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  bool volumeNode = false, actorNode = false, allWithProp = true;
  const unsigned int nodes = selection ? selection->GetNumberOfNodes() : 0u;
  for (unsigned int i = 0; i < nodes; ++i)
  {
    vtkObjectBase* prop = selection->GetNode(i)->GetProperties()->Get(vtkSelectionNode::PROP());
    allWithProp = allWithProp && prop != nullptr;
    volumeNode = volumeNode || prop == volume.Get();
    actorNode = actorNode || prop == actor.Get();
  }
  std::cout << "hardware selection: " << nodes << " nodes\n";
  Check(nodes == 2 && allWithProp && volumeNode && actorNode,
    "vtkHardwareSelector returns one node for the volume and one for the actor, each with its prop");
  Check(mapper->GetAccumulationResetCount() == resets && mapper->GetAccumulatedSamples() == samples,
    "selecting neither restarts nor adds to the accumulation");
  win->Render();
  Check(mapper->GetAccumulationResetCount() == resets && mapper->GetAccumulatedSamples() == samples + 1,
    "the next frame accumulates on");

  // Voxel ids: a 5 x 5 pixel area at the ball's centre, as points and as cells. The camera looks
  // along +y, so each id is a voxel of the ball's front surface near its axis. (A point selection
  // first renders the window normally, vtkOpenGLHardwareSelector's z-buffer pass: one more frame
  // of samples, no restart.)
  for (const bool cells : { false, true })
  {
    vtkNew<vtkHardwareSelector> voxels;
    voxels->SetRenderer(ren);
    voxels->SetFieldAssociation(
      cells ? vtkDataObject::FIELD_ASSOCIATION_CELLS : vtkDataObject::FIELD_ASSOCIATION_POINTS);
    voxels->SetArea(unsigned(vc[0]) - 2, unsigned(vc[1]) - 2, unsigned(vc[0]) + 2, unsigned(vc[1]) + 2);
    vtkSmartPointer<vtkSelection> picked;
    picked.TakeReference(voxels->Select());
    vtkIdTypeArray* list = nullptr;
    for (unsigned int i = 0; picked && i < picked->GetNumberOfNodes(); ++i)
    {
      vtkSelectionNode* node = picked->GetNode(i);
      if (node->GetProperties()->Get(vtkSelectionNode::PROP()) == volume.Get())
      {
        list = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
      }
    }
    const int n = cells ? 19 : 20;
    bool allFront = list && list->GetNumberOfTuples() > 0;
    for (vtkIdType t = 0; list && t < list->GetNumberOfTuples(); ++t)
    {
      const vtkIdType id = list->GetValue(t);
      const int x = int(id % n), y = int((id / n) % n), z = int(id / (n * n));
      // At the ball's surface (radius 8 about (9.5, 9.5, 9.5)), within 1.5 voxels: the opacity
      // threshold is crossed where the interpolated scalar starts to rise.
      const double c = cells ? 0.5 : 0.0; // a cell's centre
      const double r = std::sqrt((x + c - 9.5) * (x + c - 9.5) + (y + c - 9.5) * (y + c - 9.5) + (z + c - 9.5) * (z + c - 9.5));
      allFront = allFront && id >= 0 && id < vtkIdType(n) * n * n && std::abs(r - 8.0) < 1.5 && y < 9 &&
        std::abs(x - 9.5) < 3.0 && std::abs(z - 9.5) < 3.0;
      if (t < 3)
      {
        std::cout << (cells ? "cell " : "point ") << id << " = (" << x << ", " << y << ", " << z << ")\n";
      }
    }
    std::cout << (cells ? "cells" : "points") << " selected: " << (list ? list->GetNumberOfTuples() : 0) << "\n";
    Check(allFront, cells ? "the cell ids are those of the ball's front voxels" : "the point ids are those of the ball's front voxels");
  }
  Check(mapper->GetAccumulationResetCount() == resets && mapper->GetAccumulatedSamples() == samples + 2,
    "the voxel selections restarted nothing (the point selection's normal render added its frame)");
  Check(recorder->Warnings.empty(), "no warnings");

  // Emission-absorption: the same picks.
  mapper->SetRenderModeToEmissionAbsorption();
  win->Render();
  Check(Pick(ren, vc[0], vc[1]) == volume.Get(), "vtkPropPicker picks the volume (emission-absorption)");
  Check(Pick(ren, 1.0, 1.0) == nullptr, "vtkPropPicker picks nothing in a corner (emission-absorption)");

  // Not pickable: not picked.
  volume->PickableOff();
  Check(Pick(ren, vc[0], vc[1]) == nullptr, "a volume that is not pickable is not picked");
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
