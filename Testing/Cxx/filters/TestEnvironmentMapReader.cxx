// vtkEnvironmentMapReader and vtkEnvironmentMapSource: the real CC0 maps, a
// hand-written Radiance .hdr, errors for missing/corrupt files, output layout.
#include "vsEnvironmentMap.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkEnvironmentMapSource.h"

#include "sampling/octahedral.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

const std::string EnvDir = std::string(VISSWEEP_DATA) + "/envmaps/";

class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)
      .push_back(data ? static_cast<const char*>(data) : "");
  }
  std::vector<std::string> Errors, Warnings;
};

struct TempDir
{
  std::filesystem::path Path;
  TempDir()
  {
    Path = std::filesystem::temp_directory_path() /
      ("vissweep_envmap_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
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

/* Runs a reader on fileName and returns the messages. */
vtkSmartPointer<Messages> RunReader(vtkEnvironmentMapReader* reader, const std::string& fileName)
{
  vtkNew<Messages> msgs;
  reader->AddObserver(vtkCommand::ErrorEvent, msgs);
  reader->AddObserver(vtkCommand::WarningEvent, msgs);
  reader->SetFileName(fileName.c_str());
  reader->Update();
  reader->RemoveObserver(msgs);
  return vtkSmartPointer<Messages>(msgs.Get());
}

void ExpectErrorNamingFile(const std::string& fileName, const std::string& why)
{
  vtkNew<vtkEnvironmentMapReader> reader;
  auto msgs = RunReader(reader, fileName);
  ASSERT_EQ(msgs->Errors.size(), 1u) << why;
  EXPECT_NE(msgs->Errors[0].find(fileName), std::string::npos) << msgs->Errors[0];
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << why;
  EXPECT_FALSE(reader->GetEnvironmentMap()) << why;
  vs::LatLongImage img;
  std::string error;
  EXPECT_FALSE(vtkEnvironmentMapReader::ReadLatLong(fileName.c_str(), img, error));
  EXPECT_NE(error.find(fileName), std::string::npos) << error;
}

/* Radiance RGBE of a float triple (Greg Ward's float2rgbe). */
void ToRGBE(const float c[3], unsigned char out[4])
{
  const float v = std::max(c[0], std::max(c[1], c[2]));
  if (v < 1e-32f)
  {
    out[0] = out[1] = out[2] = out[3] = 0;
    return;
  }
  int e;
  const float m = std::frexp(v, &e) * 256.0f / v;
  out[0] = (unsigned char)(c[0] * m);
  out[1] = (unsigned char)(c[1] * m);
  out[2] = (unsigned char)(c[2] * m);
  out[3] = (unsigned char)(e + 128);
}

/* A minimal OpenEXR writer (uncompressed, one level), enough to test the reader
 * on half/float, RGB/RGBA/Y, scanline/tiled files and a data window offset
 * without linking OpenEXR into the tests. pixel(x, y, channel) gives the values,
 * x, y in display-window coordinates; channels are sorted by name as EXR requires. */
struct ExrSpec
{
  std::vector<std::string> Channels; // e.g. {"B", "G", "R"}
  bool Half = false;
  int Tile = 0; // 0: scanlines, else tile edge
  int DisplayW = 16, DisplayH = 8;
  int DataX0 = 0, DataY0 = 0, DataX1 = 15, DataY1 = 7; // inclusive data window
};

std::uint16_t ToHalf(float f)
{
  // Normal numbers and zero only (the test values are exact in half).
  std::uint32_t x;
  std::memcpy(&x, &f, 4);
  const std::uint32_t sign = (x >> 16) & 0x8000u;
  const int exp = int((x >> 23) & 0xff) - 127 + 15;
  const std::uint32_t mant = (x >> 13) & 0x3ffu;
  if ((x & 0x7fffffffu) == 0 || exp <= 0)
  {
    return std::uint16_t(sign);
  }
  return std::uint16_t(sign | (std::uint32_t(exp) << 10) | mant);
}

void WriteExr(const std::string& file, const ExrSpec& spec, const std::function<float(int, int, int)>& pixel)
{
  std::string out;
  auto u8 = [&](unsigned v) { out.push_back(char(v)); };
  auto i32 = [&](std::int32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  auto u64 = [&](std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), 8); };
  auto f32 = [&](float v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  auto str = [&](const std::string& v) { out.append(v); out.push_back('\0'); };
  auto attr = [&](const std::string& name, const std::string& type, int size) { str(name); str(type); i32(size); };

  i32(20000630);
  i32(2 | (spec.Tile ? 0x200 : 0));
  const int pixelType = spec.Half ? 1 : 2;
  const int bytes = spec.Half ? 2 : 4;
  int chlistSize = 1;
  for (const std::string& c : spec.Channels)
  {
    chlistSize += int(c.size()) + 1 + 16;
  }
  attr("channels", "chlist", chlistSize);
  for (const std::string& c : spec.Channels)
  {
    str(c);
    i32(pixelType);
    u8(0); u8(0); u8(0); u8(0);
    i32(1);
    i32(1);
  }
  u8(0);
  attr("compression", "compression", 1);
  u8(0);
  attr("dataWindow", "box2i", 16);
  i32(spec.DataX0); i32(spec.DataY0); i32(spec.DataX1); i32(spec.DataY1);
  attr("displayWindow", "box2i", 16);
  i32(0); i32(0); i32(spec.DisplayW - 1); i32(spec.DisplayH - 1);
  attr("lineOrder", "lineOrder", 1);
  u8(0);
  attr("pixelAspectRatio", "float", 4);
  f32(1.0f);
  attr("screenWindowCenter", "v2f", 8);
  f32(0.0f); f32(0.0f);
  attr("screenWindowWidth", "float", 4);
  f32(1.0f);
  if (spec.Tile)
  {
    attr("tiles", "tiledesc", 9);
    i32(spec.Tile); i32(spec.Tile); u8(0);
  }
  u8(0); // end of header

  const int dw = spec.DataX1 - spec.DataX0 + 1, dh = spec.DataY1 - spec.DataY0 + 1;
  // One chunk per scanline, or per tile (row-major tiles).
  struct Chunk { int x0, y0, x1, y1, tx, ty; };
  std::vector<Chunk> chunks;
  if (spec.Tile)
  {
    for (int ty = 0; ty * spec.Tile < dh; ++ty)
      for (int tx = 0; tx * spec.Tile < dw; ++tx)
        chunks.push_back({ spec.DataX0 + tx * spec.Tile, spec.DataY0 + ty * spec.Tile,
          std::min(spec.DataX1, spec.DataX0 + (tx + 1) * spec.Tile - 1),
          std::min(spec.DataY1, spec.DataY0 + (ty + 1) * spec.Tile - 1), tx, ty });
  }
  else
  {
    for (int y = spec.DataY0; y <= spec.DataY1; ++y)
      chunks.push_back({ spec.DataX0, y, spec.DataX1, y, 0, 0 });
  }
  const std::size_t tableAt = out.size();
  for (std::size_t i = 0; i < chunks.size(); ++i)
  {
    u64(0);
  }
  for (std::size_t i = 0; i < chunks.size(); ++i)
  {
    const std::uint64_t offset = out.size();
    std::memcpy(&out[tableAt + 8 * i], &offset, 8);
    const Chunk& k = chunks[i];
    if (spec.Tile)
    {
      i32(k.tx); i32(k.ty); i32(0); i32(0);
    }
    else
    {
      i32(k.y0);
    }
    i32((k.x1 - k.x0 + 1) * (k.y1 - k.y0 + 1) * bytes * int(spec.Channels.size()));
    for (int y = k.y0; y <= k.y1; ++y)
    {
      for (std::size_t c = 0; c < spec.Channels.size(); ++c)
      {
        for (int x = k.x0; x <= k.x1; ++x)
        {
          const float v = pixel(x, y, int(c));
          if (spec.Half)
          {
            const std::uint16_t h = ToHalf(v);
            out.append(reinterpret_cast<const char*>(&h), 2);
          }
          else
          {
            f32(v);
          }
        }
      }
    }
  }
  std::ofstream(file, std::ios::binary).write(out.data(), std::streamsize(out.size()));
}
} // namespace

TEST(EnvironmentMapReader, RealMapsKeepTheirPower)
{
  for (const char* name : { "sunrise.exr", "courtyard.exr", "city.exr", "forest.exr" })
  {
    const std::string file = EnvDir + name;
    vs::LatLongImage img;
    std::string error;
    ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(file.c_str(), img, error)) << error;
    EXPECT_EQ(img.Width, 1024);
    EXPECT_EQ(img.Height, 512);
    const double latLong = vs::LatLongPower(img);
    const vs::EnvironmentMap map = vs::EnvironmentMap::FromLatLong(img);
    EXPECT_EQ(map.Size, 512);
    EXPECT_GT(latLong, 0.0);
    EXPECT_NEAR(map.TotalPower(), latLong, 0.005 * latLong) << name;
    // The real maps carry tiny negative values (gamut clipping), no NaN/Inf.
    EXPECT_EQ(map.NonFiniteTexels, 0) << name;
  }
}

// Issue 13, item 10: the shipped HDRIs carry slightly negative pixels (299 to 1188, the largest
// 0.79% of the map's mean luminance: compression ringing); they are zeroed without a warning on
// every load. A map with real negative radiance (beyond 1% of its mean) still warns, once.
TEST(EnvironmentMapReader, ShippedMapsLoadWithoutWarnings)
{
  const std::pair<const char*, int> maps[] = { { "sunrise.exr", 570 }, { "courtyard.exr", 1188 }, { "city.exr", 299 },
    { "forest.exr", 784 } };
  for (const auto& m : maps)
  {
    vtkNew<vtkEnvironmentMapReader> reader;
    reader->SetOctahedralSize(64);
    auto msgs = RunReader(reader, EnvDir + m.first);
    EXPECT_TRUE(msgs->Errors.empty()) << m.first;
    EXPECT_TRUE(msgs->Warnings.empty()) << m.first << ": " << (msgs->Warnings.empty() ? "" : msgs->Warnings[0]);
    auto map = reader->GetEnvironmentMap();
    ASSERT_TRUE(map) << m.first;
    EXPECT_EQ(map->BadTexels, 0) << m.first;
    EXPECT_EQ(map->RingingTexels, m.second) << m.first;
  }
}

TEST(EnvironmentMapReader, RealNegativeRadianceStillWarns)
{
  TempDir tmp;
  ExrSpec spec;
  spec.Channels = { "B", "G", "R" };
  // Radiance 1 everywhere; pixel (3, 2) has a red of -0.5 (50% of the mean: no ringing), pixel
  // (9, 5) a green of -0.005 (0.5%: ringing).
  WriteExr(tmp.File("negative.exr"), spec, [](int x, int y, int c) {
    if (x == 3 && y == 2 && c == 2)
      return -0.5f;
    if (x == 9 && y == 5 && c == 1)
      return -0.005f;
    return 1.0f;
  });
  vtkNew<vtkEnvironmentMapReader> reader;
  reader->SetOctahedralSize(8);
  auto msgs = RunReader(reader, tmp.File("negative.exr"));
  EXPECT_TRUE(msgs->Errors.empty());
  ASSERT_EQ(msgs->Warnings.size(), 1u);
  EXPECT_NE(msgs->Warnings[0].find("1 pixels had a negative, NaN or infinite value"), std::string::npos)
    << msgs->Warnings[0];
  auto map = reader->GetEnvironmentMap();
  ASSERT_TRUE(map);
  EXPECT_EQ(map->BadTexels, 1);
  EXPECT_EQ(map->RingingTexels, 1);
  for (float v : map->Radiance)
  {
    EXPECT_TRUE(std::isfinite(v) && v >= 0.0f);
  }
}

// sunrise.exr: its brightest pixel (the sun, low above the horizon) lands in the
// octahedral map at the direction the lat-long convention gives.
TEST(EnvironmentMapReader, SunriseSunDirection)
{
  vtkNew<vtkEnvironmentMapReader> reader;
  auto msgs = RunReader(reader, EnvDir + "sunrise.exr");
  EXPECT_TRUE(msgs->Errors.empty());
  EXPECT_TRUE(msgs->Warnings.empty()); // its 570 slightly negative pixels are ringing (issue 13, item 10)
  auto map = reader->GetEnvironmentMap();
  ASSERT_TRUE(map);
  EXPECT_EQ(map->BadTexels, 0);
  EXPECT_EQ(map->RingingTexels, 570);

  vs::LatLongImage img;
  std::string error;
  ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong((EnvDir + "sunrise.exr").c_str(), img, error));
  int bi = 0, bj = 0;
  for (int j = 0; j < img.Height; ++j)
  {
    for (int i = 0; i < img.Width; ++i)
    {
      if (vs::Luminance(img.Pixel(i, j)) > vs::Luminance(img.Pixel(bi, bj)))
      {
        bi = i;
        bj = j;
      }
    }
  }
  const glm::dvec3 sun(vs::LatLongToDirection((bi + 0.5) / img.Width, (bj + 0.5) / img.Height));
  // The sun rises: a few degrees above the horizon.
  EXPECT_GT(sun.z, 0.0);
  EXPECT_LT(sun.z, 0.3);
  const float* lum = map->Mip(map->Levels() - 1);
  int best = 0;
  for (int t = 1; t < map->Size * map->Size; ++t)
  {
    best = lum[t] > lum[best] ? t : best;
  }
  const glm::dvec3 got(
    vs::shared::vs_texel_dir(glm::uvec2(best % map->Size, best / map->Size), unsigned(map->Size)));
  const double angle = std::atan2(glm::length(glm::cross(got, sun)), glm::dot(got, sun)) * 180.0 / Pi;
  EXPECT_LT(angle, 1.0) << "sun at pixel " << bi << "," << bj;
  // And Evaluate towards the sun sees it.
  EXPECT_GT(vs::Luminance(map->Evaluate(glm::vec3(sun))), 100.0f);

