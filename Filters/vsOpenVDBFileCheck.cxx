// vsOpenVDBFileCheck.cxx — the walk of a .vdb file's structure (vs::OpenVDBFileCheck): an
// io::Archive, for the protected readers of the file header, that skips through the metadata,
// the grid descriptors, the transforms and the float tree to be read, checking each size on the
// way. Internal to VisSweep::Filters.
#include "vsOpenVDBFileCheck.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/Compression.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace vs
{
namespace
{
/* Whether the first n bytes of a file (n <= 8) are those of OPENVDB_MAGIC: a 64-bit integer
 * in the byte order io::Archive writes and reads it in (the machine's). */
bool StartsLikeMagic(const char* bytes, std::size_t n)
{
  const int64_t magic = openvdb::OPENVDB_MAGIC;
  return std::memcmp(bytes, &magic, std::min<std::size_t>(n, sizeof(magic))) == 0;
}

/* The bytes io::Archive::readHeader (OpenVDB 10) reads from a file of format `version`: the
 * magic number (8) and the format version (4); the library major and minor versions (4 + 4,
 * from format 211); the "has grid offsets" byte (from 212); a compression byte (formats 220
 * and 221 only); the UUID, 36 ASCII characters from format 218 (16 bytes before). 57 bytes for
 * every format this reader supports (222 and later). */
int64_t HeaderBytes(uint32_t version)
{
  int64_t n = 8 + 4;
  if (version >= 211)
  {
    n += 4 + 4;
  }
  if (version >= 212)
  {
    n += 1;
  }
  if (version >= openvdb::OPENVDB_FILE_VERSION_SELECTIVE_COMPRESSION &&
    version < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
  {
    n += 1;
  }
  n += version >= openvdb::OPENVDB_FILE_VERSION_BOOST_UUID ? 36 : 16;
  return n;
}

/* The walk of OpenVDBFileCheck::Check (see vsOpenVDBFileCheck.h): an io::Archive, whose protected
 * members read the header and set the stream's format version and compression as io::File does. */
class FileChecker : public openvdb::io::Archive
{
public:
  std::vector<std::string> Names; // file order; empty for a file without grid offsets
  int64_t LastGridEnd = -1;       // largest end offset of a grid; -1 without grid offsets
  bool Streamed = false;          // the file has no grid offsets (written by io::Stream)

  /* Throws openvdb::IoError naming what is corrupt (or OpenVDB's own exceptions). */
  void Check(const std::string& path, int64_t size, const std::string& topologyGrid)
  {
    std::ifstream is(path, std::ios_base::in | std::ios_base::binary);
    if (!is)
    {
      OPENVDB_THROW(openvdb::IoError, "could not open file " << path);
    }
    this->Size = size;
    this->CheckHeaderLength(is);
    this->readHeader(is); // fixed-size fields
    if (!this->inputHasGridOffsets())
    {
      // A stream (io::Stream): OpenVDB reads it in one pass with no size checks at all (a
      // fuzzed 102-byte file made it allocate 2.9 GB for strings). Not walked: refused by the
      // caller (Streamed).
      this->Streamed = true;
      return;
    }
    openvdb::io::StreamMetadata::Ptr streamMeta(new openvdb::io::StreamMetadata);
    streamMeta->setSeekable(true);
    openvdb::io::setStreamMetadataPtr(is, streamMeta, /*transfer=*/false);
    this->setFormatVersion(is);
    this->setLibraryVersion(is);
    this->setDataCompression(is);
    const uint32_t version = openvdb::io::getFormatVersion(is);
    if (version < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
    {
      // The tree walk below follows the node-mask-compressed layout of format 222 (OpenVDB 2.0,
      // 2013) and later; an older tree would go to OpenVDB unchecked (a hand-made file with
      // version 221 made it throw mid-tree and leak a node), so such files are refused.
      OPENVDB_THROW(openvdb::IoError,
        "file format version " << version << " predates OpenVDB 2.0 (format "
                               << openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION
                               << "), which is not supported");
    }
    this->SkipMetaMap(is, "the file metadata");

    const int32_t count = this->ReadScalar<int32_t>(is, "the grid count");
    // A descriptor holds at least two strings and three offsets.
    this->Require(count >= 0 && int64_t(count) <= this->Remaining(is) / 32, "the grid count");
    std::vector<openvdb::io::GridDescriptor> descriptors;
    for (int32_t i = 0; i < count; ++i)
    {
      const std::streamoff start = is.tellg();
      const int strings = version >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING ? 3 : 2;
      for (int k = 0; k < strings; ++k)
      {
        this->SkipString(is, "a grid descriptor");
      }
      is.seekg(start);
      openvdb::io::GridDescriptor gd;
      gd.read(is);
      this->Require(is.good() && gd.getGridPos() > 0 && gd.getGridPos() <= gd.getEndPos() &&
          gd.getBlockPos() <= gd.getEndPos(),
        "the descriptor of grid \"" + gd.uniqueName() + "\"");
      if (gd.getEndPos() > size)
      {
        OPENVDB_THROW(openvdb::IoError,
          "truncated: grid \"" << gd.uniqueName() << "\" ends at byte " << gd.getEndPos()
                               << " but the file has " << size << " bytes");
      }
      this->Names.push_back(openvdb::io::GridDescriptor::nameAsString(gd.uniqueName()));
      this->LastGridEnd = std::max(this->LastGridEnd, gd.getEndPos());
      descriptors.push_back(gd);
      gd.seekToEnd(is);
    }

    for (const openvdb::io::GridDescriptor& gd : descriptors)
    {
      const std::string what = "grid \"" + gd.uniqueName() + "\"";
      gd.seekToGrid(is);
      readGridCompression(is);
      const std::streamoff metaStart = is.tellg();
      this->SkipMetaMap(is, "the metadata of " + what);
      // The transform: a map type name, then fixed-size fields.
      const std::streamoff transformStart = is.tellg();
      this->SkipString(is, "the transform of " + what);
      if (gd.isInstance() ||
        (gd.gridName() != topologyGrid &&
          openvdb::io::GridDescriptor::nameAsString(gd.uniqueName()) != topologyGrid) ||
        gd.gridType() != openvdb::FloatGrid::gridType())
      {
        continue;
      }
      // Now that they are checked, OpenVDB reads the metadata and transform as readGrid will
      // (the metadata decides whether the values are stored as half floats).
      is.seekg(metaStart);
      openvdb::GridBase::Ptr grid = openvdb::GridBase::createGrid(gd.gridType());
      grid->setSaveFloatAsHalf(gd.saveFloatAsHalf());
      grid->readMeta(is);
      this->Require(is.tellg() == transformStart, "the metadata of " + what);
      grid->readTransform(is);
      this->Require(bool(is), "the transform of " + what);
      this->CheckFloatTree(is, gd, grid->saveFloatAsHalf(), "the tree of " + what);
    }
  }

private:
  int64_t Size = 0;

  /* Before io::Archive::readHeader, which reads its fixed-size fields without checking the
   * stream: from a file that ends inside them it keeps whatever the variables held (a file of
   * only the magic number left the "has grid offsets" flag uninitialised, and failed with one
   * of two messages from run to run; a cut UUID left boost's parser reading an uninitialised
   * character). The format version decides the header's length; a file too short to hold it
   * is measured against the header of this library's format. A file that does not start like
   * a VDB file is left to readHeader ("not a VDB file"). */
  void CheckHeaderLength(std::istream& is)
  {
    char head[12] = {};
    is.read(head, sizeof(head));
    const int64_t got = int64_t(is.gcount());
    is.clear();
    is.seekg(0);
    if (!StartsLikeMagic(head, std::size_t(got)))
    {
      return;
    }
    uint32_t version = openvdb::OPENVDB_FILE_VERSION;
    if (got >= int64_t(sizeof(head)))
    {
      std::memcpy(&version, head + 8, sizeof(version));
    }
    const int64_t needed = HeaderBytes(version);
    if (this->Size < needed)
    {
      OPENVDB_THROW(openvdb::IoError,
        "truncated: the file ends inside the OpenVDB file header ("
          << this->Size << " bytes, the header needs " << needed << ")");
    }
  }

  int64_t Remaining(std::istream& is) const
  {
    const std::streamoff pos = is.tellg();
    return pos < 0 ? -1 : this->Size - int64_t(pos);
  }

  void Require(bool ok, const std::string& what) const
  {
    if (!ok)
    {
      OPENVDB_THROW(openvdb::IoError,
        "corrupt " << what << " (a size, count or offset that does not fit the file)");
    }
  }

  template <typename T>
  T ReadScalar(std::istream& is, const std::string& what)
  {
    T value{};
    is.read(reinterpret_cast<char*>(&value), sizeof(T));
    this->Require(bool(is), what);
    return value;
  }

  /* A length-prefixed block (io::readString, Metadata sizes): checks and skips it. */
  uint32_t SkipBlock(std::istream& is, const std::string& what)
  {
    const uint32_t n = this->ReadScalar<uint32_t>(is, what);
    this->Require(int64_t(n) <= this->Remaining(is), what);
    is.seekg(std::streamoff(n), std::ios_base::cur);
    return n;
  }

  void SkipString(std::istream& is, const std::string& what) { this->SkipBlock(is, what); }

  void Skip(std::istream& is, int64_t bytes, const std::string& what)
  {
    this->Require(bytes >= 0 && bytes <= this->Remaining(is), what);
    is.seekg(std::streamoff(bytes), std::ios_base::cur);
  }

  template <typename Mask>
  void Load(std::istream& is, Mask& mask, const std::string& what)
  {
    mask.load(is);
    this->Require(bool(is), what);
  }

  /* The bytes io::readCompressedValues reads for a node of destCount values of a float tree
   * (activeCount of them active; selectionBytes = the node's mask size), chunk sizes checked
   * against what they must be: OpenVDB 10's bloscFromStream/unzipFromStream copy a
   * "uncompressed" chunk into the node's buffer before comparing its size with the buffer's. */
  void SkipValues(std::istream& is, uint32_t destCount, uint32_t activeCount,
    int64_t selectionBytes, uint32_t compression, bool half, const std::string& what)
  {
    using namespace openvdb::io;
    const int8_t metadata = this->ReadScalar<int8_t>(is, what);
    if (metadata == NO_MASK_AND_ONE_INACTIVE_VAL || metadata == MASK_AND_ONE_INACTIVE_VAL ||
      metadata == MASK_AND_TWO_INACTIVE_VALS)
    {
      this->Skip(is, metadata == MASK_AND_TWO_INACTIVE_VALS ? 8 : 4, what); // float inactive values
    }
    if (metadata == MASK_AND_NO_INACTIVE_VALS || metadata == MASK_AND_ONE_INACTIVE_VAL ||
      metadata == MASK_AND_TWO_INACTIVE_VALS)
    {
      this->Skip(is, selectionBytes, what);
    }
    uint32_t count = destCount;
    if ((compression & COMPRESS_ACTIVE_MASK) && metadata != NO_MASK_AND_ALL_VALS)
    {
      count = activeCount;
    }
    if (half && count < 1)
    {
      return; // HalfReader reads nothing
    }
    const int64_t bytes = int64_t(count) * (half ? 2 : 4);
    if (!(compression & (COMPRESS_BLOSC | COMPRESS_ZIP)))
    {
      this->Skip(is, bytes, what);
      return;
    }
    const int64_t n = this->ReadScalar<int64_t>(is, what);
    if (n <= 0)
    {
      this->Require(n > std::numeric_limits<int64_t>::min() && -n == bytes, what);
      this->Skip(is, -n, what);
      return;
    }
    this->Require(n <= this->Remaining(is), what);
    if (compression & COMPRESS_BLOSC)
    {
      this->CheckBloscHeader(is, n, bytes, what);
    }
    this->Skip(is, n, what);
  }

  /* The values of an internal node (its tiles), as InternalNode::readTopology reads them:
   * sizes checked first (SkipValues), then decoded by OpenVDB's own
   * io::readCompressedValues into a scratch buffer. readTopology allocates each node before
   * reading it and RootNode stores a child only after the child's readTopology returns, so an
   * exception there (a Blosc or zip chunk of the right sizes whose data does not decompress:
   * "Expected to decompress 4 bytes, got -1 bytes") leaks the level-2 node being filled and
   * its children (found by fuzzing: 304 KB per file). Decoding here makes OpenVDB throw in the
   * check, where nothing leaks, instead of mid-tree. Costs one more decompression of the tile
   * values (at most 128 KB per level-2 node); leaf buffers (readBuffers, where the tree
   * already owns every node) are not decoded twice. */
  template <typename Mask>
  void CheckNodeValues(std::istream& is, const Mask& valueMask, std::vector<float>& scratch,
    uint32_t compression, bool half, const std::string& what)
  {
    const std::streamoff start = is.tellg();
    this->SkipValues(is, Mask::SIZE, valueMask.countOn(), Mask::SIZE / 8, compression, half, what);
    const std::streamoff end = is.tellg();
    is.seekg(start);
    scratch.resize(Mask::SIZE);
    try
    {
      openvdb::io::readCompressedValues(is, scratch.data(), Mask::SIZE, valueMask, half);
    }
    catch (const std::exception& e)
    {
      OPENVDB_THROW(openvdb::IoError, "corrupt " << what << " (" << e.what() << ")");
    }
    this->Require(bool(is) && is.tellg() == end, what);
  }

  /* Tree<RootNode<InternalNode<InternalNode<LeafNode<float,3>,4>,5>>>::readTopology then
   * readBuffers, as OpenVDB reads them (root children in key order; a leaf's buffer uses the
   * value mask of the topology, the stream being seekable). */
  void CheckFloatTree(
    std::istream& is, const openvdb::io::GridDescriptor& gd, bool half, const std::string& what)
  {
    struct Node4
    {
      openvdb::util::NodeMask<4> Children;
      std::vector<uint16_t> LeafActive;
    };
    const uint32_t compression = openvdb::io::getDataCompression(is);
    this->ReadScalar<int32_t>(is, what); // buffer count
    this->ReadScalar<float>(is, what);   // background
    const uint32_t tiles = this->ReadScalar<uint32_t>(is, what);
    const uint32_t children = this->ReadScalar<uint32_t>(is, what);
    // A tile takes 3 x 4 + 4 + 1 bytes; a child its origin and two uncompressed 32^3-bit masks.
    this->Require(
      int64_t(tiles) * 17 + int64_t(children) * (12 + 8192) <= this->Remaining(is), what);
    this->Skip(is, int64_t(tiles) * 17, what);
    std::map<openvdb::Coord, std::vector<Node4>> roots;
    std::vector<float> scratch;
    for (uint32_t c = 0; c < children; ++c)
    {
      int32_t origin[3];
      is.read(reinterpret_cast<char*>(origin), sizeof(origin));
      this->Require(bool(is), what);
      openvdb::util::NodeMask<5> childMask, valueMask;
      this->Load(is, childMask, what);
      this->Load(is, valueMask, what);
      this->CheckNodeValues(is, valueMask, scratch, compression, half, what);
      std::vector<Node4> nodes;
      for (auto it = childMask.beginOn(); it; ++it)
      {
        Node4 node;
        openvdb::util::NodeMask<4> values4;
        this->Load(is, node.Children, what);
        this->Load(is, values4, what);
        this->CheckNodeValues(is, values4, scratch, compression, half, what);
        for (auto jt = node.Children.beginOn(); jt; ++jt)
        {
          openvdb::util::NodeMask<3> leafMask;
          this->Load(is, leafMask, what);
          node.LeafActive.push_back(uint16_t(leafMask.countOn()));
        }
        nodes.push_back(std::move(node));
      }
      roots[openvdb::Coord(origin[0], origin[1], origin[2])] = std::move(nodes);
    }
    if (gd.getBlockPos() > 0)
    {
      this->Require(int64_t(is.tellg()) == gd.getBlockPos(), what);
    }
    for (const auto& root : roots)
    {
      for (const Node4& node : root.second)
      {
        for (uint16_t active : node.LeafActive)
        {
          this->Skip(is, 64, what); // the leaf's value mask (seeked over)
          this->SkipValues(is, 512, active, 64, compression, half, what);
        }
      }
    }
  }

  /* MetaMap::readMeta: a count, then per entry a name, a type name and a value as
   * Metadata::read consumes it: a size, then that many bytes (strings, unknown types), the
   * type's own size (fixed-size types read sizeof(T) whatever the size says) or, for
   * DelayedLoadMetadata, its own structure. */
  void SkipMetaMap(std::istream& is, const std::string& what)
  {
    const uint32_t count = this->ReadScalar<uint32_t>(is, what);
    this->Require(int64_t(count) * 12 <= this->Remaining(is), what);
    for (uint32_t i = 0; i < count; ++i)
    {
      this->SkipString(is, what);
      const uint32_t typeLength = this->ReadScalar<uint32_t>(is, what);
      this->Require(int64_t(typeLength) <= this->Remaining(is), what);
      std::string type(typeLength, '\0');
      is.read(&type[0], typeLength);
      this->Require(bool(is), what);
      const uint32_t bytes = this->ReadScalar<uint32_t>(is, what);
      if (!openvdb::Metadata::isRegisteredType(type) ||
        type == openvdb::StringMetadata::staticTypeName())
      {
        this->Skip(is, bytes, what);
      }
      else if (type == openvdb::io::DelayedLoadMetadata::staticTypeName())
      {
        this->SkipDelayedLoad(is, bytes, what);
      }
      else
      {
        this->Skip(is, openvdb::Metadata::createMetadata(type)->size(), what);
      }
    }
  }

  /* A blosc buffer of `bytes` bytes that must hold `expected` bytes uncompressed (checked in
   * its header: blosc trusts the header's compressed size to stay within the buffer). With
   * `padded`, OpenVDB's StreamCompression pads buffers below 128 bytes to 128. */
  void CheckBloscHeader(
    std::istream& is, int64_t bytes, int64_t expected, const std::string& what, bool padded = false)
  {
    this->Require(bytes >= 16 && bytes <= this->Remaining(is), what);
    unsigned char header[16];
    is.read(reinterpret_cast<char*>(header), 16);
    this->Require(bool(is), what);
    auto le32 = [&](int at)
    {
      return uint32_t(header[at]) | uint32_t(header[at + 1]) << 8 | uint32_t(header[at + 2]) << 16 |
        uint32_t(header[at + 3]) << 24;
    };
    const int64_t nbytes = le32(4);
    this->Require(int64_t(le32(12)) <= bytes &&
        (nbytes == expected || (padded && expected <= 128 && nbytes == 128)),
      what);
    is.seekg(std::streamoff(-16), std::ios_base::cur);
  }

  /* DelayedLoadMetadata::readValue (OpenVDB 10): a leaf count, a mask array (blosc or raw
   * int8) and a compressed-size array (blosc, raw int64, or none), then padding up to numBytes. */
  void SkipDelayedLoad(std::istream& is, uint32_t numBytes, const std::string& what)
  {
    if (numBytes == 0)
    {
      return;
    }
    int64_t total = 12;
    const uint32_t count = this->ReadScalar<uint32_t>(is, what);
    this->Require(int64_t(count) <= this->Size, what); // a file has fewer leaves than bytes
    uint32_t bytes = this->ReadScalar<uint32_t>(is, what);
    if (bytes > 0)
    {
      this->CheckBloscHeader(is, bytes, int64_t(count) * 1, what, /*padded=*/true);
      this->Skip(is, bytes, what);
      total += bytes;
    }
    else
    {
      this->Skip(is, int64_t(count) * 1, what);
      total += int64_t(count) * 1;
    }
    bytes = this->ReadScalar<uint32_t>(is, what);
    if (bytes != std::numeric_limits<uint32_t>::max())
    {
      if (bytes > 0)
      {
        this->CheckBloscHeader(is, bytes, int64_t(count) * 8, what, /*padded=*/true);
        this->Skip(is, bytes, what);
        total += bytes;
      }
      else
      {
        this->Skip(is, int64_t(count) * 8, what);
        total += int64_t(count) * 8;
      }
    }
    if (total < int64_t(numBytes))
    {
      this->Skip(is, int64_t(numBytes) - total, what);
    }
  }
};
} // namespace

//------------------------------------------------------------------------------
void OpenVDBFileCheck::Check(const std::string& path, int64_t size, const std::string& topologyGrid)
{
  FileChecker checker;
  checker.Check(path, size, topologyGrid);
  this->Names = checker.Names;
  this->LastGridEnd = checker.LastGridEnd;
  this->Streamed = checker.Streamed;
}

//------------------------------------------------------------------------------
bool OpenVDBFileCheck::EndsInsideMagic(const std::string& path, int64_t size)
{
  if (size < 0 || size >= 8)
  {
    return false;
  }
  std::ifstream is(path, std::ios_base::in | std::ios_base::binary);
  char head[8] = {};
  if (!is || !is.read(head, std::streamsize(size)))
  {
    return false;
  }
  return StartsLikeMagic(head, std::size_t(size));
}
}
