// The command-line tool's volume loading (vsToolVolume, issue 13 items 2, 8 and 9): every
// reader's failure is an error naming the file and the reason, never a render of partial or
// uninitialised data; paths that are not regular files are refused before a reader opens them
// (a FIFO blocked forever); a header claiming a huge volume is refused with its size before
// anything is allocated; zero or non-finite spacing and origin are refused. No device needed.
#include "vsToolVolume.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMetaImageWriter.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <array>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
const int Side = 16; // 16^3 float voxels = 16 KB of data

fs::path Folder()
{
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("vissweep-tool-volume-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

std::string PathOf(const std::string& name)
{
  return (Folder() / name).string();
}

vtkSmartPointer<vtkImageData> Ramp()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(Side, Side, Side);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(vtkIdType(Side) * Side * Side);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    a->SetValue(i, float(i % 251));
  }
  image->GetPointData()->SetScalars(a);
  return image;
}

std::vector<char> Bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteBytes(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

// A copy of `from` cut to `fraction` of its length.
std::string Truncated(const std::string& from, const std::string& name, double fraction)
{
  std::vector<char> b = Bytes(from);
  b.resize(size_t(double(b.size()) * fraction));
  const std::string path = PathOf(name);
  WriteBytes(path, b);
  return path;
}

std::string WriteNifti(const std::string& name)
{
  vtkNew<vtkNIFTIImageWriter> w;
  w->SetFileName(PathOf(name).c_str());
  w->SetInputData(Ramp());
  w->Write();
  return PathOf(name);
}

// A MetaImage: `.mha` with the data inline, `.mhd` with the data in `<name>.raw`.
std::string WriteMeta(const std::string& name)
{
  vtkNew<vtkMetaImageWriter> w;
  w->SetFileName(PathOf(name).c_str());
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".mhd") == 0)
  {
    w->SetRAWFileName(PathOf(name.substr(0, name.size() - 4) + ".raw").c_str());
  }
  w->SetCompression(false);
  w->SetInputData(Ramp());
  w->Write();
  return PathOf(name);
}

std::string NrrdHeader(const std::string& spacings)
{
  return "NRRD0004\ntype: float\ndimension: 3\nsizes: 16 16 16\nencoding: raw\nendian: little\nspacings: " +
    spacings + "\n\n";
}

std::string WriteNrrd(const std::string& name, const std::string& spacings = "1 1 1")
{
  std::vector<char> b;
  const std::string h = NrrdHeader(spacings);
  b.insert(b.end(), h.begin(), h.end());
  std::vector<float> v(size_t(Side) * Side * Side);
  for (size_t i = 0; i < v.size(); ++i)
  {
    v[i] = float(i % 251);
  }
  const char* p = reinterpret_cast<const char*>(v.data());
  b.insert(b.end(), p, p + v.size() * sizeof(float));
  WriteBytes(PathOf(name), b);
  return PathOf(name);
}

// ReadVolume's error for `path`; fails the test if it read the file.
std::string ErrorOf(const std::string& path, const std::string& grid = "density")
{
  try
  {
    auto image = vstool::ReadVolume(path, grid);
    ADD_FAILURE() << path << " was read (" << image->GetNumberOfPoints() << " points), expected an error";
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return std::string();
}

void ExpectReadable(const std::string& path)
{
  auto image = vstool::ReadVolume(path);
  ASSERT_TRUE(image);
  EXPECT_EQ(image->GetNumberOfPoints(), vtkIdType(Side) * Side * Side) << path;
  vtkDataArray* s = image->GetPointData()->GetScalars();
  ASSERT_TRUE(s);
  EXPECT_EQ(s->GetRange()[1], 250.0) << path;
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)
}

// The good files read: what the other tests break must first work.
TEST(ToolVolume, GoodFilesOfEveryFormatRead)
{
  ExpectReadable(WriteNifti("good.nii"));
  ExpectReadable(WriteNifti("good.nii.gz"));
  ExpectReadable(WriteMeta("good.mha"));
  ExpectReadable(WriteMeta("good.mhd"));
  ExpectReadable(WriteNrrd("good.nrrd"));
}

TEST(ToolVolume, TruncatedNiftiIsAnError)
{
  const std::string path = Truncated(WriteNifti("t.nii"), "truncated.nii", 0.5);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
}

TEST(ToolVolume, TruncatedCompressedNiftiIsAnError)
{
  const std::string path = Truncated(WriteNifti("t.nii.gz"), "truncated.nii.gz", 0.5);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
}

TEST(ToolVolume, TruncatedMetaImageIsAnError)
{
  const std::string path = Truncated(WriteMeta("t.mha"), "truncated.mha", 0.5);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
  EXPECT_CONTAINS(e, "not read completely");
}

