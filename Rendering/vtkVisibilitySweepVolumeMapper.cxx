#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsMapperInternals.h"
#include "vsAccumulationSignature.h"
#include "vsFrameGeometry.h"
#include "vsFrameTimePredictor.h"
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
#include "vsKernelOptions.h"
#include "vsMonteCarloPass.h"
#include "sampling/mc_params.h"
#include "sampling/strategies.h"
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
  vtkRenderer* view = I.RenderingView;
  I.ViewErrors.erase(std::remove_if(I.ViewErrors.begin(), I.ViewErrors.end(),
                       [](const Internals::ViewError& e) { return !e.Renderer; }),
    I.ViewErrors.end());
  auto it = std::find_if(I.ViewErrors.begin(), I.ViewErrors.end(),
    [view](const Internals::ViewError& e) { return e.Renderer == view; });
  const bool repeated = it != I.ViewErrors.end() && message == it->Message && I.RenderStamp == it->Stamp;
  if (it == I.ViewErrors.end())
  {
    I.ViewErrors.push_back({ view, message, I.RenderStamp });
  }
  else
  {
    it->Message = message;
    it->Stamp = I.RenderStamp;
  }
  I.LastError = message;
  I.Radiance = nullptr;
  I.RadianceMode = -1;
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
  if (this->ReleaseKeepsVisibilityGrid && I.Grid && I.Grid->Grid() && I.Scene)
  {
    this->GetVisibilityGrid(); // completes a grid still filling in, then downloads it
  }
  else if (!this->ReleaseKeepsVisibilityGrid)
  {
    I.VisibilityImage = nullptr; // no copy of an earlier state of the grid either
  }
  // Kernels still being made ahead go on: their threads hold the context, the kernels land in its
  // cache for the next render, and the mapper's end waits for them. (Waiting here held `vissweep
  // render`'s setup 0.34 s: a renderer joining the window releases its props, issue 39.)
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
  I.LastRenderSamples = 0;
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
  vs::WindowCompositor::Suppress suppress(!this->DrawImage);
  this->RenderAndCheck(ren, vol);
  this->TimeToDraw = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void vtkVisibilitySweepVolumeMapper::RenderAndCheck(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  I.LastFrame.Clear();
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  I.RenderStamp = vs::NewestModification({ this, input, vol,
    this->GetNumberOfInputConnections(1) > 0 ? this->GetInputAlgorithm(1, 0) : nullptr });
  I.RenderingView = ren;
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
  for (const auto& w : I.Checks.NewWarnings(ren, vs::PropertyChecks::Ignored(
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
      this->StartPrewarm(input, vol, scalars, ren);
    }
    this->DirectionsUpdatedLastFrame = 0;
    this->LastFrameSweepSeconds = 0.0;
    const auto updateStart = std::chrono::steady_clock::now();
    vs::VolumeScene::Changes changes =
      I.Scene->Update(input, scalars, vol ? vol->GetProperty() : nullptr, vol ? vol->GetMatrix() : nullptr,
        this->DensityScale);
    this->LastUpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - updateStart).count();
    I.LastFrame.Add("scene", this->LastUpdateSeconds);
    I.LastFrame.Append("scene.", I.Scene->LastPhases());
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
    // GetRadiance() is what the last render computed, or nothing: a render in a mode that computes
    // no radiance, or in another mode than the one that made the image held, drops it (it returned
    // the Monte Carlo image after a switch to emission-absorption).
    const int radianceMode =
      projection || (this->RenderMode != MonteCarlo && this->RenderMode != Preview) ? -1 : this->RenderMode;
    if (!ren->GetSelector() && radianceMode != I.RadianceMode)
    {
      I.Radiance = nullptr;
      I.RadianceMode = radianceMode;
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
      this->RenderLit(ren, vol, this->RenderMode == Preview, false);
    }
    else if (this->InteractivePreview && this->IsInteractiveFrame(ren))
    {
      this->RenderLit(ren, vol, true, true); // the preview while the user drags
    }
    else
    {
      // The first still view of a window the user can drag starts from the preview, as a still view
      // after a drag does (issue 39): the preview, then the hand-over from it.
      if (this->InteractivePreview && this->StartsWithoutPreview(ren))
      {
        this->RenderLit(ren, vol, true, true);
      }
      else if (this->RefinesHandOverPreview(ren))
      {
        this->RenderLit(ren, vol, true, true, this->HandOverPreviewFrames());
      }
      this->RenderMonteCarlo(ren, vol);
    }
    I.LastError.clear();
    I.ViewErrors.erase(std::remove_if(I.ViewErrors.begin(), I.ViewErrors.end(),
                         [ren](const Internals::ViewError& e) { return !e.Renderer || e.Renderer == ren; }),
      I.ViewErrors.end());
  }
  catch (const std::exception& e)
  {
    this->ReportError(std::string("VisSweep cannot render: ") + e.what());
  }
}

