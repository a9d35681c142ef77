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

vtkStandardNewMacro(vtkVisibilitySweepVolumeMapper);

using vs::EmissionAbsorptionFrame;

vtkVisibilitySweepVolumeMapper::vtkVisibilitySweepVolumeMapper()
  : FilterAngleFraction(vs::VisibilityGridParameters().FilterAngleFraction)
  , Impl(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkVisibilitySweepVolumeMapper::~vtkVisibilitySweepVolumeMapper()
{
  vs::RendererFrame::Forget(this);
}

const char* vtkVisibilitySweepVolumeMapper::GetLastError()
{
  return this->Impl->LastError.c_str();
}

void vtkVisibilitySweepVolumeMapper::ReportError(const std::string& message)
{
  Internals& I = *this->Impl;
  // Once per change: the same error for unchanged inputs is not reported again at every
  // Render() (an application re-rendering a bad volume would flood its log). GetLastError()
  // keeps it, and GetRadiance() has no image until a render succeeds again.
  const bool repeated = message == I.LastError && I.RenderStamp == I.ErrorStamp;
  I.LastError = message;
  I.ErrorStamp = I.RenderStamp;
  I.Radiance = nullptr;
  if (!repeated)
  {
    vtkErrorMacro(<< message);
  }
}

double* vtkVisibilitySweepVolumeMapper::GetBounds()
{
  // NaN bounds made VTK's culler drop the volume before Render(), which then never said why.
  // Uninitialised bounds keep it in the render list: Render() reports the geometry's error
  // (vs::CheckGeometry), once per change.
  double* b = this->Superclass::GetBounds();
  if (b && !std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }))
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  return b;
}

void vtkVisibilitySweepVolumeMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  // The device state is no window's (Vulkan), the accumulators are per renderer: a window that
  // lets go of the prop takes its views' accumulators; while views in other windows remain, the
  // volume, the grid and the environment stay (one volume shown in two windows would otherwise
  // start over whenever either window initialises or drops a renderer).
  // VTK calls this when the window or the renderer lets go of the prop: free the device memory
  // (passes first, they hold views of the volume and the grid) and forget what it held, so the
  // next Render() uploads and sweeps again as a first render does. What a user may still ask
  // for once the window is gone stays on the host: the last radiance image (GetRadiance(),
  // without variance; AccumulatedSamples still counts its samples) and the visibility grid
  // (downloaded now, every direction, if there is one).
  Internals& I = *this->Impl;
  if (I.ReleaseViewsOf(win))
  {
    return;
  }
  if (I.Grid && I.Grid->Grid() && I.Scene)
  {
    this->GetVisibilityGrid(); // completes a grid still filling in, then downloads it
  }
  I.Prewarm.Join();
  I.GridPrewarm.Join();
  I.Environment.Release();
  I.Light.reset();
  I.Grid.reset();
  I.Interactive.reset();
  I.MC.reset();
  I.Table.reset();
  I.MCGrid.reset();
  I.Tile.reset();
  I.OtherViews.clear();
  I.CurrentView = nullptr;
  I.HasCurrentView = false;
  I.EA.reset();
  I.Scene.reset();
  I.GridNeedsFull = true;
  I.LastGridRequest = vs::GridUpdateRequest();
  I.Selector.ResetGrid();
  I.LastRenderSeconds = 0.0;
  I.ImageSignature.clear();
}

void vtkVisibilitySweepVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  if (vs::PeelingDeferral::InsidePeeling(vol))
  {
    // vtkDualDepthPeelingPass (UseDepthPeelingForVolumes) calls this several times a frame into its
    // peeling buffers, which the Monte Carlo image cannot take part in: draw once after it, over the
    // peeled translucent geometry, as with UseDepthPeelingForVolumes off (warned by vs::PropertyChecks).
    vtkWeakPointer<vtkVolume> weakVolume(vol);
    vtkWeakPointer<vtkRenderer> weakRenderer(ren);
    this->Impl->Peeling.Defer(ren, [this, weakVolume, weakRenderer]() {
      if (weakVolume && weakRenderer)
      {
        this->Render(weakRenderer, weakVolume);
      }
    });
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  this->RenderAndCheck(ren, vol);
  this->TimeToDraw = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void vtkVisibilitySweepVolumeMapper::RenderAndCheck(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  I.RenderStamp = vs::NewestModification({ this, input, vol,
    this->GetNumberOfInputConnections(1) > 0 ? this->GetInputAlgorithm(1, 0) : nullptr });
  int cellFlag = 0;
  vtkDataArray* scalars = input
    ? vtkAbstractMapper::GetScalars(input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId,
        this->ArrayName, cellFlag)
    : nullptr;
  if (scalars && cellFlag)
  {
    this->ReportError("the input volume's scalars are cell data; VisSweep renders point scalars");
    return;
  }
  // MIP, MinIP, average and additive are projections, not light transport: the emission-absorption
  // path renders them whatever the RenderMode.
  const bool projection = EmissionAbsorptionFrame::IsProjection(this->BlendMode);
  for (const auto& w : I.Checks.NewWarnings(vs::PropertyChecks::Ignored(
         this, vol ? vol->GetProperty() : nullptr, ren, this->RenderMode != EmissionAbsorption && !projection, projection)))
  {
    vtkWarningMacro(<< w);
  }
  try
  {
    if (!I.Context)
    {
      I.Context = vs::Context::Default();
    }
    // The image size before anything is uploaded, allocated or read back (issue 13, item 7).
    const vs::Viewport port = vs::WindowCompositor::GetViewport(ren);
    if (port.Width > 0 && port.Height > 0)
    {
      vs::RenderTargetLimits::Check(*I.Context, uint32_t(port.Width), uint32_t(port.Height));
    }
    if (!I.Scene)
    {
      I.Scene = std::make_unique<vs::VolumeScene>(I.Context);
    }
    if (!I.Prewarm.Started() && this->RenderMode == MonteCarlo && !projection && vol && vol->GetProperty())
    {
      this->StartPrewarm(input, vol, scalars);
    }
    this->DirectionsUpdatedLastFrame = 0;
    this->LastFrameSweepSeconds = 0.0;
    const auto updateStart = std::chrono::steady_clock::now();
    vs::VolumeScene::Changes changes =
      I.Scene->Update(input, scalars, vol ? vol->GetProperty() : nullptr, vol ? vol->GetMatrix() : nullptr,
        this->DensityScale);
    this->LastUpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - updateStart).count();
    if (changes.Data)
    {
      ++this->VolumeUploadCount;
      this->LastMajorantSeconds = I.Scene->Majorants().LastSeconds();
      if (I.Scene->Volume().NonFiniteCount())
      {
        vtkWarningMacro(<< I.Scene->Volume().NonFiniteCount()
                        << " voxels are NaN or infinite; they are rendered as empty space");
      }
    }
    // New data under the same transfer function (a new time step) may update the grid lazily;
    // any other change of extinction or geometry needs every direction again.
    if (changes.Geometry || (changes.Extinction && (!changes.Data || changes.TransferFunction)))
    {
      I.GridNeedsFull = true;
    }
    if (ren->GetSelector())
    {
      this->RenderSelection(ren, vol); // picking: the prop's id where the volume is, no accumulation
    }
    else if (this->RenderMode == EmissionAbsorption || projection)
    {
      this->RenderEmissionAbsorption(ren, vol);
    }
    else if (this->RenderMode == Preview || this->RenderMode == AmbientOcclusion)
    {
      this->RenderLit(ren, vol);
    }
    else
    {
      this->RenderMonteCarlo(ren, vol);
    }
    I.LastError.clear();
  }
  catch (const std::exception& e)
  {
    this->ReportError(std::string("VisSweep cannot render: ") + e.what());
  }
}

