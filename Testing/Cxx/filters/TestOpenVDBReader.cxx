// vtkOpenVDBVolumeReader: values and world positions against OpenVDB's own accessor (grids
// written here with the OpenVDB API), the real Mantaflow smoke frames, the grid listing,
// file sequences as VTK time steps, union bounds, and the error cases.
#include "vtkOpenVDBVolumeReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <openvdb/io/File.h>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace
{
const std::string SmokeDir = std::string(VISSWEEP_DATA) + "/smoke/";

class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ProgressEvent)
    {
      this->Progress.push_back(*static_cast<double*>(data));
      return;
    }
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)
      .push_back(data ? static_cast<const char*>(data) : "");
  }
  std::string AllErrors() const
  {
    std::string s;
    for (const auto& e : this->Errors)
    {
      s += e + "\n";
    }
    return s;
  }
  std::vector<std::string> Errors, Warnings;
  std::vector<double> Progress;
};

struct TempDir
{
  std::filesystem::path Path;
  TempDir()
  {
    Path = std::filesystem::temp_directory_path() /
      ("vissweep_vdb_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(Path);
  }
  ~TempDir()
  {
    std::error_code ec;
    std::filesystem::remove_all(Path, ec);
  }
  std::string File(const std::string& name) const { return (Path / name).string(); }
};

/* Updates the reader (at time t when t >= 0) with observers; returns the messages. */
vtkSmartPointer<Messages> RunReader(vtkOpenVDBVolumeReader* reader, double t = -1.0)
{
  vtkNew<Messages> msgs;
  const unsigned long e = reader->AddObserver(vtkCommand::ErrorEvent, msgs);
  const unsigned long w = reader->AddObserver(vtkCommand::WarningEvent, msgs);
  const unsigned long p = reader->AddObserver(vtkCommand::ProgressEvent, msgs);
  if (t >= 0.0)
  {
    reader->UpdateTimeStep(t);
  }
  else
  {
    reader->Update();
  }
  reader->RemoveObserver(e);
  reader->RemoveObserver(w);
  reader->RemoveObserver(p);
  return vtkSmartPointer<Messages>(msgs.Get());
}

vtkSmartPointer<Messages> RunFile(vtkOpenVDBVolumeReader* reader, const std::string& file)
{
  reader->SetFileName(file.c_str());
  return RunReader(reader);
}

void Write(const std::string& path, const openvdb::GridPtrVec& grids, bool stats = true)
{
  openvdb::io::File file(path);
  file.setGridStatsMetadataEnabled(stats);
  file.write(grids);
  file.close();
}

openvdb::FloatGrid::Ptr ReadFloatGrid(const std::string& path, const std::string& name = "density")
{
  openvdb::io::File file(path);
  file.open(false);
  return openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
}

/* Every point of the image against the grid: its world position is a voxel centre
 * (indexToWorld of an integer index) and its value is the grid's (background when inactive). */
void ExpectMatchesGrid(
  vtkImageData* image, const openvdb::FloatGrid& grid, vtkIdType* activeSeen = nullptr)
{
  ASSERT_TRUE(image);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  ASSERT_TRUE(scalars);
  ASSERT_EQ(scalars->GetDataType(), VTK_FLOAT);
  ASSERT_EQ(scalars->GetNumberOfTuples(), image->GetNumberOfPoints());
  auto acc = grid.getConstAccessor();
  const double voxel = grid.voxelSize().length();
  vtkIdType active = 0, bad = 0;
  for (vtkIdType id = 0; id < image->GetNumberOfPoints(); ++id)
  {
    double x[3];
    image->GetPoint(id, x);
    const openvdb::Vec3d idx = grid.transform().worldToIndex(openvdb::Vec3d(x[0], x[1], x[2]));
    const openvdb::Coord ijk(
      int(std::lround(idx[0])), int(std::lround(idx[1])), int(std::lround(idx[2])));
    const openvdb::Vec3d centre = grid.transform().indexToWorld(ijk);
    float v;
    const bool on = acc.probeValue(ijk, v);
    const float expected = on ? v : grid.background();
    active += on;
    if ((centre - openvdb::Vec3d(x[0], x[1], x[2])).length() > 1e-9 * std::max(1.0, voxel) ||
      float(scalars->GetComponent(id, 0)) != expected)
    {
      if (++bad < 5)
      {
        ADD_FAILURE() << "point " << id << " at (" << x[0] << ", " << x[1] << ", " << x[2]
                      << ") voxel " << ijk << " centre " << centre << ": value "
                      << scalars->GetComponent(id, 0) << ", grid " << expected;
      }
    }
  }
  EXPECT_EQ(bad, 0);
  if (activeSeen)
  {
    *activeSeen = active;
  }
}

/* A small grid: a few voxels at positive and negative indices, an inactive voxel holding a
 * value that is not the background (it must read as the background), and a background of 0.25. */
openvdb::FloatGrid::Ptr SmallGrid(const openvdb::math::Transform::Ptr& xform)
{
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.25f);
  grid->setName("density");
  grid->setTransform(xform);
  auto acc = grid->getAccessor();
  acc.setValue(openvdb::Coord(-3, 2, 5), 1.5f);
  acc.setValue(openvdb::Coord(4, -1, 7), 2.5f);
  acc.setValue(openvdb::Coord(0, 0, 9), -1.0f);
  acc.setValue(openvdb::Coord(1, 1, 6), 0.75f);
  acc.setValueOff(openvdb::Coord(2, 0, 6), 9.0f);
  return grid;
}

