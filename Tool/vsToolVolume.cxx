#include "vsToolVolume.h"

#include "vtkCallbackCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDICOMImageReader.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkOpenVDBVolumeReader.h"
#include "vtkStringArray.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"
#include "vtkErrorCode.h"
#include "vtkExecutive.h"
#include "vtkImageReader2.h"
#include "vtkInformation.h"
#include "vtkXMLImageDataReader.h"
#include "vtkmetaio/metaImage.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace vstool
{
namespace
{
namespace fs = std::filesystem;

bool EndsWith(std::string s, const std::string& suffix)
{
  std::transform(s.begin(), s.end(), s.begin(), ::tolower);
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string Quote(const std::string& path)
{
  return "'" + path + "'";
}

[[noreturn]] void Fail(const std::string& what, const std::string& reason)
{
  throw std::runtime_error("cannot read a volume from " + what + ": " + reason);
}

/* A path a reader may open: it exists and is a regular file. A FIFO, a character device or a
 * socket would block the reader forever (or read an endless stream), so they are refused. */
void CheckRegularFile(const std::string& path, const std::string& role)
{
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st))
  {
    throw std::runtime_error(role + " " + Quote(path) + " does not exist");
  }
  if (!fs::is_regular_file(st))
  {
    const char* kind = fs::is_directory(st) ? "a directory"
      : fs::is_fifo(st)                     ? "a FIFO (named pipe)"
      : fs::is_character_file(st)           ? "a character device"
      : fs::is_block_file(st)               ? "a block device"
      : fs::is_socket(st)                   ? "a socket"
                                            : "not a regular file";
    throw std::runtime_error(role + " " + Quote(path) + " is " + kind + "; volumes are read from regular files");
  }
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

/* The ErrorEvents of an algorithm and of its executive (where the pipeline reports a failed
 * request), collected as text while it lives. */
class ErrorCollector
{
public:
  explicit ErrorCollector(vtkAlgorithm* algorithm)
  {
    this->Observer->SetCallback(CollectError);
    this->Observer->SetClientData(&this->Text);
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  std::string Text;

private:
  vtkNew<vtkCallbackCommand> Observer;
};

/* MetaIO (vtkMetaImageReader) reports a truncated or missing data file only on std::cerr and
 * returns success: its messages (lines from "MetaImage:"/"MetaObject:", with their indented
 * continuation lines) are captured while the reader runs, and any is an error. Other text
 * written to std::cerr meanwhile is passed on when the capture ends. */
class MetaIOMessages
{
public:
  MetaIOMessages()
    : Saved(std::cerr.rdbuf(this->Buffer.rdbuf()))
  {
  }
  ~MetaIOMessages()
  {
    std::cerr.rdbuf(this->Saved);
    std::cerr << this->Split().second << std::flush;
  }
  std::string Text() const { return this->Split().first; }

private:
  // (MetaIO's messages joined on one line, everything else as it was written)
  std::pair<std::string, std::string> Split() const
  {
    std::istringstream in(this->Buffer.str());
    std::string line, meta, other;
    bool inMeta = false;
    while (std::getline(in, line))
    {
      const bool start = line.rfind("MetaImage", 0) == 0 || line.rfind("MetaObject", 0) == 0;
      inMeta = start || (inMeta && !line.empty() && (line[0] == ' ' || line[0] == '\t'));
      if (inMeta)
      {
        const auto b = line.find_first_not_of(" \t");
        meta += (meta.empty() ? "" : " ") + line.substr(b == std::string::npos ? line.size() : b);
      }
      else
      {
        other += line + "\n";
      }
    }
    return { meta, other };
  }
  std::ostringstream Buffer;
  std::streambuf* Saved;
};

std::string Describe(const int extent[6], vtkIdType points)
{
  std::ostringstream os;
  os << (extent[1] - extent[0] + 1) << " x " << (extent[3] - extent[2] + 1) << " x " << (extent[5] - extent[4] + 1)
     << " (" << points << " points)";
  return os.str();
}

vtkIdType PointCount(const int e[6])
{
  vtkIdType n = 1;
  for (int i = 0; i < 3; ++i)
  {
    const vtkIdType len = vtkIdType(e[2 * i + 1]) - e[2 * i] + 1;
    if (len <= 0)
    {
      return 0;
    }
    if (n > std::numeric_limits<vtkIdType>::max() / len)
    {
      return std::numeric_limits<vtkIdType>::max();
    }
    n *= len;
  }
  return n;
}

/* The reader's output checked: no error reported (events, GetErrorCode()), as many scalar values
 * as points, finite positive-length spacing and a finite origin. Returns a shallow copy. */
vtkSmartPointer<vtkImageData> CheckedOutput(
  vtkAlgorithm* reader, vtkImageData* image, const std::string& what, const std::string& errors)
{
  if (!errors.empty())
  {
    Fail(what, errors);
  }
  if (reader->GetErrorCode() != 0)
  {
    Fail(what, std::string("the reader reported ") + vtkErrorCode::GetStringFromErrorCode(reader->GetErrorCode()) +
        " (truncated or corrupt file?)");
  }
  if (!image || image->GetNumberOfPoints() == 0)
  {
    Fail(what, "the file holds no voxels");
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars)
  {
    Fail(what, "the file holds no point scalars");
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    int e[6];
    image->GetExtent(e);
    Fail(what, "it describes " + Describe(e, image->GetNumberOfPoints()) + " but holds " +
        std::to_string(scalars->GetNumberOfTuples()) + " values (truncated file?)");
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  static const char* const axis[3] = { "x", "y", "z" };
  for (int i = 0; i < 3; ++i)
  {
    if (!std::isfinite(spacing[i]) || spacing[i] == 0.0)
    {
      std::ostringstream os;
      os << "its spacing along " << axis[i] << " is " << spacing[i] << " (must be finite and non-zero)";
      Fail(what, os.str());
    }
    if (!std::isfinite(origin[i]))
    {
      std::ostringstream os;
      os << "its origin along " << axis[i] << " is " << origin[i] << " (must be finite)";
      Fail(what, os.str());
    }
  }
  vtkSmartPointer<vtkImageData> copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  return copy;
}

/* vtkNrrdReader reads a raw-encoded file that is too short without a word (the rest of the
 * volume stays uninitialised): its data files (after UpdateInformation) are checked to hold the
 * bytes the header describes, and to be regular files (a detached .nhdr names them). */
class CheckedNrrdReader : public vtkNrrdReader
{
public:
  static CheckedNrrdReader* New();
  vtkTypeMacro(CheckedNrrdReader, vtkNrrdReader);

  /** Empty when the data files can hold `points` values, else the reason. */
  std::string CheckDataFiles(const std::string& header, vtkIdType points, const int extent[6])
  {
    // A header without a valid "dimension" field leaves vtkImageReader2's per-slice file
    // layout (FileDimensionality 2) in place for a multi-slice extent: the raw read then ran
    // on a stream it never opened (SEGV, found by fuzz_volume_file).
    const bool oneSlice = extent[4] == extent[5];
    if (!(this->FileDimensionality == 3 || (this->FileDimensionality == 2 && oneSlice)))
    {
      return "its header gives " + std::to_string(this->FileDimensionality) +
        " file dimensions for a volume of " + std::to_string(extent[5] - extent[4] + 1) +
        " slices (a missing or misplaced \"dimension\" field?)";
    }
    // An attached header (.nrrd) holds the data itself: no DataFiles then.
    std::vector<std::string> names;
    for (vtkIdType i = 0; this->DataFiles && i < this->DataFiles->GetNumberOfValues(); ++i)
    {
      names.push_back(this->DataFiles->GetValue(i));
    }
    if (names.empty())
    {
      names.push_back(header);
    }
    for (const std::string& file : names)
    {
      if (file != header)
      {
        CheckRegularFile(file, "the data file of " + Quote(header) + ",");
      }
    }
    const vtkIdType files = vtkIdType(names.size());
    if (this->Encoding != ENCODING_RAW)
    {
      return std::string(); // gzip and ascii readers report short data themselves
    }
    const uintmax_t bytes = uintmax_t(points) * uintmax_t(std::max(1, this->NumberOfScalarComponents)) *
      uintmax_t(vtkDataArray::GetDataTypeSize(this->DataScalarType));
    const uintmax_t perFile = bytes / uintmax_t(files);
    for (const std::string& file : names)
    {
      std::error_code ec;
      const uintmax_t size = fs::file_size(file, ec);
      const uintmax_t header = this->HeaderSize;
      if (ec || size < header || size - header < perFile)
      {
        return "the data file " + Quote(file) + " holds " + std::to_string(ec || size < header ? 0 : size - header) +
          " bytes of data, the header describes " + std::to_string(perFile) + " (truncated file?)";
      }
    }
    return std::string();
  }

protected:
  CheckedNrrdReader() = default;
  ~CheckedNrrdReader() override = default;
};
vtkStandardNewMacro(CheckedNrrdReader);

/* Runs a vtkImageReader2 (NIfTI, MetaImage, NRRD): the header first, the size it claims checked
 * against `maxPoints` before anything is allocated, then the data. */
vtkSmartPointer<vtkImageData> RunImageReader(vtkImageReader2* reader, const std::string& path, vtkIdType maxPoints,
  const VolumeSizeCheck& check, const VolumeHeaderSeen& seen)
{
  const std::string what = Quote(path);
  const bool metaImage = reader->IsA("vtkMetaImageReader");
  ErrorCollector errors(reader);
  std::unique_ptr<MetaIOMessages> metaio(metaImage ? new MetaIOMessages : nullptr);
  auto metaText = [&metaio]() { return metaio ? metaio->Text() : std::string(); };
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  if (!errors.Text.empty() || !metaText().empty())
  {
    Fail(what, errors.Text.empty() ? metaText() : errors.Text);
  }
  int extent[6];
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  const vtkIdType points = PointCount(extent);
  if (points == 0)
  {
    Fail(what, "its header describes an empty volume");
  }
  if (points > maxPoints)
  {
    Fail(what, "its header describes " + Describe(extent, points) + ", more than the " + std::to_string(maxPoints) +
        " points this tool reads");
  }
  if (check)
  {
    const std::string problem =
      check({ extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1 });
    if (!problem.empty())
    {
      Fail(what, "its header describes " + Describe(extent, points) + ": " + problem);
    }
  }
  if (reader->GetNumberOfScalarComponents() != 1)
  {
    Fail(what, "it has " + std::to_string(reader->GetNumberOfScalarComponents()) +
        " components per voxel; only single-component volumes are rendered");
  }
  if (auto* nrrd = CheckedNrrdReader::SafeDownCast(reader))
  {
    const std::string problem = nrrd->CheckDataFiles(path, points, extent);
    if (!problem.empty())
    {
      Fail(what, problem);
    }
  }
  if (seen)
  {
    VolumeHeader header;
    vtkInformation* info = reader->GetOutputInformation(0);
    std::copy(extent, extent + 6, header.Extent);
    info->Get(vtkDataObject::SPACING(), header.Spacing);
    info->Get(vtkDataObject::ORIGIN(), header.Origin);
    header.ScalarType = reader->GetDataScalarType();
    seen(header);
  }
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    Fail(what, "out of host memory for " + Describe(extent, points));
  }
  std::string text = errors.Text;
  const std::string meta = metaText();
  if (!meta.empty())
  {
    text += (text.empty() ? "" : "; ") + meta + " (truncated file or missing data file?)";
  }
  return CheckedOutput(reader, reader->GetOutput(), what, text);
}

/* A .mhd names its data file: it must be a regular file too (MetaIO would block on a FIFO). */
void CheckMetaImageDataFile(const std::string& path)
{
  MetaIOMessages quiet;
  vtkmetaio::MetaImage header;
  if (!header.Read(path.c_str(), false))
  {
    Fail(Quote(path), "not a MetaImage header" + (quiet.Text().empty() ? std::string() : " (" + quiet.Text() + ")"));
  }
  const std::string data = header.ElementDataFileName();
  if (data.empty())
  {
    // MetaIO then sizes a compressed read from a stream it failed to open (an allocation of
    // 2^63 bytes, found by fuzz_volume_file).
    Fail(Quote(path), "its ElementDataFile names no data file (LOCAL or a file name)");
  }
  const bool local = data == "LOCAL" || data == "Local" || data == "local";
  // MetaIO allocates CompressedDataSize bytes before reading them (a header claiming 2^63 was an
  // allocation failure, found by fuzz_volume_file): it must fit in the file that holds the data.
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && line.rfind("ElementDataFile", 0) != 0)
  {
    if (line.rfind("CompressedDataSize", 0) == 0)
    {
      const auto eq = line.find('=');
      const double claimed = eq == std::string::npos ? -1.0 : std::strtod(line.c_str() + eq + 1, nullptr);
      fs::path holder(local ? path : data);
      if (holder.is_relative() && !local)
      {
        holder = fs::path(path).parent_path() / holder;
      }
      std::error_code ec;
      const double size = double(fs::file_size(holder, ec));
      if (!(claimed >= 0.0) || (!ec && claimed > size))
      {
        Fail(Quote(path), "its CompressedDataSize (" + line.substr(eq == std::string::npos ? 0 : eq + 1) +
            ") exceeds the " + std::to_string(ec ? 0.0 : size) + " bytes of " + Quote(holder.string()));
      }
    }
  }
  if (local || data.find('%') != std::string::npos || data.rfind("LIST", 0) == 0)
  {
    return; // in the same file, or a list/pattern of slices MetaIO resolves itself
  }
  fs::path file(data);
  if (file.is_relative())
  {
    file = fs::path(path).parent_path() / file;
  }
  CheckRegularFile(file.string(), "the data file of " + Quote(path) + ",");
}

vtkSmartPointer<vtkImageData> RunVDB(vtkOpenVDBVolumeReader* reader, const std::string& what, int step)
{
  ErrorCollector errors(reader);
  reader->UpdateInformation();
  if (errors.Text.empty())
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
  return CheckedOutput(reader, reader->GetOutput(), what, errors.Text);
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
    CheckRegularFile(f, "volume file");
  }
  vtkNew<vtkOpenVDBVolumeReader> reader;
  for (const auto& f : files)
  {
    reader->AddFileName(f.c_str());
  }
  reader->SetGridName(grid.c_str());
  return RunVDB(reader, "'" + files[static_cast<size_t>(step)] + "' (grid '" + grid + "')", step);
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string& grid, vtkIdType maxPoints)
{
  return ReadVolume(path, grid, maxPoints, VolumeSizeCheck());
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string& grid, vtkIdType maxPoints,
  const VolumeSizeCheck& check, const VolumeHeaderSeen& seen)
{
  auto checked = [&](vtkSmartPointer<vtkImageData> image) {
    if (check && image)
    {
      int d[3];
      image->GetDimensions(d);
      const std::string problem = check({ d[0], d[1], d[2] });
      if (!problem.empty())
      {
        Fail(Quote(path), problem);
      }
    }
    return image;
  };
  std::error_code ec;
  if (fs::is_directory(path, ec))
  {
    vtkNew<vtkDICOMImageReader> reader;
    ErrorCollector errors(reader.Get());
    reader->SetDirectoryName(path.c_str());
    reader->Update();
    if (errors.Text.empty() && (!reader->GetOutput() || reader->GetOutput()->GetNumberOfPoints() == 0))
    {
      throw std::runtime_error("no DICOM series in folder '" + path + "'");
    }
    return checked(CheckedOutput(reader, reader->GetOutput(), "the DICOM folder " + Quote(path), errors.Text));
  }
  CheckRegularFile(path, "volume file");
  if (EndsWith(path, ".vti"))
  {
    vtkNew<vtkXMLImageDataReader> reader;
    ErrorCollector errors(reader.Get());
    reader->SetFileName(path.c_str());
    reader->Update();
    return checked(CheckedOutput(reader, reader->GetOutput(), Quote(path), errors.Text));
  }
  if (EndsWith(path, ".mha") || EndsWith(path, ".mhd"))
  {
    CheckMetaImageDataFile(path);
    vtkNew<vtkMetaImageReader> r;
    return RunImageReader(r.Get(), path, maxPoints, check, seen);
  }
  if (EndsWith(path, ".nrrd") || EndsWith(path, ".nhdr"))
  {
    vtkNew<CheckedNrrdReader> r;
    return RunImageReader(r.Get(), path, maxPoints, check, seen);
  }
  if (EndsWith(path, ".nii") || EndsWith(path, ".nii.gz"))
  {
    vtkNew<vtkNIFTIImageReader> r;
    return RunImageReader(r.Get(), path, maxPoints, check, seen);
  }
  if (EndsWith(path, ".vdb"))
  {
    vtkNew<vtkOpenVDBVolumeReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetGridName(grid.c_str());
    reader->SetMaximumNumberOfPoints(maxPoints);
    if (check)
    {
      // The grid's extent from its metadata, before its voxels are read.
      reader->UpdateInformation();
      int e[6];
      reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
      if (e[1] >= e[0] && e[3] >= e[2] && e[5] >= e[4])
      {
        const std::string problem = check({ e[1] - e[0] + 1, e[3] - e[2] + 1, e[5] - e[4] + 1 });
        if (!problem.empty())
        {
          Fail("'" + path + "' (grid '" + grid + "')", "its grid spans " + Describe(e, PointCount(e)) + ": " + problem);
        }
      }
    }
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