// The kernel options' names come from their one table (vsKernelOptions.cxx); the enums are the
// kernel's constants.
using KernelOption = vs::KernelOptionId;
static_assert(vtkVisibilitySweepVolumeMapper::Uniform == int(vs::shared::VS_STRATEGY_UNIFORM) &&
    vtkVisibilitySweepVolumeMapper::Environment == int(vs::shared::VS_STRATEGY_ENVIRONMENT) &&
    vtkVisibilitySweepVolumeMapper::Visibility == int(vs::shared::VS_STRATEGY_VISIBILITY) &&
    vtkVisibilitySweepVolumeMapper::Combined == int(vs::shared::VS_STRATEGY_COMBINED) &&
    vtkVisibilitySweepVolumeMapper::TwoStep == int(vs::shared::VS_STRATEGY_TWO_STEP) &&
    vtkVisibilitySweepVolumeMapper::Auto == int(vs::kAutoStrategy),
  "the mapper's strategies are the kernel's");
static_assert(vtkVisibilitySweepVolumeMapper::TrilinearCells == int(vs::shared::VS_CELL_TRILINEAR) &&
    vtkVisibilitySweepVolumeMapper::StochasticCell == int(vs::shared::VS_CELL_STOCHASTIC),
  "the mapper's cell modes are the kernel's");
static_assert(vtkVisibilitySweepVolumeMapper::CollisionCamera == int(vs::shared::VS_CAMERA_COLLISION) &&
    vtkVisibilitySweepVolumeMapper::ReservoirCamera == int(vs::shared::VS_CAMERA_RESERVOIR),
  "the mapper's camera estimators are the kernel's");
static_assert(vtkVisibilitySweepVolumeMapper::IndependentSampler == int(vs::shared::VS_SAMPLER_INDEPENDENT) &&
    vtkVisibilitySweepVolumeMapper::SobolSampler == int(vs::shared::VS_SAMPLER_SOBOL),
  "the mapper's samplers are the kernel's");
static_assert(vtkVisibilitySweepVolumeMapper::ShadowRayControl == int(vs::shared::VS_CONTROL_SHADOW) &&
    vtkVisibilitySweepVolumeMapper::CameraRayControl == int(vs::shared::VS_CONTROL_CAMERA) &&
    vtkVisibilitySweepVolumeMapper::FullControl == int(vs::shared::VS_CONTROL_SHADOW | vs::shared::VS_CONTROL_CAMERA),
  "the mapper's control extinctions are the kernel's bits");
static_assert(vtkVisibilitySweepVolumeMapper::RatioTracking == int(vs::shared::VS_TRANSMITTANCE_RATIO_TRACKING) &&
    vtkVisibilitySweepVolumeMapper::RayMarching == int(vs::shared::VS_TRANSMITTANCE_RAY_MARCHING),
  "the mapper's transmittance estimators are the kernel's");
static_assert(vtkVisibilitySweepVolumeMapper::PowerHeuristic == int(vs::shared::VS_MIS_POWER) &&
    vtkVisibilitySweepVolumeMapper::LightSamplingOnly == int(vs::shared::VS_MIS_LIGHT_ONLY) &&
    vtkVisibilitySweepVolumeMapper::PhaseSamplingOnly == int(vs::shared::VS_MIS_PHASE_ONLY) &&
    vtkVisibilitySweepVolumeMapper::BalanceHeuristic == int(vs::shared::VS_MIS_BALANCE),
  "the mapper's MIS modes are the kernel's");

int vtkVisibilitySweepVolumeMapper::GetNumberOfLastFramePhases()
{
  return int(this->Impl->LastFrame.Phases().size());
}