  // Rotated by 90 degrees, the sun turns 90 degrees about +Z.
  reader->SetRotationDegrees(90.0);
  reader->Update();
  const glm::dvec3 turned(-sun.y, sun.x, sun.z);
  EXPECT_GT(vs::Luminance(reader->GetEnvironmentMap()->Evaluate(glm::vec3(turned))), 100.0f);
  EXPECT_NEAR(reader->GetTotalPower(), map->TotalPower(), 1e-3 * map->TotalPower());
}

TEST(EnvironmentMapReader, OutputLayout)
{
  vtkNew<vtkEnvironmentMapReader> reader;
  reader->SetOctahedralSize(64);
  reader->SetIntensity(2.0);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(data));
  });
  reader->AddObserver(vtkCommand::ProgressEvent, onProgress);
  auto msgs = RunReader(reader, EnvDir + "forest.exr");
  EXPECT_TRUE(msgs->Errors.empty());
  ASSERT_GE(progress.size(), 3u);
  EXPECT_EQ(progress.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  vtkImageData* out = reader->GetOutput();
  int dims[3];
  out->GetDimensions(dims);
  EXPECT_EQ(dims[0], 64);
  EXPECT_EQ(dims[1], 64);
  EXPECT_EQ(dims[2], 1);
  EXPECT_EQ(reader->GetLatLongWidth(), 1024);
  EXPECT_EQ(reader->GetLatLongHeight(), 512);
  vtkDataArray* radiance = out->GetPointData()->GetScalars();
  ASSERT_TRUE(radiance);
  EXPECT_STREQ(radiance->GetName(), "Radiance");
  EXPECT_EQ(radiance->GetNumberOfComponents(), 3);
  vtkDataArray* importance = out->GetPointData()->GetArray("Importance");
  ASSERT_TRUE(importance);
  auto* mips = vtkFloatArray::SafeDownCast(out->GetFieldData()->GetArray("ImportanceMips"));
  ASSERT_TRUE(mips);
  EXPECT_EQ(mips->GetNumberOfTuples(), (4 * 4096 - 1) / 3);
  ASSERT_TRUE(out->GetFieldData()->GetArray("NonFiniteTexels"));
  ASSERT_TRUE(out->GetFieldData()->GetArray("BadTexels"));
  EXPECT_EQ(out->GetFieldData()->GetArray("NonFiniteTexels")->GetTuple1(0), 0.0);
  EXPECT_EQ(out->GetFieldData()->GetArray("BadTexels")->GetTuple1(0), 0.0); // forest's negatives are ringing

  auto map = reader->GetEnvironmentMap();
  ASSERT_TRUE(map);
  for (int y = 0; y < 64; y += 7)
  {
    for (int x = 0; x < 64; x += 5)
    {
      const vtkIdType id = out->ComputePointId(std::array<int, 3>{ x, y, 0 }.data());
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(radiance->GetComponent(id, c), map->Texel(x, y)[c]);
      }
      EXPECT_EQ(importance->GetComponent(id, 0), vs::Luminance(map->Texel(x, y)));
      // Point coordinates are the octahedral uv of the texel centre.
      double p[3];
      out->GetPoint(id, p);
      EXPECT_NEAR(p[0], (x + 0.5) / 64, 1e-12);
      EXPECT_NEAR(p[1], (y + 0.5) / 64, 1e-12);
    }
  }
  EXPECT_EQ(mips->GetValue(0), map->ImportanceMips[0]);
  EXPECT_NEAR(out->GetFieldData()->GetArray("TotalPower")->GetTuple1(0), map->TotalPower(), 1e-9);

  // Intensity 2 doubles the power of the default conversion.
  vs::LatLongImage img;
  std::string error;
  ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong((EnvDir + "forest.exr").c_str(), img, error));
  EXPECT_NEAR(map->TotalPower(), 2.0 * vs::LatLongPower(img), 0.01 * map->TotalPower());

  // The image converts back to the same map.
  std::string why;
  auto back = vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(out, &why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(back->Radiance, map->Radiance);
  EXPECT_EQ(back->ImportanceMips, map->ImportanceMips);
  vtkNew<vtkImageData> wrong;
  wrong->SetDimensions(6, 6, 1);
  EXPECT_FALSE(vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(wrong, &why));
  EXPECT_NE(why.find("power of two"), std::string::npos);
}

