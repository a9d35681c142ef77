// vsOpenVDBFile.cxx — opening, listing and scanning a .vdb file, and checking the grid read
// against its metadata (vsOpenVDBFile.h).
#include "vsOpenVDBFile.h"

#include "vsOpenVDBFileCheck.h"
#include "vsOpenVDBText.h"
#include "vtkOpenVDBVolumeReader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace vs
{
namespace
{
using GridSummary = OpenVDBFile::GridSummary;

/* The grid statistics OpenVDB writes as metadata (file_voxel_count, file_bbox_min/max), or
 * false when the writer left them out. */
bool StatsFromMetadata(
  const openvdb::GridBase& grid, openvdb::Index64& count, openvdb::CoordBBox& box)
{
  auto bmin = grid.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
  auto bmax = grid.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
  auto n = grid.getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT);
  if (!bmin || !bmax || !n)
  {
    return false;
  }
  count = openvdb::Index64(std::max<int64_t>(0, n->value()));
  box = openvdb::CoordBBox(openvdb::Coord(bmin->value()), openvdb::Coord(bmax->value()));
  if (count == 0 || box.empty())
  {
    box = openvdb::CoordBBox(); // empty
  }
  return true;
}

std::string ListGrids(const std::vector<GridSummary>& grids)
{
  if (grids.empty())
  {
    return "the file holds no grids";
  }
  std::string s = "the file holds ";
  for (std::size_t i = 0; i < grids.size(); ++i)
  {
    s += (i ? ", " : "") + Quote(grids[i].Name) + " (" + grids[i].Type + ")";
  }
  return s;
}

/* Walks the tree of float grid `gridName` before OpenVDB reads it in full (OpenVDBFileCheck). */
void DeepCheck(const std::string& path, const std::string& gridName)
{
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  OpenVDBFileCheck checker;
  checker.Check(path, ec ? 0 : int64_t(size), gridName);
}

/* The grids of an open file in file order (`names`, or io::File's order by name when that is
 * empty), from metadata. A grid without statistics is read in full if it is the float grid
 * `checkedGrid` (the one OpenVDBFileCheck walked); otherwise its count is -1 (unknown). */
std::vector<GridSummary> Summarize(
  openvdb::io::File& file, const std::vector<std::string>& names, const std::string& checkedGrid)
{
  std::vector<GridSummary> out;
  openvdb::GridPtrVecPtr grids;
  if (names.empty())
  {
    grids = file.readAllGridMetadata();
  }
  else
  {
    grids.reset(new openvdb::GridPtrVec);
    for (const std::string& name : names)
    {
      grids->push_back(file.readGridMetadata(name));
    }
  }
  for (std::size_t i = 0; i < grids->size(); ++i)
  {
    const openvdb::GridBase::Ptr& g = (*grids)[i];
    GridSummary s;
    // The unique name ("density[1]" for a second grid called "density") is what readGrid takes.
    s.Name = names.empty() ? g->getName() : names[i];
    s.Type = g->valueType();
    openvdb::Index64 count = 0;
    openvdb::CoordBBox box;
    s.Count = -1;
    if (StatsFromMetadata(*g, count, box))
    {
      s.Count = vtkIdType(count);
    }
    else if ((s.Name == checkedGrid || g->getName() == checkedGrid) &&
      g->isType<openvdb::FloatGrid>())
    {
      // Check the grid that is read: s.Name (the descriptor's unique name). The grid's "name"
      // metadata can differ from it in a corrupt file, and checking checkedGrid then checked
      // nothing (found by fuzzing: OpenVDB read an unchecked tree and allocated a Blosc chunk
      // whose size was text).
      DeepCheck(file.filename(), s.Name);
      openvdb::GridBase::Ptr full = file.readGrid(s.Name);
      count = full->activeVoxelCount();
      box = count ? full->evalActiveVoxelBoundingBox() : openvdb::CoordBBox();
      s.Count = vtkIdType(count);
    }
    if (!box.empty())
    {
      for (int a = 0; a < 3; ++a)
      {
        s.IndexBounds[2 * a] = box.min()[a];
        s.IndexBounds[2 * a + 1] = box.max()[a];
        s.Bounds[2 * a] = std::numeric_limits<double>::infinity();
        s.Bounds[2 * a + 1] = -std::numeric_limits<double>::infinity();
      }
      // The eight corner voxels' centres (any linear or frustum transform).
      for (int c = 0; c < 8; ++c)
      {
        const openvdb::Vec3d ijk((c & 1 ? box.max() : box.min())[0],
          (c & 2 ? box.max() : box.min())[1], (c & 4 ? box.max() : box.min())[2]);
        const openvdb::Vec3d w = g->transform().indexToWorld(ijk);
        for (int a = 0; a < 3; ++a)
        {
          s.Bounds[2 * a] = std::min(s.Bounds[2 * a], w[a]);
          s.Bounds[2 * a + 1] = std::max(s.Bounds[2 * a + 1], w[a]);
        }
      }
    }
    out.push_back(s);
  }
  return out;
}
} // namespace

