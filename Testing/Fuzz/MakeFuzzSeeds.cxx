// Writes the seed corpora of the fuzz targets: tiny but valid files exercising the paths of the
// readers (EXR compressions, half/float, scanline/tiled, Y-only, luminance/chroma, layer prefixes,
// data window != display window; a Radiance .hdr; OpenVDB grids with several transforms,
// compressions, tiles, half floats, an empty grid and extra grids). Each is a few hundred bytes
// to a few KB, so libFuzzer's mutations stay cheap. Usage: vissweep_fuzz_seeds EXR_DIR VDB_DIR
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>

#include <openvdb/openvdb.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
const int W = 8, H = 4;

float Value(int x, int y, int c)
{
  return 0.05f + 0.3f * float(c) + 0.1f * float(x) + 2.0f * float(y == 0 && x == 3); // a "sun" texel
}

void WriteScanline(const std::string& path, Imf::Compression compression, Imf::PixelType type,
  const std::vector<std::string>& names, Imath::Box2i dataWindow = Imath::Box2i({ 0, 0 }, { W - 1, H - 1 }))
{
  Imf::Header header(Imath::Box2i({ 0, 0 }, { W - 1, H - 1 }), dataWindow);
  header.compression() = compression;
  for (const auto& n : names)
  {
    header.channels().insert(n, Imf::Channel(type));
  }
  const int dw = dataWindow.max.x - dataWindow.min.x + 1, dh = dataWindow.max.y - dataWindow.min.y + 1;
  std::vector<float> f(names.size() * dw * dh);
  std::vector<half> h(f.size());
  for (int y = 0; y < dh; ++y)
    for (int x = 0; x < dw; ++x)
      for (size_t c = 0; c < names.size(); ++c)
      {
        const size_t i = (size_t(y) * dw + x) * names.size() + c;
        f[i] = Value(x, y, int(c));
        h[i] = half(f[i]);
      }
  Imf::FrameBuffer fb;
  const size_t px = (type == Imf::FLOAT ? sizeof(float) : sizeof(half)) * names.size();
  char* base = type == Imf::FLOAT ? reinterpret_cast<char*>(f.data()) : reinterpret_cast<char*>(h.data());
  base -= dataWindow.min.x * px + dataWindow.min.y * px * dw;
  for (size_t c = 0; c < names.size(); ++c)
  {
    fb.insert(names[c], Imf::Slice(type, base + c * (px / names.size()), px, px * dw));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writePixels(dh);
}

void WriteTiled(const std::string& path)
{
  Imf::Header header(W, H);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.setTileDescription(Imf::TileDescription(4, 2, Imf::ONE_LEVEL));
  std::vector<half> px(3 * W * H);
  for (int i = 0; i < W * H; ++i)
    for (int c = 0; c < 3; ++c)
      px[3 * i + c] = half(Value(i % W, i / W, c));
  const char* names[3] = { "R", "G", "B" };
  Imf::FrameBuffer fb;
  for (int c = 0; c < 3; ++c)
  {
    header.channels().insert(names[c], Imf::Channel(Imf::HALF));
    fb.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(px.data() + c), 6, 6 * W));
  }
  Imf::TiledOutputFile file(path.c_str(), header);
  file.setFrameBuffer(fb);
  file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
}

void WriteLuminanceChroma(const std::string& path)
{
  Imf::Array2D<Imf::Rgba> px(H, W);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      px[y][x] = Imf::Rgba(Value(x, y, 0), Value(x, y, 1), Value(x, y, 2), 1.0f);
  Imf::RgbaOutputFile file(path.c_str(), W, H, Imf::WRITE_YC, 1.0f, Imath::V2f(0, 0), 1.0f,
    Imf::INCREASING_Y, Imf::PIZ_COMPRESSION);
  file.setFrameBuffer(&px[0][0], 1, W);
  file.writePixels(H);
}

void WriteRadiance(const std::string& path, bool rle)
{
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n-Y " << H << " +X " << W << "\n";
  for (int y = 0; y < H; ++y)
  {
    std::vector<unsigned char> rgbe(4 * W);
    for (int x = 0; x < W; ++x)
    {
      float v[3] = { Value(x, y, 0), Value(x, y, 1), Value(x, y, 2) };
      const float m = std::max(v[0], std::max(v[1], v[2]));
      int e;
      const float scale = std::frexp(m, &e) * 256.0f / m;
      for (int c = 0; c < 3; ++c)
        rgbe[4 * x + c] = static_cast<unsigned char>(v[c] * scale);
      rgbe[4 * x + 3] = static_cast<unsigned char>(e + 128);
    }
    if (!rle)
    {
      out.write(reinterpret_cast<const char*>(rgbe.data()), std::streamsize(rgbe.size()));
      continue;
    }
    // New-style RLE needs 8 <= width < 32768: 2, 2, width (big endian), then each component as
    // runs of literal bytes (count <= 128).
    const unsigned char head[4] = { 2, 2, static_cast<unsigned char>(W >> 8), static_cast<unsigned char>(W & 255) };
    out.write(reinterpret_cast<const char*>(head), 4);
    for (int c = 0; c < 4; ++c)
    {
      out.put(static_cast<char>(W));
      for (int x = 0; x < W; ++x)
        out.put(static_cast<char>(rgbe[4 * x + c]));
    }
  }
}

