// vsMapperGrid.cxx — vtkVisibilitySweepVolumeMapper's environment input and visibility grid: the
// environment on the device, the grid updated for a frame's request (vs::GridSchedule,
// vs::VisibilityGridUpdater), its sweeps counted, and the grid completed and handed to the user
// (GetVisibilityGrid). Members of the mapper, in a file of their own.
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsMapperInternals.h"
#include "vsAccumulationSignature.h"
#include "vsFrameGeometry.h"
#include "vsCoverageComposite.h"
#include "vsPipelinePrewarm.h"
#include "vsCombinedAccumulators.h"
#include "vsRadianceImage.h"
#include "vsMapperEnvironment.h"
#include "vsGridSchedule.h"
#include "vsEmissionAbsorptionFrame.h"
#include "vsMonteCarloFrame.h"
#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsDeviceVolume.h"
#include "vsEmissionAbsorptionPass.h"
#include "vsEnvironmentBackground.h"
#include "vsEnvironmentMap.h"
#include "vsMajorantGrid.h"
#include "vsDirectionTable.h"
#include "vsMonteCarloPass.h"
#include "vsPeelingDeferral.h"
#include "vsPropertyChecks.h"
#include "vsRendererFrame.h"
#include "vsSelectionMask.h"
#include "vsVoxelPicker.h"
#include "vsRenderTargetLimits.h"
#include "vsStrategySelector.h"
#include "vsVisibilityGrid.h"
#include "vsVisibilityGridUpdater.h"
#include "sampling/interpolation.h"
#include "vsVisibilityImage.h"
#include "vsError.h"
#include "vsFloatRange.h"
#include "vsGradientOpacity.h"
#include "vsVolumeInput.h"
#include "vsVolumeScene.h"
#include "vsWindowCompositor.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCommand.h"
#include "vtkHardwareSelector.h"
#include "vtkInformation.h"
#include "vtkRenderWindow.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

using vs::EmissionAbsorptionFrame;

// The environment: port 1, or a constant white sky, on the device at DirectionResolution.
void vtkVisibilitySweepVolumeMapper::UpdateEnvironmentInput()
{
  Internals& I = *this->Impl;
  // The environment: port 1, or a constant white sky.
  vtkImageData* envImage = nullptr;
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    this->GetInputAlgorithm(1, 0)->Update();
    envImage = vtkImageData::SafeDownCast(this->GetInputDataObject(1, 0));
    if (!envImage || envImage->GetNumberOfPoints() == 0)
    {
      throw vs::InputError("the environment input (port 1) has no map; check its reader for errors");
    }
  }
  // The renderer's direction map holds at most 16 x 16 values (mc_render.glsl).
  const int side = this->DirectionResolution;
  if (side != 2 && side != 4 && side != 8 && side != 16)
  {
    throw vs::InputError("DirectionResolution " + std::to_string(side) +
      " is not supported by the renderer: use 2, 4, 8 or 16 directions per side");
  }
  if (I.Environment.Update(I.Context, envImage, side))
  {
    ++this->EnvironmentUploadCount;
  }
}

