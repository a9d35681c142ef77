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
  // Kept in float's range (a tiny unit distance or a huge density scale would overflow to inf,
  // and inf majorants stall the trackers): beyond kMaxExtinction the medium is opaque at any
  // distance float resolves anyway.
  return std::min(-std::log1p(-alpha) / unitDistance * densityScale, double(kMaxExtinction));
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
    // In double: the span of points near float's limits (-3e38 .. 3e38) overflows a float.
    double s = double(t.ScalarMin) + (double(t.ScalarMax) - double(t.ScalarMin)) * double(i) / double(count - 1);
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

std::pair<size_t, size_t> TransferFunctionSamples::EntrySpan(float s0, float s1) const
{
  const size_t n = this->Size();
  const double scale = double(n - 1) / (double(this->ScalarMax) - double(this->ScalarMin));
  auto index = [&](float s) {
    return std::clamp((double(s) - this->ScalarMin) * scale, 0.0, double(n - 1));
  };
  double a = index(std::min(s0, s1)), b = index(std::max(s0, s1));
  return { static_cast<size_t>(std::floor(a)), std::min(n - 1, static_cast<size_t>(std::ceil(b))) };
}

float TransferFunctionSamples::MaxExtinction(float s0, float s1) const
{
  auto [i0, i1] = this->EntrySpan(s0, s1);
  float m = 0.0f;
  for (size_t i = i0; i <= i1; ++i)
  {
    m = std::max(m, this->Entries[4 * i + 3]);
  }
  return m;
}

float TransferFunctionSamples::MinExtinction(float s0, float s1) const
{
  auto [i0, i1] = this->EntrySpan(s0, s1);
  float m = this->Entries[4 * i0 + 3];
  for (size_t i = i0 + 1; i <= i1; ++i)
  {
    m = std::min(m, this->Entries[4 * i + 3]);
  }
  return m;
}

std::vector<float> TransferFunctionSamples::RangeMaxLevels() const
{
  const size_t n = this->Size();
  std::vector<float> levels;
  std::vector<float> previous(n);
  for (size_t i = 0; i < n; ++i)
  {
    previous[i] = this->Entries[4 * i + 3];
  }
  for (size_t span = 1; 2 * span <= n; span *= 2)
  {
    // Level k (span 2^k): entry i = max(level k-1 at i, level k-1 at i + 2^(k-1)).
    std::vector<float> next(n);
    for (size_t i = 0; i < n; ++i)
    {
      next[i] = i + span < n ? std::max(previous[i], previous[i + span]) : previous[i];
    }
    levels.insert(levels.end(), next.begin(), next.end());
    previous.swap(next);
  }
  return levels;
}

uint32_t TransferFunctionSamples::RangeMaxLevelCount() const
{
  uint32_t levels = 1;
  for (size_t span = 2; span <= this->Size(); span *= 2)
  {
    ++levels;
  }
  return levels;
}

TransferFunctionTable::TransferFunctionTable(std::shared_ptr<Context> context, const TransferFunctionSamples& samples)
  : Samples_(samples)
{
  // The entries, then levels 1.. of the range-maximum table of their extinction (level 0 is the
  // entries' w), 4 floats per vec4 (volume_access.glsl, vs_max_extinction).
  std::vector<float> data = samples.Entries;
  std::vector<float> levels = samples.RangeMaxLevels();
  data.insert(data.end(), levels.begin(), levels.end());
  data.resize((data.size() + 3) / 4 * 4, 0.0f);
  this->Buffer_ = std::make_unique<Buffer>(context, data.size() * sizeof(float), "transfer function");
  this->Buffer_->Upload(data.data(), data.size() * sizeof(float));
}

TransferFunctionTable::~TransferFunctionTable() = default;

shared::VsTransferFunction TransferFunctionTable::Params() const
{
  const auto& s = this->Samples_;
  shared::VsTransferFunction tf;
  tf.scalar0 = s.ScalarMin;
  tf.entriesPerUnit = float(double(s.Size() - 1) / (double(s.ScalarMax) - double(s.ScalarMin)));
  tf.entries = float(s.Size());
  tf.rangeLevels = float(s.RangeMaxLevelCount());
  return tf;
}
}
