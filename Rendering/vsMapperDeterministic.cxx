// vsMapperDeterministic.cxx — vtkVisibilitySweepVolumeMapper's deterministic paths: the
// emission-absorption image (and the projections), the preview and ambient occlusion lit from the
// light volume, and the hardware selector's pass. Members of the mapper, in a file of their own.
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
#include "vsSceneLights.h"
#include "vsSurfaceScattering.h"
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
#include <cstring>

using vs::EmissionAbsorptionFrame;

namespace
{
// RenderMode Preview: the frames a still view averages, their offsets rotated (as the hand-over's 8).
const uint32_t StillPreviewFrames = 8;
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
//
// With ditherFrame > 0 (an interactive preview only): a frame of the hand-over's preview with its pixels'
// offsets rotated (dither.h vs_dither_offset), averaged into the preview the hand-over blends
// (PreviewImage::Frames), nothing drawn: the fixed offsets' moire averages out while the view is still,
// the drag frames stay deterministic (frame 0).
//
// With `guide` (DisplayDenoise, vsMapperDenoise.cxx): the still preview's radiance (rgba, as the Monte Carlo
// mean) is put there and nothing else is touched: nothing drawn, GetRadiance() and the frame's state kept.
void vtkVisibilitySweepVolumeMapper::RenderLit(
  vtkRenderer* ren, vtkVolume* vol, bool preview, bool interactive, uint32_t ditherFrame, std::vector<float>* guide)
{
  Internals& I = *this->Impl;
  if (interactive)
  {
    I.SwitchView(ren); // the view whose accumulation restarts once it is still
    this->LastDisplayDenoised = false; // a drag frame shows the preview (a still frame may filter after it)
  }
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
  }
  const std::vector<float> depth = vs::WindowCompositor::ReadDepth(ren, vp);
  bool shade = false;
  vs::shared::VsEmissionAbsorptionParams p =
    EmissionAbsorptionFrame::Params(this, ren, vol, geometry, view, *I.Scene, I.Frame++, shade);
  vs::shared::VsMonteCarloParams mc{}; // the preview's lights, phase and surface lobe, as the estimate's
  if (grid)
  {
    if (!I.Light)
    {
      I.Light = std::make_unique<vs::LightVolume>(I.Context);
    }
    // The preview carries the multiple scattering the Monte Carlo estimate has (MaximumScatteringEvents
    // events in all, PreviewScatteringOrders of them on the cell grid, the rest as their geometric
    // tail; vsLightVolume.h); ambient occlusion reads only the mean visibility.
    vs::LightVolume::MultipleScattering scattering;
    scattering.Volume = &I.Scene->Volume();
    scattering.TF = &I.Scene->TF();
    scattering.Params = p.volume;
    scattering.Events = uint32_t(std::clamp(this->MaximumScatteringEvents, 1, int(vs::shared::VS_MAX_SCATTERING_EVENTS)));
    scattering.Orders = preview ? uint32_t(std::max(this->PreviewScatteringOrders, 1)) : 1u;
    if (preview)
    {
      // Issue 38: the preview lights with what the Monte Carlo estimate lights with (VTK's lights but its
      // automatic headlight, vsSceneLights.h), scatters by its phase's anisotropy towards them and, with
      // ShadeOn, by its surface lobe. Lights that follow the camera (headlights, camera lights) move with
      // every camera move: while the user drags, the light volume keeps them where they were when it was
      // built (a rebuild per drag frame would cost more than the frame), and the view's first still frame
      // builds it for where they are. A change of any other light builds it again at once.
      vs::mapper::CopyKernelSettings(this, vol ? vol->GetProperty() : nullptr, mc);
      mc.volume = p.volume;
      vs::mapper::SetSurface(mc, vol ? vol->GetProperty() : nullptr, this->VolumetricScatteringBlending,
        I.Scene->Geometry(), this->DensityScale);
      uint32_t follows = 0u;
      vs::SceneLights::Set(mc, ren, false, &follows);
      scattering.Lights.assign(mc.lights, mc.lights + mc.lightCount);
      // Issue 39: the phase's anisotropy towards the environment needs the first order's band-1 moment
      // (built when g becomes non-zero, not for another g nor a camera move; vsLightVolume.h).
      scattering.Anisotropy = mc.anisotropy;
      const std::vector<vs::shared::VsSceneLight>& built = I.Light->Lights();
      if (this->IsInteractiveFrame(ren) && follows != 0u && I.Light->Valid() &&
        built.size() == scattering.Lights.size())
      {
        bool othersSame = true;
        for (size_t i = 0; i < built.size(); ++i)
        {
          if (!(follows & (1u << i)) && std::memcmp(&built[i], &scattering.Lights[i], sizeof(built[i])) != 0)
          {
            othersSame = false;
          }
        }
        if (othersSame)
        {
          scattering.Lights = built; // the camera's lights as the light volume has them
        }
      }
    }
    I.Light->Update(*grid, I.Environment.Device(), this->EnvironmentIntensity, scattering);
    this->LightVolumeBuildCount = int(I.Light->Builds());
  }
  // The preview's lights are those the light volume was built with (its transmittance is towards them).
  p.lightCount = 0u;
  if (preview && grid && I.Light->Transmittance())
  {
    const std::vector<vs::shared::VsSceneLight>& lights = I.Light->Lights();
    p.lightCount = uint32_t(lights.size());
    std::copy(lights.begin(), lights.end(), p.lights);
  }
  shade = false;
  if (preview)
  {
    p.anisotropy = mc.anisotropy;
    shade = vs::SurfaceScattering::Enabled(mc);
    p.surface = shade ? 1u : 0u;
    p.surfaceBlending = mc.surfaceBlending;
    p.surfaceDiffuse = mc.surfaceDiffuse;
    p.surfaceSpecular = mc.surfaceSpecular;
    p.surfaceRoughness = mc.surfaceRoughness;
    p.gradientScale = mc.gradientScale;
    p.opacityDistance = mc.opacityDistance;
  }
  if (grid)
  {
    const auto c = grid->Cells();
    p.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    p.grid.side = grid->Side();
    p.grid.cellSize = grid->CellSize();
  }
  p.lightIntensity = float(this->EnvironmentIntensity); // ambient occlusion's sky
  // The lit modes march one voxel per step unless SampleDistance says otherwise: their error is the
  // light volume's (interpolated between the grid's cells), not the step's. On ch2 at 512^2 the
  // preview's relative MSE against converged Monte Carlo was 3.14e-2, 3.12e-2 and 3.06e-2 at steps of
  // 0.5, 1 and 2 voxels (docs/benchmarks.md, samples at the steps' midpoints then), and one voxel
  // takes half the time of half a voxel.
  if (this->SampleDistance <= 0.0)
  {
    p.step = float(geometry.MinSpacing);
  }
  p.ditherFrame = ditherFrame;
  if (interactive || this->IsInteractiveFrame(ren))
  {
    // While the user drags (the Monte Carlo mode's preview, or the Preview and AmbientOcclusion modes
    // themselves) three times the step, as vtkGPUVolumeRayCastMapper samples more coarsely while
    // interacting: 3.32e-2 at three voxels against 256 spp, below Monte Carlo's 3.61e-2 at 16 spp
    // (docs/benchmarks.md), and a drag frame of ~80 ms instead of ~100 at two voxels. The pixels'
    // fixed offsets (dither.h) keep the longer steps from drawing wood-grain rings.
    p.step *= 3.0f;
  }
  // The preview's window image is made on the device with the radiance (the environment seen through
  // the volume included, ea_params.h VS_EA_DISPLAY_*): a frame while the user drags has no per-pixel
  // work left on the host, whose threads would otherwise compete with lavapipe's for the cores. It is
  // shown as the Monte Carlo mode's image is (vs_display_pixel: over the skybox with the coverage
  // 1 - T, or painting the environment, or transparent where empty).
  const uint32_t w = uint32_t(vp.Width), h = uint32_t(vp.Height);
  bool seesEnvironment = false;
  if (preview)
  {
    const bool asBackground = this->GetShowsEnvironmentAsBackground() && vs::WindowCompositor::DrawsActors(ren);
    if (asBackground)
    {
      vs::EnvironmentBackground::Observe(ren);
    }
    const bool behind = asBackground && vs::EnvironmentBackground::InFrame(ren);
    const bool paints = this->GetShowsEnvironment() && !behind && vs::RendererFrame::Claim(ren, this);
    seesEnvironment = asBackground || paints;
    p.display = vs::shared::VS_EA_DISPLAY_IMAGE;
    p.display |= seesEnvironment ? vs::shared::VS_EA_DISPLAY_ENVIRONMENT : 0u;
    p.display |= asBackground && !paints ? vs::shared::VS_EA_DISPLAY_COMPOSITE : 0u;
    p.display |= this->ToneMapping ? vs::shared::VS_EA_DISPLAY_TONE_MAPPING : 0u;
    p.exposure = float(this->Exposure);
    p.environmentSize = uint32_t(I.Environment.Device().Size());
    p.environmentScale = float(this->EnvironmentIntensity);
  }
  // RenderMode Preview, still (issue 39, item 1): successive renders of one still view average
  // StillPreviewFrames frames whose offsets are rotated (dither.h vs_dither_offset), as the Monte Carlo
  // mode's hand-over does with its preview: the fixed pattern's moire averages out. The first frame is
  // the fixed pattern (a view's first image is what it was); IsConverged() once all are in, after which
  // a render redraws the mean. Anything else that changes (camera, size, depth, transfer function, light
  // volume, display settings) starts again from frame 0.
  const bool stillPreview = preview && !interactive && !guide;
  auto& still = I.StillPreview;
  bool reuse = false;
  if (stillPreview)
  {
    vs::shared::VsEmissionAbsorptionParams k = p;
    k.camera.frame = 0; // the lit modes read no random numbers
    k.ditherFrame = 0;
    std::vector<uint8_t> key(sizeof(k));
    std::memcpy(key.data(), &k, sizeof(k));
    const double counters[] = { double(w), double(h), double(I.Light ? I.Light->Builds() : 0u),
      double(I.Scene->TableBuilds()), double(I.Scene->Uploads()), double(I.Scene->FactorBuilds()),
      double(this->EnvironmentUploadCount), double(I.GridGeneration()) };
    const auto* c = reinterpret_cast<const uint8_t*>(counters);
    key.insert(key.end(), c, c + sizeof(counters));
    const auto* d = reinterpret_cast<const uint8_t*>(depth.data());
    key.insert(key.end(), d, d + depth.size() * sizeof(float));
    if (key != still.Key)
    {
      still = Internals::StillPreviewImage();
      still.Key = std::move(key);
    }
    reuse = still.Frames >= StillPreviewFrames;
    p.ditherFrame = still.Frames;
  }
  if (!I.EA)
  {
    I.EA = std::make_unique<vs::EmissionAbsorptionPass>(I.Context);
  }
  std::vector<float> rgba = reuse ? still.Rgba
    : I.EA->Render(I.Scene->Volume(), I.Scene->TF(), &I.Scene->Majorants(), p, depth, shade,
        preview ? vs::shared::VS_EA_LIGHTING_PREVIEW : vs::shared::VS_EA_LIGHTING_AMBIENT_OCCLUSION,
        grid ? &I.Light->Image() : nullptr, preview ? &I.Environment.Device().Radiance() : nullptr,
        grid ? I.Light->Transmittance() : nullptr, grid && preview ? I.Light->Moment() : nullptr);
  if (guide)
  {
    *guide = std::move(rgba);
    return;
  }
  if (stillPreview && !reuse)
  {
    const std::vector<float>& display = I.EA->LastDisplay();
    if (still.Frames == 0 || still.Rgba.size() != rgba.size() || still.Display.size() != display.size())
    {
      still.Rgba = rgba;
      still.Display = display;
      still.Frames = 0;
    }
    else
    {
      const float n = float(still.Frames) + 1.0f;
      for (size_t i = 0; i < rgba.size(); ++i)
      {
        still.Rgba[i] += (rgba[i] - still.Rgba[i]) / n;
      }
      for (size_t i = 0; i < display.size(); ++i)
      {
        still.Display[i] += (display[i] - still.Display[i]) / n;
      }
      rgba = still.Rgba;
    }
    ++still.Frames;
  }
  this->LastDeviceSeconds = reuse ? 0.0 : I.EA->LastSeconds();
  // The Monte Carlo mode's image is still to come; a still preview's is complete with its frames.
  this->LastRenderComplete = !interactive && (!stillPreview || still.Frames >= StillPreviewFrames);
  if (!preview)
  {
    vs::WindowCompositor::Draw(ren, vp, rgba); // as the emission-absorption image
    return;
  }
  if (interactive && ditherFrame > 0)
  {
    // A refinement of the hand-over's preview: the running mean of its frames.
    if (I.HandOver.Active && I.HandOver.Width == w && I.HandOver.Height == h && rgba.size() == I.HandOver.Rgba.size())
    {
      const float k = float(I.HandOver.Frames);
      for (size_t i = 0; i < rgba.size(); ++i)
      {
        I.HandOver.Rgba[i] += (rgba[i] - I.HandOver.Rgba[i]) / (k + 1.0f);
      }
      ++I.HandOver.Frames;
    }
    return;
  }
  if (interactive)
  {
    // GetRadiance() stays the view's estimate; the accumulation restarts once the view is still, and
    // the window hands over from this image to it (vsPreviewHandOver.h).
    I.HandOver.Frames = 1;
    I.HandOver.Rgba = std::move(rgba);
    I.HandOver.Width = w;
    I.HandOver.Height = h;
    I.HandOver.Pending = true;
    I.HandOver.Active = false;
    I.ImageSignature.clear();
    this->AccumulatedSamples = 0;
    this->LastPreviewShare = 1.0;
  }
  else
  {
    // The pixels that see the environment (nothing opaque in front), as GetRadiance() reports them.
    std::vector<uint8_t> environmentPixels;
    if (seesEnvironment)
    {
      environmentPixels.assign(size_t(w) * h, 1);
      for (size_t i = 0; i < depth.size(); ++i)
      {
        environmentPixels[i] = depth[i] < 1.0f ? 0 : 1;
      }
    }
    if (!I.Radiance)
    {
      I.Radiance = vtkSmartPointer<vtkImageData>::New();
    }
    vs::RadianceImage::Fill(I.Radiance, rgba, w, h, environmentPixels, 1.0f);
    I.EnvironmentPixels = std::move(environmentPixels);
  }
  vs::WindowCompositor::Draw(ren, vp, stillPreview ? still.Display : I.EA->LastDisplay());
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
  std::vector<float> rgba = I.EA->Render(I.Scene->Volume(), I.Scene->TF(), &I.Scene->Majorants(), p, depth, shade);
  this->LastDeviceSeconds = I.EA->LastSeconds();
  return rgba;
}
