#include "vsToolVolume.h"

#include "vtkCallbackCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDICOMImageReader.h"
#include "vtkImageData.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkOpenVDBVolumeReader.h"
#include "vtkStreamingDemandDrivenPipeline.h"
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

// Collects the reader's vtkErrorMacro messages so the exception can give the reason.
void CollectError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* messages = static_cast<std::string*>(clientData);
  const char* text = static_cast<const char*>(callData);
  if (text)
  {
    std::string m(text);
    // vtkErrorMacro text: "ERROR: In file, line N\nvtkClass (0x...): message\n\n"
    const auto colon = m.find("): ");
    if (colon != std::string::npos)
    {
      m = m.substr(colon + 3);
    }
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
    {
      m.pop_back();
    }
    if (!messages->empty())
    {
      *messages += "; ";
    }
    *messages += m;
  }
}

vtkSmartPointer<vtkImageData> RunVDB(vtkOpenVDBVolumeReader* reader, const std::string& what, int step)
{
  std::string errors;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(CollectError);
  observer->SetClientData(&errors);
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->UpdateInformation();
  if (errors.empty())
  {
    if (reader->GetNumberOfTimeSteps() > 1)
    {
      reader->UpdateTimeStep(static_cast<double>(step));
    }
    else
    {
      reader->Update();
    }
  }
  vtkImageData* image = reader->GetOutput();
  if (!errors.empty() || !image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    throw std::runtime_error(
      "cannot read a volume from " + what + (errors.empty() ? std::string() : ": " + errors));
  }
  vtkSmartPointer<vtkImageData> copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  return copy;
}
}

vtkSmartPointer<vtkImageData> ReadVolumeSequence(
  const std::vector<std::string>& files, const std::string& grid, int step)
{
  if (files.empty())
  {
    throw std::runtime_error("empty list of volume files");
  }
  if (step < 0 || step >= static_cast<int>(files.size()))
  {
    throw std::runtime_error("time step " + std::to_string(step) + " outside the sequence of " +
      std::to_string(files.size()) + " files");
  }
  for (const auto& f : files)
  {
    if (!EndsWith(f, ".vdb"))
    {
      throw std::runtime_error("volume sequences must be .vdb files, not '" + f + "'");
    }
    if (!vtksys::SystemTools::FileExists(f))
    {
      throw std::runtime_error("volume file '" + f + "' does not exist");
    }
  }
  vtkNew<vtkOpenVDBVolumeReader> reader;
  for (const auto& f : files)
  {
    reader->AddFileName(f.c_str());
  }
  reader->SetGridName(grid.c_str());
  return RunVDB(reader, "'" + files[static_cast<size_t>(step)] + "' (grid '" + grid + "')", step);
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string& grid)
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
  if (EndsWith(path, ".vdb"))
  {
    vtkNew<vtkOpenVDBVolumeReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetGridName(grid.c_str());
    return RunVDB(reader, "'" + path + "' (grid '" + grid + "')", 0);
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
