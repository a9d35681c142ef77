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
  const double perSample = seconds / double(samples);
  if (this->Added == 1)
  {
    // The first frame's one-off costs stand no longer than until a frame without them.
    this->Count = this->Next = 0;
  }
  this->Recent[this->Next] = perSample;
  this->Next = (this->Next + 1) % Frames;
  this->Count = std::min(this->Count + 1, Frames);
  ++this->Added;
}

double FrameTimePredictor::SecondsPerSample() const
{
  return this->Count == 0 ? 0.0 : *std::max_element(this->Recent, this->Recent + this->Count);
}
}
