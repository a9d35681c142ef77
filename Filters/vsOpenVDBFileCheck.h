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
 *  decompressing to garbage). Covers the header (its length before anything reads it:
 *  io::Archive::readHeader does not check its stream either, and a file ending inside the
 *  header left fields uninitialised), the metadata, the grid descriptors and
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

  /** Throws openvdb::IoError naming what is corrupt (or OpenVDB's own exceptions). The first
   *  check is the length of the file header: a file that ends inside it (down to an empty
   *  file, or one cut inside the magic number) is reported as such. */
  void Check(const std::string& path, int64_t size, const std::string& topologyGrid);

  /** Whether a file of `size` bytes shorter than OpenVDB's 8-byte magic number is the start
   *  of one (an empty file included): a VDB file cut short, which Check reports as a
   *  truncated header rather than as a file of another kind. False for 8 bytes or more. */
  static bool EndsInsideMagic(const std::string& path, int64_t size);
};
}
#endif

#endif