openvdb::math::Transform::Ptr ScaleTranslate(
  double sx, double sy, double sz, double tx, double ty, double tz)
{
  openvdb::Mat4d m = openvdb::Mat4d::identity();
  m(0, 0) = sx;
  m(1, 1) = sy;
  m(2, 2) = sz;
  m(3, 0) = tx;
  m(3, 1) = ty;
  m(3, 2) = tz;
  return openvdb::math::Transform::createLinearTransform(m);
}

void ExpectErrorContaining(vtkOpenVDBVolumeReader* reader, const std::string& file,
  const std::vector<std::string>& parts, const char* why)
{
  vtkSmartPointer<Messages> msgs = RunFile(reader, file);
  ASSERT_EQ(msgs->Errors.size(), 1u) << why << ":\n" << msgs->AllErrors();
  for (const std::string& part : parts)
  {
    EXPECT_NE(msgs->Errors[0].find(part), std::string::npos)
      << why << ": no \"" << part << "\" in " << msgs->Errors[0];
  }
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << why;
}

class OpenVDBReader : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { openvdb::initialize(); }
};
} // namespace

// Values, voxel centres and the world transform (non-uniform scale + translation, and a
// mirrored axis), with padding, against OpenVDB's accessor for every output point.
TEST_F(OpenVDBReader, ValuesAndWorldPositions)
{
  TempDir tmp;
  struct Case
  {
    const char* Name;
    openvdb::math::Transform::Ptr Xform;
  };
  const Case cases[] = {
    { "scale_translate", ScaleTranslate(0.5, 0.25, 2.0, 1.0, -2.0, 3.0) },
    { "uniform", openvdb::math::Transform::createLinearTransform(0.1) },
    { "mirrored_x", ScaleTranslate(-0.5, 0.25, 2.0, 1.0, -2.0, 3.0) },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    const std::string path = tmp.File(std::string(c.Name) + ".vdb");
    openvdb::FloatGrid::Ptr grid = SmallGrid(c.Xform);
    Write(path, { grid });
    for (int padding : { 0, 2 })
    {
      SCOPED_TRACE(padding);
      vtkNew<vtkOpenVDBVolumeReader> reader;
      reader->SetPadding(padding);
      vtkSmartPointer<Messages> msgs = RunFile(reader, path);
      EXPECT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
      EXPECT_TRUE(msgs->Warnings.empty());
      ASSERT_FALSE(msgs->Progress.empty());
      EXPECT_EQ(msgs->Progress.back(), 1.0);
      vtkImageData* image = reader->GetOutput();
      // The active box is (-3,-1,5)..(4,2,9): 8 x 4 x 5 voxels, plus the padding.
      int dims[3];
      image->GetDimensions(dims);
      EXPECT_EQ(dims[0], 8 + 2 * padding);
      EXPECT_EQ(dims[1], 4 + 2 * padding);
      EXPECT_EQ(dims[2], 5 + 2 * padding);
      int extent[6];
      image->GetExtent(extent);
      EXPECT_EQ(extent[0], 0);
      EXPECT_EQ(extent[4], 0);
      double spacing[3];
      image->GetSpacing(spacing);
      const openvdb::Vec3d vs = grid->voxelSize();
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_NEAR(spacing[a], vs[a], 1e-12);
      }
      EXPECT_STREQ(image->GetPointData()->GetScalars()->GetName(), "density");
      vtkIdType active = 0;
      ExpectMatchesGrid(image, *grid, &active);
      EXPECT_EQ(active, 4);
      // Named voxels: the image point at the voxel's world centre holds its value.
      const std::pair<openvdb::Coord, float> voxels[] = { { openvdb::Coord(-3, 2, 5), 1.5f },
        { openvdb::Coord(4, -1, 7), 2.5f }, { openvdb::Coord(0, 0, 9), -1.0f },
        { openvdb::Coord(2, 0, 6), 0.25f }, { openvdb::Coord(-1, 0, 7), 0.25f } };
      for (const auto& v : voxels)
      {
        const openvdb::Vec3d w = grid->transform().indexToWorld(v.first);
        double x[3] = { w[0], w[1], w[2] };
        const vtkIdType id = image->FindPoint(x);
        ASSERT_GE(id, 0) << v.first;
        double p[3];
        image->GetPoint(id, p);
        EXPECT_NEAR(p[0], w[0], 1e-9);
        EXPECT_NEAR(p[1], w[1], 1e-9);
        EXPECT_NEAR(p[2], w[2], 1e-9);
        EXPECT_EQ(image->GetPointData()->GetScalars()->GetComponent(id, 0), v.second) << v.first;
      }
      // The padding holds the background.
      if (padding > 0)
      {
        EXPECT_EQ(image->GetPointData()->GetScalars()->GetComponent(0, 0), 0.25);
      }
      // Not temporal: no time steps.
      EXPECT_FALSE(
        reader->GetOutputInformation(0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
      EXPECT_EQ(reader->GetNumberOfTimeSteps(), 1);
    }
  }
}

// A real frame of the Mantaflow smoke: the last one of the repository's subset.
TEST_F(OpenVDBReader, SmokeFrame)
{
  const std::string path = SmokeDir + "smoke_0048.vdb";
  EXPECT_EQ(vtkOpenVDBVolumeReader::CanReadFile(path.c_str()), 1);
  vtkNew<vtkOpenVDBVolumeReader> reader;
  vtkSmartPointer<Messages> msgs = RunFile(reader, path);
  ASSERT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  // Active index box (1,1,1)..(41,41,62) (README).
  EXPECT_EQ(dims[0], 41);
  EXPECT_EQ(dims[1], 41);
  EXPECT_EQ(dims[2], 62);
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_DOUBLE_EQ(spacing[a], 0.046875);
    EXPECT_DOUBLE_EQ(origin[a], 0.046875); // voxel 1's centre
  }
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range);
  EXPECT_GE(range[0], 0.0);
  EXPECT_LE(range[1], 1.0);
  EXPECT_GT(range[1], 0.9);
  ExpectMatchesGrid(image, *ReadFloatGrid(path));
  // The listing, from metadata.
  ASSERT_EQ(reader->GetNumberOfGrids(), 1);
  EXPECT_STREQ(reader->GetGridName(0), "density");
  EXPECT_STREQ(reader->GetGridType(0), "float");
  EXPECT_EQ(reader->GetGridActiveVoxelCount(0), 93306);
  double b[6];
  reader->GetGridBounds(0, b);
  double ib[6];
  image->GetBounds(ib);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(b[i], ib[i], 1e-12) << i;
  }
  EXPECT_NEAR(b[1], 41 * 0.046875, 1e-12);
  EXPECT_NEAR(b[5], 62 * 0.046875, 1e-12);
}