TEST(ToolVolume, TruncatedNrrdIsAnError)
{
  const std::string path = Truncated(WriteNrrd("t.nrrd"), "truncated.nrrd", 0.5);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
}

TEST(ToolVolume, MetaImageWithoutItsDataFileIsAnError)
{
  const std::string path = WriteMeta("noraw.mhd");
  fs::remove(PathOf("noraw.raw"));
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, "noraw.raw");
  EXPECT_CONTAINS(e, "does not exist");
}

TEST(ToolVolume, TruncatedVdbIsAnError)
{
  const std::string path =
    Truncated(std::string(VISSWEEP_DATA) + "/smoke/smoke_0004.vdb", "truncated.vdb", 0.75);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
}

// A FIFO blocked the reader forever (the test's TIMEOUT catches a regression).
TEST(ToolVolume, FifoIsRefused)
{
  const std::string path = PathOf("pipe.nii");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
  EXPECT_CONTAINS(e, "FIFO");
}

TEST(ToolVolume, CharacterDeviceIsRefused)
{
  const std::string path = PathOf("zero.nrrd");
  fs::create_symlink("/dev/zero", path);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, "character device");
}

TEST(ToolVolume, MetaImageDataFileThatIsAFifoIsRefused)
{
  const std::string path = WriteMeta("fifodata.mhd");
  fs::remove(PathOf("fifodata.raw"));
  ASSERT_EQ(::mkfifo(PathOf("fifodata.raw").c_str(), 0600), 0);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, "fifodata.raw");
  EXPECT_CONTAINS(e, "FIFO");
}

// A NIfTI header claiming 32767^3 voxels: refused with the size before any allocation
// (it was std::bad_alloc, or a huge allocation).
TEST(ToolVolume, HugeHeaderIsRefusedWithItsSize)
{
  std::vector<char> b = Bytes(WriteNifti("h.nii"));
  ASSERT_GT(b.size(), 348u);
  for (int axis = 1; axis <= 3; ++axis)
  {
    const int16_t n = 32767;
    std::memcpy(&b[40 + 2 * axis], &n, sizeof(n)); // dim[axis]
  }
  const std::string path = PathOf("huge.nii");
  WriteBytes(path, b);
  const std::string e = ErrorOf(path);
  EXPECT_CONTAINS(e, path);
  EXPECT_CONTAINS(e, "32767 x 32767 x 32767");
}

// Issue 13, item 7: a size check runs on the header's dimensions before the data is read: for a
// header whose data is missing, its reason comes first, not the reader's "truncated".
TEST(ToolVolume, SizeCheckRunsBeforeTheDataIsRead)
{
  std::vector<char> b = Bytes(WriteNifti("s.nii"));
  ASSERT_GT(b.size(), 352u);
  const int16_t n = 1200;
  for (int axis = 1; axis <= 3; ++axis)
  {
    std::memcpy(&b[40 + 2 * axis], &n, sizeof(n)); // dim[axis]
  }
  b.resize(352); // the header only
  const std::string path = PathOf("sized.nii");
  WriteBytes(path, b);
  std::array<int, 3> seen{ 0, 0, 0 };
  std::string e;
  try
  {
    vstool::ReadVolume(path, "density", vtkIdType(1) << 31, [&seen](const std::array<int, 3>& d) {
      seen = d;
      return std::string("too large for the test's device");
    });
  }
  catch (const std::runtime_error& x)
  {
    e = x.what();
  }
  EXPECT_EQ(seen, (std::array<int, 3>{ 1200, 1200, 1200 }));
  EXPECT_CONTAINS(e, path);
  EXPECT_CONTAINS(e, "its header describes 1200 x 1200 x 1200 (1728000000 points): too large for the test's device");
  // Without a check (or one that passes) the reader says what is wrong with the file.
  EXPECT_CONTAINS(ErrorOf(path), "truncated");
}

TEST(ToolVolume, ZeroSpacingIsRefused)
{
  const std::string e = ErrorOf(WriteNrrd("zero.nrrd", "1 0 1"));
  EXPECT_CONTAINS(e, "spacing along y is 0");
}

TEST(ToolVolume, NonFiniteSpacingIsRefused)
{
  const std::string e = ErrorOf(WriteNrrd("nan.nrrd", "1 1 nan"));
  EXPECT_CONTAINS(e, "spacing along z");
}

TEST(ToolVolume, DirectoryWithoutDicomIsAnError)
{
  fs::create_directories(Folder() / "empty-folder");
  const std::string e = ErrorOf(PathOf("empty-folder"));
  EXPECT_CONTAINS(e, "empty-folder");
}
