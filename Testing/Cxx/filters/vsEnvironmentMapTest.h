// vsEnvironmentMapTest.h — what the environment-map reader's tests share: maps written here (EXR
// through OpenEXR, hand-written Radiance .hdr), the reader run with its messages collected, and the
// map's power and directions checked.
#ifndef vsEnvironmentMapTest_h
#define vsEnvironmentMapTest_h
#include "vsTestPaths.h"
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

#include "vsTempDir.h"

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

const std::string EnvDir = vstest::DataDir() + "/envmaps/";

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

using vstest::TempDir;

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

#endif
