/**
 * @class   vtkVisibilitySweepVolumeMapper
 * @brief   Physically based volume rendering with Vulkan compute, drawn into VTK's window.
 *
 * A vtkVolumeMapper for vtkImageData. The heavy work runs as Vulkan compute
 * shaders (on lavapipe when there is no GPU); the result is composited into
 * the OpenGL render window over the opaque geometry already drawn: rays stop
 * at the opaque depth, so volumes and polydata actors mix correctly.
 *
 * Render modes:
 * - MonteCarlo (default): unbiased progressive single scattering under an HDR
 *   environment, after R. von Radziewsky, T. Kroes, M. Eisemann and E. Eisemann,
 *   "Efficient stochastic rendering of static and animated volumes using visibility
 *   sweeps", IEEE TVCG 2017 (cited below as von Radziewsky et al. 2017): delta
 *   tracking, a light direction from the sampling
 *   strategy (TwoStep: environment x visibility, then the environment's own quadtree),
 *   ratio-tracked shadow rays. Each Render() adds SamplesPerFrame samples per pixel
 *   until MaximumSamples; any change that alters the image restarts accumulation,
 *   while the visibility grid is recomputed only when extinction changes (data,
 *   opacity, unit distance, density scale, clipping).
 * - EmissionAbsorption: ray casting of VTK's transfer functions (opacity per
 *   ScalarOpacityUnitDistance, colour as emission), a jittered sample per step; ShadeOn: Phong with
 *   the renderer's lights (its automatic headlight included), as vtkGPUVolumeRayCastMapper.
 * - Preview: a noise-free, deterministic ray march of the camera rays (the emission-absorption
 *   pass without jitter) lit from the light volume, the environment light reaching each visibility
 *   cell directly and after up to MaximumScatteringEvents - 1 scatterings in the volume
 *   (vs::LightVolume, PreviewScatteringOrders; interpolated trilinearly): per step,
 *   T (1 - exp(-sigma_t dt)) albedo I / (4 pi), plus T x the environment behind. Biased only by
 *   the grid's resolution and the step; the image the Monte Carlo mode converges to, at the cost
 *   of one emission-absorption render once the grid is swept. The grid (at DirectionResolution)
 *   and the light volume are made when the volume, the environment or its intensity change, never
 *   for a camera move (GetLightVolumeBuildCount()). The renderer's vtkLights (as the Monte Carlo mode
 *   takes them) light each step directly through the light volume's transmittance towards them, and
 *   their multiple scattering is in I; a light's change builds the light volume again (lights that
 *   follow the camera: at the still frames only). With ShadeOn, the Monte Carlo mode's surface lobe
 *   (docs/reference.md). Shown through the display transform as
 *   MonteCarlo (Exposure, ToneMapping, the environment as background), the window image made on
 *   the device with the radiance. Steps of one voxel unless SampleDistance is set, three times
 *   that in an interactive frame (InteractiveUpdateRate), in this mode and in AmbientOcclusion;
 *   each pixel's samples offset by a fixed pattern (no wood-grain rings, nothing random).
 * - AmbientOcclusion: the same march, each sample emitting albedo x EnvironmentIntensity x its
 *   mean visibility (the light volume's alpha, the fraction of unoccluded directions): the preview
 *   under a constant white sky, whatever the environment. Shown as EmissionAbsorption is.
 *
 * Blend modes: COMPOSITE_BLEND renders in the RenderMode. MAXIMUM_INTENSITY_BLEND,
 * MINIMUM_INTENSITY_BLEND, AVERAGE_INTENSITY_BLEND and ADDITIVE_BLEND are projections, not light
 * transport: they render through the emission-absorption path in either RenderMode, as
 * vtkGPUVolumeRayCastMapper computes them (one render per image, SampleDistance apart; additive
 * integrates opacity x normalised scalar per ScalarOpacityUnitDistance). ISOSURFACE_BLEND and
 * SLICE_BLEND are not supported: warned about once, rendered as composite.
 *
 * The vtkVolumeProperty's InterpolationType is honoured everywhere (render, majorants, sweeps):
 * nearest (VTK's default) reads the nearest voxel, so a label map never shows blended labels;
 * linear interpolates trilinearly.
 *
 * The environment is input port 1: SetEnvironmentConnection(reader->GetOutputPort())
 * with a vtkEnvironmentMapReader or vtkEnvironmentMapSource; without one, a constant
 * white sky of radiance 1 lights the volume, and the renderer's background is seen behind it
 * (EnvironmentVisible shows a connected environment only).
 *
 * Conventions (docs/reference.md): world units are those of the image data (origin,
 * spacing, direction matrix) under the vtkVolume's matrix; extinction is
 * sigma_t = -ln(1 - alpha) / unitDistance * DensityScale.
 *
 * Bad input (no scalars, several components, empty extent, a transfer
 * function without points, a volume too large for the device, no Vulkan
 * device) is reported with vtkErrorMacro, and nothing is drawn.
 */
#ifndef vtkVisibilitySweepVolumeMapper_h
#define vtkVisibilitySweepVolumeMapper_h

#include "vissweepRenderingModule.h"
#include "vtkVolumeMapper.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkAlgorithmOutput;
class vtkImageData;
class vtkRenderWindow;
class vtkVolumeProperty;

