// vsMapperMonteCarlo.cxx — vtkVisibilitySweepVolumeMapper's Monte Carlo path: the first frame's
// pipeline made ahead (StartPrewarm), and a frame of the progressive estimate (RenderMonteCarlo): the
// environment and the grid it needs, the frame's parameters, Auto's choice of estimator, the
// accumulator (the view's, a tile's or the interactive one) and what is shown. Members of the mapper,
// in a file of their own so that the mapper's own file keeps its pipeline and settings.
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsMapperInternals.h"
#include "vsAccumulationSignature.h"
#include "vsFrameGeometry.h"
#include "vsCoverageComposite.h"
#include "vsPipelinePrewarm.h"
#include "vsCombinedAccumulators.h"
#include "vsRadianceImage.h"
#include "vsPreviewHandOver.h"
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
#include "vtkVersionMacros.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"
#include "vsKernelOptions.h"
#include "vsSceneLights.h"
#include "vsSurfaceScattering.h"

#include <algorithm>
#include <chrono>
#include <cmath>

using vs::EmissionAbsorptionFrame;

namespace vs
{
namespace mapper
{
// The mapper's kernel settings in the parameters, copied here and nowhere else (the first frame's
// prewarm and every frame use it): the cell mode, the trackers, the sampler, TwoStep's ε and
// defensive weight, splitting, the environment's intensity, and the transport (the event limit, the
// phase's anisotropy: with VTK >= 9.2 the volume property's ScatteringAnisotropy where the mapper's
// is 0, MIS, Russian roulette, the benchmarks' light events). The strategy is the caller's (the
// prewarm's and Auto's differ from the setting). Out-of-range transport settings are an InputError
// naming the setting, the value and its range (vs::CheckScatteringSettings).
void CopyKernelSettings(vtkVisibilitySweepVolumeMapper* m, vtkVolumeProperty* property, vs::shared::VsMonteCarloParams& p)
{
  double anisotropy = m->GetScatteringAnisotropy();
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  if (anisotropy == 0.0 && property)
  {
    anisotropy = property->GetScatteringAnisotropy();
  }
#else
  (void)property;
#endif
  vs::CheckScatteringSettings(double(m->GetMaximumScatteringEvents()), anisotropy);
  p.maxEvents = uint32_t(m->GetMaximumScatteringEvents());
  p.anisotropy = float(anisotropy);
  p.cellMode = uint32_t(m->GetCellMode());
  p.cameraEstimator = uint32_t(m->GetCameraEstimator());
  p.controlExtinction = uint32_t(m->GetControlExtinction());
  p.pixelSampler = uint32_t(m->GetSampler());
  p.transmittance = uint32_t(m->GetTransmittanceEstimator());
  p.defensiveWeight = float(m->GetDefensiveWeight());
  p.visibilityEpsilon = float(m->GetVisibilityEpsilon());
  p.environmentIntensity = float(m->GetEnvironmentIntensity());
  p.shadowRays = uint32_t(m->GetShadowRays());
  p.mis = uint32_t(m->GetMultipleImportanceSampling());
  p.rouletteDepth = uint32_t(m->GetRussianRouletteDepth());
  const int* range = m->GetLightEventRange();
  if (range[0] > 0 || range[1] > 0)
  {
    const int lo = std::max(1, std::min(range[0], 0xffff));
    const int hi = std::max(lo, std::min(range[1] > 0 ? range[1] : 0xffff, 0xffff));
    p.lightEvents = uint32_t(lo) | (uint32_t(hi) << 16);
  }
}

// issue 38: hybrid scattering from the property's shading (ShadeOn, Diffuse, Specular, SpecularPower)
// and the mapper's VolumetricScatteringBlending; the gradient normalised by the data's range (the
// transfer function's table spans it) over the mean voxel spacing. Needs p.volume set.
void SetSurface(vs::shared::VsMonteCarloParams& p, vtkVolumeProperty* property, double blending,
  const vs::VolumeGeometry& geometry, double densityScale)
{
  vs::SurfaceScattering::Settings s;
  s.Shade = property && property->GetShade(0);
  s.Blending = blending;
  if (property)
  {
    s.Diffuse = property->GetDiffuse(0);
    s.Specular = property->GetSpecular(0);
    s.SpecularPower = property->GetSpecularPower(0);
  }
  const double meanSpacing = (geometry.Spacing(0) + geometry.Spacing(1) + geometry.Spacing(2)) / 3.0;
  vs::SurfaceScattering::Set(p, s, vs::SurfaceScattering::ScalarRange(p), meanSpacing,
    property ? property->GetScalarOpacityUnitDistance(0) : 1.0, densityScale);
}
}
}
using vs::mapper::CopyKernelSettings;
using vs::mapper::SetSurface;