const char* vtkVisibilitySweepVolumeMapper::GetLastFramePhaseName(int i)
{
  const auto& phases = this->Impl->LastFrame.Phases();
  return i >= 0 && size_t(i) < phases.size() ? phases[size_t(i)].first.c_str() : nullptr;
}

double vtkVisibilitySweepVolumeMapper::GetLastFramePhaseSeconds(int i)
{
  const auto& phases = this->Impl->LastFrame.Phases();
  return i >= 0 && size_t(i) < phases.size() ? phases[size_t(i)].second : 0.0;
}

const char* vtkVisibilitySweepVolumeMapper::GetSamplingStrategyName(int strategy)
{
  return vs::KernelOptionApiName(KernelOption::Strategy, uint32_t(strategy));
}

const char* vtkVisibilitySweepVolumeMapper::GetSamplingStrategyAsString()
{
  return GetSamplingStrategyName(this->SamplingStrategy);
}

const char* vtkVisibilitySweepVolumeMapper::GetCellModeAsString()
{
  return vs::KernelOptionApiName(KernelOption::CellMode, uint32_t(this->CellMode));
}

const char* vtkVisibilitySweepVolumeMapper::GetCameraEstimatorAsString()
{
  return vs::KernelOptionApiName(KernelOption::CameraEstimator, uint32_t(this->CameraEstimator));
}

const char* vtkVisibilitySweepVolumeMapper::GetSamplerAsString()
{
  return vs::KernelOptionApiName(KernelOption::Sampler, uint32_t(this->Sampler));
}

const char* vtkVisibilitySweepVolumeMapper::GetControlExtinctionAsString()
{
  return vs::KernelOptionApiName(KernelOption::ControlExtinction, uint32_t(this->ControlExtinction));
}

const char* vtkVisibilitySweepVolumeMapper::GetTransmittanceEstimatorAsString()
{
  return vs::KernelOptionApiName(KernelOption::Transmittance, uint32_t(this->TransmittanceEstimator));
}

