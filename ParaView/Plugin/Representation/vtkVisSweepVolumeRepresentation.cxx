#include "vtkVisSweepVolumeRepresentation.h"

#include "vtkEnvironmentMapReader.h"
#include "vtkObjectFactory.h"
#include "vtkVisibilitySweepVolumeMapper.h"

vtkStandardNewMacro(vtkVisSweepVolumeRepresentation);

namespace
{
// The mapper clamps these settings silently (vtkSetClampMacro); a value set from ParaView's panel
// or a script outside the range is worth a word in ParaView's output window.
template <typename T>
void WarnOutOfRange(vtkObject* self, const char* name, T value, T low, T high)
{
  if (value < low || value > high)
  {
    vtkWarningWithObjectMacro(self, << name << " " << value << " is outside [" << low << ", "
                                    << high << "]: the mapper uses "
                                    << (value < low ? low : high) << ".");
  }
}
}

vtkVisSweepVolumeRepresentation::vtkVisSweepVolumeRepresentation()
{
  // The superclass made its own mapper; VisSweep's takes its place (the superclass reads
  // this->VolumeMapper wherever it passes ParaView's volume settings on).
  this->VolumeMapper = vtkSmartPointer<vtkVisibilitySweepVolumeMapper>::New();
  this->EnvironmentReader = vtkEnvironmentMapReader::New();
}

vtkVisSweepVolumeRepresentation::~vtkVisSweepVolumeRepresentation()
{
  this->EnvironmentReader->Delete();
}

vtkVisibilitySweepVolumeMapper* vtkVisSweepVolumeRepresentation::GetVisSweepMapper()
{
  return static_cast<vtkVisibilitySweepVolumeMapper*>(this->VolumeMapper.GetPointer());
}

void vtkVisSweepVolumeRepresentation::SetVisSweepRenderMode(int mode)
{
  WarnOutOfRange(this, "VisSweepRenderMode", mode, 0, 3);
  this->GetVisSweepMapper()->SetRenderMode(mode);
}

void vtkVisSweepVolumeRepresentation::SetSamplingStrategy(int strategy)
{
  WarnOutOfRange(this, "SamplingStrategy", strategy, 0, 5);
  this->GetVisSweepMapper()->SetSamplingStrategy(strategy);
}

void vtkVisSweepVolumeRepresentation::SetSamplesPerFrame(int samples)
{
  WarnOutOfRange(this, "SamplesPerFrame", samples, 1, 1 << 16);
  this->GetVisSweepMapper()->SetSamplesPerFrame(samples);
}

void vtkVisSweepVolumeRepresentation::SetMaximumSamples(int samples)
{
  WarnOutOfRange(this, "MaximumSamples", samples, 1, 1 << 30);
  this->GetVisSweepMapper()->SetMaximumSamples(samples);
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentIntensity(double intensity)
{
  if (intensity < 0)
  {
    vtkWarningMacro(<< "EnvironmentIntensity " << intensity << " is negative: the mapper uses 0.");
  }
  this->GetVisSweepMapper()->SetEnvironmentIntensity(intensity);
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentVisible(bool visible)
{
  this->GetVisSweepMapper()->SetEnvironmentVisible(visible);
}

void vtkVisSweepVolumeRepresentation::SetExposure(double exposure)
{
  if (exposure < 0)
  {
    vtkWarningMacro(<< "Exposure " << exposure << " is negative: the mapper uses 0.");
  }
  this->GetVisSweepMapper()->SetExposure(exposure);
}

void vtkVisSweepVolumeRepresentation::SetToneMapping(bool toneMapping)
{
  this->GetVisSweepMapper()->SetToneMapping(toneMapping);
}

void vtkVisSweepVolumeRepresentation::SetSeed(int seed)
{
  WarnOutOfRange(this, "Seed", seed, 0, VTK_INT_MAX);
  this->GetVisSweepMapper()->SetSeed(seed);
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentFileName(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  if (name == this->EnvironmentFileName)
  {
    return;
  }
  this->EnvironmentFileName = name;
  if (name.empty())
  {
    this->GetVisSweepMapper()->SetEnvironmentConnection(nullptr);
  }
  else
  {
    this->EnvironmentReader->SetFileName(name.c_str());
    this->GetVisSweepMapper()->SetEnvironmentConnection(this->EnvironmentReader->GetOutputPort());
  }
  this->Modified();
}

void vtkVisSweepVolumeRepresentation::SetEnvironmentRotation(double degrees)
{
  if (degrees == this->EnvironmentRotation)
  {
    return;
  }
  this->EnvironmentRotation = degrees;
  this->EnvironmentReader->SetRotationDegrees(degrees);
  this->Modified();
}

int vtkVisSweepVolumeRepresentation::GetAccumulatedSamples()
{
  return this->GetVisSweepMapper()->GetAccumulatedSamples();
}

bool vtkVisSweepVolumeRepresentation::IsConverged()
{
  return this->GetVisSweepMapper()->IsConverged();
}

const char* vtkVisSweepVolumeRepresentation::GetLastError()
{
  return this->GetVisSweepMapper()->GetLastError();
}

void vtkVisSweepVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EnvironmentFileName: "
     << (this->EnvironmentFileName.empty() ? "(none: white sky)" : this->EnvironmentFileName) << "\n";
  os << indent << "EnvironmentRotation: " << this->EnvironmentRotation << "\n";
  os << indent << "Mapper:\n";
  this->VolumeMapper->PrintSelf(os, indent.GetNextIndent());
}
