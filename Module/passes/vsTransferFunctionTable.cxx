#include "vsTransferFunctionTable.h"
#include "vsBuffer.h"
#include "vsContext.h"
#include "vsError.h"

#include <algorithm>
#include <cmath>

namespace vs
{
double TransferFunctionSamples::Extinction(double alpha, double unitDistance, double densityScale)
{
  if (!(alpha > 0.0)) // also NaN
  {
    return 0.0;
  }
  alpha = std::min(alpha, 1.0 - 1e-6);
  return -std::log1p(-alpha) / unitDistance * densityScale;
}

TransferFunctionSamples TransferFunctionSamples::FromFunctions(float smin, float smax, size_t count,
  const std::function<double(double)>& opacity, const std::function<void(double, double[3])>& color,
  double unitDistance, double densityScale)
{
  if (count < 2)
  {
    throw InputError("a transfer-function table needs at least 2 entries");
  }
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance))
  {
    throw InputError("the scalar opacity unit distance must be positive and finite");
  }
  if (!(densityScale >= 0.0) || !std::isfinite(densityScale))
  {
    throw InputError("the density scale must be non-negative and finite");
  }
  TransferFunctionSamples t;
  t.ScalarMin = smin;
  t.ScalarMax = smax > smin ? smax : smin + 1.0f;
  t.Entries.resize(4 * count);
  for (size_t i = 0; i < count; ++i)
  {
    double s = t.ScalarMin + (t.ScalarMax - t.ScalarMin) * double(i) / double(count - 1);
    double rgb[3] = { 1, 1, 1 };
    color(s, rgb);
    for (int c = 0; c < 3; ++c)
    {
      double v = std::isfinite(rgb[c]) ? rgb[c] : 0.0;
      t.Entries[4 * i + c] = static_cast<float>(std::clamp(v, 0.0, 1.0));
    }
    t.Entries[4 * i + 3] = static_cast<float>(Extinction(opacity(s), unitDistance, densityScale));
  }
  return t;
}

float TransferFunctionSamples::MaxExtinction(float s0, float s1) const
{
  const size_t n = this->Size();
  const double scale = double(n - 1) / (this->ScalarMax - this->ScalarMin);
  auto index = [&](float s) {
    return std::clamp((double(s) - this->ScalarMin) * scale, 0.0, double(n - 1));
  };
  double a = index(std::min(s0, s1)), b = index(std::max(s0, s1));
  size_t i0 = static_cast<size_t>(std::floor(a));
  size_t i1 = std::min(n - 1, static_cast<size_t>(std::ceil(b)));
  float m = 0.0f;
  for (size_t i = i0; i <= i1; ++i)
  {
    m = std::max(m, this->Entries[4 * i + 3]);
  }
  return m;
}

TransferFunctionTable::TransferFunctionTable(std::shared_ptr<Context> context, const TransferFunctionSamples& samples)
  : Samples_(samples)
{
  this->Buffer_ = std::make_unique<Buffer>(context, samples.Entries.size() * sizeof(float), "transfer function");
  this->Buffer_->Upload(samples.Entries.data(), samples.Entries.size() * sizeof(float));
}

TransferFunctionTable::~TransferFunctionTable() = default;

std::array<float, 4> TransferFunctionTable::Params() const
{
  const auto& s = this->Samples_;
  return { { s.ScalarMin, float(double(s.Size() - 1) / (s.ScalarMax - s.ScalarMin)), float(s.Size()), 0.0f } };
}
}
