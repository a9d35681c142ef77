// vtkOpenVDBVolumeReader's error cases: missing, foreign, truncated and corrupt files, damaged
// compressed leaf data, and every truncation inside the file header (one error, the same on every
// read, and an empty output).
#include "vsTestPaths.h"
#include "vsOpenVDBReaderTest.h"

TEST_F(OpenVDBReader, Errors)
{
  TempDir tmp;
  vtkNew<vtkOpenVDBVolumeReader> reader;

  // Nothing to read.
  {
    vtkSmartPointer<Messages> msgs = RunReader(reader);
    ASSERT_EQ(msgs->Errors.size(), 1u);
    EXPECT_NE(msgs->Errors[0].find("No file to read"), std::string::npos);
  }
  ExpectErrorContaining(
    reader, tmp.File("missing.vdb"), { "missing.vdb", "no such file" }, "missing");
  ExpectErrorContaining(reader, tmp.Path.string(), { "directory" }, "directory");

  // A file with other grids: the message lists them; a non-float grid.
  const std::string multi = tmp.File("multi.vdb");
  {
    openvdb::Vec3SGrid::Ptr vel = openvdb::Vec3SGrid::create();
    vel->setName("vel");
    vel->tree().setValue(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1, 0, 0));
    openvdb::FloatGrid::Ptr temp = openvdb::FloatGrid::create();
    temp->setName("temperature");
    temp->tree().setValue(openvdb::Coord(1, 2, 3), 1.0f);
    Write(multi, { vel, temp });
  }
  ExpectErrorContaining(reader, multi,
    { "no grid named \"density\"", "\"vel\" (vec3s)", "\"temperature\" (float)" }, "missing grid");
  EXPECT_EQ(reader->GetNumberOfGrids(), 2); // the listing survives the error
  reader->SetGridName("vel");
  ExpectErrorContaining(
    reader, multi, { "\"vel\"", "vec3s", "only float grids" }, "non-float grid");
  reader->SetGridName("temperature");
  EXPECT_TRUE(RunFile(reader, multi)->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 1);
  reader->SetGridName("density");

  // Found by fuzzing: a file without grid offsets (a stream) is read by OpenVDB in one pass
  // with no size checks (a 102-byte file made it allocate 2.9 GB); it is refused.
  {
    const std::string path = tmp.File("streamed.vdb");
    {
      std::ofstream out(path, std::ios::binary);
      openvdb::io::Stream(out).write(openvdb::GridCPtrVec{ SmallGrid(ScaleTranslate(1, 1, 1, 0, 0, 0)) });
    }
    ExpectErrorContaining(reader, path, { "streamed.vdb", "has no grid offsets", "openvdb::io::Stream" },
      "stream");
  }

  // Found by fuzzing: a Blosc chunk whose sizes are right but whose data does not decompress,
  // in the tile values of a level-1 node of a grid without statistics (read in full while
  // listing the grids). OpenVDB threw mid-tree ("Expected to decompress 4 bytes, got -1
  // bytes") and leaked the level-2 node it was filling; the structure check now decodes the
  // internal nodes' values itself, so the error comes from the check ("corrupt the tree").
  {
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->tree().addTile(1, openvdb::Coord(0, 0, 0), 2.0f, /*active=*/true); // one 8^3 tile
    const std::string good = tmp.File("tile.vdb");
    Write(good, { grid }, /*stats=*/false);
    std::vector<char> data;
    {
      std::ifstream in(good, std::ios::binary);
      data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    // The level-1 node's one active value: a Blosc header (version 2, then 1, flags, type
    // size 4) for 4 uncompressed bytes, stored as a copy (flag 0x02, BLOSC_MEMCPYED).
    std::size_t at = std::string::npos;
    for (std::size_t i = 0; i + 8 <= data.size(); ++i)
    {
      if (data[i] == 2 && data[i + 1] == 1 && data[i + 3] == 4 && data[i + 4] == 4 &&
        data[i + 5] == 0 && data[i + 6] == 0 && data[i + 7] == 0 && (data[i + 2] & 0x02))
      {
        ASSERT_EQ(at, std::string::npos) << "two candidate chunks";
        at = i;
      }
    }
    ASSERT_NE(at, std::string::npos) << "no 4-byte Blosc chunk in " << good;
    EXPECT_TRUE(RunFile(reader, good)->Errors.empty());
    EXPECT_EQ(reader->GetGridActiveVoxelCount(0), 512);
    data[at + 2] = char(data[at + 2] & ~0x02); // now "compressed": 4 bytes that are not LZ4
    const std::string bad = tmp.File("tile_bad_blosc.vdb");
    std::ofstream(bad, std::ios::binary).write(data.data(), std::streamsize(data.size()));
    ExpectErrorContaining(reader, bad,
      { "tile_bad_blosc.vdb", "corrupt the tree of grid \"density\"", "decompress" },
      "a Blosc chunk that does not decompress");
  }

  // A file format older than 222 (OpenVDB 2.0) has a tree layout the structure check does not
  // walk; it went to OpenVDB unchecked (a hand-made version-221 file leaked a node) and is
  // now refused. The format version is the 32-bit word after the 8-byte magic number.
  {
    const std::string path = tmp.File("format221.vdb");
    Write(path, { SmallGrid(ScaleTranslate(1, 1, 1, 0, 0, 0)) });
    std::fstream io(path, std::ios::binary | std::ios::in | std::ios::out);
    io.seekp(8);
    const uint32_t version = 221;
    io.write(reinterpret_cast<const char*>(&version), 4);
    io.close();
    ExpectErrorContaining(reader, path, { "format221.vdb", "file format version 221" }, "format 221");
  }

  // A rotated transform.
  {
    openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(0.5);
    xform->preRotate(0.3, openvdb::math::Z_AXIS);
    const std::string path = tmp.File("rotated.vdb");
    Write(path, { SmallGrid(xform) });
    ExpectErrorContaining(
      reader, path, { "non-axis-aligned transforms are not supported yet" }, "rotation");
  }

  // Corrupt files: a real frame truncated at several places, garbage, an empty file.
  const std::string real = SmokeDir + "smoke_0004.vdb";
  std::vector<char> bytes;
  {
    std::ifstream in(real, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 10000u);
  for (std::size_t keep : { std::size_t(0), std::size_t(6), std::size_t(100), std::size_t(700),
         std::size_t(2000), bytes.size() / 2, bytes.size() - 300, bytes.size() - 1 })
  {
    SCOPED_TRACE(keep);
    // A new name each time: the same FileName would not re-execute the reader.
    const std::string name = "truncated_" + std::to_string(keep) + ".vdb";
    const std::string path = tmp.File(name);
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(keep));
    ExpectErrorContaining(reader, path, { name }, "truncated");
  }
  {
    const std::string path = tmp.File("garbage.vdb");
    std::ofstream out(path, std::ios::binary);
    unsigned state = 12345;
    for (int i = 0; i < 5000; ++i)
    {
      state = state * 1664525u + 1013904223u;
      out.put(char(state >> 24));
    }
    out.close();
    EXPECT_EQ(vtkOpenVDBVolumeReader::CanReadFile(path.c_str()), 0);
    ExpectErrorContaining(reader, path, { "garbage.vdb", "not a VDB file" }, "garbage");
  }
  {
    // The right magic number, then garbage.
    const std::string path = tmp.File("magic.vdb");
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), 8);
    for (int i = 0; i < 3000; ++i)
    {
      out.put(char((i * 7919) & 0xff));
    }
    out.close();
    ExpectErrorContaining(reader, path, { "magic.vdb" }, "magic then garbage");
  }

  // A bad pattern, an empty index range.
  reader->SetFilePattern("smoke_%s.vdb");
  ExpectErrorContaining(reader, real, { "FilePattern" }, "pattern %s");
  reader->SetFilePattern("smoke_%d_%d.vdb");
  ExpectErrorContaining(reader, real, { "FilePattern" }, "pattern with two conversions");
  reader->SetFilePattern((SmokeDir + "smoke_%04d.vdb").c_str());
  reader->SetFileIndexRange(8, 4);
  ExpectErrorContaining(reader, real, { "FileIndexRange" }, "empty range");
  // A sequence with a missing file names the step.
  reader->SetFileIndexRange(4, 6);
  ExpectErrorContaining(reader, real, { "time step 1", "smoke_0005.vdb", "no such file" }, "gap");
  reader->SetFilePattern(nullptr);

  // A guard against huge outputs.
  reader->SetMaximumNumberOfPoints(1000);
  ExpectErrorContaining(reader, real, { "MaximumNumberOfPoints" }, "too large");
  reader->SetMaximumNumberOfPoints(vtkIdType(1) << 31);

  // A good file, then a missing one: the output empties; then recovers.
  EXPECT_TRUE(RunFile(reader, real)->Errors.empty());
  EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0);
  ExpectErrorContaining(reader, tmp.File("gone.vdb"), { "gone.vdb" }, "gone");
  EXPECT_TRUE(RunFile(reader, real)->Errors.empty());
  EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// Issue 13, item 2: damaged compressed leaf data. Blosc has no checksum, so a damaged chunk of the
