// vsPreviewHandOver.cxx — see vsPreviewHandOver.h.
#include "vsPreviewHandOver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vs
{
double PreviewHandOver::PreviewShare(const std::vector<float>& preview, const std::vector<float>& mean,
  const std::vector<double>& variance, uint32_t samples)
{
  if (preview.size() != mean.size() || variance.size() != mean.size() || mean.size() % 4 != 0)
  {
    throw std::logic_error("PreviewHandOver: the preview, the mean and its variance differ in size");
  }
  if (samples < 2 || mean.empty())
  {
    return 1.0;
  }
  double difference = 0.0, meanVariance = 0.0;
  for (size_t i = 0; i < mean.size(); i += 4)
  {
    for (size_t c = 0; c < 3; ++c)
    {
      const double d = double(preview[i + c]) - double(mean[i + c]);
      difference += d * d;
      meanVariance += variance[i + c];
    }
  }
  if (!std::isfinite(difference) || !std::isfinite(meanVariance))
  {
    return 0.0; // a non-finite pixel: the estimate as it is
  }
  const double n = double(mean.size() / 4) * 3.0;
  const double V = meanVariance / n / double(samples);
  const double B = std::max(0.0, difference / n - V);
  return V + B > 0.0 ? V / (V + B) : 0.0; // identical images without variance: the estimate
}

double PreviewHandOver::ShareCap(double seconds, double duration)
{
  if (!(duration > 0.0) || !(seconds >= 0.0))
  {
    return duration > 0.0 ? 1.0 : 0.0; // a negative or NaN time: not begun
  }
  return std::min(1.0, std::max(0.0, 1.0 - seconds / duration));
}

void PreviewHandOver::Blend(std::vector<float>& mean, const std::vector<float>& preview, double share)
{
  if (preview.size() != mean.size())
  {
    throw std::logic_error("PreviewHandOver: the preview and the mean differ in size");
  }
  const float s = float(share);
  for (size_t i = 0; i < mean.size(); ++i)
  {
    mean[i] = (1.0f - s) * mean[i] + s * preview[i];
  }
}
}
