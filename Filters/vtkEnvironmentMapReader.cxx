// vtkEnvironmentMapReader.cxx — the reader: a file recognised by its content, a Radiance HDR file
// read through vtkHDRReader, an OpenEXR one through vsOpenEXRLatLong.cxx, then the lat-long
// converted to the octahedral map (vs::EnvironmentMap::FromLatLong).
#include "vtkEnvironmentMapReader.h"

#include "vsEnvironmentMap.h"
#include "vsLatLongFileMessages.h"
#include "vsOpenEXRLatLong.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkHDRReader.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

vtkStandardNewMacro(vtkEnvironmentMapReader);

namespace
{
enum class FileKind
{
  Missing,
  Directory,
  Unknown,
  OpenEXR,
  RadianceHDR
};

FileKind Identify(const char* fileName)
{
  std::error_code ec;
  if (std::filesystem::is_directory(fileName, ec))
  {
    return FileKind::Directory;
  }
  std::ifstream in(fileName, std::ios::binary);
  if (!in)
  {
    return FileKind::Missing;
  }
  unsigned char magic[4] = { 0, 0, 0, 0 };
  in.read(reinterpret_cast<char*>(magic), 4);
  if (in.gcount() == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01)
  {
    return FileKind::OpenEXR;
  }
  if (in.gcount() >= 2 && magic[0] == '#' && magic[1] == '?')
  {
    return FileKind::RadianceHDR;
  }
  return FileKind::Unknown;
}

/* Captures the error and warning messages of a VTK object (and keeps them off the
 * output window), so they can be reported once, naming the file. */
class MessageCatcher : public vtkCommand
{
public:
  static MessageCatcher* New() { return new MessageCatcher; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const char* text = static_cast<const char*>(data);
    std::string msg = text ? text : "";
    // VTK's messages start with "ERROR: In file, line N\nvtkClass (0x...): ": keep the reason.
    const std::size_t colon = msg.find("): ");
    if (colon != std::string::npos)
    {
      msg = msg.substr(colon + 3);
    }
    while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' '))
    {
      msg.pop_back();
    }
    if (event == vtkCommand::ErrorEvent)
    {
      this->Errors += (this->Errors.empty() ? "" : "; ") + msg;
    }
  }
  std::string Errors;
};

/* Reads the dimensions of a Radiance file through vtkHDRReader (information only when !image). */
bool ReadHDR(const char* fileName, vs::LatLongImage* image, int& width, int& height, std::string& error,
  int64_t maxPixels)
{
  vtkNew<vtkHDRReader> reader;
  vtkNew<MessageCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->AddObserver(vtkCommand::WarningEvent, catcher);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->SetFileName(fileName);
  if (!reader->CanReadFile(fileName))
  {
    error = vs::QuoteFileName(fileName) + " is not a Radiance HDR file vtkHDRReader can read (bad header)";
    return false;
  }
  reader->UpdateInformation();
  int ext[6];
  reader->GetDataExtent(ext);
  width = ext[1] - ext[0] + 1;
  height = ext[3] - ext[2] + 1;
  if (!catcher->Errors.empty() || width <= 0 || height <= 0)
  {
    error = "cannot read the Radiance HDR file " + vs::QuoteFileName(fileName) + ": " +
      (catcher->Errors.empty() ? std::string("no image size in the header") : catcher->Errors);
    return false;
  }
  error = vs::TooLargeMessage(fileName, "Radiance HDR image", width, height, maxPixels);
  if (!error.empty())
  {
    return false;
  }
  if (!image)
  {
    return true;
  }
  reader->Update();
  vtkImageData* out = reader->GetOutput();
  vtkDataArray* scalars = out ? out->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (out)
  {
    out->GetDimensions(dims);
  }
  if (!catcher->Errors.empty() || !scalars || dims[0] != width || dims[1] != height ||
    scalars->GetNumberOfComponents() < 3 || scalars->GetNumberOfTuples() != vtkIdType(width) * height)
  {
    error = "cannot read the Radiance HDR file " + vs::QuoteFileName(fileName) + ": " +
      (catcher->Errors.empty() ? std::string("the pixel data is missing or truncated") : catcher->Errors);
    return false;
  }
  image->Width = width;
  image->Height = height;
  image->RGB.resize(3 * std::size_t(width) * height);
  // VTK images are bottom-up (point row 0 is the bottom of the picture); the
  // lat-long's row 0 is the top (+Z).
  for (int j = 0; j < height; ++j)
  {
    const vtkIdType srcRow = vtkIdType(height - 1 - j) * width;
    float* dst = image->RGB.data() + 3 * std::size_t(j) * width;
    for (int i = 0; i < width; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        dst[3 * i + c] = float(scalars->GetComponent(srcRow + i, c));
      }
    }
  }
  return true;
}

