// vsFrameTimePredictor.h — how long the next frame of a progressive render will take, for a loop that
// must not start a frame it cannot finish before its deadline (`vissweep render --time-budget`,
// vtkVisibilitySweepVolumeMapper::RenderUntilConverged). Predicting from the last frame alone ran a
// 1 s budget over by a fraction of a millisecond whenever a frame came out slower than the one before
// (ParaView's TimeBudget in a clean clone, issue 39): the prediction per sample is the longest of the
// last three frames. The first frame carries one-off costs the mapper's update does not count (its
// pipelines, the upload's page faults): it stands only until the second frame replaces it.
//
// A frame also has a part that does not grow with its samples (the host's work, the display, the last
// dispatch's tail: ~0.05 s on ch2better at 160², lavapipe). A loop that sizes its last frame to fit
// what is left of the budget ran over by it when that frame had few samples (issue 39: up to 53 ms at
// 2 s). Where the recent frames had different numbers of samples, the fixed part is their least-squares
// intercept (at least 0, at most the shortest frame), and the part per sample is what is left of each
// frame; where they all had the same number, the fixed part is the last one found (0 before any).
#ifndef vsFrameTimePredictor_h
#define vsFrameTimePredictor_h

#include "vissweepCoreModule.h"

namespace vs
{
class VISSWEEPCORE_EXPORT FrameTimePredictor
{
public:
  static constexpr int Frames = 3;
  /** The frames the fixed part is fitted to (the most recent). */
  static constexpr int FitFrames = 16;
  /** Forgets every frame (a new render). */
  void Reset();
  /** A frame that took `seconds`, less its one-off update, and added `samples` samples. Frames
   *  without samples, and non-finite or negative times, are not counted. */
  void Add(double seconds, int samples = 1);
  /** The part of a frame that does not grow with its samples (see the file's comment); 0 before the
   *  frames have had two different numbers of samples. */
  double FixedSeconds() const;
  /** The seconds a sample of the next frame is expected to take beyond the fixed part: the longest of
   *  the last three frames' (the first frame's until a second comes); 0 before any frame. */
  double SecondsPerSample() const;
  /** The seconds the next frame of `samples` samples is expected to take: the fixed part and the
   *  samples'; 0 before any frame. */
  double NextFrameSeconds(int samples = 1) const;
  /** The most samples a frame can have and end within `seconds` (0 when even one cannot; at most
   *  2^30; 2^30 before any frame). */
  int SamplesWithin(double seconds) const;
  /** The frames counted so far for the part per sample (the first one dropped once the second came). */
  int GetCount() const { return this->Count; }

private:
  struct Frame
  {
    double Seconds = 0.0;
    int Samples = 0;
  };
  void Fit();
  Frame Recent[FitFrames];
  int Count = 0;  // of the last three
  int Stored = 0; // of the last FitFrames
  int Next = 0;
  int Added = 0; // frames added since the reset: at 1 the next replaces the first
  double Fixed = 0.0;
};
}

#endif
