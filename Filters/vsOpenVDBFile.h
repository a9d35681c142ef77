// vsOpenVDBFile.h — a .vdb file as vtkOpenVDBVolumeReader reads it: opened only after the checks
// that keep OpenVDB from trusting a corrupt file (missing file, directory, magic number, then the
// walk of its structure, vs::OpenVDBFileCheck), its grids listed from their metadata
// (GridSummary), what RequestInformation learns about the grid to read (Frame), and the checks of
// the grid read against what the file's metadata says (damaged leaf data). Internal to
// VisSweep::Filters (hidden from the wrappers).
#ifndef vsOpenVDBFile_h
#define vsOpenVDBFile_h

#if !defined(__VTK_WRAP__)
#include "vsOpenVDBGeometry.h" // AxisMap

#include "vtkType.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <string>
#include <vector>

namespace vs
{
class OpenVDBFile
{
public:
  /** One grid of a file, from its metadata (Count -1: unknown, the writer left the statistics
   *  out; bounds empty when unknown or without active voxels). */
  struct GridSummary
  {
    std::string Name;
    std::string Type;
    vtkIdType Count = 0;
    int IndexBounds[6] = { 0, -1, 0, -1, 0, -1 };
    double Bounds[6] = { 1, -1, 1, -1, 1, -1 };
  };

  /** One time step: its file and what RequestInformation learnt about the grid. */
  struct Frame
  {
    std::string File;
    openvdb::CoordBBox Box; // active voxels, index space (empty when none)
    openvdb::Mat4d Matrix;
    AxisMap Map;
  };

  /** openvdb::initialize(): registers the grid, map and metadata types; once per process. */
  static void Initialize();

  /** Opens a VDB file for reading with the size check; throws OpenVDB's exceptions, returns
   *  false with a message for what is not an exception (missing file, truncation). `names`
   *  receives the grid names in file order when the file has grid offsets. The check also walks
   *  the tree of float grid `topologyGrid` (the grid RequestData reads; Scan passes none). */
  static bool Open(openvdb::io::File& file, const std::string& topologyGrid, std::string& error,
    std::vector<std::string>* names = nullptr);

  /** Everything RequestInformation needs from one file, without reading voxels (unless the
   *  statistics metadata is missing). `listing` (the first file) receives the grid summaries. */
  static bool Scan(const std::string& path, const std::string& gridName,
    std::vector<GridSummary>* listing, Frame& frame, std::string& error);

  /** An empty string when `grid` (grid `gridName` of frame.File, read) agrees with the file's
   *  metadata and holds plausible values, else the reason: an active voxel count other than the
   *  one recorded, NaN or infinite values, a fog volume far outside [0, 1], active voxels outside
   *  the box RequestInformation published (frame.Box). */
  static std::string CheckGrid(
    const openvdb::FloatGrid& grid, const Frame& frame, const std::string& gridName);
};
}
#endif

#endif