class VISSWEEPRENDERING_EXPORT vtkVisibilitySweepVolumeMapper : public vtkVolumeMapper
{
public:
  static vtkVisibilitySweepVolumeMapper* New();
  vtkTypeMacro(vtkVisibilitySweepVolumeMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RenderModes
  {
    EmissionAbsorption = 0,
    MonteCarlo = 1,
    Preview = 2,         // single scattering from the light volume, deterministic
    AmbientOcclusion = 3 // albedo x mean visibility, emission-absorption composited
  };
  enum SamplingStrategies
  {
    Uniform = 0,
    Environment = 1,
    Visibility = 2,
    Combined = 3,
    TwoStep = 4,
    Auto = 5 // Environment or TwoStep, chosen by the variance measured while rendering
  };
  enum CellModes
  {
    TrilinearCells = 0,  // interpolate the 8 neighbouring cells' maps (the paper)
    StochasticCell = 1   // pick one cell with its trilinear weight (cheaper, also unbiased)
  };

  ///@{
  /** The render path. Default MonteCarlo. */
  vtkSetClampMacro(RenderMode, int, EmissionAbsorption, AmbientOcclusion);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToEmissionAbsorption() { this->SetRenderMode(EmissionAbsorption); }
  void SetRenderModeToMonteCarlo() { this->SetRenderMode(MonteCarlo); }
  void SetRenderModeToPreview() { this->SetRenderMode(Preview); }
  void SetRenderModeToAmbientOcclusion() { this->SetRenderMode(AmbientOcclusion); }
  const char* GetRenderModeAsString();
  ///@}

  ///@{
  /** The light-direction strategy at scatter events. Default Auto: Environment sampling from the
   *  first frame while the visibility grid fills in between frames (no sweeps for a volume too
   *  thin to shadow), then per frame the better of Environment and TwoStep by the efficiency
   *  1 / (variance x time per sample) measured on earlier frames (under the Sobol sampler TwoStep
   *  must measure 1.25x as efficient per sample: the sampler's strata lower Environment
   *  sampling's error by that much more, which per-sample variances do not show). A choice made from earlier
   *  samples only applies to later ones, so every sample, and their mean, stays unbiased.
   *  GetEffectiveStrategy() tells what the last frame used. */
  vtkSetClampMacro(SamplingStrategy, int, Uniform, Auto);
  vtkGetMacro(SamplingStrategy, int);
  const char* GetSamplingStrategyAsString();
  static const char* GetSamplingStrategyName(int strategy);
  /** The strategy the last Monte Carlo frame sampled with (SamplingStrategy unless that is Auto;
   *  Uniform for a volume empty under the transfer function). */
  vtkGetMacro(EffectiveStrategy, int);
  const char* GetEffectiveStrategyAsString() { return GetSamplingStrategyName(this->EffectiveStrategy); }
  void SetSamplingStrategyToAuto() { this->SetSamplingStrategy(Auto); }
  void SetSamplingStrategyToUniform() { this->SetSamplingStrategy(Uniform); }
  void SetSamplingStrategyToEnvironment() { this->SetSamplingStrategy(Environment); }
  void SetSamplingStrategyToVisibility() { this->SetSamplingStrategy(Visibility); }
  void SetSamplingStrategyToCombined() { this->SetSamplingStrategy(Combined); }
  void SetSamplingStrategyToTwoStep() { this->SetSamplingStrategy(TwoStep); }
  ///@}

  ///@{
  /** How the visibility cells around a scatter point form its map. Default StochasticCell (measured faster at equal error). */
  vtkSetClampMacro(CellMode, int, TrilinearCells, StochasticCell);
  vtkGetMacro(CellMode, int);
  void SetCellModeToTrilinear() { this->SetCellMode(TrilinearCells); }
  void SetCellModeToStochastic() { this->SetCellMode(StochasticCell); }
  const char* GetCellModeAsString();
  ///@}

  ///@{
  /** Shadow rays per scatter point (splitting, 1 to 64): their mean is the sample's light. More
   *  rays lower the part of the variance that comes from the light direction and its transmittance,
   *  at the cost of tracking each; measured on the MRI under a sun (docs/benchmarks.md), 2 rays
   *  break even with 1 at equal time and 4 lose. Default 1. */
  vtkSetClampMacro(ShadowRays, int, 1, 64);
  vtkGetMacro(ShadowRays, int);
  ///@}

  ///@{
  /** With stochastic cells, the grid strategies read each visibility cell's direction map from a
   *  table made once per grid state (a few uint reads per scatter event) instead of building the
   *  D x D map at every scatter event. Both are unbiased and give the same distribution to 1e-4;
   *  the table is faster (docs/benchmarks.md) and costs 8 (D² - 1) / 3 bytes per cell. Off only
   *  for comparisons; trilinear cells always build the map. Default on. */
  vtkSetMacro(DirectionTable, bool);
  vtkGetMacro(DirectionTable, bool);
  vtkBooleanMacro(DirectionTable, bool);
  ///@}

  ///@{
  /** TwoStep's defensive weight alpha in [0, 1]: each shadow direction is an Environment sample
   *  with probability alpha, else a TwoStep sample, scored with the mixture's pdf (one-sample MIS).
   *  Where the grid is wrong (a lit surface point in a cell the grid thinks dark, directions not
   *  swept yet) a sample then weighs at most 1/alpha times an Environment sample. 0 = plain
   *  TwoStep, the default: on the MRI under the sunrise (docs/benchmarks.md) a complete grid gains
   *  nothing from it (variance per sample 0.0159 at 0, 0.0165 at 0.25) and a grid swept only towards
   *  the sun stays worse than Environment sampling with it (0.025 at 0.25, 0.030 at 0, against
   *  0.021). */
  virtual void SetDefensiveWeight(double value); // clamped to [0.0, 1.0]; NaN is refused (an error, the setting kept)
  vtkGetMacro(DefensiveWeight, double);
  ///@}

  ///@{
  /** Full light transport: the most scattering events a path may have (1 = single scattering).
   *  At each event the environment is sampled with the strategy (a ratio-tracked shadow ray) and the
   *  path continues in a direction drawn from the phase function, the two combined by multiple
   *  importance sampling (power heuristic); Russian roulette ends paths long before the limit. At 1,
   *  with ScatteringAnisotropy 0, the single-scattering estimator renders (its images as before full
   *  transport). Values outside [1, 100000] are an error at render time naming the setting (nothing
   *  is rendered). Default 1024: truncation then loses far below 0.5% of the light on every benchmark
   *  scene (docs/benchmarks.md). */
  vtkSetMacro(MaximumScatteringEvents, int);
  vtkGetMacro(MaximumScatteringEvents, int);
  ///@}

  ///@{
  /** The Henyey-Greenstein phase function's anisotropy g, in (-1, 1): g > 0 scatters forward (the
   *  volume glows when seen towards the light), g < 0 backward, 0 isotropically (VTK 9.2's
   *  vtkVolumeProperty::ScatteringAnisotropy has the same meaning). Built against VTK >= 9.2 (as in
   *  ParaView), a mapper value of 0 takes the volume property's ScatteringAnisotropy. A value outside
   *  (-1, 1) or not finite is an error at render time naming the setting. Default 0. The preview models it
   *  towards VTK's lights and for the environment's single scattering (from the light volume's band-1
   *  moment, built when g becomes non-zero; the higher orders stay isotropic: docs/reference.md "The
   *  phase's anisotropy", with its measured bias). */
  vtkSetMacro(ScatteringAnisotropy, double);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /** The preview's multiple scattering (RenderMode Preview, and the Monte Carlo mode's preview while
   *  the user drags): the orders of scattering its light volume computes on the visibility grid's
   *  cells, the orders beyond (up to MaximumScatteringEvents) added as their geometric tail
   *  (vs::LightVolume). 1: single scattering. Made again when it changes, never for a camera move.
   *  Values below 1 count as 1. Default 4 (docs/benchmarks.md, "The preview under full transport"). */
  vtkSetMacro(PreviewScatteringOrders, int);
  vtkGetMacro(PreviewScatteringOrders, int);
  ///@}

  ///@{
  /** Hybrid scattering (issue 38), with the vtkVolumeProperty's ShadeOn in the Monte Carlo mode: a
   *  scattering event is, with a probability that grows with the normalised gradient magnitude and the
   *  opacity, a surface event off the scalar's gradient (Lambert coloured by the colour transfer
   *  function, plus a white GGX lobe: the property's Diffuse and Specular weigh them, SpecularPower sets
   *  the roughness; docs/reference.md "Surface scattering"), else a volumetric one (the phase function).
   *  VTK 9.2's vtkGPUVolumeRayCastMapper::VolumetricScatteringBlending, with its range and direction:
   *  0 (its default) a surface wherever the gradient allows, 1 where it is strong and the medium opaque
   *  (Exposure Render's rule), 2 volumetric only (the image of
   *  ShadeOff, bit for bit). Clamped to [0, 2]. Ignored with ShadeOff. */
  vtkSetClampMacro(VolumetricScatteringBlending, double, 0.0, 2.0);
  vtkGetMacro(VolumetricScatteringBlending, double);
  ///@}

  ///@{
  /** The scattering event from which Russian roulette may end a path (full transport): it then
   *  survives with probability min(max(throughput), 0.95), its throughput divided by it (unbiased;
   *  the cap ends paths of albedo 1 too). Default 4 (docs/benchmarks.md measures 1 to 16). */
  vtkSetClampMacro(RussianRouletteDepth, int, 1, 65535);
  vtkGetMacro(RussianRouletteDepth, int);
  ///@}

  enum MultipleImportanceSamplingModes
  {
    PowerHeuristic = 0,    // light sampling and phase sampling at every event, power heuristic (default)
    LightSamplingOnly = 1, // next-event estimation alone: a continuation that escapes adds nothing
    PhaseSamplingOnly = 2, // the phase-sampled continuation alone: no shadow rays
    BalanceHeuristic = 3   // both, balance heuristic
  };
  ///@{
  /** How the environment seen from a scattering event is estimated under full transport (all
   *  unbiased; the others are for comparisons, docs/benchmarks.md). Default PowerHeuristic. */
  vtkSetClampMacro(MultipleImportanceSampling, int, PowerHeuristic, BalanceHeuristic);
  vtkGetMacro(MultipleImportanceSampling, int);
  void SetMultipleImportanceSamplingToPowerHeuristic() { this->SetMultipleImportanceSampling(PowerHeuristic); }
  void SetMultipleImportanceSamplingToBalanceHeuristic() { this->SetMultipleImportanceSampling(BalanceHeuristic); }
  void SetMultipleImportanceSamplingToLightSamplingOnly() { this->SetMultipleImportanceSampling(LightSamplingOnly); }
  void SetMultipleImportanceSamplingToPhaseSamplingOnly() { this->SetMultipleImportanceSampling(PhaseSamplingOnly); }
  const char* GetMultipleImportanceSamplingAsString();
  ///@}

  ///@{
  /** Benchmarks: next-event estimation only at scattering events LightEventRange[0] ..=
   *  LightEventRange[1] (counted from 1; (0, 0), the default: at every event). With
   *  LightSamplingOnly the image is the light that reaches the camera through those events alone
   *  (vissweep bench overhead --light-events). */
  vtkSetVector2Macro(LightEventRange, int);
  vtkGetVector2Macro(LightEventRange, int);
  ///@}

  enum CameraEstimators
  {
    CollisionCamera = 0, // delta tracking to one real collision (the paper's)
    ReservoirCamera = 1  // ratio tracking; one scatter point resampled from all tentative collisions
  };
  ///@{
  /** How a camera ray finds its scatter point. CollisionCamera: delta tracking to the first real
   *  collision. ReservoirCamera: ratio tracking through the volume, one of its tentative collisions
   *  drawn in proportion to its scattering weight (one shadow ray either way); its alpha is
   *  1 - transmittance instead of 0 or 1. Both unbiased (TestMonteCarlo). Default CollisionCamera. */
  vtkSetClampMacro(CameraEstimator, int, CollisionCamera, ReservoirCamera);
  vtkGetMacro(CameraEstimator, int);
  void SetCameraEstimatorToCollision() { this->SetCameraEstimator(CollisionCamera); }
  void SetCameraEstimatorToReservoir() { this->SetCameraEstimator(ReservoirCamera); }
  const char* GetCameraEstimatorAsString();
  ///@}

  enum Samplers
  {
    IndependentSampler = 0, // every number of every sample from its own hash stream
    SobolSampler = 1        // a pixel's jitter and light directions from its scrambled Sobol sequences
  };
  ///@{
  /** Where a sample's pixel jitter and light direction come from. IndependentSampler: independent
   *  random numbers. SobolSampler: the pixel's own Owen-scrambled Sobol (0,2)-sequences, indexed by
   *  the sample, so a pixel's samples cover its footprint and the light's directions evenly; each
   *  sample stays uniform (unbiased, TestMonteCarlo), the error of the mean falls faster. The
   *  per-sample variance the mapper reports is that of one sample either way. Default SobolSampler
   *  (docs/benchmarks.md: 1.25-1.4x lower error at equal spp with Environment sampling on the MRI). */
  vtkSetClampMacro(Sampler, int, IndependentSampler, SobolSampler);
  vtkGetMacro(Sampler, int);
  void SetSamplerToIndependent() { this->SetSampler(IndependentSampler); }
  void SetSamplerToSobol() { this->SetSampler(SobolSampler); }
  const char* GetSamplerAsString();
  ///@}

  enum ControlExtinctions
  {
    NoControl = 0,         // plain ratio tracking (shadow rays) and delta tracking (camera rays)
    ShadowRayControl = 1,  // residual ratio tracking of the shadow rays (Novak et al. 2014)
    CameraRayControl = 2,  // decomposition tracking of the camera rays (Kutz et al. 2017)
    FullControl = 3        // both
  };
  ///@{
  /** Control extinction: each majorant brick also holds the smallest extinction of its samples; the
   *  trackers integrate that part exactly (an exponential) and track only the rest, at the residual
   *  majorant. Unbiased either way (TestMonteCarlo); it saves volume reads and variance where bricks
   *  are dense throughout, and costs nothing measurable elsewhere. Ignored with cropping regions.
   *  Default ShadowRayControl (docs/benchmarks.md: the camera's control saved nothing measured). */
  vtkSetClampMacro(ControlExtinction, int, NoControl, FullControl);
  vtkGetMacro(ControlExtinction, int);
  const char* GetControlExtinctionAsString();
  ///@}

  enum TransmittanceEstimators
  {
    RatioTracking = 0, // ratio tracking; residual ratio tracking with ShadowRayControl (Novak et al. 2014)
    RayMarching = 1    // the unbiased ray-marching estimator (Kettunen et al. 2021)
  };
  ///@{
  /** The shadow rays' transmittance estimator: RatioTracking (with the default ShadowRayControl,
   *  residual ratio tracking), or Kettunen et al. 2021's unbiased ray marching: a jittered ray march
   *  of the optical depth as the control and a randomly truncated power series of further marches
   *  correcting exp(-march) (with ShadowRayControl the marches integrate the brick's control
   *  exactly). Both unbiased (TestMonteCarlo). Default RatioTracking (docs/benchmarks.md). */
  vtkSetClampMacro(TransmittanceEstimator, int, RatioTracking, RayMarching);
  vtkGetMacro(TransmittanceEstimator, int);
  void SetTransmittanceEstimatorToRatioTracking() { this->SetTransmittanceEstimator(RatioTracking); }
  void SetTransmittanceEstimatorToRayMarching() { this->SetTransmittanceEstimator(RayMarching); }
  const char* GetTransmittanceEstimatorAsString();
  ///@}

  ///@{
  /** Samples per pixel added by each Render() (default 1) and the total to stop at (default 4096). */
  vtkSetClampMacro(SamplesPerFrame, int, 1, 1 << 16);
  vtkGetMacro(SamplesPerFrame, int);
  vtkSetClampMacro(MaximumSamples, int, 1, 1 << 30);
  vtkGetMacro(MaximumSamples, int);
  ///@}

  ///@{
  /** Added to the visibility before it shapes the pdf (von Radziewsky et al. 2017: 0.01). */
  virtual void SetVisibilityEpsilon(double value); // clamped to [1e-6, 1.0]; NaN is refused (an error, the setting kept)
  vtkGetMacro(VisibilityEpsilon, double);
  ///@}

  ///@{
  /** Visibility grid: directions per side (2, 4, 8 or 16, default 8: the renderer's direction
   *  map holds 256 values; other values are refused with an error and the setting is kept),
   *  voxels per cell (1 to 256; 0, the default, is automatic: 4, or 1/56 of the volume's longest
   *  axis when coarser, vs::SweepPlan::AutomaticVoxelsPerCell),
   *  kernel rays (0 = automatic: 1.25 per cell of the longest axis, 2 to 128, coarser than
   *  vtkVisibilityGridFilter's one ray per voxel: the render error is the same at equal spp and
   *  the sweeps are 2.5-6x faster, docs/benchmarks.md), sweep-space filtering (default on) and
   *  its beta/alpha. */
  virtual void SetDirectionResolution(int resolution);
  vtkGetMacro(DirectionResolution, int);
  virtual void SetVoxelsPerCell(double value); // clamped to [0.0, 256.0]; NaN is refused (an error, the setting kept)
  vtkGetMacro(VoxelsPerCell, double);
  vtkSetClampMacro(KernelResolution, int, 0, 1 << 14);
  vtkGetMacro(KernelResolution, int);
  /** Voxels per texel (per axis) of the pooled extinction volume the sweeps march: 0 (default) =
   *  half a cell, 1 = the full-resolution volume. Larger is cheaper and blurs the grid (which only
   *  shapes the pdf: never bias). */
  vtkSetClampMacro(ExtinctionPooling, int, 0, 16);
  vtkGetMacro(ExtinctionPooling, int);
  vtkSetMacro(Filtering, bool);
  vtkGetMacro(Filtering, bool);
  vtkBooleanMacro(Filtering, bool);
  virtual void SetFilterAngleFraction(double value); // clamped to [0.0, 1.0]; NaN is refused (an error, the setting kept)
  vtkGetMacro(FilterAngleFraction, double);
  ///@}

  ///@{
  /** The environment (input port 1): a vtkEnvironmentMapReader / vtkEnvironmentMapSource output. */
  void SetEnvironmentConnection(vtkAlgorithmOutput* port);
  void SetEnvironmentData(vtkImageData* environment);
  ///@}

  ///@{
  /** Scales the environment's radiance. Default 1. Negative values are clamped to 0; values the
   *  device's float cannot hold (above 3.40282e+38, or NaN/Inf) are refused with an error and the
   *  setting is kept (the same for Exposure, DensityScale and SampleDistance). */
  virtual void SetEnvironmentIntensity(double intensity);
  vtkGetMacro(EnvironmentIntensity, double);
  ///@}

  ///@{
  /** Whether camera rays that leave the volume see the environment (default on); off, they are
   *  transparent and the renderer's background shows (the environment still lights the volume).
   *  GetRadiance() holds the full radiance either way: with it on, that of the environment seen
   *  through the volume included. How the environment is drawn: EnvironmentAsBackground.
   *  Only an environment connected to port 1 is shown: without one the default white sky lights the
   *  volume but is not drawn, and the renderer's background (its colour, gradient or texture) shows,
   *  as with vtkGPUVolumeRayCastMapper (issue 38). To see a white sky, connect a
   *  vtkEnvironmentMapSource (Constant, the default); not to be lit by it, set EnvironmentIntensity 0. */
  vtkSetMacro(EnvironmentVisible, bool);
  vtkGetMacro(EnvironmentVisible, bool);
  vtkBooleanMacro(EnvironmentVisible, bool);
  /** Whether camera rays that leave the volume see the environment now: EnvironmentVisible on and an
   *  environment connected to port 1. */
  bool GetShowsEnvironment();
  ///@}

  ///@{
  /** With EnvironmentVisible on (Monte Carlo composite), show the environment the VTK way, as the
   *  renderer's background behind everything (default on): the mapper adds an unpickable vtkSkybox
   *  of a vtkEnvironmentMapBackground (this mapper's environment, EnvironmentIntensity, Exposure and
   *  ToneMapping) to the renderer and removes it when no volume wants it any more; one skybox per
   *  renderer, whatever the number of VisSweep volumes (it shows the first one's environment, in prop
   *  order). Opaque and translucent actors, other mappers' volumes and every VisSweep volume, in any
   *  prop order, are seen in front of it: the volume is composited over what the renderer drew
   *  before it with its coverage (1 - transmittance). Where only the environment is behind it, a
   *  pixel is the tone-mapped full radiance as before (environment seen through the volume included,
   *  tone mapped together); what VTK drew between the environment and the volume shows through with
   *  the volume's transmittance, in display space. A visible vtkSkybox of the user's in the renderer
   *  is taken as the background (none is added). The skybox is added at the renderer's first frame
   *  with the volume, so it is drawn from the second frame on; the first is drawn as with this off.
   *  Off: the old way, the first VisSweep volume drawn in the renderer's frame paints the environment
   *  with its own image, over whatever was drawn before it; the VisSweep volumes drawn after it are
   *  transparent where empty and composite over it. */
  vtkSetMacro(EnvironmentAsBackground, bool);
  vtkGetMacro(EnvironmentAsBackground, bool);
  vtkBooleanMacro(EnvironmentAsBackground, bool);
  /** Whether this mapper shows the environment as the renderer's background now: EnvironmentVisible
   *  and EnvironmentAsBackground on, the Monte Carlo mode and a composite blend mode. */
  bool GetShowsEnvironmentAsBackground();
  ///@}

  ///@{
  /** Display: exposure (a multiplier on radiance, default 1) and the filmic tone curve (default on;
   *  off = clamp). The radiance itself (GetRadiance) is never tone mapped. Output is sRGB. */
  virtual void SetExposure(double exposure);
  vtkGetMacro(Exposure, double);
  vtkSetMacro(ToneMapping, bool);
  vtkGetMacro(ToneMapping, bool);
  vtkBooleanMacro(ToneMapping, bool);
  ///@}

  ///@{
  /** Interaction in the MonteCarlo mode: while the render window's desired update rate is at least
   *  InteractiveUpdateRate (VTK raises it while the user drags), nothing accumulates. With
   *  InteractivePreview on (the default) each frame is the Preview at full resolution, marched at
   *  three times its still step (as vtkGPUVolumeRayCastMapper lengthens its sample distance while
   *  interacting); the first such frame sweeps the whole visibility grid if it is not yet complete.
   *  Off: 1 sample per pixel at 1/InteractiveSubsampling resolution. Once the view is still the
   *  Monte Carlo accumulation starts again (one restart, GetAccumulationResetCount()) and, after a
   *  preview, the window shows the blend (1 - s) x estimate + s x preview of least expected error:
   *  s = V / (V + B), V the estimate's variance, B the preview's squared bias measured as the two
   *  images' mean squared difference less V. s falls as samples come in; below 0.05 the hand-over
   *  ends and the estimate is shown as it is (GetLastPreviewShare() is then 0). The share is also at
   *  most 1 - t / PreviewHandOverSeconds, t the seconds since the still view's accumulation restarted:
   *  however close the preview (under full transport it carries multiple scattering, and its bias can
   *  stay below the estimate's variance for hundreds of samples), the estimate is shown alone within
   *  0.95 PreviewHandOverSeconds (and at the first frame after that). The first still view of a window
   *  with an interactor (a window the user can drag) starts from the preview too, as a still view
   *  after a drag does. GetRadiance() is always the estimate alone. */
  virtual void SetInteractiveUpdateRate(double value); // clamped to [0.0, VTK_DOUBLE_MAX]; NaN is refused (an error, the setting kept)
  vtkGetMacro(InteractiveUpdateRate, double);
  vtkSetClampMacro(InteractiveSubsampling, int, 1, 16);
  vtkGetMacro(InteractiveSubsampling, int);
  vtkSetMacro(InteractivePreview, bool);
  vtkGetMacro(InteractivePreview, bool);
  vtkBooleanMacro(InteractivePreview, bool);
  vtkSetClampMacro(PreviewHandOverSeconds, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PreviewHandOverSeconds, double);
  /** The preview's share s in the image shown last (1 for an interactive preview frame, 0 when
   *  the Monte Carlo estimate is shown alone). */
  vtkGetMacro(LastPreviewShare, double);
  ///@}

  ///@{
  /** Display only (issue 39): with DisplayDenoise on, the window shows the Monte Carlo estimate through
   *  an edge-aware filter guided by the noise-free preview of the same view, a guided filter (He et al.
   *  2010) run on the device (vsDenoisePass.h): in each window of (2 DisplayDenoiseRadius + 1)^2 pixels
   *  the estimate is fitted as a x preview + b per channel, the slope a held near 1 where the
   *  estimate's measured variance cannot resolve it; the pixel shows the windows' mean (a, b) applied to
   *  its preview. Edges of the preview stay sharp and the noise is averaged over the window; what the
   *  preview misses at finer scale than the window is smoothed, a bias that does not fall with samples:
   *  the window shows the blend of least expected error of the filtered image and the estimate (as the
   *  hand-over does with the preview), so the estimate takes over once its noise is below that bias.
   *  The guide is the hand-over's preview
   *  while it lasts, then kept; without one (no drag, no interactor: an offscreen script, the tool) the
   *  still preview is rendered for it (the whole visibility grid and the light volume on the first
   *  frame, then one preview frame per Monte Carlo frame, its offsets rotated, averaged over 4).
   *  GetRadiance() stays the unbiased estimate, bit for bit; GetDisplayedRadiance() is what was shown.
   *  Off by default (docs/reference.md, "The display's filter", has the measured errors). From 2
   *  samples per pixel on, in still frames of the view (not while dragging, not in tiles). */
  vtkSetMacro(DisplayDenoise, bool);
  vtkGetMacro(DisplayDenoise, bool);
  vtkBooleanMacro(DisplayDenoise, bool);
  vtkSetClampMacro(DisplayDenoiseRadius, int, 1, 32);
  vtkGetMacro(DisplayDenoiseRadius, int);
  /** Whether the image shown last was filtered (DisplayDenoise; a share of it above 0), and the filter's
   *  device seconds then. */
  vtkGetMacro(LastDisplayDenoised, bool);
  vtkGetMacro(LastDenoiseSeconds, double);
  /** The linear image the window showed last in the MonteCarlo mode (as GetRadiance(): "Radiance" rgb
   *  and "Alpha", rows bottom-up): the estimate, or its blend with the preview during the hand-over, or
   *  the filtered estimate with DisplayDenoise; nullptr before the first still Monte Carlo frame. What
   *  the benchmarks compare with a converged render (`vissweep bench denoise`). */
  vtkImageData* GetDisplayedRadiance();
  ///@}

  /** Samples per pixel accumulated so far (Monte Carlo) in the view rendered last. Each renderer
   *  showing the volume (two views of it, in one window or two) has its own accumulator, so every
   *  view converges; the visibility grid is shared. */
  vtkGetMacro(AccumulatedSamples, int);
  /** True when MaximumSamples are reached: further Render() calls only redraw. Also true after an
   *  emission-absorption render or a projection (blend modes MIP, MinIP, average, additive), whose
   *  one render is the whole image, so a loop `while not IsConverged(): Render()` ends in every mode. */
  bool IsConverged()
  {
    return this->LastRenderComplete || this->AccumulatedSamples >= this->MaximumSamples;
  }

  /** Renders `window` (which shows this mapper's volume) until the view is converged (IsConverged():
   *  MaximumSamples reached, or the one render of a deterministic mode or projection), in one call:
   *  where vtkGPUVolumeRayCastMapper's one Render() is the whole image, this mapper's adds only
   *  SamplesPerFrame samples per pixel. With `timeBudgetSeconds` > 0 it also stops before a frame that
   *  would end after that many seconds (predicted per sample as the longest of the last three frames,
   *  vs::FrameTimePredictor; at least one frame is rendered). It stops, too, after a render that failed (GetLastError()) or three frames that added
   *  no sample (an interactive frame, a window that does not show the volume). Returns the samples per
   *  pixel accumulated (GetAccumulatedSamples()); a vtkWindowToImageFilter with ShouldRerenderOff()
   *  then grabs the image. */
  int RenderUntilConverged(vtkRenderWindow* window, double timeBudgetSeconds = 0.0);

  /**
   * Starts making the Monte Carlo render kernel on another thread before the volume is read, so that
   * its compile (0.7-0.9 s on lavapipe, 2 cores) overlaps the read instead of delaying the first frame
   * (issue 39). `shape` holds the volume's extent, spacing, origin and direction and no scalars yet
   * (what a reader tells after UpdateInformation()); `scalarType` (VTK_UNSIGNED_CHAR, ...) and the range
   * [rangeMin, rangeMax] are the scalars' as far as known before reading (an 8-bit type's own range;
   * for other types e.g. the transfer function's), with the volume's property and this mapper's
   * settings as they will be at the first render. The first render uses the kernel when the guess
   * matches what the data turns out to be and makes its own otherwise: a wrong guess costs only the
   * other thread's work. `renderer`, if given, is the renderer the volume will be shown in, with its
   * lights as they will be at the first render (the kernel is made for a scene with VTK's lights or
   * for one without; null: without). Does nothing outside the MonteCarlo mode, after the first render,
   * or on a second call; needs no render window. `vissweep render` calls it from the volume file's
   * header.
   */
  void PrecompileRenderKernel(vtkVolume* volume, vtkImageData* shape, int scalarType, double rangeMin, double rangeMax,
    vtkRenderer* renderer = nullptr);

  /** The linear HDR radiance of the last render (of the view rendered last) as image data (width x height, point array
   *  "Radiance" with 3 floats and "Alpha"), rows bottom-up; nullptr before the first render. It is what
   *  the last render computed, or nothing: nullptr after a failed render and after a render in a mode
   *  that computes no radiance (EmissionAbsorption, AmbientOcclusion, the projection blend modes), and
   *  a switch between MonteCarlo and Preview drops the other mode's image (while the user drags in the
   *  MonteCarlo mode it stays the view's estimate).
   *  With `variance`, also "Variance" (per-sample variance of each channel, 4 components, double). */
  vtkImageData* GetRadiance(bool variance = false);

  /** The visibility grid the renderer uses, as vtkVisibilityGridFilter outputs it (nullptr before
   *  the first Monte Carlo render with a visibility-based strategy). */
  vtkImageData* GetVisibilityGrid();

  enum UpdateSchemes
  {
    FullUpdate = 0,        // every direction
    RoundRobin = 1,        // the next DirectionsPerFrame directions of the bit-reversed Morton order
    EnvironmentGuided = 2, // DirectionsPerFrame distinct directions drawn from the environment's importance
    StaticUpdate = 3       // every direction at every StaticInterval-th data change, none in between
  };

  ///@{
  /** Lazy visibility updates for animated volumes (von Radziewsky et al. 2017, Sec. 9). When only the volume's
   *  data changed (a new time step: same geometry, grid parameters, clipping planes and transfer
   *  function), the scheme chooses which directions of the visibility grid to sweep again; the
   *  others keep visibility of earlier data. That changes the variance, never the mean: the
   *  grid only shapes the sampling pdf. Any other change that alters extinction or the grid's
   *  layout recomputes every direction, and so does the first computation. Majorants are
   *  always recomputed for new data and accumulation restarts. Default RoundRobin (the
   *  paper's most robust scheme); k =
   *  DirectionsPerFrame (default 4); StaticInterval default 16. The MonteCarlo mode only: the
   *  Preview and AmbientOcclusion images are the grid's light, not estimates, so in them a data
   *  change (or a grid left stale by earlier lazy updates) recomputes every direction, as a fresh
   *  mapper would. */
  vtkSetClampMacro(UpdateScheme, int, FullUpdate, StaticUpdate);
  vtkGetMacro(UpdateScheme, int);
  void SetUpdateSchemeToFull() { this->SetUpdateScheme(FullUpdate); }
  void SetUpdateSchemeToRoundRobin() { this->SetUpdateScheme(RoundRobin); }
  void SetUpdateSchemeToEnvironmentGuided() { this->SetUpdateScheme(EnvironmentGuided); }
  void SetUpdateSchemeToStatic() { this->SetUpdateScheme(StaticUpdate); }
  const char* GetUpdateSchemeAsString();
  vtkSetClampMacro(DirectionsPerFrame, int, 1, 4096);
  vtkGetMacro(DirectionsPerFrame, int);
  vtkSetClampMacro(StaticInterval, int, 1, VTK_INT_MAX);
  vtkGetMacro(StaticInterval, int);
  ///@}

  ///@{
  /** Combined and TwoStep sample a direction of the grid with probability proportional to
   *  visibility x environment importance, so a direction whose environment has no light at
   *  the grid's resolution (e.g. the black ground of a sky-only map) is never sampled and its
   *  visibility never read. On (default): such directions are not swept, and swept only when
   *  a new environment or another strategy needs them; the image is the same bit for bit.
   *  UnlitDirections: how many the last Render() left out (0 with other strategies). */
  vtkSetMacro(SkipUnlitDirections, bool);
  vtkGetMacro(SkipUnlitDirections, bool);
  vtkBooleanMacro(SkipUnlitDirections, bool);
  vtkGetMacro(UnlitDirections, int);
  ///@}

  ///@{
  /** Progressive visibility (default on): a new visibility grid starts at visibility 1 in every
   *  direction (where TwoStep is exactly environment sampling) and fills in between frames: the
   *  first frame sweeps nothing, each later one sweeps the next directions, brightest
   *  environment first, for at most SweepFrameFraction of the previous frame's render time (and
   *  at least one direction). Accumulation does not restart as the grid fills in: samples of
   *  every stage are unbiased and averaged with equal weights. Off: every needed direction is
   *  swept before the frame that needs it. PendingDirections: directions still to sweep. */
  vtkSetMacro(ProgressiveVisibility, bool);
  vtkGetMacro(ProgressiveVisibility, bool);
  vtkBooleanMacro(ProgressiveVisibility, bool);
  virtual void SetSweepFrameFraction(double value); // clamped to [0.0, 1000.0]; NaN is refused (an error, the setting kept)
  /** Auto's sweep share of the time until TwoStep has measured more efficient than Environment
   *  sampling; then half of the measured gain (efficiency ratio - 1), at least this and at most
   *  SweepFrameFraction. Default 0.05. */
  virtual void SetAutoProbeFraction(double value); // clamped to [0.0, 1000.0]; NaN is refused (an error, the setting kept)
  vtkGetMacro(AutoProbeFraction, double);
  /** The seconds left before the loop that renders this view stops (a time budget's remainder), set
   *  before each frame by RenderUntilConverged, `vissweep render --time-budget` and ParaView's
   *  TimeBudget; 0 or less (the default): no deadline, an interactive view. Auto then fills its grid
   *  in only while the sweeps still pending can pay for themselves before the deadline
   *  (StrategySelector::AffordableSweepSeconds; README, "Auto"): at 2 s the 0.5 mm MRI's grid
   *  cannot, and Auto renders Environment sampling without sweeping. The samples left to
   *  MaximumSamples, at the last frame's cost, are a deadline too (the nearer one counts): a
   *  converged view sweeps nothing more. A loop's own state: setting
   *  it does not modify the mapper (no restart); +Inf is no deadline, NaN is refused (an error,
   *  the setting kept). */
  void SetRemainingTimeBudget(double seconds);
  double GetRemainingTimeBudget() const { return this->RemainingTimeBudget; }
  /** Sweep each direction texel towards where its light comes from (the environment's
   *  luminance-weighted mean direction inside the texel) instead of its centre: the visibility
   *  of a sun's texel is then the sun's own. Default on. The grid then depends on the
   *  environment: a new or rotated environment sweeps the grid again (progressively). */
  vtkSetMacro(LightWeightedDirections, bool);
  vtkGetMacro(LightWeightedDirections, bool);
  vtkBooleanMacro(LightWeightedDirections, bool);
  /** While the grid fills in, its directions not swept yet read, in every cell, the visibility of
   *  the nearest swept direction instead of 1 (fully visible). Either is unbiased (the grid only
   *  shapes the pdf); at 1, an unswept sky beside a swept sun that a cell sees shadowed makes
   *  TwoStep sample the sun too rarely at lit points of that cell. Default on. */
  vtkSetMacro(FillUnsweptDirections, bool);
  vtkGetMacro(FillUnsweptDirections, bool);
  vtkBooleanMacro(FillUnsweptDirections, bool);
  vtkGetMacro(SweepFrameFraction, double);
  int GetPendingDirections();
  ///@}

  ///@{
  /** Directions of the visibility grid swept by the last Render() (0 when none; D*D for a full
   *  update) and by all renders so far. */
  vtkGetMacro(DirectionsUpdatedLastFrame, int);
  vtkGetMacro(DirectionsUpdatedTotal, int);
  ///@}

  ///@{
  /** Cost of bringing the device up to date in the last Render(): host wall seconds of the
   *  volume upload, majorants and sweeps (0 when nothing changed), and the sweeps' device seconds. */
  vtkGetMacro(LastUpdateSeconds, double);
  vtkGetMacro(LastFrameSweepSeconds, double);
  ///@}

  ///@{
  /** Counters of the work done, to check that a change costs only what it must.
   *  VisibilityUpdateCount: renders that swept visibility (all directions or a lazy subset). */
  vtkGetMacro(VisibilityUpdateCount, int);
  vtkGetMacro(AccumulationResetCount, int);
  vtkGetMacro(EnvironmentUploadCount, int);
  int GetMajorantUpdateCount();
  ///@}

  /** Device seconds of the last sweeps (visibility grid computation). */
  vtkGetMacro(LastSweepSeconds, double);

  ///@{
  /** The direction table (SetDirectionTable): times it was built (once per grid state the grid
   *  strategies render with), and the device seconds of the last build (part of
   *  GetLastDeviceSeconds() in the frame that built it). */
  vtkGetMacro(DirectionTableBuildCount, int);
  /** Builds of the light volume (the Preview and AmbientOcclusion modes): it is made again only when
   *  the grid's values, the environment or its intensity change. */
  vtkGetMacro(LightVolumeBuildCount, int);
  vtkGetMacro(LastDirectionTableSeconds, double);
  ///@}

  ///@{
  /** Ray-marching step of the EmissionAbsorption, Preview and AmbientOcclusion modes in world
   *  units; 0 (default) = half the smallest voxel edge in EmissionAbsorption, the smallest voxel
   *  edge in the lit modes (whose error is the light volume's, not the step's). The MonteCarlo mode
   *  does not use it: delta and ratio tracking sample the exact free-flight distances and
   *  transmittance, so no step size enters the estimate. */
  virtual void SetSampleDistance(double distance);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /** vtkGPUVolumeRayCastMapper's AutoAdjustSampleDistances, for pipelines that swap that mapper for
   *  this one: accepted and printed, but it has no effect. VisSweep always lengthens the deterministic
   *  modes' step threefold while the user drags (InteractiveUpdateRate) and the Monte Carlo estimate
   *  has no step; turning it off is warned about once per change. Default on, as in VTK. */
  vtkSetMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkGetMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkBooleanMacro(AutoAdjustSampleDistances, vtkTypeBool);
  ///@}

  ///@{
  /** Multiplies the extinction of the transfer function. Default 1. */
  virtual void SetDensityScale(double scale);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /** Seed of the counter-based random numbers (0 to VTK_INT_MAX): a fixed seed reproduces an
   *  image bit for bit. */
  vtkSetClampMacro(Seed, int, 0, VTK_INT_MAX);
  vtkGetMacro(Seed, int);
  ///@}

  /** Renders the volume into the renderer's viewport; TimeToDraw is then its wall seconds.
   *  Settings VisSweep does not honour (gradient opacity, shading, the iso-surface and slice blend
   *  modes, depth peeling for volumes: drawn after the peels, over the translucent geometry, as with
   *  it off) are warned about once per change;
   *  an error is logged once per change too (GetLastError() holds it on every failed render). */
  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  /** Forgets the accumulators of the views (renderers) in this window; when no view in another
   *  window remains, frees the device resources too: the next Render() re-creates them and
   *  accumulates anew. The last GetRadiance() (no variance) and GetVisibilityGrid() stay on the
   *  host, e.g. after the window goes (the grid only with ReleaseKeepsVisibilityGrid). */
  void ReleaseGraphicsResources(vtkWindow*) override;
  /** Whether releasing the device resources keeps the visibility grid on the host for a later
   *  GetVisibilityGrid() (default on): it completes the directions still pending and downloads the
   *  grid first, which costs a program that has no more use for it, at exit, up to a second of
   *  sweeps on a large volume (issue 39: `vissweep render` turns it off). */
  vtkSetMacro(ReleaseKeepsVisibilityGrid, bool);
  vtkGetMacro(ReleaseKeepsVisibilityGrid, bool);
  vtkBooleanMacro(ReleaseKeepsVisibilityGrid, bool);

  /** Device seconds of the last render pass (0 if the device has no timestamps). */
  vtkGetMacro(LastDeviceSeconds, double);
  /** Scattering events per path in the view's accumulation so far (full transport: the paths' mean
   *  length; camera rays that miss the volume count 0). Single scattering (MaximumScatteringEvents 1,
   *  ScatteringAnisotropy 0) reports 1 without counting. */
  vtkGetMacro(MeanScatteringEvents, double);
  /** Device seconds of the last majorant update (brick ranges; runs when the data changes). */
  vtkGetMacro(LastMajorantSeconds, double);

  ///@{
  /** Where the last Render()'s host wall-clock time went, phase by phase in the order they ran (a
   *  first frame's fixed cost, issue 39): "scene" (bringing the volume and transfer function to the
   *  device; when it did work, its parts follow as "scene.convert", "scene.upload", "scene.ranges",
   *  "scene.table", "scene.majorants"), then in the Monte Carlo mode "environment", "grid" (the
   *  visibility grid's update), "frame" (the frame's parameters and depth), "pipeline" (waiting for
   *  the render pipeline made on another thread), "render" (the render pass: its pipeline, the
   *  dispatch and the wait for it) and "display" (the mean, tone mapping, the window's image).
   *  The parts ("scene.*") are inside "scene": sum only the names without a dot. */
  int GetNumberOfLastFramePhases();
  const char* GetLastFramePhaseName(int i);
  double GetLastFramePhaseSeconds(int i);
  ///@}

  ///@{
  /** Benchmarks: render Monte Carlo frames with an instrumented kernel that counts its reads
   *  (same samples, slower; r8 visibility grids only; 32-bit counters, so count frames of a
   *  few samples per pixel). LastLookupCounts = (trilinear volume samples, majorant-brick
   *  loads, visibility-texel loads) of the last frame; LastLaneOccupancy = the tracking steps its
   *  lanes took over the steps their SIMD groups ran times the group's width (1 = no lane waited
   *  for another; divergence lowers it). Off by default. */
  vtkSetMacro(CountLookups, bool);
  vtkGetMacro(CountLookups, bool);
  vtkBooleanMacro(CountLookups, bool);
  vtkGetVector3Macro(LastLookupCounts, double);
  vtkGetMacro(LastLaneOccupancy, double);
  /** Of the last counted frame: the shadow rays traced and those with transmittance below 0.01. */
  vtkGetVector2Macro(LastShadowRayCounts, double);
  ///@}
  /** Times the volume was uploaded to the device (changes only when the input changes). */
  vtkGetMacro(VolumeUploadCount, int);

  ///@{
  /** Picking (vtkHardwareSelector, vtkPropPicker, vtkRenderer::PickProp): in a selection pass the
   *  volume draws the selector's prop colour where its opacity along the pixel's ray exceeds 3/255
   *  (as vtkGPUVolumeRayCastMapper does; the opacity is the emission-absorption pass's, the same
   *  extinction the Monte Carlo mode tracks) and nothing else; no accumulator is touched. The point
   *  and cell id passes get the id of the voxel (the nearest point, or the cell holding it) where
   *  the pixel's ray first exceeds that opacity, marched on the host (clipping planes and the
   *  cropped box honoured; cropping regions other than one box are not).
   *  SelectionRenderCount: selection passes drawn so far. */
  vtkGetMacro(SelectionRenderCount, int);
  ///@}

  ///@{
  /** Tiled renders (vtkWindowToImageFilter with a Scale above 1, or a window's TileScale): each tile
   *  is rendered in one Render() into an accumulator of its own with as many samples per pixel as
   *  the view has accumulated (at least SamplesPerFrame, at most MaximumSamples), so a tiled
   *  screenshot is as converged as the view, and the view's accumulator is left as it was (it does
   *  not restart, before or after). TileRenderCount: tiles rendered so far. */
  vtkGetMacro(TileRenderCount, int);
  ///@}
#if !defined(__VTK_WRAP__)
  ///@{
  /** Distributed rendering: several processes render the same view of the whole volume, each with
   *  its own Seed, and show the mean of all their samples (ParaView's pvbatch or pvserver under MPI,
   *  ParaView/Plugin/Representation). A combiner, when set, is called after each still Monte Carlo
   *  frame and each tile with this process's mean radiance (RGBA per pixel, as GetRadiance() holds it,
   *  rows bottom-up) and the samples per pixel behind it; it replaces the mean with the mean of all
   *  processes' samples (each process's weighted by its samples) and returns their total. The image
   *  drawn, GetRadiance() and the preview hand-over then use the combined mean; GetAccumulatedSamples()
   *  and IsConverged() stay this process's own. It is called in every such frame, so a combiner that
   *  communicates needs every process to render the frame. Not called in interactive frames, nor in
   *  the other modes (their images are deterministic, or drawn by one process). Default: none. */
  using RadianceCombiner = std::function<uint32_t(std::vector<float>& meanRgba, uint32_t samples)>;
  void SetRadianceCombiner(RadianceCombiner combiner);
  ///@}
#endif
  ///@{
  /** Off: render (and accumulate) as usual but draw nothing of the volume's image into the window:
   *  the processes of a distributed render other than the one that shows the combined image. A
   *  skybox added for EnvironmentAsBackground is still drawn: turn that off too. Default on. */
  vtkSetMacro(DrawImage, bool);
  vtkGetMacro(DrawImage, bool);
  vtkBooleanMacro(DrawImage, bool);
  ///@}
  /** The last error reported with vtkErrorMacro, or "" after a successful render. */
  const char* GetLastError();

  /** The input's bounds, uninitialised when they are not finite (NaN or infinite spacing or
   *  origin): VTK's culler dropped such a volume before Render(), so nothing was drawn and
   *  nothing said; now Render() runs and reports the error (once per change). */
  double* GetBounds() VTK_SIZEHINT(6) override;
  void GetBounds(double bounds[6]) override { this->vtkVolumeMapper::GetBounds(bounds); }

protected:
  vtkVisibilitySweepVolumeMapper();
  ~vtkVisibilitySweepVolumeMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  int RenderMode = MonteCarlo;
  int SamplingStrategy = Auto;
  int EffectiveStrategy = Environment;
  bool ProgressiveVisibility = true;
  bool ReleaseKeepsVisibilityGrid = true;
  double SweepFrameFraction = 0.25;
  bool LightWeightedDirections = true;
  bool FillUnsweptDirections = true;
  double AutoProbeFraction = 0.05;
  double RemainingTimeBudget = 0.0; // seconds; <= 0: no deadline
  int CellMode = StochasticCell;
  int ShadowRays = 1;
  bool DirectionTable = true;
  double DefensiveWeight = 0.0;
  int MaximumScatteringEvents = 1024;
  int PreviewScatteringOrders = 4;
  double ScatteringAnisotropy = 0.0;
  double VolumetricScatteringBlending = 0.0; // issue 38
  int DirectionTableBuildCount = 0;
  int LightVolumeBuildCount = 0;
  double LastDirectionTableSeconds = 0.0;
  int CameraEstimator = CollisionCamera;
  int ControlExtinction = ShadowRayControl;
  int TransmittanceEstimator = RatioTracking;
  int Sampler = SobolSampler;
  int SamplesPerFrame = 1;
  int MaximumSamples = 4096;
  double VisibilityEpsilon = 0.01;
  int DirectionResolution = 8;
  double VoxelsPerCell = 0.0; // automatic
  int KernelResolution = 0;
  int ExtinctionPooling = 0;
  bool Filtering = true;
  double FilterAngleFraction;
  double EnvironmentIntensity = 1.0;
  bool EnvironmentVisible = true;
  bool EnvironmentAsBackground = true;
  double Exposure = 1.0;
  bool ToneMapping = true;
  double InteractiveUpdateRate = 1.0;
  int InteractiveSubsampling = 4;
  bool InteractivePreview = true;
  double PreviewHandOverSeconds = 3.0;
  double LastPreviewShare = 0.0;
  bool DisplayDenoise = false;
  int DisplayDenoiseRadius = 6;
  bool LastDisplayDenoised = false;
  double LastDenoiseSeconds = 0.0;
  int AccumulatedSamples = 0;
  bool LastRenderComplete = false; // the last render was emission-absorption or a projection
  int VisibilityUpdateCount = 0;
  int UpdateScheme = RoundRobin;
  int DirectionsPerFrame = 4;
  int StaticInterval = 16;
  bool SkipUnlitDirections = true;
  int UnlitDirections = 0;
  int DirectionsUpdatedLastFrame = 0;
  int DirectionsUpdatedTotal = 0;
  double LastUpdateSeconds = 0.0;
  double LastFrameSweepSeconds = 0.0;
  int AccumulationResetCount = 0;
  int EnvironmentUploadCount = 0;
  double LastSweepSeconds = 0.0;
  double SampleDistance = 0.0;
  vtkTypeBool AutoAdjustSampleDistances = 1;
  double DensityScale = 1.0;
  int Seed = 1;
  double LastDeviceSeconds = 0.0;
  double LastMajorantSeconds = 0.0;
  bool CountLookups = false;
  double LastLookupCounts[3] = { 0.0, 0.0, 0.0 };
  double LastLaneOccupancy = 1.0;
  double MeanScatteringEvents = 0.0;
  double LastShadowRayCounts[2] = { 0.0, 0.0 };
  int MultipleImportanceSampling = PowerHeuristic;
  int RussianRouletteDepth = 4;
  int LightEventRange[2] = { 0, 0 };
  int VolumeUploadCount = 0;
  int SelectionRenderCount = 0;
  int TileRenderCount = 0;
  bool DrawImage = true;

private:
  vtkVisibilitySweepVolumeMapper(const vtkVisibilitySweepVolumeMapper&) = delete;
  void operator=(const vtkVisibilitySweepVolumeMapper&) = delete;

  void ReportError(const std::string& message);
  bool SetFloatSetting(const char* name, double value, double& setting);
  // A setting clamped to [lo, hi] as vtkSetClampMacro does, except that NaN (which passes any clamp)
  // is refused with an error and the setting kept (issue 35: InteractiveUpdateRate took NaN).
  void SetClampedSetting(const char* name, double value, double lo, double hi, double& setting);
  void RenderAndCheck(vtkRenderer* ren, vtkVolume* vol);
  void RenderEmissionAbsorption(vtkRenderer* ren, vtkVolume* vol);
  std::vector<float> EmissionAbsorptionImage(vtkRenderer* ren, vtkVolume* vol);
  void RenderSelection(vtkRenderer* ren, vtkVolume* vol);
  void RenderMonteCarlo(vtkRenderer* ren, vtkVolume* vol);
  /** Preview (`preview`) and AmbientOcclusion: the emission-absorption pass lit from the light
   *  volume, at three times the step in an interactive frame. `interactive`: a preview frame while the
   *  user drags in the MonteCarlo mode (GetRadiance() is left as it is, the image kept for the
   *  hand-over). */
  void RenderLit(vtkRenderer* ren, vtkVolume* vol, bool preview, bool interactive, uint32_t ditherFrame = 0,
    std::vector<float>* guide = nullptr);
  /** DisplayDenoise (vsMapperDenoise.cxx): the guide's next frame for a still w x h view (nothing once it
   *  has its frames or the hand-over's preview guides), and the filter of the image shown. */
  void UpdateDenoiseGuide(vtkRenderer* ren, vtkVolume* vol, uint32_t w, uint32_t h);
  void DenoiseDisplay(std::vector<float>& shown, const std::vector<double>& variance, uint32_t samples,
    double previewShare, uint32_t w, uint32_t h);
  /** Whether this frame of `ren` is an interactive one (the window's desired update rate at least
   *  InteractiveUpdateRate, not a tile of a tiled render). */
  bool IsInteractiveFrame(vtkRenderer* ren) const;
  bool StartsWithoutPreview(vtkRenderer* ren);
  bool RefinesHandOverPreview(vtkRenderer* ren);
  uint32_t HandOverPreviewFrames() const;
  /** Port 1's environment (or the white sky) on the device at DirectionResolution. */
  void UpdateEnvironmentInput();
  /** Starts making the first frame's render pipeline on another thread (the scene's conversion
   *  and upload keep this one busy meanwhile): the strategy's, or Environment sampling's for Auto. */
  void StartPrewarm(vtkImageData* input, vtkVolume* volume, vtkDataArray* scalars, vtkRenderer* renderer);
  void UpdateVisibilityGrid(bool needGrid, bool usesGridOnly);
  void NoteSweeps(unsigned int directions, double deviceSeconds, double wallSeconds);
  void CompleteVisibilityGrid();
  uint32_t AccumulatedSamplesOf(bool autoStrategy);
  std::vector<float> CombinedMean(bool autoStrategy);
  std::vector<double> CombinedVariance(bool autoStrategy);
  float OpaqueAlpha(bool autoStrategy);

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
