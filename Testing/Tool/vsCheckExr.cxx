// vsCheckExr FILE.exr WIDTH HEIGHT [framed] — exits 0 when FILE is a readable OpenEXR image of that
// size with finite, non-negative R, G, B everywhere and some light (used by the tool's ctest).
// "framed": also the volume is in view and centred, as vtkRenderer::ResetCamera frames it: the
// centre pixel is covered (alpha > 0.3) and the four corner pixels are not (alpha < 0.05).
#include <ImfArray.h>
#include <ImfRgbaFile.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 4 && !(argc == 5 && std::string(argv[4]) == "framed"))
  {
    std::fprintf(stderr, "usage: vsCheckExr FILE.exr WIDTH HEIGHT [framed]\n");
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
