// vtkOpenVDBVolumeReader: values and world positions against OpenVDB's own accessor (grids
// written here with the OpenVDB API), the real Mantaflow smoke frames, the grid listing,
// file sequences as VTK time steps, union bounds, the tree shapes OpenVDB writes, stale metadata
// and empty grids. The error cases are in TestOpenVDBReaderErrors.cxx.
#include "vsOpenVDBReaderTest.h"

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
