// vsCheckExr FILE.exr WIDTH HEIGHT [framed] — exits 0 when FILE is a readable OpenEXR image of that
// size with finite, non-negative R, G, B everywhere and some light (used by the tool's ctest).
// "framed": also the volume is in view and centred, as vtkRenderer::ResetCamera frames it: the
// centre pixel is covered (alpha > 0.3) and the four corner pixels are not (alpha < 0.05).
// vsCheckExr --header FILE.exr — prints the header's "vissweep.*" attributes, one "name=value" a line.
// vsCheckExr --same A.exr B.exr — exits 0 when the two images have the same size and the same pixels
// bit for bit (their headers may differ: the render time is in them).
// vsCheckExr --brighter A.exr B.exr FACTOR — exits 0 when A's mean radiance (R + G + B) is more than
// FACTOR times B's (issue 38: a scene's light brightens the image).
// vsCheckExr --compare A.exr B.exr — prints A against the reference B: the ratio of their mean radiance
// and the relative MSE, sum (a - b)^2 / sum b^2 over the pixels' R, G, B (as `vissweep bench preview`);
// exits 0 when both are finite and the sizes match (a measuring aid: it asserts nothing about the values).
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfAttribute.h>
#include <ImfDoubleAttribute.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace
{
int PrintHeader(const char* path)
{
  Imf::InputFile file(path);
  const Imf::Header& header = file.header();
  for (auto it = header.begin(); it != header.end(); ++it)
  {
    const std::string name = it.name();
    if (name.rfind("vissweep.", 0) != 0)
    {
      continue;
    }
    const Imf::Attribute& a = it.attribute();
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a))
    {
      std::printf("%s=%s\n", name.c_str(), s->value().c_str());
    }
    else if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a))
    {
      std::printf("%s=%d\n", name.c_str(), i->value());
    }
    else if (const auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&a))
    {
      std::printf("%s=%.17g\n", name.c_str(), d->value());
    }
    else if (const auto* v = dynamic_cast<const Imf::V3dAttribute*>(&a))
    {
      std::printf("%s=%.17g,%.17g,%.17g\n", name.c_str(), v->value().x, v->value().y, v->value().z);
    }
    else
    {
      std::printf("%s=<%s>\n", name.c_str(), a.typeName());
    }
  }
  return 0;
}

// The mean of R + G + B over the image.
// The pixels' R, G, B as doubles, row by row.
std::vector<double> Rgb(const char* path, int& w, int& h)
{
  Imf::RgbaInputFile file(path);
  const Imath::Box2i dw = file.dataWindow();
  w = dw.max.x - dw.min.x + 1;
  h = dw.max.y - dw.min.y + 1;
  Imf::Array2D<Imf::Rgba> px(h, w);
  file.setFrameBuffer(&px[0][0] - dw.min.x - dw.min.y * w, 1, size_t(w));
  file.readPixels(dw.min.y, dw.max.y);
  std::vector<double> rgb;
  rgb.reserve(size_t(3) * size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      rgb.insert(rgb.end(), { double(px[y][x].r), double(px[y][x].g), double(px[y][x].b) });
    }
  }
  return rgb;
}

double MeanRadiance(const char* path)
{
  Imf::RgbaInputFile file(path);
  const Imath::Box2i dw = file.dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  Imf::Array2D<Imf::Rgba> px(h, w);
  file.setFrameBuffer(&px[0][0] - dw.min.x - dw.min.y * w, 1, size_t(w));
  file.readPixels(dw.min.y, dw.max.y);
  double sum = 0.0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      sum += double(px[y][x].r) + double(px[y][x].g) + double(px[y][x].b);
    }
  }
  return sum / (double(w) * double(h));
}

// Every channel's pixels as 32-bit floats' bit patterns (channel by channel, in the header's
// order), with the channels' names and the size.
std::vector<unsigned> Pixels(const char* path, int& w, int& h, std::string& channels)
{
  Imf::InputFile file(path);
  const Imath::Box2i dw = file.header().dataWindow();
  w = dw.max.x - dw.min.x + 1;
  h = dw.max.y - dw.min.y + 1;
  std::vector<std::vector<float>> planes;
  Imf::FrameBuffer frame;
  for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c)
  {
    channels += std::string(c.name()) + " ";
    planes.emplace_back(size_t(w) * size_t(h));
    frame.insert(c.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes.back().data() - dw.min.x - dw.min.y * w),
      sizeof(float), sizeof(float) * size_t(w)));
  }
  file.setFrameBuffer(frame);
  file.readPixels(dw.min.y, dw.max.y);
  std::vector<unsigned> bits;
  for (const auto& plane : planes)
  {
    for (float v : plane)
    {
      unsigned u = 0;
      std::memcpy(&u, &v, sizeof(u));
      bits.push_back(u);
    }
  }
  return bits;
}
}

