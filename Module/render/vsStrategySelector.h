// vsStrategySelector.h — the Auto strategy's choice, frame by frame, between two unbiased
// estimators of the same image: Environment sampling and TwoStep over the visibility grid.
//
// Each estimator accumulates into its own buffers; the image is the mean of all samples of both.
// After every frame the renderer reports the frame's samples, its device time and the sums of
// squares of the estimator's accumulator; per epoch of frames the selector estimates each
// estimator's per-sample variance over the epoch's samples,
//     v = (sum of squares added) / (pixels x samples added) - mean over pixels of m^2,
// where m is the current mean image (the same for both: they estimate the same image), and picks
// the one with the larger efficiency 1 / (v x device seconds per sample). The other still gets
// one frame in ExplorationInterval, so its estimate stays current.
//
// Unbiasedness: a choice depends only on samples drawn before it, so each sample is unbiased
// given the past (a martingale difference), and the mean over a number of samples that does not
// depend on their values (a fixed spp, or a time budget) is unbiased.
// Host-only, no device.
#ifndef vsStrategySelector_h
#define vsStrategySelector_h

#include "vissweepCoreModule.h"

#include <cstdint>

namespace vs
{
class VISSWEEPCORE_EXPORT StrategySelector
{
public:
  enum Estimator
  {
    EnvironmentEstimator = 0,
    GridEstimator = 1
  };

  /** Accumulation restarted: forget everything but the grid verdict of this grid generation. */
  void Reset();
  /** A new visibility grid (full invalidation): the grid's worth is unknown again. */
  void ResetGrid();

  /** The estimator for the next frame. gridReady: the grid holds enough swept directions for
   *  TwoStep to be worth measuring. */
  Estimator Choose(bool gridReady);

  /** The samples per pixel a frame of `estimator` may add when `requested` were asked for and
   *  `accumulated` are in both accumulators: all of them for the preferred estimator; at most
   *  ProbeShare of `accumulated` (at least one) for an estimator being probed (the grid before
   *  the first verdict, then whichever lost). A probe's samples cost their extra variance, so
   *  probing is bounded in samples, not frames: with 64-sample frames, probing by frames gave
   *  TwoStep 128 of blind_sunrise's 500 samples in a 16 s budget, a grid that then lost. */
  uint32_t SamplesFor(Estimator estimator, uint32_t requested, double accumulated) const;
  static constexpr double ProbeShare = 1.0 / 32.0;

  /** After a frame of `estimator`: its samples per pixel, device seconds, and the accumulator's
   *  totals: samples so far and the sum over pixels of the sum of squares (rgb mean) so far;
   *  meanSquare: the mean over pixels of the squared mean image (rgb mean) now; pixels: count. */
  void Record(Estimator estimator, uint32_t spp, double deviceSeconds, uint64_t pixels, double totalSamples,
    double sumOfSquares, double meanSquare);

  /** Whether sweeping more directions is worth it: false while TwoStep, measured on a grid that
   *  can be judged (SetGridJudgeable), is less efficient than Environment sampling (re-evaluated
   *  at every epoch that measured TwoStep). While the grid is incomplete, TwoStep within
   *  PartialGridTolerance of Environment sampling per sample (PerSampleEfficiencyRatio: the
   *  question there is whether the grid's pdf is heading somewhere) is worth completing: its
   *  unswept directions read swept ones (FillUnswept), so a partial grid measures at best about as
   *  good as Environment sampling, and only the complete grid shows what the grid gains. */
  bool GridWorthSweeping() const { return this->GridWorth_; }
  /** The share of the render time to grant the grid's sweeps, between `probe` and `full`: `probe`
   *  until TwoStep has measured more efficient than Environment sampling, then half of the measured
   *  gain (GridEfficiencyRatio() - 1) within [probe, full]. A grid is worth what it gains: on the
   *  0.5 mm MRI TwoStep measures ~10% more efficient per sample (gain the Sobol sampler's
   *  stratification mostly takes back), and sweeping it at the full 25% of the time made Auto hold
   *  10-14% fewer samples than Environment sampling over 32 s. */
  double SweepFraction(double probe, double full) const;
  /** The most device seconds of sweeps still pending that can pay for themselves before a deadline
   *  `remaining` seconds away (infinite when remaining <= 0 or not finite: no deadline), swept at
   *  `fraction` of the render time (SweepFraction) and then sampled by TwoStep `efficiency` times as
   *  efficiently as Environment sampling. A linear model of the frames to the deadline: finishing C
   *  seconds of sweeps at fraction f takes C (1 + f) / f seconds of frames, whose render time C / f is
   *  worth no more than Environment sampling's (a partial grid measures at best about as good); the
   *  time left after it renders E times as efficiently. That beats rendering Environment sampling
   *  throughout (R seconds) iff
   *      C < f R (E - 1) / (E - 1 + E f).
   *  0 when E <= 1 or f <= 0: nothing pending pays. */
  static double AffordableSweepSeconds(double remaining, double fraction, double efficiency);
  /** TwoStep's efficiency over Environment sampling assumed for AffordableSweepSeconds before a
   *  complete grid has measured it: optimistic, the largest per-sample gain measured (2.05x on
   *  phantom_forest, docs/benchmarks.md), which the Sobol sampler's stratification mostly takes back. */
  static constexpr double PriorGridEfficiency = 2.0;
  /** The efficiency AffordableSweepSeconds is given: the measured GridEfficiencyRatio() on a complete
   *  grid, else the larger of it and PriorGridEfficiency (a partial grid's TwoStep reads swept
   *  directions for the unswept ones and cannot show the complete grid's gain). */
  double ExpectedGridEfficiency() const;