// right size decodes to other values without an error from OpenVDB. The reader refuses what it can
// tell: NaN or infinite active values, a fog volume far outside [0, 1], and an active-voxel count
// other than the one the writer recorded. (Damage that decodes to plausible values cannot be told.)
TEST_F(OpenVDBReader, DamagedLeafValuesAreErrors)
{
  TempDir tmp;
  // The shipped smoke step with 64 bytes of 0xff in its Blosc leaf data at byte 19900: it decodes
  // (before: 16,100 points read without a word), with 3 NaN densities.
  {
    std::ifstream in(vstest::DataDir() + "/smoke/smoke_0004.vdb", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 20000u);
    std::fill(bytes.begin() + 19900, bytes.begin() + 19964, '\xff');
    const std::string path = tmp.File("damaged_smoke.vdb");
    std::ofstream(path, std::ios::binary) << bytes;
    vtkNew<vtkOpenVDBVolumeReader> reader;
    ExpectErrorContaining(reader, path, { "active voxels of grid", "are NaN or infinite", "damaged leaf data" },
      "damaged smoke");
  }
  {
    openvdb::FloatGrid::Ptr grid = SmallGrid(openvdb::math::Transform::createLinearTransform(1.0));
    grid->getAccessor().setValue(openvdb::Coord(1, 1, 6), std::numeric_limits<float>::quiet_NaN());
    const std::string path = tmp.File("nan.vdb");
    Write(path, { grid });
    vtkNew<vtkOpenVDBVolumeReader> reader;
    ExpectErrorContaining(reader, path, { "1 active voxels", "NaN or infinite" }, "NaN value");
  }
  {
    openvdb::FloatGrid::Ptr grid = SmallGrid(openvdb::math::Transform::createLinearTransform(1.0));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->getAccessor().setValue(openvdb::Coord(1, 1, 6), 2.5e36f);
    const std::string path = tmp.File("fog_huge.vdb");
    Write(path, { grid });
    vtkNew<vtkOpenVDBVolumeReader> reader;
    ExpectErrorContaining(reader, path, { "is a fog volume", "2.5e+36" }, "fog volume far beyond 1");
  }
  {
    // A fog volume somewhat past 1 (real exports do that; SmallGrid holds -1 to 2.5) reads.
    openvdb::FloatGrid::Ptr grid = SmallGrid(openvdb::math::Transform::createLinearTransform(1.0));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    const std::string path = tmp.File("fog.vdb");
    Write(path, { grid });
    vtkNew<vtkOpenVDBVolumeReader> reader;
    vtkSmartPointer<Messages> msgs = RunFile(reader, path);
    EXPECT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
    EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    openvdb::FloatGrid::Ptr grid = SmallGrid(openvdb::math::Transform::createLinearTransform(1.0));
    grid->insertMeta(openvdb::GridBase::META_FILE_BBOX_MIN, openvdb::Vec3IMetadata(openvdb::Vec3i(-3, -1, 5)));
    grid->insertMeta(openvdb::GridBase::META_FILE_BBOX_MAX, openvdb::Vec3IMetadata(openvdb::Vec3i(4, 2, 9)));
    grid->insertMeta(openvdb::GridBase::META_FILE_VOXEL_COUNT, openvdb::Int64Metadata(5));
    const std::string path = tmp.File("count.vdb");
    Write(path, { grid }, /*stats=*/false);
    vtkNew<vtkOpenVDBVolumeReader> reader;
    ExpectErrorContaining(reader, path, { "has 4 active voxels but the file's metadata says 5" }, "voxel count");
  }
}

