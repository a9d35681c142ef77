// vsCombinedAccumulators.h — Auto's two accumulators (Environment's samples and TwoStep's) as one
// estimate: both are unbiased estimates of the same image, so the mapper's image is their means
// weighted by sample counts, and its variance likewise; with any other strategy, the first alone.
// Also the alpha an opaque image has where a pixel sees the environment (GetRadiance() under the
// coverage alpha) and the mean square radiance Auto's selector records. Not wrapped.
#ifndef vsCombinedAccumulators_h
#define vsCombinedAccumulators_h

#include <cstdint>
#include <vector>

namespace vs
{
class MonteCarloPass;

class CombinedAccumulators
{
public:
  /** Samples of `mc` (none without it), plus `grid`'s for Auto. */
  static uint32_t Samples(const MonteCarloPass* mc, const MonteCarloPass* grid, bool autoStrategy);
  /** The mean of all samples (rgba per pixel). */
  static std::vector<float> Mean(const MonteCarloPass& mc, const MonteCarloPass* grid, bool autoStrategy);
  /** The per-sample variance of that mean (variance / samples is its squared standard error). */
  static std::vector<double> Variance(const MonteCarloPass& mc, const MonteCarloPass* grid, bool autoStrategy);
  /** The combined mean of accumulators whose alpha samples are all 1. */
  static float OpaqueAlpha(const MonteCarloPass* mc, const MonteCarloPass* grid, bool autoStrategy);
  /** The combined variance of such alpha samples, ne and ng samples (ng = 0: the first alone). */
  static double OpaqueAlphaVariance(uint32_t ne, uint32_t ng);
  /** The mean over pixels of the mean square of rgb (rgba per pixel). */
  static double MeanSquare(const std::vector<float>& mean);
};
}

#endif
