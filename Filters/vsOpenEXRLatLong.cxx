// vsOpenEXRLatLong.cxx — the OpenEXR lat-long reader of vtkEnvironmentMapReader (vsOpenEXRLatLong.h),
// with the header size checks that keep corrupt files from making OpenEXR allocate gigabytes.
#include "vsOpenEXRLatLong.h"

#include "vsEnvironmentMap.h"
#include "vsLatLongFileMessages.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStdIO.h>
#include <ImfRgbaFile.h>
#include <ImfArray.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace vs
{
namespace
{
/* The channel called `name`, or failing that the first one called "<layer>.name". */
std::string FindChannel(const Imf::ChannelList& channels, const char* name)
{
  if (channels.findChannel(name))
  {
    return name;
  }
  const std::string suffix = std::string(".") + name;
  for (auto it = channels.begin(); it != channels.end(); ++it)
  {
    const std::string n = it.name();
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
    {
      return n;
    }
  }
  return std::string();
}

/* Walks the attribute list of an OpenEXR header (every header of a multi-part file) and checks
 * that each attribute's size fits in the file. OpenEXR 3.1 trusts the size: an attribute of an
 * unknown type claiming 2 GB made Header::readFrom allocate 2 GB for a 300-byte file (found by
 * fuzzing). Returns "" or the reason the header is corrupt. */
std::string CheckExrHeaderSizes(const char* fileName)
{
  std::error_code ec;
  const auto fileSize = std::filesystem::file_size(fileName, ec);
  std::ifstream in(fileName, std::ios::binary);
  if (ec || !in)
  {
    return "cannot open it";
  }
  unsigned char mv[8];
  if (!in.read(reinterpret_cast<char*>(mv), 8))
  {
    return "the file ends inside the magic number and version";
  }
  const bool multiPart = (mv[5] & 0x10) != 0; // version flag 0x1000
  const std::size_t maxName = (mv[5] & 0x04) ? 255 : 31; // long names flag 0x400
  // Reads a null-terminated string of at most maxName characters.
  auto readName = [&](std::string& out) {
    out.clear();
    for (char c; in.get(c);)
    {
      if (c == '\0')
      {
        return true;
      }
      out.push_back(c);
      if (out.size() > maxName)
      {
        return false;
      }
    }
    return false;
  };
  for (int header = 0;; ++header)
  {
    std::string name, type;
    for (int attributes = 0;; ++attributes)
    {
      if (!readName(name))
      {
        return "header attribute " + std::to_string(attributes) + ": the name is cut off or too long";
      }
      if (name.empty())
      {
        break; // end of this header
      }
      if (!readName(type))
      {
        return "header attribute '" + name + "': the type name is cut off or too long";
      }
      unsigned char sz[4];
      if (!in.read(reinterpret_cast<char*>(sz), 4))
      {
        return "header attribute '" + name + "': the file ends inside its size";
      }
      const int32_t size = int32_t(uint32_t(sz[0]) | uint32_t(sz[1]) << 8 | uint32_t(sz[2]) << 16 |
        uint32_t(sz[3]) << 24);
      const std::streamoff at = in.tellg();
      if (size < 0 || at < 0 || uint64_t(at) + uint64_t(size) > fileSize)
      {
        return "header attribute '" + name + "' (" + type + ") claims " + std::to_string(size) +
          " bytes, more than the file holds";
      }
      in.seekg(size, std::ios::cur);
    }
    if (!multiPart)
    {
      return std::string();
    }
    // Multi-part: the headers end with an empty header (a lone null byte).
    if (in.peek() == 0)
    {
      return std::string();
    }
    if (in.peek() == std::char_traits<char>::eof() || header > 100000)
    {
      return "the multi-part header list is cut off";
    }
  }
}
} // namespace

bool ReadOpenEXRLatLong(const char* fileName, LatLongImage* image, int& width, int& height, std::string& error,
  const std::function<void(double)>& progress, int64_t maxPixels)
{
  try
  {
    // The size check runs on the header alone, before Imf::InputFile: its constructor already
    // allocates line buffers for the whole data window's width and block height (a fuzzed
    // 340-byte file spent seconds in there).
    Imath::Box2i display, data;
    const std::string corrupt = CheckExrHeaderSizes(fileName);
    if (!corrupt.empty())
    {
      error = "the OpenEXR file " + QuoteFileName(fileName) + " has a corrupt header: " + corrupt;
      return false;
    }
    {
      Imf::StdIFStream is(fileName);
      char magicAndVersion[8];
      is.read(magicAndVersion, 8);
      int version = int(static_cast<unsigned char>(magicAndVersion[4])) |
        int(static_cast<unsigned char>(magicAndVersion[5])) << 8 |
        int(static_cast<unsigned char>(magicAndVersion[6])) << 16 |
        int(static_cast<unsigned char>(magicAndVersion[7])) << 24;
      Imf::Header first;
      first.readFrom(is, version);
      display = first.displayWindow();
      data = first.dataWindow();
    }
    // In 64 bits: the corners are whatever the file says.
    const int64_t w64 = int64_t(display.max.x) - display.min.x + 1;
    const int64_t h64 = int64_t(display.max.y) - display.min.y + 1;
    if (w64 <= 0 || h64 <= 0)
    {
      error = "the OpenEXR file " + QuoteFileName(fileName) + " has an empty display window";
      return false;
    }
    // A corrupt header can claim any size; refuse before allocating (found by fuzzing: a
    // 400-byte file asked for 10 GB).
    error = TooLargeMessage(fileName, "display window", w64, h64, maxPixels);
    if (error.empty())
    {
      const int64_t dw64 = int64_t(data.max.x) - data.min.x + 1, dh64 = int64_t(data.max.y) - data.min.y + 1;
      if (dw64 > 0 && dh64 > 0)
      {
        error = TooLargeMessage(fileName, "data window", dw64, dh64, maxPixels);
      }
    }
    if (!error.empty())
    {
      return false;
    }
    width = int(w64);
    height = int(h64);
    Imf::InputFile file(fileName);
    const Imf::Header& header = file.header();
    if (header.displayWindow() != display || header.dataWindow() != data)
    {
      error = "the OpenEXR file " + QuoteFileName(fileName) + " has inconsistent headers";
      return false;
    }
    const Imf::ChannelList& channels = header.channels();
    const std::string rgb[3] = { FindChannel(channels, "R"), FindChannel(channels, "G"),
      FindChannel(channels, "B") };
    const bool hasRGB = !rgb[0].empty() || !rgb[1].empty() || !rgb[2].empty();
    const std::string y = FindChannel(channels, "Y");
    const bool hasChroma = !FindChannel(channels, "RY").empty() || !FindChannel(channels, "BY").empty();
    if (!hasRGB && y.empty())
    {
      std::string names;
      for (auto it = channels.begin(); it != channels.end(); ++it)
      {
        names += (names.empty() ? "" : ", ") + std::string(it.name());
      }
      error = "the OpenEXR file " + QuoteFileName(fileName) + " has no R, G, B or Y channel (channels: " +
        (names.empty() ? std::string("none") : names) + ")";
      return false;
    }
    if (!image)
    {
      return true;
    }

    const int dw = data.max.x - data.min.x + 1;
    const int dh = data.max.y - data.min.y + 1;
    // The data window, 3 floats per pixel.
    std::vector<float> buffer(3 * std::size_t(std::max(dw, 0)) * std::max(dh, 0), 0.0f);
    if (dw > 0 && dh > 0)
    {
      const std::ptrdiff_t stride = 3 * std::ptrdiff_t(sizeof(float));
      const std::ptrdiff_t rowStride = stride * dw;
      char* base = reinterpret_cast<char*>(buffer.data()) - data.min.x * stride - data.min.y * rowStride;
      auto readRows = [&](auto&& readBlock) {
        const int block = 64;
        for (int r = data.min.y; r <= data.max.y; r += block)
        {
          readBlock(r, std::min(data.max.y, r + block - 1));
          if (progress)
          {
            progress(double(r - data.min.y + 1) / dh);
          }
        }
      };
      if (hasRGB || !hasChroma)
      {
        Imf::FrameBuffer fb;
        if (hasRGB)
        {
          for (int c = 0; c < 3; ++c)
          {
            // A missing colour channel reads as 0 (the fill value).
            fb.insert(rgb[c].empty() ? (std::string("__missing_") + "RGB"[c]) : rgb[c],
              Imf::Slice(Imf::FLOAT, base + c * sizeof(float), stride, rowStride, 1, 1, 0.0));
          }
        }
        else
        {
          fb.insert(y, Imf::Slice(Imf::FLOAT, base, stride, rowStride, 1, 1, 0.0));
        }
        file.setFrameBuffer(fb);
        readRows([&](int r0, int r1) { file.readPixels(r0, r1); });
        if (!hasRGB)
        {
          for (std::size_t i = 0; i < buffer.size(); i += 3)
          {
            buffer[i + 1] = buffer[i + 2] = buffer[i];
          }
        }
      }
      else
      {
        // Luminance/chroma (Y, RY, BY): let RgbaInputFile convert to RGB (half).
        Imf::RgbaInputFile rgbaFile(fileName);
        Imf::Array2D<Imf::Rgba> pixels(dh, dw);
        rgbaFile.setFrameBuffer(&pixels[0][0] - data.min.x - std::ptrdiff_t(data.min.y) * dw, 1, dw);
        readRows([&](int r0, int r1) { rgbaFile.readPixels(r0, r1); });
        for (int j = 0; j < dh; ++j)
        {
          for (int i = 0; i < dw; ++i)
          {
            float* p = &buffer[3 * (std::size_t(j) * dw + i)];
            p[0] = float(pixels[j][i].r);
            p[1] = float(pixels[j][i].g);
            p[2] = float(pixels[j][i].b);
          }
        }
      }
    }
    image->Width = width;
    image->Height = height;
    image->RGB.assign(3 * std::size_t(width) * height, 0.0f);
    // Copy the part of the data window inside the display window (EXR rows go
    // top to bottom, as the lat-long's).
    const int x0 = std::max(data.min.x, display.min.x), x1 = std::min(data.max.x, display.max.x);
    const int y0 = std::max(data.min.y, display.min.y), y1 = std::min(data.max.y, display.max.y);
    for (int yy = y0; yy <= y1; ++yy)
    {
      for (int xx = x0; xx <= x1; ++xx)
      {
        const float* s = &buffer[3 * (std::size_t(yy - data.min.y) * dw + (xx - data.min.x))];
        float* d = &image->RGB[3 * (std::size_t(yy - display.min.y) * width + (xx - display.min.x))];
        d[0] = s[0];
        d[1] = s[1];
        d[2] = s[2];
      }
    }
    return true;
  }
  catch (const std::exception& e)
  {
    error = "cannot read the OpenEXR file " + QuoteFileName(fileName) + ": " + e.what();
    while (!error.empty() && std::isspace(static_cast<unsigned char>(error.back())))
    {
      error.pop_back();
    }
  }
  catch (...)
  {
    error = "cannot read the OpenEXR file " + QuoteFileName(fileName) + ": unknown error";
  }
  return false;
}
}
