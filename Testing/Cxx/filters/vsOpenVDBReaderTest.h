// vsOpenVDBReaderTest.h — what the OpenVDB reader's tests share: the fixture (OpenVDB initialised
// once), a reader run that collects its messages, grids written with the OpenVDB API and compared
// voxel by voxel, and the check of an error that leaves the output empty.
#ifndef vsOpenVDBReaderTest_h
#define vsOpenVDBReaderTest_h
#include "vsTestPaths.h"
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

#include "vsTempDir.h"

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
const std::string SmokeDir = vstest::DataDir() + "/smoke/";

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

using vstest::TempDir;

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
} // namespace

// Outside the anonymous namespace: both test files' TEST_Fs must use one fixture type.
class OpenVDBReader : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { openvdb::initialize(); }
};

#endif
