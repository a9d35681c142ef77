/**
 * @class   vtkVisSweepVolumeRepresentation
 * @brief   ParaView's image volume representation, rendered with vtkVisibilitySweepVolumeMapper.
 *
 * A vtkImageVolumeRepresentation whose volume mapper is VisSweep's: the transfer functions, the
 * scalar opacity unit distance, interpolation, cropping and the blend mode come from ParaView's
 * own volume controls (the superclass passes them to the mapper as it does to its own mappers);
 * this class adds VisSweep's settings, forwarded to the mapper, and the environment, read from a
 * file by a vtkEnvironmentMapReader (no file: the mapper's constant white sky).
 *
 * In the Monte Carlo mode the colour transfer function is the single-scattering albedo, not an
 * emission (docs/reference.md). Each still render adds SamplesPerFrame samples per pixel until
 * MaximumSamples, or until the TimeBudget is spent; GetAccumulatedSamples() and IsConverged() say
 * how far it got.
 *
 * Distributed (pvbatch or pvserver under MPI, N > 1 processes): light transport needs the whole
 * volume at every scattering event, so every process gathers the pieces ParaView gives the others
 * (RequestData) and renders the whole volume with a seed of its own and its share of
 * MaximumSamples (MaximumSamples / N, the first MaximumSamples % N one more); after each still
 * frame the processes average their mean radiance (weighted by their samples) and only the first
 * draws it, so ParaView's compositing passes it through. N processes thus add N x SamplesPerFrame
 * samples per pixel per frame, and AccumulatedSamples and Converged report all of them. The
 * environment lights the volume but is not drawn behind it (EnvironmentVisible is taken as off,
 * with a warning): ParaView's compositing keeps of each process's image only the pixels inside its
 * data's projected bounds. docs/paraview.md says more.
 *
 * Bad settings are reported in ParaView's output window and crash nothing: an environment file
 * that cannot be read is an error of the reader and the mapper (the volume is not drawn until the
 * name is fixed or cleared), a value the device cannot hold (NaN, infinite) an error of the mapper
 * (the setting is kept), and a value outside a setting's range a warning naming the setting and
 * the value the mapper clamps it to.
 */
#ifndef vtkVisSweepVolumeRepresentation_h
#define vtkVisSweepVolumeRepresentation_h

#include "vissweepParaViewRepresentationModule.h"
#include "vtkImageVolumeRepresentation.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkEnvironmentMapReader;
class vtkEnvironmentMapSource;
class vtkVisibilitySweepVolumeMapper;

