// vsCoverageComposite.h — the mapper's Monte Carlo image as the window shows it, under the coverage
// alpha (the environment as the renderer's background, VS_BACKGROUND_ENVIRONMENT_COVERAGE): the alpha an opaque image
// would have where a pixel sees the environment (what GetRadiance() reports there), the display
// colour of the environment behind each pixel (made again only when the view, the environment or the
// display transform changed), and the premultiplied display image, composited over that background
// or painting it. Not wrapped.
#ifndef vsCoverageComposite_h
#define vsCoverageComposite_h

#include "vsEnvironmentMap.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace vs
{
class CoverageComposite
{
public:
  /** The mean of an accumulator of n samples of alpha 1, as MonteCarloPass::Mean() computes it. */
  static float OpaqueMean(uint32_t n);
  /** Its per-sample variance, as MonteCarloPass::Variance() computes it. */
  static double OpaqueVariance(uint32_t n);
  /** The environment's radiance times `scale` (rgb) through each pixel's centre of a w x h image. */
  static std::vector<float> EnvironmentRadiance(
    const EnvironmentMap& map, const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale);
  /** The environment's display colour (rgb in [0, 1]) through each pixel's centre of a w x h image. */
  static std::vector<float> EnvironmentDisplay(
    const EnvironmentMap& map, const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale, bool toneMapping);

  /** Makes the background behind a w x h view again if the view, the map (its upload count), the
   *  scale (intensity x exposure) or the tone mapping changed. */
  void UpdateBackground(const EnvironmentMap& map, const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale,
    bool toneMapping, int environmentUploads);

  /** The premultiplied display image of `mean` (rgba per pixel). Pixels flagged in
   *  `environmentPixels` see the environment: composited over the background (composite: after
   *  UpdateBackground) or, painting it, with `opaqueAlpha`. */
  std::vector<float> Display(const std::vector<float>& mean, const std::vector<uint8_t>& environmentPixels,
    float opaqueAlpha, bool composite, float exposure, bool toneMapping) const;

private:
  /** Whether the background must be made again for this view (and records the view as made). */
  bool BackgroundStale(
    const glm::mat4& invViewProj, uint32_t w, uint32_t h, float scale, bool toneMapping, int environmentUploads);

  // The environment's display colour per pixel (rgb) behind the last composited view, and what for.
  std::vector<float> BackgroundDisplay;
  std::vector<double> BackgroundKey;
};
}

#endif
