#include "vtkVisSweepDevice.h"

#include "vtkObjectFactory.h"
#include "vsContext.h"
#include "vsError.h"

vtkStandardNewMacro(vtkVisSweepDevice);

bool vtkVisSweepDevice::IsAvailable()
{
  try
  {
    auto ctx = vs::Context::Default();
    this->Error.clear();
    this->Description = ctx->Info().Describe();
    this->Name = ctx->Info().Name;
    return true;
  }
  catch (const std::exception& e)
  {
    this->Error = e.what();
    return false;
  }
}

const char* vtkVisSweepDevice::GetErrorMessage()
{
  this->IsAvailable();
  return this->Error.c_str();
}

const char* vtkVisSweepDevice::GetDescription()
{
  this->IsAvailable();
  return this->Description.c_str();
}

const char* vtkVisSweepDevice::GetDeviceName()
{
  this->IsAvailable();
  return this->Name.c_str();
}

unsigned int vtkVisSweepDevice::GetMaxImageDimension3D()
{
  return this->IsAvailable() ? vs::Context::Default()->Info().MaxImageDimension3D : 0u;
}

double vtkVisSweepDevice::GetMemoryHeapBytes()
{
  return this->IsAvailable() ? double(vs::Context::Default()->Info().DeviceLocalHeapBytes) : 0.0;
}

double vtkVisSweepDevice::GetValidationMessageCount()
{
  return this->IsAvailable() ? double(vs::Context::Default()->ValidationMessageCount()) : 0.0;
}

void vtkVisSweepDevice::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  if (this->IsAvailable())
  {
    os << indent << "Device: " << this->Name << "\n";
    os << indent << "MaxImageDimension3D: " << this->GetMaxImageDimension3D() << "\n";
    os << indent << "MemoryHeapBytes: " << this->GetMemoryHeapBytes() << "\n";
    os << indent << "ValidationMessageCount: " << this->GetValidationMessageCount() << "\n";
  }
  else
  {
    os << indent << "Unavailable: " << this->Error << "\n";
  }
}