void WriteVdb(const std::string& path, const std::string& kind)
{
  openvdb::GridPtrVec grids;
  auto density = openvdb::FloatGrid::create(0.0f);
  density->setName("density");
  auto acc = density->getAccessor();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      acc.setValue(openvdb::Coord(i, j, i + j), 0.25f * float(1 + i + j));
  if (kind == "scaled")
  {
    density->setTransform(openvdb::math::Transform::createLinearTransform(0.5));
    density->transform().postTranslate(openvdb::Vec3d(1.0, -2.0, 3.0));
  }
  else if (kind == "nonuniform")
  {
    auto map = openvdb::math::MapBase::Ptr(new openvdb::math::ScaleMap(openvdb::Vec3d(1.0, 2.0, -0.5)));
    density->setTransform(openvdb::math::Transform::Ptr(new openvdb::math::Transform(map)));
  }
  else if (kind == "rotated")
  {
    auto t = openvdb::math::Transform::createLinearTransform(1.0);
    t->postRotate(0.3, openvdb::math::Z_AXIS);
    density->setTransform(t);
  }
  else if (kind == "tile")
  {
    density->tree().addTile(1, openvdb::Coord(8, 0, 0), 0.5f, true); // an active 8^3 tile
  }
  else if (kind == "half")
  {
    density->setSaveFloatAsHalf(true);
  }
  else if (kind == "empty")
  {
    density->clear();
  }
  grids.push_back(density);
  if (kind == "multi")
  {
    auto vel = openvdb::Vec3SGrid::create();
    vel->setName("vel");
    vel->getAccessor().setValue(openvdb::Coord(1, 1, 1), openvdb::Vec3s(1, 0, 0));
    grids.push_back(vel);
    auto temp = openvdb::FloatGrid::create(0.0f);
    temp->setName("temperature");
    temp->getAccessor().setValue(openvdb::Coord(0, 0, 0), 300.0f);
    grids.push_back(temp);
  }
  if (kind == "wrongtype")
  {
    grids.clear();
    auto d = openvdb::DoubleGrid::create();
    d->setName("density");
    d->getAccessor().setValue(openvdb::Coord(0, 0, 0), 1.0);
    grids.push_back(d);
  }
  openvdb::io::File file(path);
  if (kind == "maskonly") // uncompressed chunks (COMPRESS_NONE would write 128 KiB of root tile values)
    file.setCompression(openvdb::io::COMPRESS_ACTIVE_MASK);
  else if (kind == "zip")
    file.setCompression(openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK);
  else
    file.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
  file.write(grids);
  file.close();
}
}

int main(int argc, char** argv)
{
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: %s EXR_SEED_DIR VDB_SEED_DIR\n", argv[0]);
    return 2;
  }
  const std::filesystem::path exr(argv[1]), vdb(argv[2]);
  std::filesystem::create_directories(exr);
  std::filesystem::create_directories(vdb);
  try
  {
    const std::vector<std::string> rgb{ "R", "G", "B" };
    WriteScanline((exr / "none_half.exr").string(), Imf::NO_COMPRESSION, Imf::HALF, rgb);
    WriteScanline((exr / "rle_half.exr").string(), Imf::RLE_COMPRESSION, Imf::HALF, rgb);
    WriteScanline((exr / "zips_float.exr").string(), Imf::ZIPS_COMPRESSION, Imf::FLOAT, rgb);
    WriteScanline((exr / "zip_half.exr").string(), Imf::ZIP_COMPRESSION, Imf::HALF, rgb);
    WriteScanline((exr / "piz_half.exr").string(), Imf::PIZ_COMPRESSION, Imf::HALF, rgb);
    WriteScanline((exr / "pxr24_float.exr").string(), Imf::PXR24_COMPRESSION, Imf::FLOAT, rgb);
    WriteScanline((exr / "b44_half.exr").string(), Imf::B44_COMPRESSION, Imf::HALF, rgb);
    WriteScanline((exr / "dwaa_half.exr").string(), Imf::DWAA_COMPRESSION, Imf::HALF, rgb);
    WriteScanline((exr / "rgba_half.exr").string(), Imf::ZIP_COMPRESSION, Imf::HALF, { "A", "B", "G", "R" });
    WriteScanline((exr / "y_only.exr").string(), Imf::RLE_COMPRESSION, Imf::HALF, { "Y" });
    WriteScanline((exr / "layer.exr").string(), Imf::NO_COMPRESSION, Imf::HALF,
      { "rgba.B", "rgba.G", "rgba.R" });
    WriteScanline((exr / "no_rgb.exr").string(), Imf::NO_COMPRESSION, Imf::HALF, { "Z" });
    WriteScanline((exr / "datawindow.exr").string(), Imf::NO_COMPRESSION, Imf::HALF, rgb,
      Imath::Box2i({ 2, -1 }, { 9, 2 }));
    WriteTiled((exr / "tiled_zip.exr").string());
    WriteLuminanceChroma((exr / "yc_piz.exr").string());
    WriteRadiance((exr / "flat.hdr").string(), false);
    WriteRadiance((exr / "rle.hdr").string(), true);

    openvdb::initialize();
    for (const char* kind :
      { "plain", "scaled", "nonuniform", "rotated", "tile", "half", "empty", "multi", "wrongtype", "maskonly", "zip" })
    {
      WriteVdb((vdb / (std::string(kind) + ".vdb")).string(), kind);
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "vissweep_fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