TEST(EnvironmentMapReader, Errors)
{
  TempDir tmp;
  // Missing file.
  ExpectErrorNamingFile(tmp.File("does_not_exist.exr"), "missing");
  // A text file named .exr.
  {
    std::ofstream(tmp.File("text.exr")) << "this is not an image\n";
    ExpectErrorNamingFile(tmp.File("text.exr"), "text");
  }
  // An empty file.
  {
    std::ofstream(tmp.File("empty.exr")).flush();
    ExpectErrorNamingFile(tmp.File("empty.exr"), "empty");
  }
  // A real EXR cut short: the header survives, the pixel data does not.
  {
    std::ifstream in(EnvDir + "city.exr", std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 20000u);
    std::ofstream(tmp.File("truncated.exr"), std::ios::binary).write(bytes.data(), 20000);
    ExpectErrorNamingFile(tmp.File("truncated.exr"), "truncated");
    // The EXR magic number followed by garbage.
    std::vector<char> garbage(4096);
    for (std::size_t i = 0; i < garbage.size(); ++i)
    {
      garbage[i] = char((i * 7919u) >> 3);
    }
    std::copy(bytes.begin(), bytes.begin() + 4, garbage.begin());
    std::ofstream(tmp.File("garbage.exr"), std::ios::binary).write(garbage.data(), garbage.size());
    ExpectErrorNamingFile(tmp.File("garbage.exr"), "garbage");
  }
  // A Radiance header with no pixels.
  {
    std::ofstream(tmp.File("short.hdr"), std::ios::binary) << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
    ExpectErrorNamingFile(tmp.File("short.hdr"), "short hdr");
  }
  // A directory.
  ExpectErrorNamingFile(tmp.Path.string(), "directory");
  EXPECT_EQ(vtkEnvironmentMapReader::CanReadFile(tmp.File("text.exr").c_str()), 0);
  EXPECT_EQ(vtkEnvironmentMapReader::CanReadFile((EnvDir + "city.exr").c_str()), 1);
  EXPECT_EQ(vtkEnvironmentMapReader::CanReadFile(nullptr), 0);

  // A good file, then a missing one: the output empties (no stale map).
  vtkNew<vtkEnvironmentMapReader> reader;
  reader->SetOctahedralSize(16);
  EXPECT_TRUE(RunReader(reader, EnvDir + "city.exr")->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 256);
  EXPECT_EQ(RunReader(reader, tmp.File("gone.exr"))->Errors.size(), 1u);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_FALSE(reader->GetEnvironmentMap());
  EXPECT_EQ(reader->GetTotalPower(), 0.0);
  // And recovers.
  EXPECT_TRUE(RunReader(reader, EnvDir + "city.exr")->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 256);
  // A size that is not a power of two is an error.
  reader->SetOctahedralSize(48);
  EXPECT_EQ(RunReader(reader, EnvDir + "city.exr")->Errors.size(), 1u);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// Found by the environment map fuzz target: a 400-byte EXR whose header claims a display window
// of 7 x 117,440,512 pixels made the reader allocate 9.8 GB for the lat-long. Headers that claim
// more than MaximumNumberOfPixels are now an error before any allocation.
TEST(EnvironmentMapReader, HeaderClaimingAHugeImageIsRefused)
{
  TempDir tmp;
  ExrSpec huge;
  huge.Channels = { "B", "G", "R" };
  huge.Half = true;
  huge.DisplayW = 7;
  huge.DisplayH = 117440512;
  huge.DataX1 = 6;
  huge.DataY1 = 3;
  WriteExr(tmp.File("huge.exr"), huge, [](int, int, int) { return 1.0f; });
  ExpectErrorNamingFile(tmp.File("huge.exr"), "huge display window");
  {
    vtkNew<vtkEnvironmentMapReader> reader;
    auto msgs = RunReader(reader, tmp.File("huge.exr"));
    ASSERT_EQ(msgs->Errors.size(), 1u);
    EXPECT_NE(msgs->Errors[0].find("7 x 117440512"), std::string::npos) << msgs->Errors[0];
    EXPECT_NE(msgs->Errors[0].find("MaximumNumberOfPixels"), std::string::npos) << msgs->Errors[0];
  }
  // Found by fuzzing: an attribute claiming 2 GB in a 40-byte header made OpenEXR allocate 2 GB
  // before noticing the file is short. The reader now checks attribute sizes against the file.
  {
    std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    bytes += std::string("junk\0opaquetype\0", 16);
    bytes += std::string("\x00\xff\xff\x7f", 4); // 2147483392
    bytes += std::string(8, '\0');
    std::ofstream(tmp.File("bigattr.exr"), std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    ExpectErrorNamingFile(tmp.File("bigattr.exr"), "huge attribute");
    vtkNew<vtkEnvironmentMapReader> reader;
    auto msgs = RunReader(reader, tmp.File("bigattr.exr"));
    ASSERT_EQ(msgs->Errors.size(), 1u);
    EXPECT_NE(msgs->Errors[0].find("corrupt header: header attribute 'junk' (opaquetype) claims 2147483392 bytes"),
      std::string::npos) << msgs->Errors[0];
  }
  // A Radiance header claiming 10^10 pixels (and holding none).
  std::ofstream(tmp.File("huge.hdr"), std::ios::binary)
    << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n";
  ExpectErrorNamingFile(tmp.File("huge.hdr"), "huge hdr");

  // The limit is the reader's: a 16 x 8 file passes at 128 pixels and fails at 127.
  ExrSpec small;
  small.Channels = { "B", "G", "R" };
  WriteExr(tmp.File("small.exr"), small, [](int, int, int) { return 0.5f; });
  vtkNew<vtkEnvironmentMapReader> reader;
  reader->SetOctahedralSize(8);
  reader->SetMaximumNumberOfPixels(128);
  EXPECT_TRUE(RunReader(reader, tmp.File("small.exr"))->Errors.empty());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 64);
  reader->SetMaximumNumberOfPixels(127);
  auto msgs = RunReader(reader, tmp.File("small.exr"));
  ASSERT_EQ(msgs->Errors.size(), 1u);
  EXPECT_NE(msgs->Errors[0].find("16 x 8 = 128 pixels, more than MaximumNumberOfPixels (127)"), std::string::npos)
    << msgs->Errors[0];
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// A Radiance RGBE file written here (uncompressed scanlines, standard -Y H +X W
// orientation: the first scanline is the top of the picture).
TEST(EnvironmentMapReader, RadianceHDR)
{
  TempDir tmp;
  const int w = 32, h = 16;
  std::vector<float> rgb(3 * w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      float* p = &rgb[3 * (j * w + i)];
      p[0] = 0.25f + i / 8.0f;   // grows to the right
      p[1] = 0.5f + 4.0f * j;    // grows downwards
      p[2] = j == 0 ? 1000.0f : 0.125f; // the top row is very bright in blue
    }
  }
  {
    std::ofstream out(tmp.File("ramp.hdr"), std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n";
    for (int k = 0; k < w * h; ++k)
    {
      unsigned char e[4];
      ToRGBE(&rgb[3 * k], e);
      out.write(reinterpret_cast<const char*>(e), 4);
    }
  }
  vs::LatLongImage img;
  std::string error;
  ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(tmp.File("ramp.hdr").c_str(), img, error)) << error;
  ASSERT_EQ(img.Width, w);
  ASSERT_EQ(img.Height, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const glm::vec3 got = img.Pixel(i, j);
      for (int c = 0; c < 3; ++c)
      {
        const float want = rgb[3 * (j * w + i) + c];
        // RGBE keeps 8 bits of mantissa relative to the largest channel.
        const float largest = std::max(rgb[3 * (j * w + i)], std::max(rgb[3 * (j * w + i) + 1], rgb[3 * (j * w + i) + 2]));
        EXPECT_NEAR(got[c], want, largest / 128.0f) << i << "," << j << " channel " << c;
      }
    }
  }
  // Through the reader: the bright top row is the zenith (+Z).
  vtkNew<vtkEnvironmentMapReader> reader;
  auto msgs = RunReader(reader, tmp.File("ramp.hdr"));
  EXPECT_TRUE(msgs->Errors.empty());
  auto map = reader->GetEnvironmentMap();
  ASSERT_TRUE(map);
  EXPECT_EQ(map->Size, 16);
  EXPECT_GT(map->Evaluate(glm::vec3(0, 0, 1)).z, 100.0f);
  EXPECT_LT(map->Evaluate(glm::vec3(0, 0, -1)).z, 1.0f);
  EXPECT_NEAR(map->TotalPower(), vs::LatLongPower(img), 0.005 * map->TotalPower());
  // Same map as converting the lat-long directly.
  EXPECT_EQ(map->Radiance, vs::EnvironmentMap::FromLatLong(img).Radiance);
}