namespace
{
// The first frame's kernel settings for StartPrewarm and PrecompileRenderKernel (false: none to guess);
// `renderer` (may be null: no lights) for its lights, which the kernel is specialized on.
bool PrewarmParameters(vtkVisibilitySweepVolumeMapper* mapper, vtkVolume* volume, vtkRenderer* renderer,
  vs::shared::VsMonteCarloParams& p)
{
  vtkVolumeProperty* property = volume->GetProperty();
  if (mapper->GetCropping())
  {
    return false; // the pipeline depends on the regions the geometry keeps: made when known
  }
  // Auto's first frames sample the environment (its grid fills in first), and so does TwoStep's
  // first progressive frame: its new grid is flat, where TwoStep is rendered as Environment sampling.
  const bool flatFirst = mapper->GetSamplingStrategy() == vtkVisibilitySweepVolumeMapper::Auto || (mapper->GetSamplingStrategy() == vtkVisibilitySweepVolumeMapper::TwoStep && mapper->GetProgressiveVisibility());
  p.strategy = uint32_t(flatFirst ? int(vtkVisibilitySweepVolumeMapper::Environment) : mapper->GetSamplingStrategy());
  p.volume.interpolation = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? vs::shared::VS_INTERPOLATION_NEAREST
    : vs::shared::VS_INTERPOLATION_LINEAR;
  p.volume.extinctionFactor = vs::HasEffectiveGradientOpacity(property) ? 1u : 0u; // the kernel's factor volume
  try
  {
    CopyKernelSettings(mapper, property, p);
    p.surface = property->GetShade(0) && mapper->GetVolumetricScatteringBlending() < 2.0 ? 1u : 0u; // issue 38
    if (renderer)
    {
      // The key-lit MRI's first frame waited 0.2 s for a kernel with lights when the guess had none.
      vs::SceneLights::Set(p, renderer);
    }
  }
  catch (const vs::InputError&)
  {
    return false; // the render reports it
  }
  return true;
}
}

void vtkVisibilitySweepVolumeMapper::StartPrewarm(
  vtkImageData* input, vtkVolume* volume, vtkDataArray* scalars, vtkRenderer* renderer)
{
  Internals& I = *this->Impl;
  I.Prewarm.MarkStarted();
  vs::shared::VsMonteCarloParams p{};
  if (!PrewarmParameters(this, volume, renderer, p))
  {
    return;
  }
  // A pass of its own: the pipeline lands in the context's cache, where the view's pass finds it
  // (waiting for it if the render gets there first); the view's passes come and go (SwitchView).
  const bool quads = vs::PipelinePrewarm::GuessQuads(scalars);
  const bool cellWalk = vs::PipelinePrewarm::GuessCellWalk(input, scalars, volume, this->DensityScale, p);
  I.Prewarm.Start(I.Context, p, this->DirectionTable, quads, cellWalk, false);
}

