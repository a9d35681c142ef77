// vsOpenVDBFileCheck.h — the check of a .vdb file's structure before OpenVDB reads it, for
// vtkOpenVDBVolumeReader. OpenVDB trusts every length and count it reads (a corrupt one makes it
// allocate without bound, or loop over a failed stream leaking nodes, instead of failing), so the
// check walks the file the way io::File and io::Archive read it and compares each of them with
// the bytes the file has. Internal to VisSweep::Filters (hidden from the wrappers).
#ifndef vsOpenVDBFileCheck_h
#define vsOpenVDBFileCheck_h

#if !defined(__VTK_WRAP__)
#include <cstdint>
#include <string>
#include <vector>

namespace vs
{
/** Walks the structure of a VDB file the way io::File and io::Archive read it, checking
 *  every length and count that OpenVDB would trust before allocating, against the bytes the
 *  file has: OpenVDB does not check its stream while it reads, so a corrupt length can make
 *  it allocate without bound (or loop over a failed stream leaking nodes) instead of failing.
 *  Also collects what io::File keeps private: the grids in file order and where each ends (a
 *  file cut short inside its last leaf nodes still "reads" in OpenVDB, the missing tail
 *  decompressing to garbage). Covers the header, the metadata, the grid descriptors and
 *  the transforms of every grid and, for the float grid to be read (topologyGrid), its whole
 *  tree: node masks, and the size and blosc header of every compressed chunk. What it cannot
 *  judge is left to OpenVDB (a map type it does not know, a blosc stream that does not
 *  decompress, values). */
class OpenVDBFileCheck
{
public:
  std::vector<std::string> Names; // file order; empty for a file without grid offsets
  int64_t LastGridEnd = -1;       // largest end offset of a grid; -1 without grid offsets
  bool Streamed = false;          // the file has no grid offsets (written by io::Stream)

  /** Throws openvdb::IoError naming what is corrupt (or OpenVDB's own exceptions). */
  void Check(const std::string& path, int64_t size, const std::string& topologyGrid);
};
}
#endif

#endif
