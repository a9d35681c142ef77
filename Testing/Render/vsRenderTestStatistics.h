// Per-pixel z-scores between two progressive renders (mean and per-sample variance of each
// pixel from vtkVisibilitySweepVolumeMapper::GetRadiance(true)): the unbiasedness checks of the
// render tests. Header-only.
#ifndef vsRenderTestStatistics_h
#define vsRenderTestStatistics_h

#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vstest
{
struct Image
{
  std::vector<double> Mean, Variance; // 3 per pixel (RGB)
  int Samples = 0;
};

inline Image Grab(vtkVisibilitySweepVolumeMapper* mapper)
{
  Image out;
  vtkImageData* r = mapper->GetRadiance(true);
  vtkDataArray* rgb = r->GetPointData()->GetArray("Radiance");
  vtkDataArray* var = r->GetPointData()->GetArray("Variance");
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Mean.push_back(rgb->GetComponent(i, c));
      out.Variance.push_back(var->GetComponent(i, c));
    }
  }
  out.Samples = mapper->GetAccumulatedSamples();
  return out;
}

struct ZStats
{
  int Pixels = 0;
  double MeanZ = 0.0, Chi2 = 0.0, Beyond3 = 0.0;
};

/** Per-pixel z of the green channel (pixels are independent; channels are not). */
inline ZStats Compare(const Image& x, const Image& y)
{
  ZStats s;
  for (size_t i = 1; i < x.Mean.size(); i += 3)
  {
    const double se = std::sqrt(x.Variance[i] / x.Samples + y.Variance[i] / y.Samples);
    if (se <= 0.0)
      continue; // both deterministic (the sky seen directly)
    const double z = (x.Mean[i] - y.Mean[i]) / se;
    ++s.Pixels;
    s.MeanZ += z;
    s.Chi2 += z * z;
    s.Beyond3 += std::abs(z) > 3.0;
  }
  s.MeanZ /= std::max(1, s.Pixels);
  s.Beyond3 /= std::max(1, s.Pixels);
  return s;
}

/** mean z within 4 standard errors; chi-square(n) within 5 standard deviations; |z| > 3 for
 *  less than 2 % of the pixels (0.27 % expected). The radiance is heavy-tailed, so studentized z
 *  has a variance below 1 for two unbiased renders: these bounds are conservative for them. */
inline bool ConsistentWithZeroMean(const ZStats& z)
{
  const double n = z.Pixels;
  return n >= 100 && std::abs(z.MeanZ) < 4.0 / std::sqrt(n) && z.Chi2 < n + 5.0 * std::sqrt(2.0 * n) &&
    z.Beyond3 < 0.02;
}

inline double MeanVariance(const Image& x)
{
  double v = 0.0;
  for (size_t i = 1; i < x.Variance.size(); i += 3)
    v += x.Variance[i];
  return v / double(std::max<size_t>(1, x.Variance.size() / 3));
}
}

#endif
