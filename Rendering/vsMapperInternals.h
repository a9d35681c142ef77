// vsMapperInternals.h — vtkVisibilitySweepVolumeMapper's private state (its pimpl, Internals),
// moved out of the mapper's .cxx into this private header so that the mapper's .cxx and
// vsMapperInternals.cxx (the per-renderer views: SwitchView, ReleaseViewsOf) share one definition.
// The device state (scene, passes, grid, environment), the accumulators of the current view and
// the other views', and the host bookkeeping of errors and warnings. Not wrapped.
#ifndef vsMapperInternals_h
#define vsMapperInternals_h

#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsContext.h"
#include "vsCoverageComposite.h"
#include "vsDenoisePass.h"
#include "vsDeviceEnvironment.h"
#include "vsDirectionTable.h"
#include "vsEmissionAbsorptionPass.h"
#include "vsEnvironmentMap.h"
#include "vsLightVolume.h"
#include "vsMapperEnvironment.h"
#include "vsMonteCarloPass.h"
#include "vsPeelingDeferral.h"
#include "vsPhaseTimes.h"
#include "vsPipelinePrewarm.h"
#include "vsPropertyChecks.h"
#include "vsStrategySelector.h"
#include "vsVisibilityGridUpdater.h"
#include "vsVolumeScene.h"

#include "vtkImageData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <glm/glm.hpp>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkWindow;
class vtkVolumeProperty;

namespace vs
{
namespace mapper
{
// vsMapperMonteCarlo.cxx: the mapper's kernel settings (transport, phase anisotropy, ...) and the surface
// lobe's (issue 38) in Monte Carlo parameters; the preview reads its anisotropy and lobe from them too.
void CopyKernelSettings(vtkVisibilitySweepVolumeMapper* m, vtkVolumeProperty* property, shared::VsMonteCarloParams& p);
void SetSurface(shared::VsMonteCarloParams& p, vtkVolumeProperty* property, double blending,
  const VolumeGeometry& geometry, double densityScale);
}
}

