#include "vtkOpenVDBVolumeReader.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "vsOpenVDBFile.h"
#include "vsOpenVDBGeometry.h"
#include "vsOpenVDBText.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <new>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenVDBVolumeReader);

namespace
{
using Frame = vs::OpenVDBFile::Frame;
using GridSummary = vs::OpenVDBFile::GridSummary;

/* Checks the printf pattern: exactly one integer conversion, %% allowed. */
bool CheckPattern(const std::string& pattern, std::string& why)
{
  int conversions = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i)
  {
    if (pattern[i] != '%')
    {
      continue;
    }
    ++i;
    if (i < pattern.size() && pattern[i] == '%')
    {
      continue;
    }
    while (i < pattern.size() && std::string("-+ 0#").find(pattern[i]) != std::string::npos)
    {
      ++i;
    }
    std::size_t digits = 0;
    while (i < pattern.size() && pattern[i] >= '0' && pattern[i] <= '9')
    {
      ++i;
      ++digits;
    }
    if (i >= pattern.size() || digits > 3 ||
      std::string("diu").find(pattern[i]) == std::string::npos)
    {
      why = "it must hold exactly one integer conversion such as %d or %04d (and %% for a "
            "literal %), and holds an unsupported one";
      return false;
    }
    ++conversions;
  }
  if (conversions != 1)
  {
    why = "it must hold exactly one integer conversion such as %d or %04d, and holds " +
      std::to_string(conversions);
    return false;
  }
  return true;
}

/* Index of the time value nearest to t (0 when there are none). */
int NearestStep(const std::vector<double>& times, double t)
{
  int best = 0;
  for (int i = 1; i < int(times.size()); ++i)
  {
    if (std::abs(times[i] - t) < std::abs(times[best] - t))
    {
      best = i;
    }
  }
  return best;
}
} // namespace

struct vtkOpenVDBVolumeReader::Internals
{
  std::vector<std::string> FileNames; // the user's list
  std::vector<Frame> Frames;          // the resolved sequence (RequestInformation)
  std::vector<double> Times;          // TIME_STEPS (empty when not temporal)
  std::vector<GridSummary> Grids;     // grids of the first file
  bool InformationFailed = true;
  bool UseUnion = false;
  openvdb::CoordBBox Union;
  int PublishedStep = -1;

  int StepFor(vtkInformation* outInfo) const
  {
    if (this->Times.empty() || !outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      return 0;
    }
    return NearestStep(
      this->Times, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  }

  const openvdb::CoordBBox& BoxFor(int step) const
  {
    return this->UseUnion ? this->Union : this->Frames[step].Box;
  }
};

//------------------------------------------------------------------------------
vtkOpenVDBVolumeReader::vtkOpenVDBVolumeReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
  this->SetGridName("density");
}

vtkOpenVDBVolumeReader::~vtkOpenVDBVolumeReader()
{
  this->SetFileName(nullptr);
  this->SetFilePattern(nullptr);
  this->SetGridName(nullptr);
  delete this->Internal;
}

//------------------------------------------------------------------------------
void vtkOpenVDBVolumeReader::AddFileName(const char* fileName)
{
  this->Internal->FileNames.emplace_back(fileName ? fileName : "");
  this->Modified();
}

void vtkOpenVDBVolumeReader::RemoveAllFileNames()
{
  if (!this->Internal->FileNames.empty())
  {
    this->Internal->FileNames.clear();
    this->Modified();
  }
}

int vtkOpenVDBVolumeReader::GetNumberOfFileNames()
{
  return int(this->Internal->FileNames.size());
}

const char* vtkOpenVDBVolumeReader::GetNthFileName(int i)
{
  const auto& names = this->Internal->FileNames;
  return i >= 0 && i < int(names.size()) ? names[i].c_str() : nullptr;
}

int vtkOpenVDBVolumeReader::GetNumberOfTimeSteps()
{
  return int(this->Internal->Frames.size());
}

const char* vtkOpenVDBVolumeReader::GetTimeStepFileName(int i)
{
  const auto& frames = this->Internal->Frames;
  return i >= 0 && i < int(frames.size()) ? frames[i].File.c_str() : nullptr;
}

//------------------------------------------------------------------------------
int vtkOpenVDBVolumeReader::GetNumberOfGrids()
{
  return int(this->Internal->Grids.size());
}

const char* vtkOpenVDBVolumeReader::GetGridName(int i)
{
  const auto& g = this->Internal->Grids;
  return i >= 0 && i < int(g.size()) ? g[i].Name.c_str() : nullptr;
}