  /** Whether the grid TwoStep is measured with is complete (the default: assumed complete). */
  void SetGridComplete(bool complete) { this->GridComplete_ = complete; }
  /** Whether the grid TwoStep is measured with holds enough of the light to judge it by (the
   *  default): the renderer says so from half of the light's importance swept. TwoStep is
   *  measured earlier (on any grid that is not flat), but a loss there does not stop the fill-in. */
  void SetGridJudgeable(bool judgeable) { this->GridJudgeable_ = judgeable; }
  static constexpr double PartialGridTolerance = 0.9;

  /** How much further Environment sampling's error of the mean falls below v / N than TwoStep's
   *  does (>= 1; 1, the default, for independent samples). Per-sample variances cannot see a
   *  stratified sampler: under the Sobol sampler the error of the mean falls faster than v / N, and
   *  by more for Environment sampling, whose one warp keeps the sequence's strata, than for
   *  TwoStep, which warps each number through the table of a cell picked per sample. Measured
   *  at equal spp (docs/benchmarks.md): 1.21-1.27 on mri_sunrise and 1.21-1.37 on mri_courtyard
   *  over 16-256 spp (SobolStratificationGain). */
  void SetStratificationGain(double gain) { this->StratificationGain_ = gain >= 1.0 ? gain : 1.0; }
  double GetStratificationGain() const { return this->StratificationGain_; }
  static constexpr double SobolStratificationGain = 1.25;

  /** Measured per-sample variance and device seconds per sample of an estimator (0 = unknown). */
  double Variance(Estimator e) const { return this->Stats_[e].Variance; }
  double SecondsPerSample(Estimator e) const { return this->Stats_[e].SecondsPerSample; }
  /** Efficiency of TwoStep over Environment at equal time: the 1/(v t) ratio divided by the
   *  stratification gain; 0 while unknown. */
  double GridEfficiencyRatio() const;
  /** The 1/(v t) ratio of the per-sample measurements alone; 0 while unknown. */
  double PerSampleEfficiencyRatio() const;
  Estimator Preferred() const { return this->Preferred_; }
  uint32_t Decisions() const { return this->Decisions_; }

  /** Frames per epoch, and one frame in ExplorationInterval for the estimator that lost. */
  static constexpr uint32_t EpochFrames = 8;
  static constexpr uint32_t ExplorationInterval = 16;
  /** Once TwoStep has lost with the grid it was judged on and the grid stops filling in
   *  (GridWorthSweeping() false), that grid no longer improves: TwoStep then gets one frame in
   *  SettledExplorationInterval only (each such frame costs its extra variance: on mri_sunrise
   *  TwoStep's sun-only grid has 1.4x Environment's variance per sample, so 1 in 16 cost ~2.6%). */
  static constexpr uint32_t SettledExplorationInterval = 64;

private:
  struct Stats
  {
    double Samples = 0.0, SumOfSquares = 0.0;           // accumulator totals at the last record
    double EpochSamples0 = 0.0, EpochSquares0 = 0.0;    // at the start of the epoch
    double EpochSeconds = 0.0, EpochPixelSamples = 0.0; // device time and pixel-samples this epoch
    double Variance = 0.0, SecondsPerSample = 0.0;      // estimates (0 = unknown)
  };
  void EndEpoch(double meanSquare);

  Stats Stats_[2];
  Estimator Preferred_ = EnvironmentEstimator;
  bool Comparing_ = false;    // both estimators measured in this epoch (the first epochs alternate)
  bool GridWorth_ = true;
  bool GridVerdict_ = false;  // GridWorth_ was decided for this grid
  bool GridComplete_ = true;
  bool GridJudgeable_ = true;
  double StratificationGain_ = 1.0;
  uint32_t Frame_ = 0, EpochFrame_ = 0, Decisions_ = 0;
  uint64_t Pixels_ = 0;
  double MeanSquare_ = 0.0;
};
}

#endif
