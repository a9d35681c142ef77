#include "vsStrategySelector.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vs
{
void StrategySelector::Reset()
{
  for (Stats& s : this->Stats_)
  {
    const double v = s.Variance, t = s.SecondsPerSample;
    s = Stats();
    // The estimates describe the scene, not the accumulation: keep them as a prior.
    s.Variance = v;
    s.SecondsPerSample = t;
  }
  this->Frame_ = 0;
  this->EpochFrame_ = 0;
  this->MeanSquare_ = 0.0;
}

void StrategySelector::ResetGrid()
{
  this->Reset();
  for (Stats& s : this->Stats_)
  {
    s.Variance = 0.0;
    s.SecondsPerSample = 0.0;
  }
  this->Preferred_ = EnvironmentEstimator;
  this->GridWorth_ = true;
  this->GridVerdict_ = false;
  this->Decisions_ = 0;
}

double StrategySelector::GridEfficiencyRatio() const
{
  return this->PerSampleEfficiencyRatio() / this->StratificationGain_;
}

double StrategySelector::PerSampleEfficiencyRatio() const
{
  const Stats& e = this->Stats_[EnvironmentEstimator];
  const Stats& g = this->Stats_[GridEstimator];
  if (e.Variance <= 0.0 || g.Variance <= 0.0 || e.SecondsPerSample <= 0.0 || g.SecondsPerSample <= 0.0)
  {
    return 0.0;
  }
  return (e.Variance * e.SecondsPerSample) / (g.Variance * g.SecondsPerSample);
}

double StrategySelector::SweepFraction(double probe, double full) const
{
  probe = std::min(probe, full);
  const double ratio = this->GridEfficiencyRatio();
  return ratio > 1.0 ? std::clamp(0.5 * (ratio - 1.0), probe, full) : probe;
}

double StrategySelector::AffordableSweepSeconds(double remaining, double fraction, double efficiency)
{
  if (!(remaining > 0.0) || !std::isfinite(remaining))
  {
    return std::numeric_limits<double>::infinity();
  }
  if (!(efficiency > 1.0) || !(fraction > 0.0))
  {
    return 0.0;
  }
  if (!std::isfinite(efficiency))
  {
    return fraction * remaining / (1.0 + fraction); // the limit E -> infinity
  }
  return fraction * remaining * (efficiency - 1.0) / (efficiency - 1.0 + efficiency * fraction);
}

double StrategySelector::ExpectedGridEfficiency() const
{
  const double measured = this->GridEfficiencyRatio();
  return this->GridComplete_ && measured > 0.0 ? measured : std::max(measured, PriorGridEfficiency);
}

StrategySelector::Estimator StrategySelector::Choose(bool gridReady)
{
  if (!gridReady)
  {
    return EnvironmentEstimator;
  }
  if (this->Decisions_ == 0 || this->Stats_[GridEstimator].Variance <= 0.0)
  {
    // Not compared yet: alternate, the grid first.
    return this->EpochFrame_ % 2 == 0 ? GridEstimator : EnvironmentEstimator;
  }
  const Estimator other = this->Preferred_ == GridEstimator ? EnvironmentEstimator : GridEstimator;
  const bool settled = this->GridVerdict_ && !this->GridWorth_ && this->Preferred_ == EnvironmentEstimator;
  const uint32_t interval = settled ? SettledExplorationInterval : ExplorationInterval;
  return this->Frame_ % interval == interval - 1 ? other : this->Preferred_;
}

uint32_t StrategySelector::SamplesFor(Estimator estimator, uint32_t requested, double accumulated) const
{
  if (estimator == this->Preferred_ || requested == 0)
  {
    return requested;
  }
  const double share = std::floor(ProbeShare * std::max(0.0, accumulated));
  return uint32_t(std::clamp(share, 1.0, double(requested)));
}

void StrategySelector::Record(Estimator estimator, uint32_t spp, double deviceSeconds, uint64_t pixels,
  double totalSamples, double sumOfSquares, double meanSquare)
{
  Stats& s = this->Stats_[estimator];
  s.Samples = totalSamples;
  s.SumOfSquares = sumOfSquares;
  s.EpochSeconds += deviceSeconds;
  s.EpochPixelSamples += double(spp) * double(pixels);
  this->Pixels_ = pixels;
  this->MeanSquare_ = meanSquare;
  ++this->Frame_;
  if (++this->EpochFrame_ >= EpochFrames)
  {
    this->EndEpoch(meanSquare);
  }
}

void StrategySelector::EndEpoch(double meanSquare)
{
  bool measured[2] = { false, false };
  for (int e = 0; e < 2; ++e)
  {
    Stats& s = this->Stats_[e];
    const double added = s.Samples - s.EpochSamples0;
    if (added > 0.0 && this->Pixels_ > 0 && s.EpochPixelSamples > 0.0)
    {
      const double secondMoment = (s.SumOfSquares - s.EpochSquares0) / (double(this->Pixels_) * added);
      // Both estimate the same image: its mean square is shared. Clamped: variance >= 0.
      const double v = std::max(secondMoment - meanSquare, 1e-30 * std::max(secondMoment, 1e-30));
      const double t = s.EpochSeconds / s.EpochPixelSamples;
      // The grid estimator improves while the grid fills in: the newest epoch counts most.
      s.Variance = s.Variance > 0.0 ? 0.25 * s.Variance + 0.75 * v : v;
      s.SecondsPerSample = s.SecondsPerSample > 0.0 ? 0.25 * s.SecondsPerSample + 0.75 * t : t;
      measured[e] = true;
    }
    s.EpochSamples0 = s.Samples;
    s.EpochSquares0 = s.SumOfSquares;
    s.EpochSeconds = 0.0;
    s.EpochPixelSamples = 0.0;
  }
  this->EpochFrame_ = 0;
  const double ratio = this->GridEfficiencyRatio();
  if (ratio > 0.0 && (measured[0] || measured[1]))
  {
    this->Preferred_ = ratio > 1.0 ? GridEstimator : EnvironmentEstimator;
    ++this->Decisions_;
    // Sweeping on pays only while TwoStep wins at equal time: a grid that loses stops filling
    // in (measured on mri_sunrise: Auto swept 21% of a 16 s budget for a grid it then did not use).
    if (measured[GridEstimator])
    {
      this->GridWorth_ = ratio > 1.0 || !this->GridJudgeable_ ||
        (!this->GridComplete_ && this->PerSampleEfficiencyRatio() > PartialGridTolerance);
      this->GridVerdict_ = true;
    }
  }
}
}
