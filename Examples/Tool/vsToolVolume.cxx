#include "vsToolVolume.h"

#include "vtkColorTransferFunction.h"
#include "vtkDICOMImageReader.h"
#include "vtkImageData.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataReader.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <stdexcept>

namespace vstool
{
namespace
{
bool EndsWith(std::string s, const std::string& suffix)
{
  std::transform(s.begin(), s.end(), s.begin(), ::tolower);
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

template <class Reader>
vtkSmartPointer<vtkImageData> Run(Reader* reader, const std::string& path)
{
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    throw std::runtime_error("cannot read a volume from '" + path + "'");
  }
  vtkSmartPointer<vtkImageData> copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  return copy;
}
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string&)
{
  if (!vtksys::SystemTools::FileExists(path))
  {
    throw std::runtime_error("volume file '" + path + "' does not exist");
  }
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    vtkNew<vtkDICOMImageReader> reader;
    reader->SetDirectoryName(path.c_str());
    reader->Update();
    if (!reader->GetOutput() || reader->GetOutput()->GetNumberOfPoints() == 0)
    {
      throw std::runtime_error("no DICOM series in folder '" + path + "'");
    }
    vtkSmartPointer<vtkImageData> copy = vtkSmartPointer<vtkImageData>::New();
    copy->ShallowCopy(reader->GetOutput());
    return copy;
  }
  if (EndsWith(path, ".vti"))
  {
    vtkNew<vtkXMLImageDataReader> r;
    return Run(r.Get(), path);
  }
  if (EndsWith(path, ".mha") || EndsWith(path, ".mhd"))
  {
    vtkNew<vtkMetaImageReader> r;
    return Run(r.Get(), path);
  }
  if (EndsWith(path, ".nrrd") || EndsWith(path, ".nhdr"))
  {
    vtkNew<vtkNrrdReader> r;
    return Run(r.Get(), path);
  }
  if (EndsWith(path, ".nii") || EndsWith(path, ".nii.gz"))
  {
    vtkNew<vtkNIFTIImageReader> r;
    return Run(r.Get(), path);
  }
  throw std::runtime_error("unknown volume format of '" + path +
    "' (expected .vti, .mha, .mhd, .nrrd, .nhdr, .nii, .nii.gz, .vdb or a DICOM folder)");
}

vtkSmartPointer<vtkVolumeProperty> SkinProperty()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(80, 0.3);
  opacity->AddPoint(255, 0.6);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.9, 0.7, 0.6);
  color->AddRGBPoint(255, 1.0, 0.95, 0.9);
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(1.0);
  return property;
}

std::string DefaultBrainPath()
{
  return "/usr/share/mricron/templates/ch2.nii.gz";
}
}