// The grid listing: several grids of several types, with and without the statistics metadata.
TEST_F(OpenVDBReader, GridListing)
{
  TempDir tmp;
  openvdb::FloatGrid::Ptr density = SmallGrid(ScaleTranslate(0.5, 0.25, 2.0, 1.0, -2.0, 3.0));
  openvdb::Vec3SGrid::Ptr vel = openvdb::Vec3SGrid::create();
  vel->setName("vel");
  vel->tree().setValue(openvdb::Coord(10, 20, 30), openvdb::Vec3s(1, 2, 3));
  vel->tree().setValue(openvdb::Coord(11, 20, 30), openvdb::Vec3s(1, 2, 3));
  openvdb::Int32Grid::Ptr flags = openvdb::Int32Grid::create(0);
  flags->setName("flags");
  flags->tree().setValue(openvdb::Coord(0, 0, 0), 3);
  openvdb::FloatGrid::Ptr empty = openvdb::FloatGrid::create(0.0f);
  empty->setName("empty");
  for (bool stats : { true, false })
  {
    SCOPED_TRACE(stats ? "with statistics" : "without statistics");
    const std::string path = tmp.File(stats ? "stats.vdb" : "nostats.vdb");
    Write(path, { density, vel, flags, empty }, stats);
    vtkNew<vtkOpenVDBVolumeReader> reader;
    reader->SetFileName(path.c_str());
    reader->UpdateInformation();
    ASSERT_EQ(reader->GetNumberOfGrids(), 4);
    const char* names[] = { "density", "vel", "flags", "empty" };
    const char* types[] = { "float", "vec3s", "int32", "float" };
    // Without statistics only the grid to read ("density") is read to count its voxels.
    const vtkIdType counts[] = { 4, stats ? 2 : -1, stats ? 1 : -1, stats ? 0 : -1 };
    for (int i = 0; i < 4; ++i)
    {
      EXPECT_STREQ(reader->GetGridName(i), names[i]);
      EXPECT_STREQ(reader->GetGridType(i), types[i]);
      EXPECT_EQ(reader->GetGridActiveVoxelCount(i), counts[i]);
    }
    EXPECT_EQ(reader->GetGridName(4), nullptr);
    EXPECT_EQ(reader->GetGridActiveVoxelCount(-1), 0);
    int ib[6];
    reader->GetGridIndexBounds(0, ib);
    const int expectedIndex[6] = { -3, 4, -1, 2, 5, 9 };
    for (int i = 0; i < 6; ++i)
    {
      EXPECT_EQ(ib[i], expectedIndex[i]);
    }
    double b[6];
    reader->GetGridBounds(0, b);
    const double expected[6] = { 1 - 1.5, 1 + 2.0, -2 - 0.25, -2 + 0.5, 3 + 10, 3 + 18 };
    for (int i = 0; i < 6; ++i)
    {
      EXPECT_NEAR(b[i], expected[i], 1e-12) << i;
    }
    reader->GetGridBounds(1, b);
    if (stats)
    {
      EXPECT_DOUBLE_EQ(b[0], 10.0);
      EXPECT_DOUBLE_EQ(b[1], 11.0);
    }
    else
    {
      EXPECT_GT(b[0], b[1]); // unknown
    }
    reader->GetGridBounds(3, b);
    EXPECT_GT(b[0], b[1]); // empty
    // Reading density works from the same file; the output matches the grid.
    vtkSmartPointer<Messages> msgs = RunReader(reader);
    EXPECT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
    ExpectMatchesGrid(reader->GetOutput(), *density);
  }
}

