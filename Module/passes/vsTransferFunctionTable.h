// vsTransferFunctionTable.h — the transfer function as a device lookup table of
// (albedo r, g, b, extinction) over a scalar range (docs/reference.md conventions):
// sigma_t(s) = -ln(1 - alpha(s)) / unitDistance * densityScale, alpha clamped
// below 1; the colour transfer function is the single-scattering albedo.
#ifndef vsTransferFunctionTable_h
#define vsTransferFunctionTable_h

#include "vissweepCoreModule.h"

#include <array>
#include <functional>
#include <memory>
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

  /** Extinction for opacity alpha over unit distance u (alpha clamped to [0, 1 - 1e-6]). */
  static double Extinction(double alpha, double unitDistance, double densityScale);

  /** Max extinction over scalars in [s0, s1] (both clamped to the table), on the table's linear interpolant. */
  float MaxExtinction(float s0, float s1) const;
};

class VISSWEEPCORE_EXPORT TransferFunctionTable
{
public:
  TransferFunctionTable(std::shared_ptr<Context> context, const TransferFunctionSamples& samples);
  ~TransferFunctionTable();

  const Buffer& Lut() const { return *this->Buffer_; }
  const TransferFunctionSamples& Samples() const { return this->Samples_; }
  /** The `tf` vector of VsFrameParams: (scalar at entry 0, entries per unit, entries, 0). */
  std::array<float, 4> Params() const;

private:
  TransferFunctionSamples Samples_;
  std::unique_ptr<Buffer> Buffer_;
};
}

#endif