bool ReadAny(const char* fileName, vs::LatLongImage* image, int& width, int& height, std::string& error,
  const std::function<void(double)>& progress, int64_t maxPixels)
{
  width = height = 0;
  if (!fileName || !*fileName)
  {
    error = "no file name given";
    return false;
  }
  switch (Identify(fileName))
  {
    case FileKind::Missing:
      error = "cannot open " + vs::QuoteFileName(fileName) + ": " + std::strerror(errno);
      return false;
    case FileKind::Directory:
      error = vs::QuoteFileName(fileName) + " is a directory, not an environment map file";
      return false;
    case FileKind::Unknown:
      error = vs::QuoteFileName(fileName) +
        " is neither an OpenEXR nor a Radiance HDR file (its first bytes are not an EXR magic number or \"#?\")";
      return false;
    case FileKind::OpenEXR:
      return vs::ReadOpenEXRLatLong(fileName, image, width, height, error, progress, maxPixels);
    case FileKind::RadianceHDR:
      return ReadHDR(fileName, image, width, height, error, maxPixels);
  }
  return false;
}
} // namespace

vtkEnvironmentMapReader::vtkEnvironmentMapReader() = default;

vtkEnvironmentMapReader::~vtkEnvironmentMapReader()
{
  this->SetFileName(nullptr);
}

int vtkEnvironmentMapReader::CanReadFile(const char* fileName)
{
  const FileKind kind = fileName ? Identify(fileName) : FileKind::Missing;
  return kind == FileKind::OpenEXR || kind == FileKind::RadianceHDR ? 1 : 0;
}

bool vtkEnvironmentMapReader::ReadLatLong(const char* fileName, vs::LatLongImage& image, std::string& error)
{
  int w, h;
  return ReadAny(fileName, &image, w, h, error, nullptr, vtkIdType(1) << 28);
}

std::string vtkEnvironmentMapReader::DescribeSource()
{
  return vs::QuoteFileName(this->FileName);
}

int vtkEnvironmentMapReader::ComputeOutputSize()
{
  std::string error;
  int w, h;
  if (!ReadAny(this->FileName, nullptr, w, h, error, nullptr, this->MaximumNumberOfPixels))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (this->OctahedralSize != 0 && !vs::EnvironmentMap::IsPowerOfTwo(this->OctahedralSize))
  {
    vtkErrorMacro(<< "OctahedralSize must be 0 (automatic) or a power of two, not " << this->OctahedralSize);
    return 0;
  }
  try
  {
    // A user's size that the machine cannot hold is refused here, before the file is read.
    vs::EnvironmentMap::CheckMemory(this->OctahedralSize, "OctahedralSize");
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return this->OctahedralSize > 0 ? this->OctahedralSize : vs::EnvironmentMap::DefaultSize(w, h);
}

std::shared_ptr<vs::EnvironmentMap> vtkEnvironmentMapReader::ComputeMap()
{
  this->LatLongWidth = this->LatLongHeight = 0;
  vs::LatLongImage image;
  std::string error;
  int w, h;
  // Reading is the first quarter of the progress, the conversion the rest.
  auto readProgress = [this](double f) { this->UpdateProgress(0.25 * f); };
  if (!ReadAny(this->FileName, &image, w, h, error, readProgress, this->MaximumNumberOfPixels))
  {
    vtkErrorMacro(<< error);
    return nullptr;
  }
  this->LatLongWidth = image.Width;
  this->LatLongHeight = image.Height;
  if (std::abs(image.Width - 2 * image.Height) > std::max(1, image.Width / 100))
  {
    vtkWarningMacro(<< vs::QuoteFileName(this->FileName) << " is " << image.Width << " x " << image.Height
                    << ", not 2:1; reading it as an equirectangular map anyway.");
  }
  try
  {
    auto convertProgress = [this](double f) { this->UpdateProgress(0.25 + 0.75 * f); };
    return std::make_shared<vs::EnvironmentMap>(vs::EnvironmentMap::FromLatLong(image,
      this->OctahedralSize, this->RotationDegrees, this->Intensity, convertProgress,
      vtkSMPTools::GetEstimatedNumberOfThreads()));
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< vs::QuoteFileName(this->FileName) << ": " << e.what());
    return nullptr;
  }
}

void vtkEnvironmentMapReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "OctahedralSize: " << this->OctahedralSize << "\n";
  os << indent << "RotationDegrees: " << this->RotationDegrees << "\n";
  os << indent << "LatLongWidth: " << this->LatLongWidth << "\n";
  os << indent << "LatLongHeight: " << this->LatLongHeight << "\n";
  os << indent << "MaximumNumberOfPixels: " << this->MaximumNumberOfPixels << "\n";
}