// A 3-file sequence as VTK time steps, by pattern and by list.
TEST_F(OpenVDBReader, TimeSteps)
{
  const std::string files[3] = { SmokeDir + "smoke_0004.vdb", SmokeDir + "smoke_0008.vdb",
    SmokeDir + "smoke_0012.vdb" };
  vtkNew<vtkOpenVDBVolumeReader> byPattern;
  byPattern->SetFilePattern((SmokeDir + "smoke_%04d.vdb").c_str());
  byPattern->SetFileIndexRange(4, 12);
  byPattern->SetFileIndexIncrement(4);
  vtkNew<vtkOpenVDBVolumeReader> byList;
  for (const std::string& f : files)
  {
    byList->AddFileName(f.c_str());
  }
  byList->SetFileName("ignored.vdb"); // the list takes precedence
  EXPECT_EQ(byList->GetNumberOfFileNames(), 3);
  EXPECT_EQ(byList->GetNthFileName(1), files[1]);
  for (vtkOpenVDBVolumeReader* reader : { byPattern.Get(), byList.Get() })
  {
    SCOPED_TRACE(reader == byPattern.Get() ? "pattern" : "list");
    reader->UpdateInformation();
    vtkInformation* outInfo = reader->GetOutputInformation(0);
    ASSERT_TRUE(outInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
    ASSERT_EQ(outInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 3);
    const double* times = outInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    EXPECT_EQ(times[0], 0.0);
    EXPECT_EQ(times[1], 1.0);
    EXPECT_EQ(times[2], 2.0);
    const double* range = outInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    EXPECT_EQ(range[0], 0.0);
    EXPECT_EQ(range[1], 2.0);
    ASSERT_EQ(reader->GetNumberOfTimeSteps(), 3);
    EXPECT_EQ(reader->GetTimeStepFileName(2), files[2]);

    // time 1 -> frame 1 (smoke_0008); 1.4 -> nearest (1); 7 -> clamped to the last.
    const std::pair<double, int> requests[] = { { 1.0, 1 }, { 0.0, 0 }, { 1.4, 1 }, { 7.0, 2 } };
    for (const auto& r : requests)
    {
      SCOPED_TRACE(r.first);
      vtkSmartPointer<Messages> msgs = RunReader(reader, r.first);
      EXPECT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
      vtkImageData* image = reader->GetOutput();
      ASSERT_TRUE(image->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()));
      EXPECT_EQ(image->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), double(r.second));
      vtkIdType active = 0;
      ExpectMatchesGrid(image, *ReadFloatGrid(files[r.second]), &active);
      EXPECT_EQ(active, ReadFloatGrid(files[r.second])->activeVoxelCount());
    }
  }
}

