#include "vtkEnvironmentMapSource.h"

#include "vsFloatRange.h"

#include "vsEnvironmentMap.h"

#include "vtkObjectFactory.h"

#include <stdexcept>

vtkStandardNewMacro(vtkEnvironmentMapSource);

vtkEnvironmentMapSource::vtkEnvironmentMapSource() = default;
vtkEnvironmentMapSource::~vtkEnvironmentMapSource() = default;

const char* vtkEnvironmentMapSource::GetTypeAsString()
{
  switch (this->Type)
  {
    case SunDisk:
      return "SunDisk";
    case TwoToneSky:
      return "TwoToneSky";
    default:
      return "Constant";
  }
}

std::string vtkEnvironmentMapSource::DescribeSource()
{
  return std::string("procedural ") + this->GetTypeAsString() + " environment";
}

int vtkEnvironmentMapSource::ComputeOutputSize()
{
  if (!vs::EnvironmentMap::IsPowerOfTwo(this->OctahedralSize))
  {
    vtkErrorMacro(<< "OctahedralSize must be a power of two, not " << this->OctahedralSize);
    return 0;
  }
  return this->OctahedralSize;
}

std::shared_ptr<vs::EnvironmentMap> vtkEnvironmentMapSource::ComputeMap()
{
  const float k = float(this->Intensity);
  auto rgb = [k](const double c[3]) { return glm::vec3(float(c[0]), float(c[1]), float(c[2])) * k; };
  try
  {
    vs::EnvironmentMap map;
    switch (this->Type)
    {
      case SunDisk:
      {
        // Normalised in double first (issue 13, item 9): a direction of (1e300, 0, 0) was an
        // infinity in float, refused as "must be a non-zero vector"; it is +X.
        double d[3] = { this->SunDirection[0], this->SunDirection[1], this->SunDirection[2] };
        vs::FloatRange::Normalize(this->SunDirection, d);
        map = vs::EnvironmentMap::SunDisk(this->OctahedralSize, glm::vec3(float(d[0]), float(d[1]), float(d[2])),
          this->SunAngularRadius, rgb(this->SunRadiance), rgb(this->SkyColor));
        break;
      }
      case TwoToneSky:
        map = vs::EnvironmentMap::TwoToneSky(this->OctahedralSize, rgb(this->UpperColor), rgb(this->LowerColor));
        break;
      default:
        map = vs::EnvironmentMap::Constant(this->OctahedralSize, rgb(this->Color));
        break;
    }
    return std::make_shared<vs::EnvironmentMap>(std::move(map));
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< this->DescribeSource() << ": " << e.what());
    return nullptr;
  }
}

void vtkEnvironmentMapSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto v3 = [&os](const double* v) { os << v[0] << " " << v[1] << " " << v[2] << "\n"; };
  os << indent << "Type: " << this->GetTypeAsString() << "\n";
  os << indent << "OctahedralSize: " << this->OctahedralSize << "\n";
  os << indent << "Color: ";
  v3(this->Color);
  os << indent << "SunDirection: ";
  v3(this->SunDirection);
  os << indent << "SunAngularRadius: " << this->SunAngularRadius << "\n";
  os << indent << "SunRadiance: ";
  v3(this->SunRadiance);
  os << indent << "SkyColor: ";
  v3(this->SkyColor);
  os << indent << "UpperColor: ";
  v3(this->UpperColor);
  os << indent << "LowerColor: ";
  v3(this->LowerColor);
}