void vtkVisibilitySweepVolumeMapper::RenderEmissionAbsorption(vtkRenderer* ren, vtkVolume* vol)
{
  std::vector<float> rgba = this->EmissionAbsorptionImage(ren, vol);
  if (!rgba.empty())
  {
    this->LastRenderComplete = true;
    vs::WindowCompositor::Draw(ren, vs::WindowCompositor::GetViewport(ren), rgba);
  }
}

// Preview and AmbientOcclusion: the emission-absorption pass lit from the light volume of the whole
// visibility grid (swept at once at DirectionResolution: a still must not change as a grid fills in).
// The light volume is made again only when the grid's values, the environment or its intensity
// change, never for a camera move. A volume without extinction (or cropped away) needs neither: its
// lit image is transparent, and the preview shows the environment alone.
void vtkVisibilitySweepVolumeMapper::RenderLit(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  const bool preview = this->RenderMode == Preview;
  const vs::VolumeGeometry geometry = vs::FrameGeometry::CroppedGeometry(this, I.Scene->Geometry());
  const bool croppedAway = glm::any(glm::greaterThan(geometry.BoxMin, geometry.BoxMax));
  vs::CameraView view = vs::FrameGeometry::MakeView(ren);
  const vs::Viewport vp = view.Port;
  if (vp.Width <= 0 || vp.Height <= 0)
  {
    return;
  }
  vs::FrameGeometry::CheckViewport(*I.Context, vp);
  this->UpdateEnvironmentInput();
  const bool emptyVolume = I.Scene->Majorants().MaxMajorant() <= 0.0f || croppedAway;
  I.GridGeometry = geometry;
  this->UpdateVisibilityGrid(!emptyVolume, false);
  const vs::VisibilityGrid* grid = nullptr;
  if (!emptyVolume && I.Grid && I.Grid->Grid())
  {
    this->CompleteVisibilityGrid();
    grid = I.Grid->Grid();
    if (!I.Light)
    {
      I.Light = std::make_unique<vs::LightVolume>(I.Context);
    }
    I.Light->Update(*grid, I.Environment.Device(), this->EnvironmentIntensity);
    this->LightVolumeBuildCount = int(I.Light->Builds());
  }
  const std::vector<float> depth = vs::WindowCompositor::ReadDepth(ren, vp);
  bool shade = false;
  vs::shared::VsEmissionAbsorptionParams p =
    EmissionAbsorptionFrame::Params(this, ren, vol, geometry, view, *I.Scene, I.Frame++, shade);
  if (grid)
  {
    const auto c = grid->Cells();
    p.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    p.grid.side = grid->Side();
    p.grid.cellSize = grid->CellSize();
  }
  p.lightIntensity = float(this->EnvironmentIntensity); // ambient occlusion's sky
  if (!I.EA)
  {
    I.EA = std::make_unique<vs::EmissionAbsorptionPass>(I.Context);
  }
  std::vector<float> rgba = I.EA->Render(I.Scene->Volume(), I.Scene->TF(), p, depth, false,
    preview ? vs::shared::VS_EA_LIGHTING_PREVIEW : vs::shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION,
    grid ? &I.Light->Image() : nullptr);
  this->LastDeviceSeconds = I.EA->LastSeconds();
  this->LastRenderComplete = true;
  if (!preview)
  {
    vs::WindowCompositor::Draw(ren, vp, rgba); // as the emission-absorption image
    return;
  }
  // The environment seen through the volume, T x L_env through each pixel's centre, and the image
  // shown as the Monte Carlo mode's is (vs::CoverageComposite: over the skybox with the coverage
  // 1 - T, or painting the environment, or transparent where empty).
  const uint32_t w = uint32_t(vp.Width), h = uint32_t(vp.Height);
  const bool asBackground = this->GetShowsEnvironmentAsBackground();
  if (asBackground)
  {
    vs::EnvironmentBackground::Observe(ren);
  }
  const bool behind = asBackground && vs::EnvironmentBackground::InFrame(ren);
  const bool paints = this->EnvironmentVisible && !behind && vs::RendererFrame::Claim(ren, this);
  std::vector<uint8_t> environmentPixels;
  if (asBackground || paints)
  {
    const std::vector<float> environment = vs::CoverageComposite::EnvironmentRadiance(
      I.Environment.Map(), p.camera.invViewProj, w, h, float(this->EnvironmentIntensity));
    environmentPixels.assign(size_t(w) * h, 0);
    for (size_t i = 0; i < environmentPixels.size(); ++i)
    {
      if (!depth.empty() && depth[i] < 1.0f)
      {
        continue; // opaque geometry in front of the environment
      }
      environmentPixels[i] = 1;
      const float T = 1.0f - rgba[4 * i + 3];
      for (int c = 0; c < 3; ++c)
      {
        rgba[4 * i + c] += T * environment[3 * i + c];
      }
    }
  }
  if (!I.Radiance)
  {
    I.Radiance = vtkSmartPointer<vtkImageData>::New();
  }
  vs::RadianceImage::Fill(I.Radiance, rgba, w, h, environmentPixels, 1.0f);
  I.EnvironmentPixels = environmentPixels;
  const bool composite = asBackground && !paints;
  if (composite)
  {
    I.Composite.UpdateBackground(I.Environment.Map(), p.camera.invViewProj, w, h,
      float(this->EnvironmentIntensity * this->Exposure), this->ToneMapping, this->EnvironmentUploadCount);
  }
  vs::WindowCompositor::Draw(
    ren, vp, I.Composite.Display(rgba, environmentPixels, 1.0f, composite, float(this->Exposure), this->ToneMapping));
}