// UnionBounds: one extent for the whole sequence, the union of the frames' active boxes;
// off: each frame its own box, also when one reader steps through time.
TEST_F(OpenVDBReader, UnionBounds)
{
  vtkNew<vtkOpenVDBVolumeReader> reader;
  reader->SetFilePattern((SmokeDir + "smoke_%04d.vdb").c_str());
  reader->SetFileIndexRange(4, 48);
  reader->SetFileIndexIncrement(12); // 4, 16, 28, 40
  reader->SetPadding(1);
  const int n = 4;
  openvdb::CoordBBox unionBox;
  std::vector<openvdb::CoordBBox> boxes;
  for (int i = 0; i < n; ++i)
  {
    char name[64];
    std::snprintf(name, sizeof(name), "smoke_%04d.vdb", 4 + 12 * i);
    boxes.push_back(ReadFloatGrid(SmokeDir + name)->evalActiveVoxelBoundingBox());
    unionBox.expand(boxes.back());
  }
  ASSERT_NE(boxes.front(), boxes.back()); // the plume grows

  EXPECT_TRUE(reader->GetUnionBounds());
  int firstExtent[6];
  double firstOrigin[3];
  for (int t = 0; t < n; ++t)
  {
    SCOPED_TRACE(t);
    vtkSmartPointer<Messages> msgs = RunReader(reader, t);
    ASSERT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
    vtkImageData* image = reader->GetOutput();
    int extent[6];
    double origin[3];
    image->GetExtent(extent);
    image->GetOrigin(origin);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(extent[2 * a + 1] + 1, unionBox.dim()[a] + 2);
      EXPECT_DOUBLE_EQ(origin[a], 0.046875 * (unionBox.min()[a] - 1));
    }
    if (t == 0)
    {
      std::copy(extent, extent + 6, firstExtent);
      std::copy(origin, origin + 3, firstOrigin);
    }
    EXPECT_TRUE(std::equal(extent, extent + 6, firstExtent));
    EXPECT_TRUE(std::equal(origin, origin + 3, firstOrigin));
    int whole[6];
    reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    EXPECT_TRUE(std::equal(whole, whole + 6, firstExtent));
  }

  // Off: each step covers its own box (+ padding), and the published whole extent follows.
  reader->UnionBoundsOff();
  for (int t : { 0, 3, 1 })
  {
    SCOPED_TRACE(t);
    vtkSmartPointer<Messages> msgs = RunReader(reader, t);
    ASSERT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    double origin[3];
    image->GetDimensions(dims);
    image->GetOrigin(origin);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(dims[a], boxes[t].dim()[a] + 2);
      EXPECT_DOUBLE_EQ(origin[a], 0.046875 * (boxes[t].min()[a] - 1));
    }
    int whole[6], extent[6];
    image->GetExtent(extent);
    reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    EXPECT_TRUE(std::equal(whole, whole + 6, extent));
  }
}