class VISSWEEPPARAVIEWREPRESENTATION_EXPORT vtkVisSweepVolumeRepresentation
  : public vtkImageVolumeRepresentation
{
public:
  static vtkVisSweepVolumeRepresentation* New();
  vtkTypeMacro(vtkVisSweepVolumeRepresentation, vtkImageVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Forwarded to vtkVisibilitySweepVolumeMapper (its documentation says what each does). */
  void SetVisSweepRenderMode(int mode);
  void SetSamplingStrategy(int strategy);
  void SetSamplesPerFrame(int samples);
  void SetMaximumSamples(int samples);
  void SetEnvironmentIntensity(double intensity);
  void SetEnvironmentVisible(bool visible);
  void SetExposure(double exposure);
  void SetToneMapping(bool toneMapping);
  void SetSeed(int seed);
  void SetMaximumScatteringEvents(int events);
  void SetScatteringAnisotropy(double g);
  void SetMultipleImportanceSampling(int mode);
  ///@}

  ///@{
  /** The environment: a lat-long .exr/.hdr file, or empty (default) for the white sky. */
  void SetEnvironmentFileName(const char* fileName);
  const char* GetEnvironmentFileName() { return this->EnvironmentFileName.c_str(); }
  /** Rotation of the environment file about +Z, in degrees. */
  void SetEnvironmentRotation(double degrees);
  ///@}

  ///@{
  /** A time budget for the still view's accumulation, in seconds; 0 (the default) is none:
   *  MaximumSamples alone ends it. The mapper has no clock of its own (its progressive stop is
   *  MaximumSamples), so the representation keeps one: before each render (ParaView's render
   *  request) it adds up the still frames of the current accumulation (their render times, the
   *  mapper's TimeToDraw; distributed, the slowest process's), and when that sum plus the next
   *  frame's expected time (the last frame's, less its visibility update, as the vissweep tool's
   *  --time-budget predicts it) would exceed the budget, it holds the mapper's MaximumSamples at the
   *  samples reached: further renders only redraw and IsConverged() is true. The first frame of an
   *  accumulation always renders. Anything that restarts the accumulation (the camera, a transfer
   *  function, a setting) restarts the clock; a larger budget (or a larger MaximumSamples within it)
   *  resumes refinement. Distributed, every process decides from the same (reduced) times, so all
   *  stop at the same frame. Negative or NaN: a warning, and 0 is used. Monte Carlo mode only. */
  void SetTimeBudget(double seconds);
  double GetTimeBudget() { return this->TimeBudget; }
  /** Seconds of rendering the current accumulation has taken (its still frames summed, as the
   *  budget counts them); 0 before the first still frame. */
  double GetAccumulationTime() { return this->AccumulationSeconds; }
  ///@}

  /** Samples per pixel accumulated in the view rendered last (all processes' when distributed),
   *  and whether they reached MaximumSamples or spent the TimeBudget. */
  int GetAccumulatedSamples();
  bool IsConverged();
  /** The mapper's last error ("" after a successful render). */
  const char* GetLastError();

#if !defined(__VTK_WRAP__)
  /** The mapper (for tests and C++ users). */
  vtkVisibilitySweepVolumeMapper* GetVisSweepMapper();
#endif

  /** The processes that render the view together (1 unless under MPI). */
  int GetNumberOfRenderingProcesses() { return this->Processes; }

protected:
  vtkVisSweepVolumeRepresentation();
  ~vtkVisSweepVolumeRepresentation() override;

  /** The superclass's piece, then, when distributed, the whole volume gathered from every process. */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** The superclass's settings, then EnvironmentVisible off when distributed; then the time budget
   *  (called before every render, ParaView's REQUEST_RENDER). */
  void UpdateMapperParameters() override;

private:
  vtkVisSweepVolumeRepresentation(const vtkVisSweepVolumeRepresentation&) = delete;
  void operator=(const vtkVisSweepVolumeRepresentation&) = delete;

  /** The mapper's Seed and MaximumSamples for this process's share. */
  void UpdateDistributedSettings();
  /** Distributed: all processes' mean radiance and samples (the mapper's RadianceCombiner). */
  uint32_t CombineRadiance(std::vector<float>& mean, uint32_t samples);
  /** Before a render: counts the frame rendered since the last call and holds or releases the
   *  mapper's MaximumSamples by the TimeBudget. */
  void UpdateTimeBudget();

  int Processes = 1;   // rendering together (the global controller's, 1 on a client)
  int ProcessId = 0;
  int Seed = 1;        // as the user set them; the mapper holds this process's share
  int MaximumSamples = 4096;
  int SampleShare = 4096;         // this process's share of MaximumSamples
  double TimeBudget = 0.0;        // seconds, 0: none
  double AccumulationSeconds = 0.0; // the current accumulation's still frames, summed
  double NextFrameSeconds = 0.0;  // the next frame's expected time: the longest of the last RecentFrames and
                                  // its excess over their median (UpdateTimeBudget)
  static constexpr int RecentFrames = 16;
  double RecentFrameSeconds[RecentFrames] = {}; // the last frames' times without their updates
  int RecentFrame = 0;                                         // where the next one goes
  bool FirstFrameOnly = false;    // RecentFrameSeconds hold the accumulation's first frame alone
  int BudgetResets = -1;          // the mapper's AccumulationResetCount the sum belongs to
  int BudgetSamples = 0;          // this process's samples when last counted
  bool BudgetSpent = false;       // the mapper's MaximumSamples is held at BudgetSamples
  double FrameStart = 0.0;        // distributed: when this process's render began (seconds, steady clock)
  double CombinedFrameSeconds[2] = { 0.0, 0.0 }; // distributed: the slowest process's frame, and next frame
  int CombinedSamples = -1;       // all processes' samples behind the last combined image (-1: none)
  int CombinedLocalSamples = -1;  // this process's then
  bool EnvironmentVisible = true;
  bool WarnedEnvironment = false;
  std::string EnvironmentFileName;
  double EnvironmentRotation = 0.0;
  vtkEnvironmentMapReader* EnvironmentReader = nullptr;
  // Without a file, the plugin's white sky, connected so that it is shown as before: the mapper shows
  // only a connected environment (issue 38) and would otherwise show the view's background.
  vtkEnvironmentMapSource* WhiteSky = nullptr;
};

#endif