// In a vtkHardwareSelector pass: the prop's colour where the volume's opacity exceeds 3/255, as
// vtkOpenGLGPUVolumeRayCastMapper draws it (vs::SelectionMask). The opacity is that of the
// emission-absorption pass (deterministic, 1 - transmittance), whatever the render mode; the
// accumulators, the image signature and the radiance are left as they are.
void vtkVisibilitySweepVolumeMapper::RenderSelection(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  vtkHardwareSelector* selector = ren->GetSelector();
  selector->BeginRenderProp();
  const bool savedComplete = this->LastRenderComplete;
  std::vector<float> rgba = this->EmissionAbsorptionImage(ren, vol);
  this->LastRenderComplete = savedComplete;
  const vs::Viewport vp = vs::WindowCompositor::GetViewport(ren);
  if (!rgba.empty() && vs::SelectionMask::AsksForIds(selector))
  {
    // The voxel where each covered pixel's ray crosses the selection opacity, marched on the host.
    const vs::VoxelPicker::Volume v = EmissionAbsorptionFrame::PickerVolume(this, vol, *I.Scene);
    std::vector<bool> covered(rgba.size() / 4);
    for (size_t i = 0; i < covered.size(); ++i)
    {
      covered[i] = rgba[4 * i + 3] > vs::SelectionMask::Threshold;
    }
    const glm::dmat4 invViewProj = EmissionAbsorptionFrame::PickerInvViewProj(ren, vp);
    const std::vector<vtkIdType> ids = vs::VoxelPicker::Ids(v, invViewProj, vp.Width, vp.Height,
      vs::WindowCompositor::ReadDepth(ren, vp), covered, vs::SelectionMask::Threshold,
      vs::SelectionMask::AsksForCellIds(selector));
    vs::WindowCompositor::Draw(ren, vp, vs::SelectionMask::IdImage(selector, ids));
    const auto& d = v.Geometry.Dims;
    selector->UpdateMaximumPointId(vtkIdType(d[0]) * d[1] * d[2]);
    selector->UpdateMaximumCellId(vtkIdType(d[0]) * d[1] * d[2]);
    ++this->SelectionRenderCount;
  }
  else if (!rgba.empty())
  {
    vs::WindowCompositor::Draw(ren, vp, vs::SelectionMask::Image(selector, rgba));
    ++this->SelectionRenderCount;
  }
  selector->EndRenderProp();
}

// The emission-absorption image of the viewport (premultiplied RGBA, rows bottom-up), or nothing
// for an empty viewport.
std::vector<float> vtkVisibilitySweepVolumeMapper::EmissionAbsorptionImage(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  const vs::VolumeGeometry geometry = vs::FrameGeometry::CroppedGeometry(this, I.Scene->Geometry());
  vs::CameraView view = vs::FrameGeometry::MakeView(ren);
  vs::Viewport vp = view.Port;
  if (vp.Width <= 0 || vp.Height <= 0)
  {
    return {};
  }
  vs::FrameGeometry::CheckViewport(*I.Context, vp);
  std::vector<float> depth = vs::WindowCompositor::ReadDepth(ren, vp);
  bool shade = false;
  const vs::shared::VsEmissionAbsorptionParams p =
    EmissionAbsorptionFrame::Params(this, ren, vol, geometry, view, *I.Scene, I.Frame++, shade);
  if (!I.EA)
  {
    I.EA = std::make_unique<vs::EmissionAbsorptionPass>(I.Context);
  }
  std::vector<float> rgba = I.EA->Render(I.Scene->Volume(), I.Scene->TF(), p, depth, shade);
  this->LastDeviceSeconds = I.EA->LastSeconds();
  return rgba;
}

void vtkVisibilitySweepVolumeMapper::StartPrewarm(vtkImageData* input, vtkVolume* volume, vtkDataArray* scalars)
{
  Internals& I = *this->Impl;
  vtkVolumeProperty* property = volume->GetProperty();
  I.Prewarm.MarkStarted();
  if (this->Cropping)
  {
    return; // the pipeline depends on the regions the geometry keeps: made when known
  }
  vs::shared::VsMonteCarloParams p{};
  // Auto's first frames sample the environment (its grid fills in first), and so does TwoStep's
  // first progressive frame: its new grid is flat, where TwoStep is rendered as Environment sampling.
  const bool flatFirst = this->SamplingStrategy == Auto || (this->SamplingStrategy == TwoStep && this->ProgressiveVisibility);
  p.strategy = uint32_t(flatFirst ? int(Environment) : this->SamplingStrategy);
  p.cellMode = uint32_t(this->CellMode);
  p.cameraEstimator = uint32_t(this->CameraEstimator);
  p.controlExtinction = uint32_t(this->ControlExtinction);
  p.pixelSampler = uint32_t(this->Sampler);
  p.volume.interpolation = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? vs::shared::VS_INTERPOLATION_NEAREST
    : vs::shared::VS_INTERPOLATION_LINEAR;
  p.defensiveWeight = float(this->DefensiveWeight);
  p.transmittance = uint32_t(this->TransmittanceEstimator);
  p.volume.extinctionFactor = vs::HasEffectiveGradientOpacity(property) ? 1u : 0u; // the kernel's factor volume
  // A pass of its own: the pipeline lands in the context's cache, where the view's pass finds it
  // (waiting for it if the render gets there first); the view's passes come and go (SwitchView).
  const bool table = this->DirectionTable;
  const bool quads = vs::PipelinePrewarm::GuessQuads(scalars);
  const bool cellWalk = vs::PipelinePrewarm::GuessCellWalk(input, scalars, volume, this->DensityScale, p);
  I.Prewarm.Start(I.Context, p, table, quads, cellWalk, false);
}

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

