// vsExtinctionRangeQuery.h — the largest and the smallest extinction a transfer function gives
// scalars in a range, for many ranges at once: the majorant and the control extinction of every
// brick of the majorant grid. TransferFunctionSamples::MaxExtinction / MinExtinction scan the
// table's entries of the range, up to the table's 4096 entries per brick: 88 ms of the first
// frame on ch2 (14k bricks, most of them spanning air to skin). Two sparse tables (level k, entry
// i: the max or min over entries [i, i + 2^k)) answer each range with two reads, and give the same
// values bit for bit (max and min are exact).
#ifndef vsExtinctionRangeQuery_h
#define vsExtinctionRangeQuery_h

#include "vissweepCoreModule.h"

#include <vector>

namespace vs
{
struct TransferFunctionSamples;

class VISSWEEPCORE_EXPORT ExtinctionRangeQuery
{
public:
  /** Builds the tables, O(n log n) for n entries. The table must outlive the query. */
  explicit ExtinctionRangeQuery(const TransferFunctionSamples& tf);

  /** The same as tf.MaxExtinction(s0, s1) and tf.MinExtinction(s0, s1). */
  float Max(float s0, float s1) const;
  float Min(float s0, float s1) const;

private:
  const TransferFunctionSamples& TF_;
  std::vector<std::vector<float>> Max_, Min_; // level k: spans of 2^k entries
};
}

#endif