// The ways OpenVDB stores a float tree: blosc, zip or no compression, with or without active
// mask compression, full or half floats; a level set (inactive values +-background, so
// selection masks), active tiles, inactive values that are not the background.
TEST_F(OpenVDBReader, CompressionAndTreeShapes)
{
  TempDir tmp;
  openvdb::FloatGrid::Ptr grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
    4.0f, openvdb::Vec3f(1, 2, 3), 0.5f, 2.0f);
  grid->setName("density");
  grid->tree().addTile(1, openvdb::Coord(40, 0, 0), 0.5f, true); // an active 8^3 tile
  auto acc = grid->getAccessor();
  acc.setValueOff(openvdb::Coord(0, 0, 0), 7.0f); // inactive, not +-background
  acc.setValueOff(openvdb::Coord(1, 0, 0), 8.0f);
  acc.setValueOff(openvdb::Coord(2, 0, 0), 9.0f);
  using namespace openvdb::io;
  const uint32_t modes[] = { COMPRESS_BLOSC | COMPRESS_ACTIVE_MASK,
    COMPRESS_ZIP | COMPRESS_ACTIVE_MASK, COMPRESS_ZIP, COMPRESS_BLOSC, COMPRESS_ACTIVE_MASK,
    COMPRESS_NONE };
  int n = 0;
  for (uint32_t mode : modes)
  {
    for (bool half : { false, true })
    {
      SCOPED_TRACE(compressionToString(mode) + (half ? ", half" : ""));
      const std::string path = tmp.File("tree" + std::to_string(n++) + ".vdb");
      grid->setSaveFloatAsHalf(half);
      openvdb::io::File file(path);
      file.setCompression(mode);
      file.write({ grid });
      file.close();
      vtkNew<vtkOpenVDBVolumeReader> reader;
      vtkSmartPointer<Messages> msgs = RunFile(reader, path);
      ASSERT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
      vtkIdType active = 0;
      openvdb::FloatGrid::Ptr stored = ReadFloatGrid(path);
      ExpectMatchesGrid(reader->GetOutput(), *stored, &active);
      EXPECT_EQ(active, vtkIdType(grid->activeVoxelCount()));
    }
  }
}

// Statistics metadata that does not describe the voxels is an error (it sizes the output).
TEST_F(OpenVDBReader, StaleMetadata)
{
  TempDir tmp;
  openvdb::FloatGrid::Ptr grid = SmallGrid(openvdb::math::Transform::createLinearTransform(1.0));
  grid->insertMeta(
    openvdb::GridBase::META_FILE_BBOX_MIN, openvdb::Vec3IMetadata(openvdb::Vec3i(-500, 0, 0)));
  grid->insertMeta(
    openvdb::GridBase::META_FILE_BBOX_MAX, openvdb::Vec3IMetadata(openvdb::Vec3i(500, 9, 9)));
  grid->insertMeta(openvdb::GridBase::META_FILE_VOXEL_COUNT, openvdb::Int64Metadata(4));
  const std::string path = tmp.File("stale.vdb");
  Write(path, { grid }, /*stats=*/false);
  vtkNew<vtkOpenVDBVolumeReader> reader;
  ExpectErrorContaining(reader, path, { "metadata", "[-500, 0, 0]" }, "stale bbox");
}

// An empty grid: a single background voxel and a warning, not an error.
TEST_F(OpenVDBReader, EmptyGrid)
{
  TempDir tmp;
  openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.5f);
  grid->setName("density");
  grid->setTransform(openvdb::math::Transform::createLinearTransform(0.2));
  const std::string path = tmp.File("empty.vdb");
  Write(path, { grid });
  vtkNew<vtkOpenVDBVolumeReader> reader;
  vtkSmartPointer<Messages> msgs = RunFile(reader, path);
  EXPECT_TRUE(msgs->Errors.empty()) << msgs->AllErrors();
  ASSERT_EQ(msgs->Warnings.size(), 1u);
  EXPECT_NE(msgs->Warnings[0].find("no active voxels"), std::string::npos) << msgs->Warnings[0];
  vtkImageData* image = reader->GetOutput();
  ASSERT_EQ(image->GetNumberOfPoints(), 1);
  EXPECT_EQ(image->GetPointData()->GetScalars()->GetComponent(0, 0), 0.5);
  double origin[3];
  image->GetOrigin(origin);
  EXPECT_EQ(origin[0], 0.0);
  reader->SetPadding(1);
  msgs = RunReader(reader);
  EXPECT_EQ(image->GetNumberOfPoints(), 27);
}

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
    std::ifstream in(std::string(VISSWEEP_DATA) + "/smoke/smoke_0004.vdb", std::ios::binary);
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
