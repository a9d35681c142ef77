// vsTransferFunctionTable.h — the transfer function as a device lookup table of
// (albedo r, g, b, extinction) over a scalar range (docs/reference.md conventions):
// sigma_t(s) = -ln(1 - alpha(s)) / unitDistance * densityScale, alpha clamped
// below 1; the colour transfer function is the single-scattering albedo.
#ifndef vsTransferFunctionTable_h
#define vsTransferFunctionTable_h

#include "vissweepCoreModule.h"
#include "sampling/volume_params.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace vs
{
class Buffer;
class Context;

struct VISSWEEPCORE_EXPORT TransferFunctionSamples
{
  float ScalarMin = 0.0f;
  float ScalarMax = 1.0f;
  /** Entries of (r, g, b, sigma_t), evenly spaced over [ScalarMin, ScalarMax]. */
  std::vector<float> Entries; // 4 floats per entry

  size_t Size() const { return this->Entries.size() / 4; }

  /** Samples opacity(s) and colour(s) into `count` entries. */
  static TransferFunctionSamples FromFunctions(float smin, float smax, size_t count,
    const std::function<double(double)>& opacity, const std::function<void(double, double[3])>& color,
    double unitDistance, double densityScale);

  /** The largest extinction a table holds (per world unit): larger values are clamped to it. */
  static constexpr float kMaxExtinction = 1e30f;

  /** Extinction for opacity alpha over unit distance u (alpha clamped to [0, 1 - 1e-6]), at most kMaxExtinction. */
  static double Extinction(double alpha, double unitDistance, double densityScale);

  /** Max extinction over scalars in [s0, s1] (both clamped to the table), on the table's linear interpolant. */
  float MaxExtinction(float s0, float s1) const;
  /** A lower bound of the extinction of every scalar in [s0, s1] (the smallest entry the range's
   *  linear interpolation reads): the control extinction of residual tracking. */
  float MinExtinction(float s0, float s1) const;

  /** A range-maximum (sparse) table of the extinction for the device: levels k = 1 .. L-1 of
   *  Size() values each, entry i of level k = max extinction of entries [i, i + 2^k) (clamped to the
   *  table). With level 0 = the entries, the max over [i, j] is max(level k at i, level k at
   *  j - 2^k + 1) for k = floor(log2(j - i + 1)): two reads, whatever the range. */
  std::vector<float> RangeMaxLevels() const;
  /** L: the levels of that table, including level 0. */
  uint32_t RangeMaxLevelCount() const;

  /** The entries [i0, i1] the linear interpolant reads for scalars in [s0, s1]. */
  std::pair<size_t, size_t> EntrySpan(float s0, float s1) const;
};

class VISSWEEPCORE_EXPORT TransferFunctionTable
{
public:
  TransferFunctionTable(std::shared_ptr<Context> context, const TransferFunctionSamples& samples);
  ~TransferFunctionTable();

  const Buffer& Lut() const { return *this->Buffer_; }
  const TransferFunctionSamples& Samples() const { return this->Samples_; }
  /** How the shaders read this table (volume_params.h VsTransferFunction). */
  shared::VsTransferFunction Params() const;

private:
  TransferFunctionSamples Samples_;
  std::unique_ptr<Buffer> Buffer_;
};
}

#endif
