// vsFrameTimePredictor.cxx — see the header.
#include "vsFrameTimePredictor.h"

#include <algorithm>
#include <cmath>

namespace vs
{
void FrameTimePredictor::Reset()
{
  *this = FrameTimePredictor();
}

void FrameTimePredictor::Add(double seconds, int samples)
{
  if (samples <= 0 || !std::isfinite(seconds) || seconds < 0.0)
  {
    return;
  }
  if (this->Added == 1)
  {
    // The first frame's one-off costs stand no longer than until a frame without them.
    this->Count = this->Stored = this->Next = 0;
  }
  this->Recent[this->Next] = Frame{ seconds, samples };
  this->Next = (this->Next + 1) % FitFrames;
  this->Count = std::min(this->Count + 1, Frames);
  this->Stored = std::min(this->Stored + 1, FitFrames);
  ++this->Added;
  this->Fit();
}

void FrameTimePredictor::Fit()
{
  // The least-squares line seconds = fixed + perSample * samples through the stored frames.
  double n = 0.0, sx = 0.0, sy = 0.0, shortest = HUGE_VAL;
  for (int i = 0; i < this->Stored; ++i)
  {
    n += 1.0;
    sx += this->Recent[i].Samples;
    sy += this->Recent[i].Seconds;
    shortest = std::min(shortest, this->Recent[i].Seconds);
  }
  if (n < 2.0)
  {
    return;
  }
  const double mx = sx / n, my = sy / n;
  double sxx = 0.0, sxy = 0.0;
  for (int i = 0; i < this->Stored; ++i)
  {
    const double dx = this->Recent[i].Samples - mx;
    sxx += dx * dx;
    sxy += dx * (this->Recent[i].Seconds - my);
  }
  if (sxx <= 0.0)
  {
    return; // one number of samples: the fixed part found before stands
  }
  const double intercept = my - (sxy / sxx) * mx;
  this->Fixed = std::clamp(std::isfinite(intercept) ? intercept : 0.0, 0.0, shortest);
}

double FrameTimePredictor::FixedSeconds() const
{
  return this->Count == 0 ? 0.0 : this->Fixed;
}

double FrameTimePredictor::SecondsPerSample() const
{
  double longest = 0.0;
  for (int k = 1; k <= this->Count; ++k)
  {
    const Frame& f = this->Recent[(this->Next - k + FitFrames) % FitFrames];
    longest = std::max(longest, std::max(0.0, f.Seconds - this->FixedSeconds()) / f.Samples);
  }
  return longest;
}

double FrameTimePredictor::NextFrameSeconds(int samples) const
{
  return this->Count == 0 ? 0.0 : this->FixedSeconds() + this->SecondsPerSample() * samples;
}

int FrameTimePredictor::SamplesWithin(double seconds) const
{
  constexpr int most = 1 << 30;
  const double perSample = this->SecondsPerSample();
  const double left = seconds - this->FixedSeconds();
  if (this->Count == 0)
  {
    return most; // nothing known
  }
  if (!(left >= 0.0))
  {
    return 0; // not even the fixed part fits
  }
  return perSample > 0.0 ? int(std::min(std::floor(left / perSample), double(most))) : most;
}
}
