// vsAccumulationSignature.h — what the mapper's accumulated Monte Carlo image was rendered for:
// every value of the render parameters as doubles (the mapper appends the scene's and the grid's
// versions and the depth), and the comparison that tells a change (which restarts accumulation)
// from the last-bit noise of camera matrices VTK recomputes.
#ifndef vsAccumulationSignature_h
#define vsAccumulationSignature_h

#include "sampling/mc_params.h"

#include <vector>

namespace vs
{
class AccumulationSignature
{
public:
  /** Every value of `p` but directionSources, integers by value. */
  static std::vector<double> Of(const vs::shared::VsMonteCarloParams& p);
  /** Equal sizes and values equal up to a relative 1e-6. */
  static bool NearlyEqual(const std::vector<double>& a, const std::vector<double>& b);
};
}

#endif
