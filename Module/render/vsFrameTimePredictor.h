// vsFrameTimePredictor.h — how long the next frame of a progressive render will take, for a loop that
// must not start a frame it cannot finish before its deadline (`vissweep render --time-budget`,
// vtkVisibilitySweepVolumeMapper::RenderUntilConverged). Predicting from the last frame alone ran a
// 1 s budget over by a fraction of a millisecond whenever a frame came out slower than the one before
// (ParaView's TimeBudget in a clean clone, issue 39): the prediction is the longest of the last three
// frames, per sample. The first frame carries one-off costs the mapper's update does not count (its
// pipelines, the upload's page faults): it stands only until the second frame replaces it.
#ifndef vsFrameTimePredictor_h
#define vsFrameTimePredictor_h

#include "vissweepCoreModule.h"

namespace vs
{
class VISSWEEPCORE_EXPORT FrameTimePredictor
{
public:
  static constexpr int Frames = 3;
  /** Forgets every frame (a new render). */
  void Reset();
  /** A frame that took `seconds`, less its one-off update, and added `samples` samples. Frames
   *  without samples, and non-finite or negative times, are not counted. */
  void Add(double seconds, int samples = 1);
  /** The seconds a sample of the next frame is expected to take: the longest of the last three
   *  frames' (the first frame's until a second comes); 0 before any frame. */
  double SecondsPerSample() const;
  /** The seconds the next frame of `samples` samples is expected to take. */
  double NextFrameSeconds(int samples = 1) const { return this->SecondsPerSample() * samples; }
  /** The frames counted so far (the first one dropped once the second came). */
  int GetCount() const { return this->Count; }

private:
  double Recent[Frames] = { 0.0, 0.0, 0.0 };
  int Count = 0;
  int Next = 0;
  int Added = 0; // frames added since the reset: at 1 the next replaces the first
};
}

#endif