//------------------------------------------------------------------------------
void OpenVDBFile::Initialize()
{
  // openvdb::initialize() registers the grid, map and metadata types; once per process.
  static const bool initialized = []()
  {
    openvdb::initialize();
    return true;
  }();
  (void)initialized;
}

//------------------------------------------------------------------------------
bool OpenVDBFile::Open(openvdb::io::File& file, const std::string& topologyGrid,
  std::string& error, std::vector<std::string>* names)
{
  const std::string& path = file.filename();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
  {
    error = Quote(path) + ": no such file";
    return false;
  }
  if (std::filesystem::is_directory(status))
  {
    error = Quote(path) + " is a directory, not a .vdb file";
    return false;
  }
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec)
  {
    error = Quote(path) + ": cannot read the file size (" + ec.message() + ")";
    return false;
  }
  // A file shorter than the magic number that is the start of it (an empty file too) is a VDB
  // file cut short: the check reports its truncated header.
  if (!vtkOpenVDBVolumeReader::CanReadFile(path.c_str()) &&
    !OpenVDBFileCheck::EndsInsideMagic(path, int64_t(size)))
  {
    error = Quote(path) + " is not a VDB file (it does not start with OpenVDB's magic number)";
    return false;
  }
  // Checked before OpenVDB parses anything beyond the magic number (first the header's length).
  OpenVDBFileCheck checker;
  try
  {
    checker.Check(path, int64_t(size), topologyGrid);
  }
  catch (const std::exception& e)
  {
    std::string why = Describe(e);
    if (why.rfind("IoError: ", 0) == 0)
    {
      why = why.substr(9);
    }
    error = Quote(path) + " is truncated or corrupt: " + why;
    return false;
  }
  if (checker.Streamed)
  {
    error = Quote(path) + " has no grid offsets (it was written as a stream, openvdb::io::Stream): "
      "OpenVDB reads such files without checking any size, so they are not supported; "
      "write it with openvdb::io::File (openvdb.write in Python)";
    return false;
  }
  // Without delayed loading: every read error surfaces in readGrid, not later.
  file.open(/*delayLoad=*/false);
  if (names)
  {
    *names = checker.Names;
  }
  return true;
}

