#include "vtkEnvironmentMapBackground.h"

#include "sampling/octahedral.h"
#include "sampling/display_transform.h"
#include "vsEnvironmentMap.h"
#include "vtkEnvironmentMapAlgorithm.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSkybox.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <memory>
#include <string>

vtkStandardNewMacro(vtkEnvironmentMapBackground);

vtkEnvironmentMapBackground::vtkEnvironmentMapBackground()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkEnvironmentMapBackground::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkEnvironmentMapBackground::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* out = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Width - 1, 0, this->Width / 2 - 1, 0, 0 };
  out->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 }, origin[3] = { 0.0, 0.0, 0.0 };
  out->Set(vtkDataObject::SPACING(), spacing, 3);
  out->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(out, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

// The whole map, whatever extent of the lat-long image is asked for: vtkImageAlgorithm's default
// asked the input for the output's extent (the image's width x height), outside the map's whole
// extent, an error that also made the map's source execute again, and a mapper sharing that source
// then re-upload the environment and restart its accumulation.
int vtkEnvironmentMapBackground::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkInformation* in = inputVector[0]->GetNumberOfInformationObjects() > 0 ? inputVector[0]->GetInformationObject(0) : nullptr;
  if (in && in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
  return 1;
}

int vtkEnvironmentMapBackground::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  vtkImageData* input = this->GetNumberOfInputConnections(0) > 0 ? vtkImageData::GetData(inputVector[0], 0) : nullptr;
  std::shared_ptr<const vs::EnvironmentMap> map;
  if (input)
  {
    std::string error;
    map = vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(input, &error);
    if (!map)
    {
      vtkErrorMacro(<< "the input is not an environment map: " << error);
      return 0;
    }
  }
  else
  {
    map = std::make_shared<vs::EnvironmentMap>(vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
  }
  const int w = this->Width, h = this->Width / 2;
  output->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  output->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(output->GetScalarPointer());
  const float scale = float(this->Intensity * this->Exposure);
  const uint32_t n = uint32_t(map->Size);
  for (int j = 0; j < h; ++j)
  {
    // vtkSkybox's Sphere projection with up +Z, right +X (front +Y): column u is the azimuth
    // atan2(x, y), row v (bottom up) the elevation.
    const double elevation = ((j + 0.5) / h - 0.5) * vtkMath::Pi();
    for (int i = 0; i < w; ++i)
    {
      const double azimuth = ((i + 0.5) / w - 0.5) * 2.0 * vtkMath::Pi();
      const glm::vec3 d(float(std::cos(elevation) * std::sin(azimuth)), float(std::cos(elevation) * std::cos(azimuth)),
        float(std::sin(elevation)));
      // Bilinear between octahedral texels, as the mapper shows the environment (mc_render.glsl).
      const glm::vec2 uv = vs::shared::vs_dir_to_octa(d);
      glm::vec3 radiance(0.0f);
      for (uint32_t c = 0; c < 4u; ++c)
      {
        float weight = 0.0f;
        const glm::uvec2 t = vs::shared::vs_octa_bilinear_texel(uv, n, c, weight);
        radiance += weight * map->Texel(int(t.x), int(t.y));
      }
      unsigned char* p = pixels + 3 * (size_t(j) * w + i);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = static_cast<unsigned char>(std::lround(255.0f * vs::shared::vs_display_value(scale * radiance[k], this->ToneMapping)));
      }
    }
  }
  return 1;
}

void vtkEnvironmentMapBackground::CopyDisplaySettings(vtkVisibilitySweepVolumeMapper* mapper)
{
  if (mapper)
  {
    this->SetIntensity(mapper->GetEnvironmentIntensity());
    this->SetExposure(mapper->GetExposure());
    this->SetToneMapping(mapper->GetToneMapping());
  }
}

void vtkEnvironmentMapBackground::ConfigureSkybox(vtkSkybox* skybox)
{
  if (!skybox)
  {
    return;
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(this->GetOutputPort());
  texture->InterpolateOn();
  texture->RepeatOn();
  skybox->SetTexture(texture);
  skybox->SetProjectionToSphere();
  skybox->SetFloorPlane(0.0f, 0.0f, 1.0f, 0.0f);
  skybox->SetFloorRight(1.0f, 0.0f, 0.0f);
  skybox->SetGammaCorrect(false);
}

void vtkEnvironmentMapBackground::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Width: " << this->Width << " (height " << this->Width / 2 << ")\n";
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << (this->ToneMapping ? "On (filmic)" : "Off (clamp)") << "\n";
  os << indent << "Environment: "
     << (this->GetNumberOfInputConnections(0) > 0 ? "input port 0" : "none: a constant white sky of radiance 1") << "\n";
}