const char* vtkOpenVDBVolumeReader::GetGridType(int i)
{
  const auto& g = this->Internal->Grids;
  return i >= 0 && i < int(g.size()) ? g[i].Type.c_str() : nullptr;
}

vtkIdType vtkOpenVDBVolumeReader::GetGridActiveVoxelCount(int i)
{
  const auto& g = this->Internal->Grids;
  return i >= 0 && i < int(g.size()) ? g[i].Count : 0;
}

void vtkOpenVDBVolumeReader::GetGridBounds(int i, double bounds[6])
{
  const auto& g = this->Internal->Grids;
  const GridSummary empty;
  const GridSummary& s = i >= 0 && i < int(g.size()) ? g[i] : empty;
  std::copy(s.Bounds, s.Bounds + 6, bounds);
}

void vtkOpenVDBVolumeReader::GetGridIndexBounds(int i, int bounds[6])
{
  const auto& g = this->Internal->Grids;
  const GridSummary empty;
  const GridSummary& s = i >= 0 && i < int(g.size()) ? g[i] : empty;
  std::copy(s.IndexBounds, s.IndexBounds + 6, bounds);
}

//------------------------------------------------------------------------------
int vtkOpenVDBVolumeReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::ifstream in(fileName, std::ios::binary);
  unsigned char magic[8] = { 0 };
  if (!in || !in.read(reinterpret_cast<char*>(magic), 8))
  {
    return 0;
  }
  // OPENVDB_MAGIC (0x56444220, " BDV") as a little-endian 64-bit integer.
  const unsigned char expected[8] = { 0x20, 0x42, 0x44, 0x56, 0, 0, 0, 0 };
  return std::equal(magic, magic + 8, expected) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkOpenVDBVolumeReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  Internals& in = *this->Internal;
  in.Frames.clear();
  in.Times.clear();
  in.Grids.clear();
  in.InformationFailed = true;
  in.UseUnion = false;
  in.Union = openvdb::CoordBBox();
  in.PublishedStep = -1;
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  // A failure publishes an empty extent (the error is reported), not a pipeline failure, and
  // RequestData then empties the output.
  const int emptyExtent[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), emptyExtent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);

  // The files of the sequence.
  std::vector<std::string> files;
  if (!in.FileNames.empty())
  {
    files = in.FileNames;
  }
  else if (this->FilePattern && *this->FilePattern)
  {
    std::string why;
    if (!CheckPattern(this->FilePattern, why))
    {
      vtkErrorMacro("FilePattern " << vs::Quote(this->FilePattern) << " is not usable: " << why);
      return 1;
    }
    if (this->FileIndexRange[1] < this->FileIndexRange[0])
    {
      vtkErrorMacro("FileIndexRange (" << this->FileIndexRange[0] << ", " << this->FileIndexRange[1]
                                       << ") is empty: the last index is below the first");
      return 1;
    }
    for (int64_t i = this->FileIndexRange[0]; i <= this->FileIndexRange[1];
         i += this->FileIndexIncrement)
    {
      // CheckPattern allows widths up to 999 and no other conversion.
      std::vector<char> buffer(std::string(this->FilePattern).size() + 1024);
      std::snprintf(buffer.data(), buffer.size(), this->FilePattern, int(i));
      files.emplace_back(buffer.data());
    }
  }
  else if (this->FileName && *this->FileName)
  {
    files.emplace_back(this->FileName);
  }
  else
  {
    vtkErrorMacro(
      "No file to read: set FileName, FilePattern (with FileIndexRange) or AddFileName().");
    return 1;
  }
  if (!this->GridName || !*this->GridName)
  {
    vtkErrorMacro("GridName is empty: name the float grid to read (default \"density\").");
    return 1;
  }

  vs::OpenVDBFile::Initialize();
  for (std::size_t s = 0; s < files.size(); ++s)
  {
    Frame frame;
    std::string error;
    if (!vs::OpenVDBFile::Scan(
          files[s], this->GridName, s == 0 ? &in.Grids : nullptr, frame, error))
    {
      in.Frames.clear();
      vtkErrorMacro(<< (files.size() > 1 ? "time step " + std::to_string(s) + ": " : std::string())
                    << error);
      return 1;
    }
    in.Frames.push_back(frame);
  }

  const int n = int(in.Frames.size());
  if (n > 1)
  {
    for (int s = 0; s < n; ++s)
    {
      in.Times.push_back(double(s));
    }
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), in.Times.data(), n);
    const double range[2] = { in.Times.front(), in.Times.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }

  if (this->UnionBounds && n > 1)
  {
    in.UseUnion = true;
    for (int s = 1; s < n && in.UseUnion; ++s)
    {
      in.UseUnion = vs::SameTransform(in.Frames[s].Matrix, in.Frames[0].Matrix);
    }
    if (!in.UseUnion)
    {
      vtkWarningMacro("UnionBounds: the files of the sequence do not share one transform (e.g. "
        << vs::Quote(in.Frames[0].File)
        << " and another differ in voxel size or origin); each time step covers its own bounding "
           "box.");
    }
    for (int s = 0; s < n && in.UseUnion; ++s)
    {
      if (!in.Frames[s].Box.empty())
      {
        in.Union.expand(in.Frames[s].Box);
      }
    }
  }

  const int step = in.StepFor(outInfo);
  vs::OutputGeometry g;
  std::string error;
  if (!vs::MakeOutputGeometry(
        in.BoxFor(step), in.Frames[step].Map, this->Padding, this->MaximumNumberOfPoints, g, error))
  {
    vtkErrorMacro(<< vs::Quote(in.Frames[step].File) << ": " << error);
    return 1;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), g.Extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), g.Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), g.Spacing, 3);
  in.PublishedStep = step;
  in.InformationFailed = false;
  return 1;
}