//------------------------------------------------------------------------------
bool OpenVDBFile::Scan(const std::string& path, const std::string& gridName,
  std::vector<GridSummary>* listing, Frame& frame, std::string& error)
{
  frame.File = path;
  try
  {
    openvdb::io::File file(path);
    std::vector<std::string> names;
    // The metadata only (RequestInformation opens every file of a sequence): no tree walk.
    if (!Open(file, std::string(), error, &names))
    {
      return false;
    }
    std::vector<GridSummary> grids;
    if (listing || !file.hasGrid(gridName))
    {
      grids = Summarize(file, names, gridName);
      if (listing)
      {
        *listing = grids;
      }
    }
    if (!file.hasGrid(gridName))
    {
      error = Quote(path) + " has no grid named " + Quote(gridName) + "; " + ListGrids(grids);
      return false;
    }
    openvdb::GridBase::Ptr grid = file.readGridMetadata(gridName);
    if (!grid->isType<openvdb::FloatGrid>())
    {
      error = "grid " + Quote(gridName) + " of " + Quote(path) + " holds " + grid->valueType() +
        " values (" + grid->type() + "); only float grids are supported";
      return false;
    }
    std::string why;
    if (!GetAxisMap(grid->transform(), frame.Map, why))
    {
      error = "grid " + Quote(gridName) + " of " + Quote(path) + ": " + why;
      return false;
    }
    frame.Matrix = grid->transform().baseMap()->getAffineMap()->getMat4();
    openvdb::Index64 count = 0;
    if (!StatsFromMetadata(*grid, count, frame.Box))
    {
      DeepCheck(path, gridName);
      openvdb::GridBase::Ptr full = file.readGrid(gridName);
      frame.Box =
        full->activeVoxelCount() ? full->evalActiveVoxelBoundingBox() : openvdb::CoordBBox();
    }
    return true;
  }
  catch (const std::exception& e)
  {
    error =
      "cannot read " + Quote(path) + " (not a VDB file, truncated or corrupt?): " + Describe(e);
    return false;
  }
}

//------------------------------------------------------------------------------
std::string OpenVDBFile::CheckGrid(
  const openvdb::FloatGrid& grid, const Frame& frame, const std::string& gridName)
{
  std::ostringstream s;
  // Damaged compressed leaf data (issue 13, item 2): Blosc carries no checksum, so a damaged chunk
  // of the right size decodes to other values without an error. What can be checked is: the
  // active voxels against the count the writer recorded (damaged value masks), and the values
  // themselves: a density grid holds finite values, and a fog volume (OpenVDB's convention:
  // densities from 0 to 1) none far outside [0, 1]. Damage that decodes to plausible values is
  // undetectable in this format.
  const auto recorded =
    grid.getMetadata<openvdb::Int64Metadata>(openvdb::GridBase::META_FILE_VOXEL_COUNT);
  if (recorded && recorded->value() >= 0 &&
    openvdb::Index64(recorded->value()) != grid.activeVoxelCount())
  {
    s << "grid " << Quote(gridName) << " of " << Quote(frame.File) << " has "
      << grid.activeVoxelCount() << " active voxels but the file's metadata says "
      << recorded->value() << " (damaged leaf data?)";
    return s.str();
  }
  openvdb::Index64 nonFinite = 0;
  float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
  for (auto it = grid.cbeginValueOn(); it; ++it)
  {
    const float v = *it;
    if (!std::isfinite(v))
    {
      ++nonFinite;
    }
    else
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (nonFinite > 0)
  {
    s << nonFinite << " active voxels of grid " << Quote(gridName) << " of " << Quote(frame.File)
      << " are NaN or infinite (damaged leaf data?)";
    return s.str();
  }
  // Fog volumes: far outside [0, 1] (by more than a factor 1000: real exports go somewhat past 1).
  if (grid.getGridClass() == openvdb::GRID_FOG_VOLUME && grid.activeVoxelCount() > 0 &&
    (lo < -1e3f || hi > 1e3f))
  {
    s << "grid " << Quote(gridName) << " of " << Quote(frame.File)
      << " is a fog volume (densities from 0 to 1) but holds values from " << lo << " to " << hi
      << " (damaged leaf data?)";
    return s.str();
  }

  // The extent came from the file's metadata: it must describe these voxels (checked before
  // allocating, a corrupt box being the way to a huge allocation).
  const openvdb::CoordBBox active =
    grid.activeVoxelCount() ? grid.evalActiveVoxelBoundingBox() : openvdb::CoordBBox();
  if (active != frame.Box && !(active.empty() && frame.Box.empty()))
  {
    s << "the active voxels of grid " << Quote(gridName) << " of " << Quote(frame.File) << " span "
      << active << " but the file's metadata says " << frame.Box
      << " (corrupt or stale file_bbox_min/max metadata).";
    return s.str();
  }
  return std::string();
}
}