TEST(EnvironmentMapSource, TypesAndPower)
{
  vtkNew<vtkEnvironmentMapSource> src;
  src->SetOctahedralSize(32);
  src->SetColor(0.5, 1.0, 2.0);
  src->Update();
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 1024);
  EXPECT_NEAR(src->GetTotalPower(), 4.0 * Pi * vs::Luminance(glm::vec3(0.5f, 1.0f, 2.0f)), 1e-4);
  EXPECT_STREQ(src->GetTypeAsString(), "Constant");

  src->SetTypeToSunDisk();
  src->SetSunDirection(0.3, -0.5, 0.2);
  src->SetSunAngularRadius(0.5);
  src->SetSunRadiance(2e4, 2e4, 2e4);
  src->SetSkyColor(0, 0, 0);
  src->Update();
  const double r = 0.5 * Pi / 180.0;
  EXPECT_NEAR(src->GetTotalPower(), Pi * r * r * 2e4, 0.01 * Pi * r * r * 2e4);
  auto sun = src->GetEnvironmentMap();
  ASSERT_TRUE(sun);
  EXPECT_GT(sun->Evaluate(glm::vec3(0.3f, -0.5f, 0.2f)).x, 0.0f);

  src->SetTypeToTwoToneSky();
  src->SetUpperColor(1, 1, 1);
  src->SetLowerColor(0, 0, 0);
  src->SetIntensity(3.0);
  src->Update();
  EXPECT_NEAR(src->GetTotalPower(), 3.0 * 2.0 * Pi, 1e-4);
  EXPECT_EQ(src->GetEnvironmentMap()->Evaluate(glm::vec3(0, 0, 1)).x, 3.0f);

  vtkNew<Messages> msgs;
  src->AddObserver(vtkCommand::ErrorEvent, msgs);
  src->SetOctahedralSize(24);
  src->Update();
  EXPECT_EQ(msgs->Errors.size(), 1u);
  EXPECT_EQ(src->GetOutput()->GetNumberOfPoints(), 0);
}

