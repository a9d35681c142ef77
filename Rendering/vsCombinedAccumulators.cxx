#include "vsCombinedAccumulators.h"

#include "vsCoverageComposite.h"
#include "vsMonteCarloPass.h"

#include <algorithm>

namespace vs
{
uint32_t CombinedAccumulators::Samples(const MonteCarloPass* mc, const MonteCarloPass* grid, bool autoStrategy)
{
  uint32_t n = mc ? mc->Samples() : 0u;
  return n + (autoStrategy && grid ? grid->Samples() : 0u);
}

// The mean of all samples: Auto's two accumulators weighted by their sample counts (equal weight
// per sample: both are unbiased estimates of the same image).
std::vector<float> CombinedAccumulators::Mean(const MonteCarloPass& mc, const MonteCarloPass* grid, bool autoStrategy)
{
  std::vector<float> mean = mc.Mean();
  if (!autoStrategy || !grid || grid->Samples() == 0)
  {
    return mean;
  }
  const double ne = mc.Samples(), ng = grid->Samples();
  const std::vector<float> g = grid->Mean();
  for (size_t i = 0; i < mean.size() && i < g.size(); ++i)
  {
    mean[i] = float((ne * double(mean[i]) + ng * double(g[i])) / (ne + ng));
  }
  return mean;
}

// Per-sample variance of the combined mean, such that variance / samples is its squared standard
// error: (n_e v_e + n_g v_g) / (n_e + n_g).
std::vector<double> CombinedAccumulators::Variance(const MonteCarloPass& mc, const MonteCarloPass* grid, bool autoStrategy)
{
  std::vector<double> var = mc.Variance();
  if (!autoStrategy || !grid || grid->Samples() == 0)
  {
    return var;
  }
  const double ne = mc.Samples(), ng = grid->Samples();
  const std::vector<double> g = grid->Variance();
  for (size_t i = 0; i < var.size() && i < g.size(); ++i)
  {
    var[i] = (ne * var[i] + ng * g[i]) / (ne + ng);
  }
  return var;
}

// The alpha the opaque image's pixels that see the environment have (CombinedMean of accumulators
// whose alpha samples are all 1).
float CombinedAccumulators::OpaqueAlpha(const MonteCarloPass* mc, const MonteCarloPass* grid, bool autoStrategy)
{
  const uint32_t ne = mc ? mc->Samples() : 0u;
  const float a = CoverageComposite::OpaqueMean(ne);
  if (!autoStrategy || !grid || grid->Samples() == 0)
  {
    return a;
  }
  const double ng = grid->Samples();
  return float((double(ne) * double(a) + ng * double(CoverageComposite::OpaqueMean(grid->Samples()))) / (double(ne) + ng));
}

// The alpha's variance of the opaque image where the pixel sees the environment
// (CombinedVariance of accumulators whose alpha samples are all 1).
double CombinedAccumulators::OpaqueAlphaVariance(uint32_t ne, uint32_t ng)
{
  return ng == 0 ? CoverageComposite::OpaqueVariance(ne)
                 : (double(ne) * CoverageComposite::OpaqueVariance(ne) + double(ng) * CoverageComposite::OpaqueVariance(ng)) / (double(ne) + ng);
}

double CombinedAccumulators::MeanSquare(const std::vector<float>& mean)
{
  double meanSquare = 0.0;
  for (size_t i = 0; i < mean.size(); i += 4)
  {
    meanSquare += (double(mean[i]) * mean[i] + double(mean[i + 1]) * mean[i + 1] + double(mean[i + 2]) * mean[i + 2]) / 3.0;
  }
  meanSquare /= std::max<double>(1.0, double(mean.size() / 4));
  return meanSquare;
}
}