struct vtkVisibilitySweepVolumeMapper::Internals
{
  std::shared_ptr<vs::Context> Context;
  std::unique_ptr<vs::VolumeScene> Scene;
  std::unique_ptr<vs::EmissionAbsorptionPass> EA;
  std::unique_ptr<vs::MonteCarloPass> MC, Interactive;
  std::unique_ptr<vs::MonteCarloPass> MCGrid; // Auto: the TwoStep samples (MC holds Environment's)
  std::shared_ptr<vs::DirectionTable> Table;   // the grid strategies' direction table, shared by the passes
  vs::PipelinePrewarm Prewarm;     // the first frame's render pipeline, made while the scene uploads
  /** Auto: TwoStep's pipeline, made on another thread once the grid has swept a direction, so the
   *  first TwoStep frame does not wait for its creation (a TwoStep frame that comes first waits in
   *  the context's pipeline cache). */
  vs::PipelinePrewarm GridPrewarm;
  vs::PhaseTimes LastFrame; // the last Render()'s host time by phase (GetLastFramePhaseName)
  ~Internals()
  {
    this->Prewarm.Join();
    this->GridPrewarm.Join();
  }
  std::unique_ptr<vs::MonteCarloPass> Tile;   // the tiles of a tiled render (the views' accumulators stay)
  vs::PeelingDeferral Peeling; // inside VTK's depth peeling of volumes: draw at the frame's end instead
  std::unique_ptr<vs::VisibilityGridUpdater> Grid;
  std::unique_ptr<vs::LightVolume> Light; // Preview and AmbientOcclusion: the light reaching each cell
  vs::MapperEnvironment Environment; // port 1's map (or a white sky) on the device
  bool GridNeedsFull = true;          // extinction or geometry changed since the last full sweep
  vs::VolumeGeometry GridGeometry;    // the geometry the grid is computed for (set each frame)
  vs::GridUpdateRequest LastGridRequest;
  vs::StrategySelector Selector;      // Auto: Environment or TwoStep, frame by frame
  double LastRenderSeconds = 0.0;     // device seconds of the last Monte Carlo frame (the sweep budget)
  uint32_t LastRenderSamples = 0;     // its samples per pixel (Auto's time left to a sample target)
  std::vector<double> ImageSignature; // what the accumulated image was rendered for
  vtkSmartPointer<vtkImageData> Radiance;
  // The pixels of Radiance that see the environment under the coverage alpha (VS_BACKGROUND_ENVIRONMENT_COVERAGE):
  // their "Alpha" (and variance) are set to what the opaque image had, so GetRadiance() is unchanged.
  std::vector<uint8_t> EnvironmentPixels;
  vs::CoverageComposite Composite; // the display image, over the environment's display colour
  vtkSmartPointer<vtkImageData> VisibilityImage;
  // The hand-over from the preview drawn while dragging to the accumulation once the view is still
  // (vsPreviewHandOver.h): the last interactive preview of the current view (rgba as the Monte Carlo
  // mean), Pending until the accumulation restarts for the still view, then Active while its share
  // is shown. Any other restart, an interactive Monte Carlo frame or another view ends it.
  struct PreviewImage
  {
    std::vector<float> Rgba;
    uint32_t Width = 0, Height = 0;
    bool Pending = false, Active = false;
    std::chrono::steady_clock::time_point Start; // when it became Active (PreviewHandOverSeconds)
    uint32_t Frames = 1; // preview frames averaged in Rgba (their offsets rotated: dither.h vs_dither_offset)
  } HandOver;
  // DisplayDenoise (vsMapperDenoise.cxx): the filter's guide for the current accumulation (the still
  // preview, Frames of its rotated offsets averaged, or the hand-over's preview once it ended), the
  // filter, and the image shown last (GetDisplayedRadiance).
  struct DenoiseGuide
  {
    std::vector<float> Rgba;
    uint32_t Width = 0, Height = 0, Frames = 0;
  } Guide;
  std::unique_ptr<vs::DenoisePass> Denoise;
  vtkSmartPointer<vtkImageData> Displayed;
  // RenderMode Preview while the view is still (issue 39, item 1): what the frame is of (its parameters
  // but the offsets' rotation, the image's size and depth, the inputs' builds), and the mean of its first
  // Frames frames, each with the pixels' offsets rotated (dither.h): radiance and window image.
  struct StillPreviewImage
  {
    std::vector<uint8_t> Key;
    std::vector<float> Rgba, Display;
    uint32_t Frames = 0;
  } StillPreview;
  // One accumulator per renderer (two views of one volume): MC, MCGrid, Interactive, ImageSignature
  // and Selector above are the current view's; the other views' wait here (SwitchView).
  struct View
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    std::unique_ptr<vs::MonteCarloPass> MC, MCGrid, Interactive;
    std::vector<double> ImageSignature;
    vs::StrategySelector Selector;
    uint64_t GridGeneration = 0; // the grid its selector knows
  };
  vtkWeakPointer<vtkRenderer> CurrentView;
  bool HasCurrentView = false;
  std::vector<View> OtherViews;
  uint64_t GridGeneration() const { return this->Grid ? uint64_t(this->Grid->Generation()) : 0u; }
  void SwitchView(vtkRenderer* ren);
  bool ReleaseViewsOf(vtkWindow* win);
  std::string LastError;
  vs::PropertyChecks Checks; // the settings VisSweep ignores, warned once per change
  vtkMTimeType RenderStamp = 0;       // the inputs' newest modification time, for the Render() in progress
  vtkWeakPointer<vtkRenderer> RenderingView; // the renderer of the Render() in progress
  // Per renderer, the error last logged and RenderStamp then: an error is logged once per change of
  // the inputs in each view (one view failing and another succeeding logged it on every frame).
  struct ViewError
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    std::string Message;
    vtkMTimeType Stamp = 0;
  };
  std::vector<ViewError> ViewErrors;
  // The render mode whose radiance I.Radiance holds (MonteCarlo or Preview; -1: none): a render in a
  // mode that computes none (emission-absorption, ambient occlusion, projections) or another one
  // drops it, so GetRadiance() is never an earlier mode's image.
  int RadianceMode = -1;
  uint32_t Frame = 0;
  RadianceCombiner Combiner; // distributed rendering (SetRadianceCombiner); empty: none
};

#endif