// Found with valgrind: a file of only OpenVDB's 8-byte magic number failed with one of two
// different messages from run to run. OpenVDB's io::Archive::readHeader reads the fixed-size
// header (magic, format version, library major and minor, the "has grid offsets" byte, the
// 36-character UUID) without checking the stream, so a file that ends inside it left the flag
// uninitialised: sometimes "has no grid offsets", sometimes a corrupt metadata count. The
// structure check now measures the header before anything reads it. Every truncation of a
// valid file inside its header (from an empty file up to one byte short of the header) must
// give one error, the same on every read, that names the truncation, and an empty output.
namespace
{
/* The bytes of a .vdb file (the whole file). */
std::vector<char> ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/* The length of OpenVDB's file header in a file of format 222 or later: the 8-byte magic
 * number, the 32-bit format version, the library major and minor versions (32 bits each), the
 * "has grid offsets" byte and the UUID as 36 ASCII characters. Checked against the bytes. */
std::size_t HeaderLength(const std::vector<char>& bytes)
{
  EXPECT_GE(bytes.size(), 61u);
  uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 8, 4);
  EXPECT_GE(version, uint32_t(openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION));
  EXPECT_EQ(bytes[20], 1) << "has grid offsets";
  const std::size_t uuid = 21, length = uuid + 36;
  for (std::size_t i = uuid; i < length; ++i)
  {
    const bool hyphen = i == uuid + 8 || i == uuid + 13 || i == uuid + 18 || i == uuid + 23;
    EXPECT_TRUE(hyphen ? bytes[i] == '-' : std::isxdigit(static_cast<unsigned char>(bytes[i])))
      << "UUID character " << (i - uuid) << ": " << int(bytes[i]);
  }
  return length;
}