// The grid's update policy lives in vs::VisibilityGridUpdater; vs::GridSchedule says what the frame
// needs of it (the request).
void vtkVisibilitySweepVolumeMapper::UpdateVisibilityGrid(bool needGrid, bool autoStrategy)
{
  Internals& I = *this->Impl;
  this->UnlitDirections = 0;
  if (!needGrid)
  {
    return;
  }
  vs::GridUpdateRequest& r = I.LastGridRequest;
  // Auto's horizon: the deadline, and the samples left to MaximumSamples at the last frame's cost.
  const double remaining = vs::GridSchedule::RemainingSeconds(this->RemainingTimeBudget, this->MaximumSamples,
    this->AccumulatedSamples, I.LastRenderSamples > 0 ? I.LastRenderSeconds / I.LastRenderSamples : 0.0);
  vs::GridSchedule::FillRequest(this, r, I.GridGeometry, I.Environment, *I.Scene, I.GridNeedsFull, I.Selector,
    I.LastRenderSeconds, autoStrategy, remaining, I.Grid ? I.Grid->PendingSweepSeconds() : 0.0);
  this->UnlitDirections = int(std::count(r.Required.begin(), r.Required.end(), uint8_t(0)));
  if (!I.Grid)
  {
    I.Grid = std::make_unique<vs::VisibilityGridUpdater>(I.Context);
  }
  const auto start = std::chrono::steady_clock::now();
  const vs::GridUpdateResult result = I.Grid->Update(I.Scene->Volume(), I.Scene->TF(), I.Scene->Majorants(), r,
    [this](double f) { this->UpdateProgress(f); });
  I.GridNeedsFull = false;
  if (result.NewGrid)
  {
    I.Selector.ResetGrid();
    I.VisibilityImage = nullptr;
  }
  if (result.DirectionsSwept > 0)
  {
    this->NoteSweeps(result.DirectionsSwept, result.Seconds,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  else if (result.Seconds > 0.0)
  {
    this->LastFrameSweepSeconds = result.Seconds; // a slab of the pooled extinction, no direction yet
  }
}

// Counters and events of a render that swept visibility.
void vtkVisibilitySweepVolumeMapper::NoteSweeps(unsigned int directions, double deviceSeconds, double wallSeconds)
{
  Internals& I = *this->Impl;
  this->InvokeEvent(vtkCommand::StartEvent);
  this->InvokeEvent(vtkCommand::EndEvent);
  this->LastSweepSeconds = deviceSeconds;
  this->LastFrameSweepSeconds = deviceSeconds;
  this->DirectionsUpdatedLastFrame = int(directions);
  this->DirectionsUpdatedTotal += int(directions);
  this->LastUpdateSeconds += wallSeconds;
  ++this->VisibilityUpdateCount;
  I.VisibilityImage = nullptr;
}

// Sweeps the grid's directions the renders left unswept or pending (every direction, with the last
// request's settings), counted as sweeps.
void vtkVisibilitySweepVolumeMapper::CompleteVisibilityGrid()
{
  Internals& I = *this->Impl;
  const uint32_t side = I.Grid->Grid()->Side();
  if (I.Grid->PendingDirections() == 0 && I.Grid->SweptDirections() >= side * side)
  {
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  const vs::GridUpdateResult result = I.Grid->Complete(I.Scene->Volume(), I.Scene->TF(), I.Scene->Majorants(),
    I.LastGridRequest, [this](double f) { this->UpdateProgress(f); });
  if (result.DirectionsSwept > 0)
  {
    this->NoteSweeps(result.DirectionsSwept, result.Seconds,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

int vtkVisibilitySweepVolumeMapper::GetPendingDirections()
{
  return this->Impl->Grid ? int(this->Impl->Grid->PendingDirections()) : 0;
}

vtkImageData* vtkVisibilitySweepVolumeMapper::GetVisibilityGrid()
{
  Internals& I = *this->Impl;
  if (!I.Grid || !I.Grid->Grid() || !I.Scene)
  {
    return I.Grid ? nullptr : I.VisibilityImage.Get(); // after ReleaseGraphicsResources: its copy
  }
  // The renderer may have left directions unswept (without environment light, or not yet filled
  // in): a user asking for the grid gets every direction.
  try
  {
    this->CompleteVisibilityGrid();
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("GetVisibilityGrid: sweeping the directions the render skipped failed: " << e.what());
    return nullptr;
  }
  if (!I.VisibilityImage)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
    try
    {
      // In data coordinates (no prop matrix), over the box the grid covers (cropped or not).
      vs::VisibilityGridToImage(*I.Grid->Grid(), vs::FrameGeometry::CroppedGeometry(this, vs::ComputeGeometry(input, nullptr)), image);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< "GetVisibilityGrid: cannot read the grid back from the device: " << e.what());
      return nullptr;
    }
    I.VisibilityImage = image;
  }
  return I.VisibilityImage;
}
