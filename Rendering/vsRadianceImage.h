// vsRadianceImage.h — the image GetRadiance() returns: the view's mean radiance ("Radiance", rgb
// linear) and its alpha ("Alpha"; where the pixel sees the environment under the coverage alpha, the
// opaque image's alpha), and on request the per-sample variance ("Variance", rgba, double: a dim
// map's variance is below float's range). Not wrapped.
#ifndef vsRadianceImage_h
#define vsRadianceImage_h

#include <cstdint>
#include <vector>

class vtkImageData;

namespace vs
{
class RadianceImage
{
public:
  /** `image` becomes w x h with the rgb and alpha of `mean` (rgba per pixel); pixels flagged in
   *  `environmentPixels` get `opaqueAlpha`. */
  static void Fill(vtkImageData* image, const std::vector<float>& mean, uint32_t w, uint32_t h,
    const std::vector<uint8_t>& environmentPixels, float opaqueAlpha);
  /** Adds the "Variance" array `var` (rgba per pixel), the alpha's of the pixels flagged in
   *  `environmentPixels` set to `alphaVariance`. */
  static void AddVariance(vtkImageData* image, std::vector<double> var, const std::vector<uint8_t>& environmentPixels,
    double alphaVariance);
};
}

#endif