/* Reads `path` twice, each time with a new reader: one error each time, the same, and an
 * empty output. Returns the error. */
std::string ReadTwiceExpectingOneError(const std::string& path)
{
  std::string first;
  for (int pass = 0; pass < 2; ++pass)
  {
    SCOPED_TRACE(pass);
    vtkNew<vtkOpenVDBVolumeReader> reader;
    vtkSmartPointer<Messages> msgs = RunFile(reader, path);
    EXPECT_EQ(msgs->Errors.size(), 1u) << msgs->AllErrors();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(reader->GetOutput()->GetPointData()->GetNumberOfArrays(), 0);
    EXPECT_EQ(reader->GetNumberOfGrids(), 0);
    // vtkErrorMacro's text without its "ERROR: In <file>, line <n>\n<class> (<address>): "
    // prefix (the address changes with the reader).
    std::string error = msgs->Errors.empty() ? std::string() : msgs->Errors[0];
    const std::size_t text = error.find("): ");
    EXPECT_NE(text, std::string::npos) << error;
    if (text != std::string::npos)
    {
      error = error.substr(text + 3);
    }
    if (pass == 0)
    {
      first = error;
    }
    else
    {
      EXPECT_EQ(error, first) << "a different message on the second read";
    }
  }
  return first;
}

