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
 * MaximumSamples; GetAccumulatedSamples() and IsConverged() say how far it got.
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

#include <string>

class vtkEnvironmentMapReader;
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
  ///@}

  ///@{
  /** The environment: a lat-long .exr/.hdr file, or empty (default) for the white sky. */
  void SetEnvironmentFileName(const char* fileName);
  const char* GetEnvironmentFileName() { return this->EnvironmentFileName.c_str(); }
  /** Rotation of the environment file about +Z, in degrees. */
  void SetEnvironmentRotation(double degrees);
  ///@}

  /** Samples per pixel accumulated in the view rendered last, and whether they reached MaximumSamples. */
  int GetAccumulatedSamples();
  bool IsConverged();
  /** The mapper's last error ("" after a successful render). */
  const char* GetLastError();

#if !defined(__VTK_WRAP__)
  /** The mapper (for tests and C++ users). */
  vtkVisibilitySweepVolumeMapper* GetVisSweepMapper();
#endif

protected:
  vtkVisSweepVolumeRepresentation();
  ~vtkVisSweepVolumeRepresentation() override;

private:
  vtkVisSweepVolumeRepresentation(const vtkVisSweepVolumeRepresentation&) = delete;
  void operator=(const vtkVisSweepVolumeRepresentation&) = delete;

  std::string EnvironmentFileName;
  double EnvironmentRotation = 0.0;
  vtkEnvironmentMapReader* EnvironmentReader = nullptr;
};

#endif