const char* vtkVisibilitySweepVolumeMapper::GetMultipleImportanceSamplingAsString()
{
  return vs::KernelOptionApiName(KernelOption::Mis, uint32_t(this->MultipleImportanceSampling));
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

bool vtkVisibilitySweepVolumeMapper::GetShowsEnvironment()
{
  // Issue 38: the default white sky lights the volume but is not shown; the renderer's background is,
  // as a vtkGPUVolumeRayCastMapper pipeline had it before the mapper was swapped.
  return this->EnvironmentVisible && this->GetNumberOfInputConnections(1) > 0;
}

bool vtkVisibilitySweepVolumeMapper::GetShowsEnvironmentAsBackground()
{
  return this->GetShowsEnvironment() && this->EnvironmentAsBackground &&
    (this->RenderMode == MonteCarlo || this->RenderMode == Preview) &&
    !EmissionAbsorptionFrame::IsProjection(this->BlendMode);
}

int vtkVisibilitySweepVolumeMapper::RenderUntilConverged(vtkRenderWindow* window, double timeBudgetSeconds)
{
  if (!window)
  {
    vtkErrorMacro(<< "RenderUntilConverged: no render window");
    return this->AccumulatedSamples;
  }
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const bool timed = timeBudgetSeconds > 0.0 && std::isfinite(timeBudgetSeconds);
  // The deadline, for Auto's sweeps (SetRemainingTimeBudget); the caller's value back afterwards.
  const double callerRemaining = this->RemainingTimeBudget;
  int stalled = 0;
  vs::FrameTimePredictor predictor;
  while (true)
  {
    const int before = this->AccumulatedSamples;
    const auto frameStart = Clock::now();
    if (timed)
    {
      this->RemainingTimeBudget =
        std::max(1e-3, timeBudgetSeconds - std::chrono::duration<double>(frameStart - start).count());
    }
    window->Render();
    const auto now = Clock::now();
    if (!this->Impl->LastError.empty() || this->IsConverged())
    {
      break;
    }
    // A frame that adds nothing (an interactive frame, a window without this volume) would spin.
    stalled = this->AccumulatedSamples > before ? 0 : stalled + 1;
    if (stalled >= 3)
    {
      break;
    }
    // The next frame costs what these did less their one-off updates (new data, sweeps): the longest of
    // the last three per sample (vs::FrameTimePredictor), so that a frame slower than the one before does
    // not run the budget over.
    const int added = this->AccumulatedSamples - before;
    predictor.Add(
      std::max(0.0, std::chrono::duration<double>(now - frameStart).count() - this->LastUpdateSeconds), added);
    const double frame = predictor.NextFrameSeconds(std::max(added, 1));
    if (timed && std::chrono::duration<double>(now - start).count() + frame > timeBudgetSeconds)
    {
      break;
    }
  }
  this->RemainingTimeBudget = callerRemaining;
  return this->AccumulatedSamples;
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

void vtkVisibilitySweepVolumeMapper::SetClampedSetting(
  const char* name, double value, double lo, double hi, double& setting)
{
  if (std::isnan(value))
  {
    vtkErrorMacro(<< name << " NaN is refused; keeping " << setting);
    return;
  }
  value = std::min(std::max(value, lo), hi);
  if (setting != value)
  {
    setting = value;
    this->Modified();
  }
}

void vtkVisibilitySweepVolumeMapper::SetDefensiveWeight(double value)
{
  this->SetClampedSetting("DefensiveWeight", value, 0.0, 1.0, this->DefensiveWeight);
}

void vtkVisibilitySweepVolumeMapper::SetVisibilityEpsilon(double value)
{
  this->SetClampedSetting("VisibilityEpsilon", value, 1e-6, 1.0, this->VisibilityEpsilon);
}

void vtkVisibilitySweepVolumeMapper::SetVoxelsPerCell(double value)
{
  this->SetClampedSetting("VoxelsPerCell", value, 0.0, 256.0, this->VoxelsPerCell);
}

void vtkVisibilitySweepVolumeMapper::SetFilterAngleFraction(double value)
{
  this->SetClampedSetting("FilterAngleFraction", value, 0.0, 1.0, this->FilterAngleFraction);
}

void vtkVisibilitySweepVolumeMapper::SetInteractiveUpdateRate(double value)
{
  this->SetClampedSetting("InteractiveUpdateRate", value, 0.0, VTK_DOUBLE_MAX, this->InteractiveUpdateRate);
}

void vtkVisibilitySweepVolumeMapper::SetSweepFrameFraction(double value)
{
  this->SetClampedSetting("SweepFrameFraction", value, 0.0, 1000.0, this->SweepFrameFraction);
}

void vtkVisibilitySweepVolumeMapper::SetAutoProbeFraction(double value)
{
  this->SetClampedSetting("AutoProbeFraction", value, 0.0, 1000.0, this->AutoProbeFraction);
}

void vtkVisibilitySweepVolumeMapper::SetRemainingTimeBudget(double seconds)
{
  if (std::isnan(seconds))
  {
    vtkErrorMacro(<< "RemainingTimeBudget: NaN is not a number of seconds; kept " << this->RemainingTimeBudget);
    return;
  }
  this->RemainingTimeBudget = seconds; // the render loop's state: no Modified(), no restart
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

void vtkVisibilitySweepVolumeMapper::SetRadianceCombiner(RadianceCombiner combiner)
{
  this->Impl->Combiner = std::move(combiner);
  this->Modified();
}

void vtkVisibilitySweepVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << this->GetRenderModeAsString() << "\n";
  os << indent << "SamplingStrategy: " << this->GetSamplingStrategyAsString() << "\n";
  os << indent << "EffectiveStrategy: " << this->GetEffectiveStrategyAsString() << "\n";
  os << indent << "ProgressiveVisibility: " << (this->ProgressiveVisibility ? "On" : "Off") << "\n";
  os << indent << "ReleaseKeepsVisibilityGrid: " << (this->ReleaseKeepsVisibilityGrid ? "On" : "Off") << "\n";
  os << indent << "SweepFrameFraction: " << this->SweepFrameFraction << "\n";
  os << indent << "AutoProbeFraction: " << this->AutoProbeFraction << "\n";
  os << indent << "RemainingTimeBudget: " << this->RemainingTimeBudget << " s (<= 0: no deadline)\n";
  os << indent << "LightWeightedDirections: " << (this->LightWeightedDirections ? "On" : "Off") << "\n";
  os << indent << "FillUnsweptDirections: " << (this->FillUnsweptDirections ? "On" : "Off") << "\n";
  os << indent << "PendingDirections: " << this->GetPendingDirections() << "\n";
  os << indent << "CellMode: " << this->GetCellModeAsString() << "\n";
  os << indent << "ShadowRays: " << this->ShadowRays << " per scatter point\n";
  os << indent << "DirectionTable: " << (this->DirectionTable ? "on" : "off") << "\n";
  os << indent << "DefensiveWeight: " << this->DefensiveWeight << "\n";
  os << indent << "MaximumScatteringEvents: " << this->MaximumScatteringEvents << "\n";
  os << indent << "PreviewScatteringOrders: " << this->PreviewScatteringOrders << "\n";
  os << indent << "ScatteringAnisotropy: " << this->ScatteringAnisotropy << "\n";
  os << indent << "VolumetricScatteringBlending: " << this->VolumetricScatteringBlending << "\n";
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
  os << indent << "ShowsEnvironment: " << (this->GetShowsEnvironment() ? "Yes" : "No")
     << " (only a connected environment is shown; the default white sky lights the volume unseen)\n";
  os << indent << "EnvironmentAsBackground: " << (this->EnvironmentAsBackground ? "On" : "Off")
     << " (the visible environment as the renderer's background, a vtkSkybox behind everything)\n";
  os << indent << "ShowsEnvironmentAsBackground: " << (this->GetShowsEnvironmentAsBackground() ? "Yes" : "No") << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << (this->ToneMapping ? "On" : "Off") << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveSubsampling: " << this->InteractiveSubsampling << "\n";
  os << indent << "InteractivePreview: " << (this->InteractivePreview ? "On" : "Off") << "\n";
  os << indent << "PreviewHandOverSeconds: " << this->PreviewHandOverSeconds << "\n";
  os << indent << "LastPreviewShare: " << this->LastPreviewShare << "\n";
  os << indent << "DisplayDenoise: " << (this->DisplayDenoise ? "On" : "Off") << "\n";
  os << indent << "DisplayDenoiseRadius: " << this->DisplayDenoiseRadius << "\n";
  os << indent << "LastDisplayDenoised: " << (this->LastDisplayDenoised ? "true" : "false") << "\n";
  os << indent << "LastDenoiseSeconds: " << this->LastDenoiseSeconds << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance
     << " (EmissionAbsorption, Preview and AmbientOcclusion: MonteCarlo tracking is exact and needs no step)\n";
  os << indent << "AutoAdjustSampleDistances: " << (this->AutoAdjustSampleDistances ? "On" : "Off")
     << " (vtkGPUVolumeRayCastMapper's; no effect here)\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "VolumeUploadCount: " << this->VolumeUploadCount << "\n";
  os << indent << "SelectionRenderCount: " << this->SelectionRenderCount << "\n";
  os << indent << "TileRenderCount: " << this->TileRenderCount << "\n";
  os << indent << "DrawImage: " << (this->DrawImage ? "On" : "Off") << "\n";
  os << indent << "RadianceCombiner: " << (this->Impl->Combiner ? "set" : "none") << "\n";
  os << indent << "LastDeviceSeconds: " << this->LastDeviceSeconds << "\n";
  os << indent << "NumberOfLastFramePhases: " << this->GetNumberOfLastFramePhases() << "\n";
  for (int i = 0; i < this->GetNumberOfLastFramePhases(); ++i)
  {
    os << indent.GetNextIndent() << this->GetLastFramePhaseName(i) << ": " << this->GetLastFramePhaseSeconds(i)
       << " s\n";
  }
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
  os << indent << "MeanScatteringEvents: " << this->MeanScatteringEvents << "\n";
  os << indent << "MultipleImportanceSampling: " << this->GetMultipleImportanceSamplingAsString() << "\n";
  os << indent << "LastShadowRayCounts: " << this->LastShadowRayCounts[0] << " " << this->LastShadowRayCounts[1]
     << "\n";
  os << indent << "RussianRouletteDepth: " << this->RussianRouletteDepth << "\n";
  os << indent << "LightEventRange: " << this->LightEventRange[0] << " " << this->LightEventRange[1] << "\n";
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
