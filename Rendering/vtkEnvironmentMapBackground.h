/**
 * @class   vtkEnvironmentMapBackground
 * @brief   The visible environment as a vtkSkybox, drawn behind everything the VTK way.
 *
 * A vtkVisibilitySweepVolumeMapper with EnvironmentVisible and EnvironmentAsBackground on (the
 * defaults) makes one of these itself and adds its skybox to the renderer, behind everything. A
 * skybox of your own (e.g. a wider image, or with EnvironmentAsBackground off) is taken as the
 * background instead: this filter turns an environment map (the output of vtkEnvironmentMapReader
 * or vtkEnvironmentMapSource, the mapper's input port 1; none = the mapper's default constant white
 * sky of radiance 1) into the 8-bit lat-long image of a vtkSkybox in Sphere projection, through the
 * mapper's display transform (Intensity, Exposure, filmic tone curve or clamp, sRGB), and
 * ConfigureSkybox() sets a skybox up to show it with VisSweep's orientation (+Z up; docs/reference.md):
 *
 *   background->SetInputConnection(reader->GetOutputPort());
 *   background->CopyDisplaySettings(mapper);
 *   vtkNew<vtkSkybox> sky; background->ConfigureSkybox(sky); renderer->AddActor(sky);
 *
 * The skybox is drawn first and at the far plane: opaque and translucent actors and every volume sit
 * in front of it. With the mapper's EnvironmentVisible on, a partly covered pixel with only the
 * environment behind it is the volume's radiance and the environment seen through it tone mapped
 * together; with it off, the volume's tone-mapped radiance over the tone-mapped environment. The
 * background is bilinear in the lat-long image rather than in the octahedral map.
 */
#ifndef vtkEnvironmentMapBackground_h
#define vtkEnvironmentMapBackground_h

#include "vissweepRenderingModule.h"
#include "vtkImageAlgorithm.h"

class vtkSkybox;
class vtkVisibilitySweepVolumeMapper;

class VISSWEEPRENDERING_EXPORT vtkEnvironmentMapBackground : public vtkImageAlgorithm
{
public:
  static vtkEnvironmentMapBackground* New();
  vtkTypeMacro(vtkEnvironmentMapBackground, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Width of the lat-long image in pixels (its height is half). Default 1024. */
  vtkSetClampMacro(Width, int, 8, 16384);
  vtkGetMacro(Width, int);
  ///@}

  ///@{
  /** The display transform, as the mapper's: radiance x Intensity x Exposure, then the filmic tone
   *  curve (ToneMapping on, the default) or a clamp, then sRGB. Defaults 1, 1, on. */
  vtkSetClampMacro(Intensity, double, 0.0, VTK_FLOAT_MAX);
  vtkGetMacro(Intensity, double);
  vtkSetClampMacro(Exposure, double, 0.0, VTK_FLOAT_MAX);
  vtkGetMacro(Exposure, double);
  vtkSetMacro(ToneMapping, bool);
  vtkGetMacro(ToneMapping, bool);
  vtkBooleanMacro(ToneMapping, bool);
  ///@}

  /** Intensity, Exposure and ToneMapping from the mapper (its EnvironmentIntensity, Exposure,
   *  ToneMapping), so that the background looks as the mapper's visible environment does. */
  void CopyDisplaySettings(vtkVisibilitySweepVolumeMapper* mapper);

  /** Sets `skybox` up to show this filter's output: Sphere projection, FloorPlane (0, 0, 1, 0)
   *  (+Z up), FloorRight (1, 0, 0), no gamma correction (the image is sRGB already), and a linearly
   *  interpolated texture on this filter's output port. */
  void ConfigureSkybox(vtkSkybox* skybox);

protected:
  vtkEnvironmentMapBackground();
  ~vtkEnvironmentMapBackground() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Width = 1024;
  double Intensity = 1.0;
  double Exposure = 1.0;
  bool ToneMapping = true;

private:
  vtkEnvironmentMapBackground(const vtkEnvironmentMapBackground&) = delete;
  void operator=(const vtkEnvironmentMapBackground&) = delete;
};

#endif