// OpenEXR variants written here: half/float, RGB/RGBA/Y-only, scanline/tiled,
// a data window smaller than the display window.
TEST(EnvironmentMapReader, OpenEXRVariants)
{
  TempDir tmp;
  // Exact in half: multiples of 1/8 up to 64.
  auto value = [](int x, int y, int c) { return 0.125f * float(1 + ((x * 3 + y * 5 + c * 7) % 64)); };
  struct Case
  {
    const char* name;
    std::vector<std::string> channels; // sorted, as in the file
    bool half;
    int tile;
  };
  const Case cases[] = { { "rgb_float_scan", { "B", "G", "R" }, false, 0 },
    { "rgba_half_scan", { "A", "B", "G", "R" }, true, 0 }, { "rgb_half_tiled", { "B", "G", "R" }, true, 4 },
    { "rgba_float_tiled", { "A", "B", "G", "R" }, false, 3 }, { "y_half_scan", { "Y" }, true, 0 },
    { "layer_float_scan", { "diffuse.B", "diffuse.G", "diffuse.R" }, false, 0 } };
  for (const Case& c : cases)
  {
    ExrSpec spec;
    spec.Channels = c.channels;
    spec.Half = c.half;
    spec.Tile = c.tile;
    const std::string file = tmp.File(std::string(c.name) + ".exr");
    // Channel index in the file -> its value function's channel (R=0, G=1, B=2, Y=0, A=9).
    auto fileChannel = [&](int k) {
      const std::string& n = c.channels[k];
      const char last = n.back();
      return last == 'R' || last == 'Y' ? 0 : last == 'G' ? 1 : last == 'B' ? 2 : 9;
    };
    WriteExr(file, spec, [&](int x, int y, int k) { return value(x, y, fileChannel(k)); });
    vs::LatLongImage img;
    std::string error;
    ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(file.c_str(), img, error)) << c.name << ": " << error;
    ASSERT_EQ(img.Width, 16) << c.name;
    ASSERT_EQ(img.Height, 8) << c.name;
    for (int y = 0; y < 8; ++y)
    {
      for (int x = 0; x < 16; ++x)
      {
        for (int k = 0; k < 3; ++k)
        {
          const float want = c.channels.size() == 1 ? value(x, y, 0) : value(x, y, k);
          ASSERT_EQ(img.Pixel(x, y)[k], want) << c.name << " pixel " << x << "," << y << " channel " << k;
        }
      }
    }
  }
  // A data window inside the display window: the rest is black.
  ExrSpec spec;
  spec.Channels = { "B", "G", "R" };
  spec.DataX0 = 2;
  spec.DataY0 = 1;
  spec.DataX1 = 12;
  spec.DataY1 = 5;
  WriteExr(tmp.File("window.exr"), spec, [&](int x, int y, int k) { return value(x, y, 2 - k); });
  vs::LatLongImage img;
  std::string error;
  ASSERT_TRUE(vtkEnvironmentMapReader::ReadLatLong(tmp.File("window.exr").c_str(), img, error)) << error;
  ASSERT_EQ(img.Width, 16);
  ASSERT_EQ(img.Height, 8);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      const bool inside = x >= 2 && x <= 12 && y >= 1 && y <= 5;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(img.Pixel(x, y)[k], inside ? value(x, y, k) : 0.0f) << x << "," << y;
      }
    }
  }
  // No colour channel at all: an error naming the channels found.
  ExrSpec alpha;
  alpha.Channels = { "A" };
  WriteExr(tmp.File("alpha.exr"), alpha, [&](int x, int y, int) { return value(x, y, 0); });
  EXPECT_FALSE(vtkEnvironmentMapReader::ReadLatLong(tmp.File("alpha.exr").c_str(), img, error));
  EXPECT_NE(error.find("no R, G, B or Y channel (channels: A)"), std::string::npos) << error;
}

