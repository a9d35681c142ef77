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
 * - EmissionAbsorption: ray casting of VTK's transfer functions (opacity per
 *   ScalarOpacityUnitDistance, colour as emission), a jittered sample per step.
 *
 * Conventions (DESIGN.md): world units are those of the image data (origin,
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

#include <memory>
#include <string>

class VISSWEEPRENDERING_EXPORT vtkVisibilitySweepVolumeMapper : public vtkVolumeMapper
{
public:
  static vtkVisibilitySweepVolumeMapper* New();
  vtkTypeMacro(vtkVisibilitySweepVolumeMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RenderModes
  {
    EmissionAbsorption = 0
  };

  ///@{
  /** The render path. Default EmissionAbsorption. */
  vtkSetClampMacro(RenderMode, int, EmissionAbsorption, EmissionAbsorption);
  vtkGetMacro(RenderMode, int);
  ///@}

  ///@{
  /** Ray-marching step in world units; 0 (default) = half the smallest voxel edge. */
  vtkSetClampMacro(SampleDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /** Multiplies the extinction of the transfer function. Default 1. */
  vtkSetClampMacro(DensityScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /** Seed of the counter-based random numbers: a fixed seed reproduces an image bit for bit. */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  /** Renders the volume into the renderer's viewport. */
  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow*) override;

  /** Device seconds of the last render pass (0 if the device has no timestamps). */
  vtkGetMacro(LastDeviceSeconds, double);
  /** Times the volume was uploaded to the device (changes only when the input changes). */
  vtkGetMacro(VolumeUploadCount, int);
  /** The last error reported with vtkErrorMacro, or "" after a successful render. */
  const char* GetLastError();

protected:
  vtkVisibilitySweepVolumeMapper();
  ~vtkVisibilitySweepVolumeMapper() override;

  int RenderMode = EmissionAbsorption;
  double SampleDistance = 0.0;
  double DensityScale = 1.0;
  int Seed = 1;
  double LastDeviceSeconds = 0.0;
  int VolumeUploadCount = 0;

private:
  vtkVisibilitySweepVolumeMapper(const vtkVisibilitySweepVolumeMapper&) = delete;
  void operator=(const vtkVisibilitySweepVolumeMapper&) = delete;

  void ReportError(const std::string& message);

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