int main(int argc, char** argv)
{
  try
  {
    if (argc == 3 && std::strcmp(argv[1], "--header") == 0)
    {
      return PrintHeader(argv[2]);
    }
    if (argc == 5 && std::strcmp(argv[1], "--brighter") == 0)
    {
      const double a = MeanRadiance(argv[2]), b = MeanRadiance(argv[3]), factor = std::atof(argv[4]);
      std::printf("mean radiance: %s %.6g, %s %.6g (ratio %.4g, expected above %g)\n", argv[2], a, argv[3], b,
        b > 0.0 ? a / b : 0.0, factor);
      return std::isfinite(a) && std::isfinite(b) && a > factor * b ? 0 : 1;
    }
    if (argc == 4 && std::strcmp(argv[1], "--compare") == 0)
    {
      int wa = 0, ha = 0, wb = 0, hb = 0;
      const std::vector<double> a = Rgb(argv[2], wa, ha), b = Rgb(argv[3], wb, hb);
      if (wa != wb || ha != hb)
      {
        std::fprintf(stderr, "%s (%d x %d) and %s (%d x %d) differ in size\n", argv[2], wa, ha, argv[3], wb, hb);
        return 1;
      }
      double sa = 0.0, sb = 0.0, num = 0.0, den = 0.0;
      for (size_t i = 0; i < a.size(); ++i)
      {
        sa += a[i];
        sb += b[i];
        num += (a[i] - b[i]) * (a[i] - b[i]);
        den += b[i] * b[i];
      }
      const double ratio = sb > 0.0 ? sa / sb : std::nan(""), mse = den > 0.0 ? num / den : std::nan("");
      std::printf("%s against %s: mean ratio %.4f, relative MSE %.4e\n", argv[2], argv[3], ratio, mse);
      return std::isfinite(ratio) && std::isfinite(mse) ? 0 : 1;
    }
    if (argc == 4 && std::strcmp(argv[1], "--same") == 0)
    {
      int wa = 0, ha = 0, wb = 0, hb = 0;
      std::string ca, cb;
      const auto a = Pixels(argv[2], wa, ha, ca);
      const auto b = Pixels(argv[3], wb, hb, cb);
      if (wa != wb || ha != hb || ca != cb)
      {
        std::fprintf(stderr, "%s (%d x %d; %s) and %s (%d x %d; %s) differ in size or channels\n", argv[2], wa, ha,
          ca.c_str(), argv[3], wb, hb, cb.c_str());
        return 1;
      }
      if (a != b)
      {
        // Which channels differ, in how many pixels, and by how much at most (what tells a float's last
        // bit from a pixel that went wrong).
        std::fprintf(stderr, "%s and %s (%d x %d) differ:", argv[2], argv[3], wa, ha);
        std::istringstream names(ca);
        const size_t pixels = size_t(wa) * size_t(ha);
        for (size_t c = 0; c * pixels < a.size(); ++c)
        {
          std::string name;
          names >> name;
          size_t count = 0;
          double largest = 0.0;
          for (size_t i = c * pixels; i < (c + 1) * pixels; ++i)
          {
            if (a[i] != b[i])
            {
              float fa = 0.0f, fb = 0.0f;
              std::memcpy(&fa, &a[i], sizeof(fa));
              std::memcpy(&fb, &b[i], sizeof(fb));
              ++count;
              largest = std::max(largest, std::abs(double(fa) - double(fb)));
            }
          }
          if (count > 0)
          {
            std::fprintf(stderr, " %s in %zu pixels (largest difference %.3g);", name.c_str(), count, largest);
          }
        }
        std::fprintf(stderr, "\n");
        return 1;
      }
      std::printf("%s and %s: the same %d x %d pixels\n", argv[2], argv[3], wa, ha);
      return 0;
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  if (argc != 4 && !(argc == 5 && std::string(argv[4]) == "framed"))
  {
    std::fprintf(stderr, "usage: vsCheckExr FILE.exr WIDTH HEIGHT [framed] | --header FILE.exr | --same A.exr B.exr | "
                         "--brighter A.exr B.exr FACTOR | --compare A.exr REFERENCE.exr\n");
    return 2;
  }
  try
  {
    Imf::RgbaInputFile file(argv[1]);
    const Imath::Box2i dw = file.dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    if (w != std::atoi(argv[2]) || h != std::atoi(argv[3]))
    {
      std::fprintf(stderr, "%s: %d x %d, expected %s x %s\n", argv[1], w, h, argv[2], argv[3]);
      return 1;
    }
    Imf::Array2D<Imf::Rgba> pixels(h, w);
    file.setFrameBuffer(&pixels[0][0] - dw.min.x - dw.min.y * w, 1, w);
    file.readPixels(dw.min.y, dw.max.y);
    double sum = 0.0;
    long bad = 0;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const float c[3] = { pixels[y][x].r, pixels[y][x].g, pixels[y][x].b };
        for (float v : c)
        {
          if (!std::isfinite(v) || v < 0.0f)
          {
            ++bad;
          }
          else
          {
            sum += v;
          }
        }
      }
    }
    const double mean = sum / (3.0 * w * h);
    std::printf("%s: %d x %d, mean %g, %ld bad values\n", argv[1], w, h, mean, bad);
    if (bad > 0)
    {
      return 1;
    }
    if (!(mean > 0.0))
    {
      std::fprintf(stderr, "%s: the image is black\n", argv[1]);
      return 1;
    }
    if (argc == 5)
    {
      const float centre = pixels[h / 2][w / 2].a;
      const float corners[4] = { pixels[0][0].a, pixels[0][w - 1].a, pixels[h - 1][0].a, pixels[h - 1][w - 1].a };
      std::printf("alpha: centre %g, corners %g %g %g %g\n", double(centre), double(corners[0]),
        double(corners[1]), double(corners[2]), double(corners[3]));
      bool framed = centre > 0.3f;
      for (float a : corners)
      {
        framed = framed && a < 0.05f;
      }
      if (!framed)
      {
        std::fprintf(stderr, "%s: the volume is not centred in the view\n", argv[1]);
        return 1;
      }
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "%s: %s\n", argv[1], e.what());
    return 1;
  }
  return 0;
}