// Issue 13, item 9: a huge (or tiny) sun direction is a direction, normalised in double; it was an
// infinity in float and refused as "the sun direction must be a non-zero vector".
TEST(EnvironmentMapSource, HugeSunDirectionIsADirection)
{
  auto sunMap = [](double x, double y, double z, size_t* errors) {
    vtkNew<vtkEnvironmentMapSource> src;
    vtkNew<Messages> msgs;
    src->AddObserver(vtkCommand::ErrorEvent, msgs);
    src->SetOctahedralSize(32);
    src->SetTypeToSunDisk();
    src->SetSunDirection(x, y, z);
    src->SetSunAngularRadius(2.0);
    src->SetSunRadiance(100, 100, 100);
    src->Update();
    *errors = msgs->Errors.size();
    auto map = src->GetEnvironmentMap();
    return map ? map->Radiance : std::vector<float>();
  };
  size_t errors = 0;
  const std::vector<float> unit = sunMap(1, 0, 1, &errors);
  ASSERT_EQ(errors, 0u);
  ASSERT_FALSE(unit.empty());
  EXPECT_EQ(sunMap(1e300, 0, 1e300, &errors), unit);
  EXPECT_EQ(errors, 0u);
  EXPECT_EQ(sunMap(1e-300, 0, 1e-300, &errors), unit);
  EXPECT_EQ(errors, 0u);
  sunMap(0, 0, 0, &errors);
  EXPECT_EQ(errors, 1u) << "a zero direction is still an error";
}