void ExpectHeaderTruncation(const std::string& error, const std::string& name, std::size_t size,
  std::size_t needed)
{
  const std::string cause = "ends inside the OpenVDB file header (" + std::to_string(size) +
    " bytes, the header needs " + std::to_string(needed) + ")";
  EXPECT_NE(error.find(name), std::string::npos) << error;
  EXPECT_NE(error.find(cause), std::string::npos) << "no \"" << cause << "\" in " << error;
}
} // namespace

TEST_F(OpenVDBReader, MagicNumberOnlyIsOneTruncationError)
{
  TempDir tmp;
  const std::vector<char> bytes = ReadBytes(SmokeDir + "smoke_0004.vdb");
  const std::size_t header = HeaderLength(bytes);
  ASSERT_EQ(header, 57u);
  const std::string path = tmp.File("magic_only.vdb");
  std::ofstream(path, std::ios::binary).write(bytes.data(), 8);
  ASSERT_EQ(vtkOpenVDBVolumeReader::CanReadFile(path.c_str()), 1);
  // More reads than two: the old failure changed with the stack's garbage.
  std::string first;
  for (int i = 0; i < 5; ++i)
  {
    const std::string error = ReadTwiceExpectingOneError(path);
    ExpectHeaderTruncation(error, "magic_only.vdb", 8, header);
    if (i == 0)
    {
      first = error;
    }
    EXPECT_EQ(error, first);
  }
}

TEST_F(OpenVDBReader, EveryTruncationInsideTheHeaderIsOneTruncationError)
{
  TempDir tmp;
  // The real smoke frame (written by Blender's OpenVDB) and a file written here.
  const std::string written = tmp.File("written.vdb");
  Write(written, { SmallGrid(ScaleTranslate(1, 1, 1, 0, 0, 0)) });
  for (const std::string& source : { SmokeDir + "smoke_0004.vdb", written })
  {
    SCOPED_TRACE(source);
    const std::vector<char> bytes = ReadBytes(source);
    const std::size_t header = HeaderLength(bytes);
    ASSERT_EQ(header, 57u);
    {
      vtkNew<vtkOpenVDBVolumeReader> reader;
      EXPECT_TRUE(RunFile(reader, source)->Errors.empty()) << "the whole file reads";
    }
    const std::string stem = source == written ? "written_" : "smoke_";
    for (std::size_t keep = 0; keep < header; ++keep)
    {
      SCOPED_TRACE(keep);
      const std::string name = stem + std::to_string(keep) + ".vdb";
      const std::string path = tmp.File(name);
      std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(keep));
      ExpectHeaderTruncation(ReadTwiceExpectingOneError(path), name, keep, header);
    }
    // The whole header and nothing after it: the file metadata (its count first) is missing.
    // Not a header truncation, but still one deterministic error.
    const std::string name = stem + std::to_string(header) + ".vdb";
    const std::string path = tmp.File(name);
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(header));
    const std::string error = ReadTwiceExpectingOneError(path);
    EXPECT_NE(error.find(name), std::string::npos) << error;
    EXPECT_NE(error.find("the file metadata"), std::string::npos) << error;
    EXPECT_EQ(error.find("file header"), std::string::npos) << error;
  }

  // The header's length follows the format version: formats 220 and 221 have a compression
  // byte before the UUID (58 bytes), so 57 bytes of a format-221 file end inside the header.
  {
    std::vector<char> bytes = ReadBytes(written);
    const uint32_t version = 221;
    std::memcpy(bytes.data() + 8, &version, 4);
    const std::string path = tmp.File("format221_57.vdb");
    std::ofstream(path, std::ios::binary).write(bytes.data(), 57);
    ExpectHeaderTruncation(ReadTwiceExpectingOneError(path), "format221_57.vdb", 57, 58);
  }

  // A short file that is not the start of a VDB file is still "not a VDB file".
  const std::string path = tmp.File("short_text.vdb");
  std::ofstream(path, std::ios::binary) << "VDB";
  const std::string error = ReadTwiceExpectingOneError(path);
  EXPECT_NE(error.find("not a VDB file"), std::string::npos) << error;
}