//------------------------------------------------------------------------------
int vtkOpenVDBVolumeReader::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Without a union box the extent follows the time step: publish the requested step's
  // geometry (this reader always produces a step's whole extent).
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  Internals& in = *this->Internal;
  if (in.InformationFailed || in.UseUnion || in.Frames.size() < 2)
  {
    return 1;
  }
  const int step = in.StepFor(outInfo);
  if (step == in.PublishedStep)
  {
    return 1;
  }
  vs::OutputGeometry g;
  std::string error;
  if (vs::MakeOutputGeometry(
        in.BoxFor(step), in.Frames[step].Map, this->Padding, this->MaximumNumberOfPoints, g, error))
  {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), g.Extent, 6);
    outInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), g.Extent, 6);
    outInfo->Set(vtkDataObject::ORIGIN(), g.Origin, 3);
    outInfo->Set(vtkDataObject::SPACING(), g.Spacing, 3);
    in.PublishedStep = step;
  }
  return 1; // a geometry error is reported by RequestData
}

//------------------------------------------------------------------------------
int vtkOpenVDBVolumeReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  Internals& in = *this->Internal;
  output->Initialize();
  if (in.InformationFailed || in.Frames.empty())
  {
    return 1; // reported by RequestInformation
  }
  this->UpdateProgress(0.0);
  const int step = in.StepFor(outInfo);
  const Frame& frame = in.Frames[step];
  const std::string stepText =
    in.Frames.size() > 1 ? "time step " + std::to_string(step) + ": " : std::string();
  vs::OutputGeometry g;
  std::string error;
  if (!vs::MakeOutputGeometry(
        in.BoxFor(step), frame.Map, this->Padding, this->MaximumNumberOfPoints, g, error))
  {
    vtkErrorMacro(<< stepText << vs::Quote(frame.File) << ": " << error);
    return 1;
  }

  openvdb::FloatGrid::Ptr grid;
  try
  {
    openvdb::io::File file(frame.File);
    if (!vs::OpenVDBFile::Open(file, this->GridName, error))
    {
      vtkErrorMacro(<< stepText << error);
      return 1;
    }
    this->UpdateProgress(0.1);
    // The type first: the file was only checked deeply for a float tree.
    openvdb::GridBase::Ptr meta = file.readGridMetadata(this->GridName);
    if (!meta->isType<openvdb::FloatGrid>())
    {
      vtkErrorMacro(<< stepText << "grid " << vs::Quote(this->GridName) << " of "
                    << vs::Quote(frame.File) << " holds " << meta->valueType()
                    << " values; only float grids are supported");
      return 1;
    }
    grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(this->GridName));
    if (!grid)
    {
      vtkErrorMacro(<< stepText << "cannot read grid " << vs::Quote(this->GridName) << " of "
                    << vs::Quote(frame.File));
      return 1;
    }
    if (!vs::SameTransform(grid->transform().baseMap()->getAffineMap()->getMat4(), frame.Matrix))
    {
      vtkErrorMacro(
        << stepText << vs::Quote(frame.File)
        << " changed since RequestInformation (another transform); call Modified() to re-read it.");
      return 1;
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< stepText << "cannot read grid " << vs::Quote(this->GridName) << " of "
                  << vs::Quote(frame.File) << " (truncated or corrupt?): " << vs::Describe(e));
    return 1;
  }
  this->UpdateProgress(0.6);

  // The values and the active voxels' box against the file's metadata (damaged leaf data; a
  // corrupt box, checked before allocating).
  const std::string damage = vs::OpenVDBFile::CheckGrid(*grid, frame, this->GridName);
  if (!damage.empty())
  {
    vtkErrorMacro(<< stepText << damage);
    return 1;
  }
  if (g.Empty)
  {
    vtkWarningMacro(
      << stepText << "grid " << vs::Quote(this->GridName) << " of " << vs::Quote(frame.File)
      << " has no active voxels: the output is one voxel of background at index (0,0,0)"
      << (this->Padding ? " plus padding" : "") << ".");
  }

  vtkNew<vtkFloatArray> values;
  values->SetName(this->GridName);
  try
  {
    values->SetNumberOfValues(g.Points);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< stepText << "out of memory for " << g.Points << " voxels of "
                  << vs::Quote(frame.File));
    return 1;
  }
  if (values->GetNumberOfValues() != g.Points)
  {
    vtkErrorMacro(<< stepText << "out of memory for " << g.Points << " voxels of "
                  << vs::Quote(frame.File));
    return 1;
  }

  // Point (x, y, z) of the image is voxel lo + p (hi - p on a flipped axis); inactive
  // voxels read as the background, whatever value they store.
  const int nx = g.Extent[1] + 1, ny = g.Extent[3] + 1, nz = g.Extent[5] + 1;
  const openvdb::Coord lo = g.Region.min(), hi = g.Region.max();
  const float background = grid->background();
  float* dst = values->GetPointer(0);
  const openvdb::FloatGrid& source = *grid;
  auto index = [&](int axis, int p) { return g.Flip[axis] ? hi[axis] - p : lo[axis] + p; };
  const int chunks = std::max(1, std::min(nz, 10));
  for (int c = 0; c < chunks && !this->GetAbortExecute(); ++c)
  {
    const vtkIdType k0 = vtkIdType(nz) * c / chunks, k1 = vtkIdType(nz) * (c + 1) / chunks;
    vtkSMPTools::For(k0, k1,
      [&](vtkIdType kb, vtkIdType ke)
      {
        openvdb::FloatGrid::ConstAccessor acc = source.getConstAccessor();
        for (vtkIdType z = kb; z < ke; ++z)
        {
          for (int y = 0; y < ny; ++y)
          {
            float* row = dst + (vtkIdType(z) * ny + y) * nx;
            openvdb::Coord ijk(0, index(1, y), index(2, int(z)));
            for (int x = 0; x < nx; ++x)
            {
              ijk[0] = index(0, x);
              float v;
              row[x] = acc.probeValue(ijk, v) ? v : background;
            }
          }
        }
      });
    this->UpdateProgress(0.6 + 0.4 * double(c + 1) / chunks);
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }

  output->SetExtent(g.Extent);
  output->SetOrigin(g.Origin);
  output->SetSpacing(g.Spacing);
  output->GetPointData()->SetScalars(values);
  if (!in.Times.empty())
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), in.Times[step]);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenVDBVolumeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NumberOfFileNames: " << this->Internal->FileNames.size() << "\n";
  for (const std::string& f : this->Internal->FileNames)
  {
    os << indent.GetNextIndent() << f << "\n";
  }
  os << indent << "FilePattern: " << (this->FilePattern ? this->FilePattern : "(none)") << "\n";
  os << indent << "FileIndexRange: " << this->FileIndexRange[0] << ", " << this->FileIndexRange[1]
     << "\n";
  os << indent << "FileIndexIncrement: " << this->FileIndexIncrement << "\n";
  os << indent << "GridName: " << (this->GridName ? this->GridName : "(none)") << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "UnionBounds: " << (this->UnionBounds ? "On" : "Off") << "\n";
  os << indent << "MaximumNumberOfPoints: " << this->MaximumNumberOfPoints << "\n";
  os << indent << "NumberOfTimeSteps: " << this->Internal->Frames.size() << "\n";
  os << indent << "NumberOfGrids: " << this->Internal->Grids.size() << "\n";
  for (const GridSummary& s : this->Internal->Grids)
  {
    os << indent.GetNextIndent() << s.Name << " (" << s.Type << ", " << s.Count
       << " active voxels)\n";
  }
}
