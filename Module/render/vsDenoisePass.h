// vsDenoisePass.h — the display's edge-aware filter of the Monte Carlo estimate (issue 39): a guided
// filter whose guide is the noise-free preview of the same view (denoise_params.h has the model),
// run as compute stages on the device (denoise.comp): the pixels' moments, their window means (two
// box passes), the coefficients, their window means, the output. What the window shows only: the
// estimate itself (GetRadiance(), the EXR) is never filtered. Deterministic.
#ifndef vsDenoisePass_h
#define vsDenoisePass_h

#include "vissweepCoreModule.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace vs
{
class Buffer;
class Context;

class VISSWEEPCORE_EXPORT DenoisePass
{
public:
  explicit DenoisePass(std::shared_ptr<Context> context);
  ~DenoisePass();
  DenoisePass(const DenoisePass&) = delete;
  DenoisePass& operator=(const DenoisePass&) = delete;

  /** The filtered estimate (rgba per pixel; alpha the estimate's) of `estimate` (rgba per pixel, w x h),
   *  guided by `guide` (rgba, the same size; its alpha unused), `variance` the variance of each pixel's
   *  estimate (rgba: the accumulator's per-sample variance over its samples). `radius` is the window's
   *  half width (clamped to [1, 64]), `slopeSpread` the prior's tau (denoise_params.h). Throws
   *  std::invalid_argument when the sizes differ. A non-finite input pixel spreads over its windows: the
   *  caller passes finite images (the mapper shows the estimate unfiltered otherwise). */
  std::vector<float> Filter(const std::vector<float>& estimate, const std::vector<float>& guide,
    const std::vector<float>& variance, uint32_t width, uint32_t height, uint32_t radius,
    double slopeSpread = kSlopeSpread);

  /** The slope prior's spread tau: the estimate's local slope against the preview is taken to lie
   *  within ~1 +- tau where the samples do not resolve it. */
  static constexpr double kSlopeSpread = 1.0;

  /** Device seconds of the last Filter. */
  double LastSeconds() const { return this->LastSeconds_; }

private:
  std::shared_ptr<Context> Context_;
  std::unique_ptr<Buffer> Input_, X_, Y_, Output_;
  double LastSeconds_ = 0.0;
};
}

#endif
