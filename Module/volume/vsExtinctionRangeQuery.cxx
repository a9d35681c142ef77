#include "vsExtinctionRangeQuery.h"

#include "vsTransferFunctionTable.h"

#include <algorithm>

namespace vs
{
namespace
{
// The level of the largest power-of-two span within a range of `length` >= 1 entries.
size_t Level(size_t length)
{
  size_t k = 0;
  while ((size_t(2) << k) <= length)
  {
    ++k;
  }
  return k;
}
}

ExtinctionRangeQuery::ExtinctionRangeQuery(const TransferFunctionSamples& tf)
  : TF_(tf)
{
  const size_t n = tf.Size();
  std::vector<float> level(n);
  for (size_t i = 0; i < n; ++i)
  {
    level[i] = tf.Entries[4 * i + 3];
  }
  this->Max_.push_back(level);
  this->Min_.push_back(level);
  for (size_t span = 1; 2 * span <= n; span *= 2)
  {
    const std::vector<float>& maxBelow = this->Max_.back();
    const std::vector<float>& minBelow = this->Min_.back();
    std::vector<float> maxLevel(n - 2 * span + 1), minLevel(n - 2 * span + 1);
    for (size_t i = 0; i < maxLevel.size(); ++i)
    {
      maxLevel[i] = std::max(maxBelow[i], maxBelow[i + span]);
      minLevel[i] = std::min(minBelow[i], minBelow[i + span]);
    }
    this->Max_.push_back(std::move(maxLevel));
    this->Min_.push_back(std::move(minLevel));
  }
}

float ExtinctionRangeQuery::Max(float s0, float s1) const
{
  const auto [i0, i1] = this->TF_.EntrySpan(s0, s1);
  const size_t k = Level(i1 - i0 + 1);
  // As MaxExtinction, which starts from 0.
  return std::max(0.0f, std::max(this->Max_[k][i0], this->Max_[k][i1 + 1 - (size_t(1) << k)]));
}

float ExtinctionRangeQuery::Min(float s0, float s1) const
{
  const auto [i0, i1] = this->TF_.EntrySpan(s0, s1);
  const size_t k = Level(i1 - i0 + 1);
  return std::min(this->Min_[k][i0], this->Min_[k][i1 + 1 - (size_t(1) << k)]);
}
}