void vtkVisibilitySweepVolumeMapper::PrecompileRenderKernel(
  vtkVolume* volume, vtkImageData* shape, int scalarType, double rangeMin, double rangeMax, vtkRenderer* renderer)
{
  Internals& I = *this->Impl;
  if (I.Prewarm.Started() || this->RenderMode != MonteCarlo || !volume || !volume->GetProperty() || !shape ||
    EmissionAbsorptionFrame::IsProjection(this->BlendMode))
  {
    return;
  }
  try
  {
    if (!I.Context)
    {
      I.Context = vs::Context::Default();
    }
  }
  catch (const std::exception&)
  {
    return; // no device: the first render says so
  }
  I.Prewarm.MarkStarted();
  vs::shared::VsMonteCarloParams p{};
  if (!PrewarmParameters(this, volume, renderer, p))
  {
    return;
  }
  const double range[2] = { rangeMin, rangeMax };
  const bool quads =
    vs::PipelinePrewarm::GuessQuads(scalarType, 1, uint64_t(std::max<vtkIdType>(0, shape->GetNumberOfPoints())), range);
  const bool cellWalk = vs::PipelinePrewarm::GuessCellWalk(shape, range, volume, this->DensityScale, p);
  I.Prewarm.Start(I.Context, p, this->DirectionTable, quads, cellWalk, false);
}