void vtkVisibilitySweepVolumeMapper::RenderMonteCarlo(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  this->LastRenderComplete = false;
  I.SwitchView(ren); // one accumulator per renderer
  const vs::VolumeGeometry geometry = vs::FrameGeometry::CroppedGeometry(this, I.Scene->Geometry());
  const bool croppedAway = glm::any(glm::greaterThan(geometry.BoxMin, geometry.BoxMax));
  // The camera and the image size first: nothing is uploaded, swept or read back for a view
  // that cannot render.
  vs::CameraView view = vs::FrameGeometry::MakeView(ren);
  vs::FrameGeometry::CheckViewport(*I.Context, view.Port);

  this->UpdateEnvironmentInput();

  // The visibility grid, only for the strategies that use it.
  const std::vector<glm::dvec4> planes = vs::FrameGeometry::WorldPlanes(this->ClippingPlanes, geometry);
  const bool emptyVolume = I.Scene->Majorants().MaxMajorant() <= 0.0f || croppedAway;
  const bool autoStrategy = this->SamplingStrategy == Auto;
  // Auto skips the grid of a volume too thin to shadow: with the largest extinction along the
  // whole box diagonal the transmittance stays above exp(-0.05) = 0.95 everywhere, so the
  // visibility factor of the pdf would be flat.
  const double diagonal = glm::length(glm::dvec3(geometry.IndexToWorld * glm::dvec4(geometry.BoxMax - geometry.BoxMin, 0.0)));
  const bool thinVolume = double(I.Scene->Majorants().MaxMajorant()) * diagonal < 0.05;
  const bool needGrid = this->SamplingStrategy >= Visibility && !emptyVolume && !(autoStrategy && thinVolume);
  I.GridGeometry = geometry;
  this->UpdateVisibilityGrid(needGrid, autoStrategy);

  // Parameters of this frame.
  vtkRenderWindow* win = ren->GetRenderWindow();
  // A tile of a tiled render (vtkWindowToImageFilter's Scale): the camera is that of the tile, so
  // the view's accumulator would restart for every tile and again afterwards. A tile renders into
  // an accumulator of its own instead, as many samples as the view holds, in one Render().
  int tileScale[2] = { 1, 1 };
  if (win)
  {
    win->GetTileScale(tileScale);
  }
  const bool tiled = tileScale[0] > 1 || tileScale[1] > 1;
  const bool interactive = !tiled && this->InteractiveUpdateRate > 0.0 && win &&
    win->GetDesiredUpdateRate() >= this->InteractiveUpdateRate;
  const int sub = interactive ? this->InteractiveSubsampling : 1;
  vs::Viewport vp = view.Port;
  if (vp.Width <= 0 || vp.Height <= 0)
  {
    return;
  }
  const uint32_t w = uint32_t(std::max(1, vp.Width / sub)), h = uint32_t(std::max(1, vp.Height / sub));
  // Without opaque actors the depth buffer holds nothing of ours to respect; not reading it also
  // keeps passes that re-render the window (vtkWindowToImageFilter) from restarting accumulation.
  std::vector<float> fullDepth = ren->VisibleActorCount() > 0 ? vs::WindowCompositor::ReadDepth(ren, vp)
                                                             : std::vector<float>(size_t(vp.Width) * vp.Height, 1.0f);
  const std::vector<float> depth = vs::MonteCarloFrame::SubsampledDepth(fullDepth, vp, w, h, sub);

  vs::shared::VsMonteCarloParams p{};
  vs::MonteCarloFrame::SetPlacement(p, view, geometry, *I.Scene, planes);
  // The visible environment. As the renderer's background (EnvironmentAsBackground, the default):
  // the kernel's radiance includes the environment seen through the volume (GetRadiance() is the
  // same as with the opaque image) and its alpha is the volume's coverage, with which the image is
  // composited over what the renderer drew before it: the skybox vs::EnvironmentBackground adds
  // at the start of the renderer's frames, and whatever VTK drew over that. In a frame without a
  // skybox yet (the renderer's first with this volume), or with EnvironmentAsBackground off, the
  // first VisSweep volume of the renderer's frame paints the environment with its own (opaque)
  // image; with EnvironmentAsBackground off the others are transparent where empty (vs::RendererFrame).
  const bool asBackground = this->GetShowsEnvironmentAsBackground();
  if (asBackground)
  {
    vs::EnvironmentBackground::Observe(ren);
  }
  const bool behind = asBackground && vs::EnvironmentBackground::InFrame(ren);
  const bool paints = this->EnvironmentVisible && !behind && vs::RendererFrame::Claim(ren, this);
  p.background = asBackground ? vs::shared::VS_BACKGROUND_ENVIRONMENT_COVERAGE
    : paints                   ? vs::shared::VS_BACKGROUND_ENVIRONMENT
                               : vs::shared::VS_BACKGROUND_TRANSPARENT;
  p.camera.width = w;
  p.camera.height = h;
  p.camera.seed = static_cast<uint32_t>(this->Seed);
  // Auto: which estimator renders this frame (Environment while the grid is mostly unswept or not
  // needed; then the better one by measured efficiency).
  const vs::VisibilityGrid* grid = needGrid && I.Grid ? I.Grid->Grid() : nullptr;
  bool gridFrame = grid != nullptr;
  // A grid whose every cell reads one value in all directions (a new grid at visibility 1, or one
  // swept direction copied into the others) makes TwoStep's product pdf env x V / sum(env x V) the
  // environment's: TwoStep is then Environment sampling.
  const bool flatGrid = grid &&
    (I.Grid->SweptDirections() == 0 || (this->FillUnsweptDirections && I.Grid->SweptDirections() == 1));
  int effective = emptyVolume ? int(Uniform) : this->SamplingStrategy;
  vs::StrategySelector::Estimator estimator = vs::StrategySelector::EnvironmentEstimator;
  if (autoStrategy && !emptyVolume)
  {
    // TwoStep is measured as soon as the grid is not flat: its probes are bounded in samples
    // (StrategySelector::SamplesFor), and its verdict on the partial grid decides how fast the
    // grid fills in (waiting for half of the light's importance swept at AutoProbeFraction left
    // mri_courtyard's grid unmeasured for 13 s of a 16 s budget).
    const bool ready = grid && !flatGrid;
    // The Sobol sampler's strata lower Environment sampling's error of the mean more than TwoStep's.
    I.Selector.SetStratificationGain(
      this->Sampler == SobolSampler ? vs::StrategySelector::SobolStratificationGain : 1.0);
    // A tile (not a frame of the view) leaves the selector alone: TwoStep once it has measured better.
    estimator = interactive ? vs::StrategySelector::EnvironmentEstimator
      : tiled ? (ready && I.Selector.GridEfficiencyRatio() > 1.0 ? vs::StrategySelector::GridEstimator
                                                                 : vs::StrategySelector::EnvironmentEstimator)
              : I.Selector.Choose(ready);
    gridFrame = estimator == vs::StrategySelector::GridEstimator;
    effective = gridFrame ? int(TwoStep) : int(Environment);
  }
  // The signature sees the user's strategy: Auto's frame-by-frame choice does not restart accumulation.
  p.strategy = uint32_t(autoStrategy && !emptyVolume ? int(Auto) : effective);
  p.samplesPerFrame = 1u;
  p.cellMode = uint32_t(this->CellMode);
  p.environmentLevels = uint32_t(I.Environment.Device().FinestLevel());
  // TwoStep on a flat grid is rendered as Environment sampling, without building a direction table
  // for it (27-170 ms on the MRIs) or paying the table's descent per sample. (Auto waits for a grid
  // that is not flat: `ready` above.)
  if (effective == TwoStep && !autoStrategy && flatGrid)
  {
    effective = Environment;
    gridFrame = false;
  }
  this->EffectiveStrategy = effective;
  // The variance's squares are of radiance relative to the brightest light (no underflow for dim maps).
  const double brightest = I.Environment.Device().MaxLuminance() * this->EnvironmentIntensity;
  const float squareScale = brightest > 0.0 && std::isfinite(1.0 / brightest) && 1.0 / brightest < 1e37
    ? float(1.0 / brightest) : 1.0f;
  p.visibilityEpsilon = float(this->VisibilityEpsilon);
  p.environmentIntensity = float(this->EnvironmentIntensity);
  p.squareScale = squareScale;
  p.defensiveWeight = float(this->DefensiveWeight);
  p.shadowRays = uint32_t(this->ShadowRays);
  p.transmittance = uint32_t(this->TransmittanceEstimator);
  p.cameraEstimator = uint32_t(this->CameraEstimator);
  p.controlExtinction = uint32_t(this->ControlExtinction);
  p.pixelSampler = uint32_t(this->Sampler);
  if (grid)
  {
    auto c = grid->Cells();
    p.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    p.grid.side = grid->Side();
    p.grid.cellSize = grid->CellSize();
  }

  I.Prewarm.Join();
  if (autoStrategy && grid && !I.GridPrewarm.Started() && I.Grid->SweptDirections() > 0)
  {
    I.GridPrewarm.MarkStarted();
    vs::shared::VsMonteCarloParams q = p;
    q.strategy = uint32_t(TwoStep);
    q.volume.extinctionFactor = I.Scene->Volume().Factor() ? 1u : 0u; // as MonteCarloPass::Render sets it
    const bool cellWalk = vs::MonteCarloPass::NeedsCellWalk(I.Scene->Majorants(), q);
    const bool quads = I.MC && I.MC->LastUsedVolumeQuads();
    const bool table = this->DirectionTable;
    // On a CPU device the compile would take cores from the frames rendering meanwhile (Auto's
    // paths per device second fell 10-20% in its first seconds): it takes only what they leave.
    I.GridPrewarm.Start(I.Context, q, table, quads, cellWalk, true);
  }
  vs::MonteCarloPass* pass = nullptr;
  if (interactive)
  {
    if (!I.Interactive)
    {
      I.Interactive = std::make_unique<vs::MonteCarloPass>(I.Context);
    }
    pass = I.Interactive.get();
    pass->Reset(w, h);
    I.ImageSignature.clear(); // refine from scratch once the view is still
  }
  else if (tiled)
  {
    if (!I.Tile)
    {
      I.Tile = std::make_unique<vs::MonteCarloPass>(I.Context);
    }
    pass = I.Tile.get();
    pass->Reset(w, h);
    // Each tile its own random streams (the same pixel of two tiles must not share its noise).
    const double* tvp = win->GetTileViewport();
    const uint32_t tx = uint32_t(std::lround(tvp[0] * tileScale[0]));
    const uint32_t ty = uint32_t(std::lround(tvp[1] * tileScale[1]));
    p.camera.seed = static_cast<uint32_t>(this->Seed) ^ (0x9e3779b9u * (1u + tx + 4099u * ty));
    ++this->TileRenderCount;
  }
  else
  {
    if (!I.MC)
    {
      I.MC = std::make_unique<vs::MonteCarloPass>(I.Context);
    }
    if (autoStrategy && !I.MCGrid)
    {
      I.MCGrid = std::make_unique<vs::MonteCarloPass>(I.Context);
    }
    // Everything the accumulated image depends on; any difference restarts accumulation. The
    // grid's generation, not its sweeps: a grid filling in (or updated lazily) changes the pdf,
    // never the mean, so samples of every stage average into one estimate.
    std::vector<double> signature = vs::AccumulationSignature::Of(p);
    signature.push_back(double(I.Scene->TableBuilds()));
    signature.push_back(double(I.Scene->Uploads()));
    signature.push_back(double(I.Scene->FactorBuilds())); // a new gradient-opacity factor
    signature.push_back(double(this->EnvironmentUploadCount));
    signature.push_back(double(I.Grid && needGrid ? I.Grid->Generation() : 0));
    signature.insert(signature.end(), depth.begin(), depth.end());
    if (!vs::AccumulationSignature::NearlyEqual(signature, I.ImageSignature) || I.MC->Width() != w || I.MC->Height() != h)
    {
      I.MC->Reset(w, h);
      if (I.MCGrid)
      {
        I.MCGrid->Reset(w, h);
      }
      I.Selector.Reset();
      I.ImageSignature = signature;
      ++this->AccumulationResetCount;
    }
    pass = gridFrame && autoStrategy ? I.MCGrid.get() : I.MC.get();
    if (pass == I.MCGrid.get())
    {
      // Its own random streams: sample k of both accumulators must not share random numbers.
      p.camera.seed = static_cast<uint32_t>(this->Seed) ^ 0x5bd1e995u;
    }
  }
  const uint32_t accumulated = interactive || tiled ? 0u : this->AccumulatedSamplesOf(autoStrategy);
  const uint32_t remaining = uint32_t(std::max(0, this->MaximumSamples - int(accumulated)));
  // A tile: as many samples as the view holds (it is that view, magnified), at least a frame's.
  const uint32_t tileSpp = uint32_t(std::min(this->MaximumSamples,
    std::max(this->SamplesPerFrame, int(this->AccumulatedSamplesOf(autoStrategy)))));
  const uint32_t frameSpp = interactive ? 1u
    : tiled                             ? tileSpp
                                        : std::min<uint32_t>(uint32_t(this->SamplesPerFrame), remaining);
  // Auto: a frame that probes the estimator not preferred adds a bounded share of the samples.
  const uint32_t spp = autoStrategy && !interactive && !tiled && !emptyVolume
    ? I.Selector.SamplesFor(estimator, frameSpp, double(accumulated))
    : frameSpp;
  if (spp > 0)
  {
    p.strategy = uint32_t(effective);
    p.samplesPerFrame = spp;
    pass->SetCountLookups(this->CountLookups);
    pass->SetDirectionTable(this->DirectionTable);
    if (!I.Table)
    {
      I.Table = std::make_shared<vs::DirectionTable>(I.Context);
    }
    pass->ShareDirectionTable(I.Table);
    // While the grid fills in (directions pending) a table of its earlier state may lag until its
    // build is paid for; a complete grid's table is always current, so its image is reproducible.
    pass->SetTableRebuildRatio(
      I.Grid && I.Grid->PendingDirections() > 0 ? vs::MonteCarloPass::kTableRebuildRatio : 0.0);
    pass->Render(I.Scene->Volume(), I.Scene->TF(), I.Scene->Majorants(), gridFrame ? grid : nullptr,
      I.Environment.Device(), p, depth);
    this->LastDeviceSeconds = pass->LastSeconds();
    if (!tiled)
    {
      // A frame's cost (the sweeps' budget), without the direction table's build.
      I.LastRenderSeconds = pass->LastSeconds() - pass->LastDirectionTableSeconds();
    }
    if (pass->LastDirectionTableSeconds() > 0.0)
    {
      this->LastDirectionTableSeconds = pass->LastDirectionTableSeconds();
    }
    this->DirectionTableBuildCount = int(I.Table->Builds());
    if (this->CountLookups)
    {
      auto n = pass->LastLookups();
      this->LastLookupCounts[0] = double(n[0]);
      this->LastLookupCounts[1] = double(n[1]);
      this->LastLookupCounts[2] = double(n[2]);
      this->LastLaneOccupancy = pass->LastLaneOccupancy();
    }
  }
  if (!tiled)
  {
    this->AccumulatedSamples = interactive ? 0 : int(this->AccumulatedSamplesOf(autoStrategy));
  }

  // Keep the linear radiance; show it tone mapped.
  std::vector<float> mean = interactive || tiled ? pass->Mean() : this->CombinedMean(autoStrategy);
  // Under the coverage alpha, the pixels that see the environment (no opaque depth in front): their
  // alpha in the opaque image (what GetRadiance() reports, and what a painting volume shows).
  std::vector<uint8_t> environmentPixels;
  float opaqueAlpha = 1.0f;
  if (asBackground)
  {
    environmentPixels.resize(size_t(w) * h);
    for (size_t i = 0; i < environmentPixels.size(); ++i)
    {
      environmentPixels[i] = depth[i] >= 1.0f ? 1 : 0;
    }
    opaqueAlpha = interactive || tiled ? vs::CoverageComposite::OpaqueMean(pass->Samples()) : this->OpaqueAlpha(autoStrategy);
  }
  if (autoStrategy && !interactive && !tiled && spp > 0 && !emptyVolume)
  {
    const double meanSquare = vs::CombinedAccumulators::MeanSquare(mean);
    // The cost per sample without the direction table's build, which (like the sweeps) is the
    // grid's update, made once per grid state, not per sample.
    I.Selector.SetGridComplete(I.Grid && I.Grid->IsComplete());
    I.Selector.SetGridJudgeable(I.Grid && (I.Grid->IsComplete() || I.Grid->SweptImportance() >= 0.5));
    I.Selector.Record(estimator, spp, I.LastRenderSeconds, uint64_t(w) * h, double(pass->Samples()), pass->SquareSum(),
      meanSquare);
  }
  if (!interactive && !tiled) // GetRadiance() stays the view's
  {
    if (!I.Radiance)
    {
      I.Radiance = vtkSmartPointer<vtkImageData>::New();
    }
    vs::RadianceImage::Fill(I.Radiance, mean, w, h, environmentPixels, opaqueAlpha);
    I.EnvironmentPixels = environmentPixels;
  }
  // Composited over the background: the environment's display colour behind each pixel (made again
  // only when the view, the environment or the display transform changed).
  const float exposure = float(this->Exposure);
  const bool composite = asBackground && !paints;
  if (composite)
  {
    const float scale = float(this->EnvironmentIntensity * this->Exposure);
    I.Composite.UpdateBackground(
      I.Environment.Map(), p.camera.invViewProj, w, h, scale, this->ToneMapping, this->EnvironmentUploadCount);
  }
  const std::vector<float> display =
    I.Composite.Display(mean, environmentPixels, opaqueAlpha, composite, exposure, this->ToneMapping);
  if (sub == 1)
  {
    vs::WindowCompositor::Draw(ren, vp, display);
  }
  else
  {
    vs::WindowCompositor::DrawScaled(ren, vp, display, int(w), int(h));
  }
  (void)vol;
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
  vs::GridSchedule::FillRequest(this, r, I.GridGeometry, I.Environment, *I.Scene, I.GridNeedsFull, I.Selector,
    I.LastRenderSeconds, autoStrategy);
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

const char* vtkVisibilitySweepVolumeMapper::GetSamplingStrategyName(int strategy)
{
  switch (strategy)
  {
    case Uniform:
      return "Uniform";
    case Environment:
      return "Environment";
    case Visibility:
      return "Visibility";
    case Combined:
      return "Combined";
    case TwoStep:
      return "TwoStep";
    case Auto:
      return "Auto";
    default:
      return "Unknown";
  }
}

const char* vtkVisibilitySweepVolumeMapper::GetSamplingStrategyAsString()
{
  return GetSamplingStrategyName(this->SamplingStrategy);
}

const char* vtkVisibilitySweepVolumeMapper::GetUpdateSchemeAsString()
{
  switch (this->UpdateScheme)
  {
    case RoundRobin:
      return "RoundRobin";
    case EnvironmentGuided:
      return "EnvironmentGuided";
    case StaticUpdate:
      return "Static";
    default:
      return "Full";
  }
}

uint32_t vtkVisibilitySweepVolumeMapper::AccumulatedSamplesOf(bool autoStrategy)
{
  return vs::CombinedAccumulators::Samples(this->Impl->MC.get(), this->Impl->MCGrid.get(), autoStrategy);
}

std::vector<float> vtkVisibilitySweepVolumeMapper::CombinedMean(bool autoStrategy)
{
  return vs::CombinedAccumulators::Mean(*this->Impl->MC, this->Impl->MCGrid.get(), autoStrategy);
}

std::vector<double> vtkVisibilitySweepVolumeMapper::CombinedVariance(bool autoStrategy)
{
  return vs::CombinedAccumulators::Variance(*this->Impl->MC, this->Impl->MCGrid.get(), autoStrategy);
}

float vtkVisibilitySweepVolumeMapper::OpaqueAlpha(bool autoStrategy)
{
  return vs::CombinedAccumulators::OpaqueAlpha(this->Impl->MC.get(), this->Impl->MCGrid.get(), autoStrategy);
}

bool vtkVisibilitySweepVolumeMapper::GetShowsEnvironmentAsBackground()
{
  return this->EnvironmentVisible && this->EnvironmentAsBackground &&
    (this->RenderMode == MonteCarlo || this->RenderMode == Preview) &&
    !EmissionAbsorptionFrame::IsProjection(this->BlendMode);
}

vtkImageData* vtkVisibilitySweepVolumeMapper::GetRadiance(bool variance)
{
  Internals& I = *this->Impl;
  if (!I.Radiance || (!I.MC && variance)) // after ReleaseGraphicsResources: the radiance, not its variance
  {
    return nullptr;
  }
  if (variance)
  {
    // Double: the variance of radiance below ~1e-19 (a dim map in physical units) is below float's range.
    try
    {
      const bool autoStrategy = this->SamplingStrategy == Auto;
      std::vector<double> var = this->CombinedVariance(autoStrategy);
      const uint32_t ne = I.MC->Samples(), ng = autoStrategy && I.MCGrid ? I.MCGrid->Samples() : 0u;
      vs::RadianceImage::AddVariance(
        I.Radiance, std::move(var), I.EnvironmentPixels, vs::CombinedAccumulators::OpaqueAlphaVariance(ne, ng));
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< "GetRadiance: cannot read the variance back from the device: " << e.what());
      return nullptr;
    }
  }
  return I.Radiance;
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

int vtkVisibilitySweepVolumeMapper::GetMajorantUpdateCount()
{
  return this->Impl->Scene && this->Impl->Scene->Ready()
    ? int(this->Impl->Scene->Majorants().MajorantUpdates())
    : 0;
}

void vtkVisibilitySweepVolumeMapper::SetEnvironmentConnection(vtkAlgorithmOutput* port)
{
  this->SetInputConnection(1, port);
}

void vtkVisibilitySweepVolumeMapper::SetEnvironmentData(vtkImageData* environment)
{
  this->SetInputDataInternal(1, environment);
}

int vtkVisibilitySweepVolumeMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

// The device computes in float: a finite double beyond float's range turned into an infinity
// there (an intensity of 1e39 gave an all-NaN image, a density scale of 1e39 an infinite
// extinction), so such values are refused and the setting kept. Below the range (negative)
// they are clamped to 0 as vtkSetClampMacro did.
bool vtkVisibilitySweepVolumeMapper::SetFloatSetting(const char* name, double value, double& setting)
{
  const std::string problem = vs::FloatRange::Check(value);
  if (!problem.empty())
  {
    vtkErrorMacro(<< name << " " << value << " is refused: " << problem << "; keeping " << setting);
    return false;
  }
  value = std::max(value, 0.0);
  if (setting != value)
  {
    setting = value;
    this->Modified();
  }
  return true;
}

void vtkVisibilitySweepVolumeMapper::SetEnvironmentIntensity(double intensity)
{
  this->SetFloatSetting("EnvironmentIntensity", intensity, this->EnvironmentIntensity);
}

void vtkVisibilitySweepVolumeMapper::SetExposure(double exposure)
{
  this->SetFloatSetting("Exposure", exposure, this->Exposure);
}

void vtkVisibilitySweepVolumeMapper::SetSampleDistance(double distance)
{
  this->SetFloatSetting("SampleDistance", distance, this->SampleDistance);
}

void vtkVisibilitySweepVolumeMapper::SetDensityScale(double scale)
{
  this->SetFloatSetting("DensityScale", scale, this->DensityScale);
}

void vtkVisibilitySweepVolumeMapper::SetDirectionResolution(int resolution)
{
  if (resolution != 2 && resolution != 4 && resolution != 8 && resolution != 16)
  {
    vtkErrorMacro(<< "DirectionResolution " << resolution << " is not supported (the renderer supports 2, 4, 8 or "
                  << "16 directions per side); keeping " << this->DirectionResolution);
    return;
  }
  if (this->DirectionResolution != resolution)
  {
    this->DirectionResolution = resolution;
    this->Modified();
  }
}

const char* vtkVisibilitySweepVolumeMapper::GetRenderModeAsString()
{
  switch (this->RenderMode)
  {
    case EmissionAbsorption:
      return "EmissionAbsorption";
    case Preview:
      return "Preview";
    case AmbientOcclusion:
      return "AmbientOcclusion";
    default:
      return "MonteCarlo";
  }
}

const char* vtkVisibilitySweepVolumeMapper::GetCellModeAsString()
{
  return this->CellMode == TrilinearCells ? "TrilinearCells" : "StochasticCell";
}

void vtkVisibilitySweepVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << this->GetRenderModeAsString() << "\n";
  os << indent << "SamplingStrategy: " << this->GetSamplingStrategyAsString() << "\n";
  os << indent << "EffectiveStrategy: " << this->GetEffectiveStrategyAsString() << "\n";
  os << indent << "ProgressiveVisibility: " << (this->ProgressiveVisibility ? "On" : "Off") << "\n";
  os << indent << "SweepFrameFraction: " << this->SweepFrameFraction << "\n";
  os << indent << "AutoProbeFraction: " << this->AutoProbeFraction << "\n";
  os << indent << "LightWeightedDirections: " << (this->LightWeightedDirections ? "On" : "Off") << "\n";
  os << indent << "FillUnsweptDirections: " << (this->FillUnsweptDirections ? "On" : "Off") << "\n";
  os << indent << "PendingDirections: " << this->GetPendingDirections() << "\n";
  os << indent << "CellMode: " << this->GetCellModeAsString() << "\n";
  os << indent << "ShadowRays: " << this->ShadowRays << " per scatter point\n";
  os << indent << "DirectionTable: " << (this->DirectionTable ? "on" : "off") << "\n";
  os << indent << "DefensiveWeight: " << this->DefensiveWeight << "\n";
  os << indent << "CameraEstimator: " << this->GetCameraEstimatorAsString() << "\n";
  os << indent << "ControlExtinction: " << this->GetControlExtinctionAsString() << "\n";
  os << indent << "TransmittanceEstimator: " << this->GetTransmittanceEstimatorAsString() << "\n";
  os << indent << "Sampler: " << this->GetSamplerAsString() << "\n";
  os << indent << "SamplesPerFrame: " << this->SamplesPerFrame << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "AccumulatedSamples: " << this->AccumulatedSamples << "\n";
  os << indent << "Views: " << (this->Impl->OtherViews.size() + (this->Impl->CurrentView ? 1 : 0))
     << " (renderers with their own accumulator)\n";
  os << indent << "VisibilityEpsilon: " << this->VisibilityEpsilon << "\n";
  os << indent << "DirectionResolution: " << this->DirectionResolution << "\n";
  os << indent << "VoxelsPerCell: " << this->VoxelsPerCell << "\n";
  os << indent << "KernelResolution: " << this->KernelResolution << "\n";
  os << indent << "ExtinctionPooling: " << this->ExtinctionPooling << (this->ExtinctionPooling == 0 ? " (half a cell)" : "")
     << "\n";
  os << indent << "Filtering: " << (this->Filtering ? "On" : "Off") << "\n";
  os << indent << "FilterAngleFraction: " << this->FilterAngleFraction << "\n";
  // Issue 13, item 9: without an environment the mapper lights with white; say so.
  os << indent << "Environment: "
     << (this->GetNumberOfInputConnections(1) > 0 ? "input port 1"
                                                  : "none connected: a constant white sky of radiance 1 (the default)")
     << "\n";
  os << indent << "EnvironmentIntensity: " << this->EnvironmentIntensity << "\n";
  os << indent << "EnvironmentVisible: " << (this->EnvironmentVisible ? "On" : "Off") << "\n";
  os << indent << "EnvironmentAsBackground: " << (this->EnvironmentAsBackground ? "On" : "Off")
     << " (the visible environment as the renderer's background, a vtkSkybox behind everything)\n";
  os << indent << "ShowsEnvironmentAsBackground: " << (this->GetShowsEnvironmentAsBackground() ? "Yes" : "No") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << (this->ToneMapping ? "On" : "Off") << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveSubsampling: " << this->InteractiveSubsampling << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance
     << " (EmissionAbsorption, Preview and AmbientOcclusion: MonteCarlo tracking is exact and needs no step)\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "VolumeUploadCount: " << this->VolumeUploadCount << "\n";
  os << indent << "SelectionRenderCount: " << this->SelectionRenderCount << "\n";
  os << indent << "TileRenderCount: " << this->TileRenderCount << "\n";
  os << indent << "LastDeviceSeconds: " << this->LastDeviceSeconds << "\n";
  os << indent << "LastMajorantSeconds: " << this->LastMajorantSeconds << "\n";
  os << indent << "GradientOpacity: "
     << (this->Impl->Scene && this->Impl->Scene->HasGradientOpacity()
            ? "honoured (a factor volume scales the extinction; computed in " +
             std::to_string(this->Impl->Scene->LastFactorSeconds()) + " s)"
            : std::string("none effective"))
     << "\n";
  os << indent << "CountLookups: " << (this->CountLookups ? "On" : "Off") << "\n";
  os << indent << "LastLookupCounts: " << this->LastLookupCounts[0] << " " << this->LastLookupCounts[1] << " "
     << this->LastLookupCounts[2] << "\n";
  os << indent << "LastLaneOccupancy: " << this->LastLaneOccupancy << "\n";
  os << indent << "UpdateScheme: " << this->GetUpdateSchemeAsString() << "\n";
  os << indent << "SkipUnlitDirections: " << (this->SkipUnlitDirections ? "On" : "Off") << "\n";
  os << indent << "UnlitDirections: " << this->UnlitDirections << "\n";
  os << indent << "DirectionsPerFrame: " << this->DirectionsPerFrame << "\n";
  os << indent << "StaticInterval: " << this->StaticInterval << "\n";
  os << indent << "DirectionsUpdatedLastFrame: " << this->DirectionsUpdatedLastFrame << "\n";
  os << indent << "DirectionsUpdatedTotal: " << this->DirectionsUpdatedTotal << "\n";
  os << indent << "VisibilityUpdateCount: " << this->VisibilityUpdateCount << "\n";
  os << indent << "AccumulationResetCount: " << this->AccumulationResetCount << "\n";
  os << indent << "EnvironmentUploadCount: " << this->EnvironmentUploadCount << "\n";
  os << indent << "MajorantUpdateCount: " << this->GetMajorantUpdateCount() << "\n";
  os << indent << "LastSweepSeconds: " << this->LastSweepSeconds << "\n";
  os << indent << "DirectionTableBuildCount: " << this->DirectionTableBuildCount << "\n";
  os << indent << "LightVolumeBuildCount: " << this->LightVolumeBuildCount << "\n";
  os << indent << "LastDirectionTableSeconds: " << this->LastDirectionTableSeconds << "\n";
  os << indent << "LastUpdateSeconds: " << this->LastUpdateSeconds << "\n";
  os << indent << "LastFrameSweepSeconds: " << this->LastFrameSweepSeconds << "\n";
  os << indent << "LastError: " << (this->Impl->LastError.empty() ? "(none)" : this->Impl->LastError) << "\n";
}