void vtkVisibilitySweepVolumeMapper::RenderMonteCarlo(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  auto lap = vs::PhaseTimes::Clock::now();
  this->LastRenderComplete = false;
  I.SwitchView(ren); // one accumulator per renderer
  const vs::VolumeGeometry geometry = vs::FrameGeometry::CroppedGeometry(this, I.Scene->Geometry());
  const bool croppedAway = glm::any(glm::greaterThan(geometry.BoxMin, geometry.BoxMax));
  // The camera and the image size first: nothing is uploaded, swept or read back for a view
  // that cannot render.
  vs::CameraView view = vs::FrameGeometry::MakeView(ren);
  vs::FrameGeometry::CheckViewport(*I.Context, view.Port);

  this->UpdateEnvironmentInput();
  lap = I.LastFrame.Lap("environment", lap);

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
  lap = I.LastFrame.Lap("grid", lap);

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
  const bool interactive = this->IsInteractiveFrame(ren);
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
  const bool asBackground = this->GetShowsEnvironmentAsBackground() && vs::WindowCompositor::DrawsActors(ren);
  if (asBackground)
  {
    vs::EnvironmentBackground::Observe(ren);
  }
  const bool behind = asBackground && vs::EnvironmentBackground::InFrame(ren);
  const bool paints = this->GetShowsEnvironment() && !behind && vs::RendererFrame::Claim(ren, this);
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
  CopyKernelSettings(this, vol->GetProperty(), p);
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
  p.squareScale = squareScale;
  SetSurface(p, vol->GetProperty(), this->VolumetricScatteringBlending, I.Scene->Geometry(), this->DensityScale); // issue 38
  vs::SceneLights::Set(p, ren); // issue 38: the renderer's lights beside the environment
  if (grid)
  {
    auto c = grid->Cells();
    p.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    p.grid.side = grid->Side();
    p.grid.cellSize = grid->CellSize();
  }

  lap = I.LastFrame.Lap("frame", lap);
  I.Prewarm.Join();
  lap = I.LastFrame.Lap("pipeline", lap);
  // Auto's TwoStep pipeline once the grid has swept a direction (Auto may never use it before), and
  // TwoStep's own from its first flat-grid frame, rendered as Environment sampling: ready, or begun,
  // when the grid fills in (issue 39: ch2better's first TwoStep frame waited 1.4 s for the compile).
  const bool twoStepLater = this->SamplingStrategy == TwoStep && flatGrid && !interactive && !tiled;
  if ((autoStrategy ? grid && I.Grid->SweptDirections() > 0 : twoStepLater) && !I.GridPrewarm.Started())
  {
    I.GridPrewarm.MarkStarted();
    vs::shared::VsMonteCarloParams q = p;
    q.strategy = uint32_t(TwoStep);
    q.volume.extinctionFactor = I.Scene->Volume().Factor() ? 1u : 0u; // as MonteCarloPass::Render sets it
    const bool cellWalk = vs::MonteCarloPass::NeedsCellWalk(I.Scene->Majorants(), q);
    // As MonteCarloPass::Render decides (VolumeQuads on by default): the view's pass may not exist yet.
    const bool quads = I.MC ? I.MC->LastUsedVolumeQuads()
                            : I.Scene->Volume().Quads() != nullptr && q.volume.interpolation == 0u;
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
    I.HandOver = Internals::PreviewImage(); // no preview to hand over from
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
      // The restart for the view the preview showed while dragging starts the hand-over; any other
      // restart (a new transfer function, say) ends it: the preview is of another image.
      I.HandOver.Active = I.HandOver.Pending;
      I.HandOver.Pending = false;
      I.HandOver.Start = std::chrono::steady_clock::now();
      I.Guide = Internals::DenoiseGuide(); // DisplayDenoise's guide was of the image before
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
    lap = I.LastFrame.Lap("frame", lap);
    pass->Render(I.Scene->Volume(), I.Scene->TF(), I.Scene->Majorants(), gridFrame ? grid : nullptr,
      I.Environment.Device(), p, depth);
    lap = I.LastFrame.Lap("render", lap);
    this->LastDeviceSeconds = pass->LastSeconds();
    if (!tiled)
    {
      // A frame's cost (the sweeps' budget), without the direction table's build.
      I.LastRenderSeconds = pass->LastSeconds() - pass->LastDirectionTableSeconds();
      I.LastRenderSamples = spp;
    }
    if (pass->LastDirectionTableSeconds() > 0.0)
    {
      this->LastDirectionTableSeconds = pass->LastDirectionTableSeconds();
    }
    this->DirectionTableBuildCount = int(I.Table->Builds());
    this->MeanScatteringEvents = pass->MeanEventsPerPath();
    if (this->CountLookups)
    {
      auto n = pass->LastLookups();
      this->LastLookupCounts[0] = double(n[0]);
      this->LastLookupCounts[1] = double(n[1]);
      this->LastLookupCounts[2] = double(n[2]);
      this->LastLaneOccupancy = pass->LastLaneOccupancy();
      this->LastShadowRayCounts[0] = double(pass->LastShadowRays()[0]);
      this->LastShadowRayCounts[1] = double(pass->LastShadowRays()[1]);
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
  // Distributed rendering (SetRadianceCombiner): from here on the mean of every process's samples.
  // (Auto's selector above measured this process's own.)
  uint32_t combinedSamples = interactive || tiled ? uint32_t(pass->Samples()) : this->AccumulatedSamplesOf(autoStrategy);
  if (I.Combiner && !interactive)
  {
    combinedSamples = I.Combiner(mean, combinedSamples);
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
  // After an interactive preview: the window shows the blend of least expected error of the estimate
  // and the preview until the preview's share falls below PreviewHandOver::EndShare.
  this->LastPreviewShare = 0.0;
  if (I.HandOver.Active && !interactive && !tiled)
  {
    const uint32_t n = combinedSamples; // the samples behind `mean` (all processes' when combined)
    double share = 0.0;
    if (I.HandOver.Width == w && I.HandOver.Height == h && this->AccumulatedSamplesOf(autoStrategy) < uint32_t(this->MaximumSamples))
    {
      share = vs::PreviewHandOver::PreviewShare(I.HandOver.Rgba, mean, this->CombinedVariance(autoStrategy), n);
      // At most 1 - t / PreviewHandOverSeconds: the estimate is shown alone within the documented time,
      // however close the preview is.
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - I.HandOver.Start).count();
      share = std::min(share, vs::PreviewHandOver::ShareCap(t, this->PreviewHandOverSeconds));
    }
    if (share < vs::PreviewHandOver::EndShare)
    {
      if (this->DisplayDenoise && I.HandOver.Width == w && I.HandOver.Height == h)
      {
        // The preview stays DisplayDenoise's guide (its offsets averaged over the hand-over's frames).
        I.Guide.Rgba = std::move(I.HandOver.Rgba);
        I.Guide.Width = w;
        I.Guide.Height = h;
        I.Guide.Frames = I.HandOver.Frames;
      }
      I.HandOver = Internals::PreviewImage(); // from now on the estimate as it is
    }
    else
    {
      vs::PreviewHandOver::Blend(mean, I.HandOver.Rgba, share);
      this->LastPreviewShare = share;
    }
  }
  // DisplayDenoise: the image shown through the filter guided by the preview (vsMapperDenoise.cxx); what
  // is shown, in linear radiance, is kept (GetDisplayedRadiance).
  this->LastDisplayDenoised = false;
  if (!interactive && !tiled)
  {
    if (this->DisplayDenoise && combinedSamples >= 2)
    {
      this->DenoiseDisplay(mean, this->CombinedVariance(autoStrategy), combinedSamples, this->LastPreviewShare, w, h);
    }
    if (!I.Displayed)
    {
      I.Displayed = vtkSmartPointer<vtkImageData>::New();
    }
    vs::RadianceImage::Fill(I.Displayed, mean, w, h, environmentPixels, opaqueAlpha);
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
  lap = I.LastFrame.Lap("display", lap);
  if (!interactive && !tiled && this->DisplayDenoise)
  {
    // The guide's next frame for the frames to come, rendered last: its preview sweeps the whole grid on
    // first use, which must not happen under this frame's pointers to the grid.
    this->UpdateDenoiseGuide(ren, vol, w, h);
    I.LastFrame.Lap("denoise guide", lap);
  }
}

// A still Monte Carlo frame of a view that has no accumulation yet nor a preview to hand over from, in a
// window with an interactor (one the user can drag; an offscreen script or the command-line tool has
// none, and pays nothing for a preview it would not show).
bool vtkVisibilitySweepVolumeMapper::StartsWithoutPreview(vtkRenderer* ren)
{
  Internals& I = *this->Impl;
  vtkRenderWindow* win = ren ? ren->GetRenderWindow() : nullptr;
  if (!win || !win->GetInteractor() || !this->InteractivePreview || this->InteractiveUpdateRate <= 0.0)
  {
    return false;
  }
  int tileScale[2] = { 1, 1 };
  win->GetTileScale(tileScale);
  if (tileScale[0] > 1 || tileScale[1] > 1)
  {
    return false;
  }
  I.SwitchView(ren);
  return I.ImageSignature.empty() && !I.HandOver.Pending && !I.HandOver.Active;
}

// While the hand-over shows the preview, its first frames refine it: HandOverRefinements preview frames
// in all, each with the pixels' offsets rotated (dither.h), averaged (RenderLit with a ditherFrame).
namespace
{
const uint32_t HandOverRefinements = 8;
}

bool vtkVisibilitySweepVolumeMapper::RefinesHandOverPreview(vtkRenderer* ren)
{
  Internals& I = *this->Impl;
  vtkRenderWindow* win = ren ? ren->GetRenderWindow() : nullptr;
  if (!win || !this->InteractivePreview || !I.HandOver.Active || I.HandOver.Frames >= HandOverRefinements)
  {
    return false;
  }
  int tileScale[2] = { 1, 1 };
  win->GetTileScale(tileScale);
  return tileScale[0] <= 1 && tileScale[1] <= 1;
}

uint32_t vtkVisibilitySweepVolumeMapper::HandOverPreviewFrames() const
{
  return this->Impl->HandOver.Frames;
}

bool vtkVisibilitySweepVolumeMapper::IsInteractiveFrame(vtkRenderer* ren) const
{
  vtkRenderWindow* win = ren ? ren->GetRenderWindow() : nullptr;
  if (!win || this->InteractiveUpdateRate <= 0.0)
  {
    return false;
  }
  int tileScale[2] = { 1, 1 };
  win->GetTileScale(tileScale);
  return tileScale[0] <= 1 && tileScale[1] <= 1 && win->GetDesiredUpdateRate() >= this->InteractiveUpdateRate;
}
