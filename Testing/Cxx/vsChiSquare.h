// vsChiSquare.h — statistical tests of direction samplers against their own pdf,
// the way Mitsuba's ChiSquareTest and pbrt's sampling tests do it:
//
//  1. Bin the sphere into res x res equal-area octahedral bins (every bin 4π/res² sr).
//  2. Integrate the pdf over each bin numerically (midpoint rule on sub x sub
//     cells per bin; exact for pdfs that are piecewise constant on octahedral
//     texels of resolution <= res * sub, as all our tabulated strategies are).
//     The integral over the sphere must be 1.
//  3. Draw samples with a fixed seed (vs_rng), histogram them, and compare with
//     Pearson's chi-square test, pooling bins whose expected count is below 5.
//     The p-value must exceed the significance 1e-3 / (number of chi-square
//     tests in the suite) (a Bonferroni correction, so the suite as a whole has
//     a 1e-3 false-failure rate were the seeds not fixed).
//  4. Every sample's pdf must equal pdf(direction), and no sample may land where
//     the pdf is 0 — except for the few that the float round trip
//     uv -> direction -> uv moves across a texel edge (within 1e-5 in uv).
//
// Also BuildEnvMips(): the flat environment quadtree array of warp.h, which the
// tests pass to the shared functions as their first argument (VS_MIPS_PARAM).
#ifndef VS_TEST_CHI_SQUARE_H
#define VS_TEST_CHI_SQUARE_H

#include "sampling/octahedral.h"
#include "sampling/rng.h"
#include "sampling/warp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace vstest
{

// Upper bound of the number of chi-square tests (ChiSquare() calls) in the unit tests: the Bonferroni
// correction's count. ChiSquareRuns() counts them; when the binary runs them all in one process
// (ctest's Sampling.ChiSquareBudget) a global test environment fails if the count passes the bound.
// Measured 2026-12-05: 177 (the Sampling* suites, microfacet included).
constexpr int kChiSquareTestCount = 200;
constexpr double kChiSquareSignificance = 1e-3 / kChiSquareTestCount;

inline int& ChiSquareRuns()
{
  static int runs = 0;
  return runs;
}

class ChiSquareBudget : public testing::Environment
{
public:
  void TearDown() override
  {
    if (ChiSquareRuns() > 0)
    {
      std::cout << "[ chi-square ] " << ChiSquareRuns() << " tests run, at most " << kChiSquareTestCount
                << " budgeted (significance " << kChiSquareSignificance << " each)\n";
    }
    EXPECT_LE(ChiSquareRuns(), kChiSquareTestCount)
      << "more chi-square tests than kChiSquareTestCount (vsChiSquare.h): the suite's false-failure rate "
         "exceeds 1e-3; raise the bound to the count";
  }
};
inline testing::Environment* const kChiSquareBudgetEnvironment =
  testing::AddGlobalTestEnvironment(new ChiSquareBudget);

// ------------------------------------------------------------ distributions

// Regularised upper incomplete gamma Q(a, x) = Γ(a, x) / Γ(a)
// (series below a + 1, Lentz's continued fraction above; Numerical Recipes 6.2).
inline double RegularizedGammaQ(double a, double x)
{
  if (x <= 0.0)
  {
    return 1.0;
  }
  const double logPrefactor = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0)
  {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 100000 && std::abs(term) > std::abs(sum) * 1e-16; ++n)
    {
      term *= x / (a + n);
      sum += term;
    }
    return std::max(0.0, 1.0 - sum * std::exp(logPrefactor));
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i)
  {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    d = std::abs(d) < tiny ? tiny : d;
    c = b + an / c;
    c = std::abs(c) < tiny ? tiny : c;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16)
    {
      break;
    }
  }
  return std::exp(logPrefactor) * h;
}

// P(X >= chi2) for X ~ chi-square with dof degrees of freedom.
inline double ChiSquarePValue(double chi2, double dof)
{
  return RegularizedGammaQ(0.5 * dof, 0.5 * chi2);
}

struct ChiSquareResult
{
  double chi2 = 0.0;
  int dof = 0;
  double pValue = 1.0;
  std::string failure; // non-empty: observations where none are expected
};

// Pearson's test of observed counts against expected counts. Bins expected
// below minExpected are pooled into one (merged into the smallest regular bin
// if the pool itself stays below minExpected).
inline ChiSquareResult ChiSquare(const std::vector<double>& observed,
  const std::vector<double>& expected, double minExpected = 5.0)
{
  ++ChiSquareRuns();
  ChiSquareResult r;
  std::vector<std::pair<double, double>> cells; // (expected, observed)
  double pooledExpected = 0.0, pooledObserved = 0.0;
  for (size_t i = 0; i < expected.size(); ++i)
  {
    if (expected[i] <= 0.0)
    {
      if (observed[i] > 0.0)
      {
        std::ostringstream s;
        s << observed[i] << " samples in bin " << i << " where the pdf is 0";
        r.failure = s.str();
      }
      continue;
    }
    if (expected[i] < minExpected)
    {
      pooledExpected += expected[i];
      pooledObserved += observed[i];
    }
    else
    {
      cells.emplace_back(expected[i], observed[i]);
    }
  }
  if (pooledExpected > 0.0)
  {
    if (pooledExpected >= minExpected || cells.empty())
    {
      cells.emplace_back(pooledExpected, pooledObserved);
    }
    else
    {
      auto smallest = std::min_element(cells.begin(), cells.end());
      smallest->first += pooledExpected;
      smallest->second += pooledObserved;
    }
  }
  for (const auto& c : cells)
  {
    r.chi2 += (c.second - c.first) * (c.second - c.first) / c.first;
  }
  r.dof = int(cells.size()) - 1;
  r.pValue = r.dof > 0 ? ChiSquarePValue(r.chi2, r.dof) : 1.0;
  return r;
}

// ----------------------------------------------------- equal-area sphere bins

inline int SphereBin(glm::vec3 d, int res)
{
  glm::uvec2 t = vs::shared::vs_dir_to_texel(d, glm::uint(res));
  return int(t.y) * res + int(t.x);
}

// True if uv lies within tol of an edge of the res x res texel grid (including
// the outer border, where the octahedral map folds onto itself).
inline bool NearTexelEdge(glm::vec2 uv, int res, double tol = 1e-5)
{
  for (int a = 0; a < 2; ++a)
  {
    double x = double(uv[a]) * res;
    double f = x - std::floor(x);
    if (std::min(f, 1.0 - f) < tol * res)
    {
      return true;
    }
  }
  return false;
}

using PdfFn = std::function<float(glm::vec3)>;
using SampleFn = std::function<glm::vec3(glm::vec2, float&)>;

// The pdf integrated over each of res x res equal-area bins (probabilities).
inline std::vector<double> IntegratePdfOverBins(const PdfFn& pdf, int res, int sub)
{
  const int fine = res * sub;
  const double cellSolidAngle = 4.0 * M_PI / (double(fine) * fine);
  std::vector<double> prob(size_t(res) * res, 0.0);
  for (int y = 0; y < fine; ++y)
  {
    for (int x = 0; x < fine; ++x)
    {
      glm::vec2 uv((x + 0.5f) / float(fine), (y + 0.5f) / float(fine));
      prob[size_t(y / sub) * res + size_t(x / sub)] +=
        double(pdf(vs::shared::vs_octa_to_dir(uv))) * cellSolidAngle;
    }
  }
  return prob;
}

inline double IntegratePdf(const PdfFn& pdf, int res = 64, int sub = 4)
{
  double total = 0.0;
  for (double p : IntegratePdfOverBins(pdf, res, sub))
  {
    total += p;
  }
  return total;
}

// ------------------------------------------------------------ the full check

struct SamplerTestOptions
{
  int samples = 100000;
  int bins = 32; // bins per side of the octahedral histogram
  int sub = 4;   // integration cells per bin side
  glm::uint seed = 1;
  int edgeResolution = 0; // finest texel grid of the pdf (0: pdf is continuous)
  double integralTolerance = 1e-4;
  double pdfTolerance = 1e-5; // relative, sample pdf vs pdf(direction)
  double significance = kChiSquareSignificance;
};

struct SamplerReport
{
  double integral = 0.0;
  ChiSquareResult chi;
  int badDirections = 0; // not unit length or not finite
  int zeroPdf = 0;       // sample() said pdf 0 (invalid) although the pdf integrates to 1
  int pdfMismatches = 0; // sample pdf != pdf(direction), away from texel edges
  int edgeMismatches = 0;
  int edgeSpills = 0; // samples the round trip moved into a zero-pdf bin
  double worstMismatch = 0.0;

  std::string Summary() const
  {
    std::ostringstream s;
    s << "integral " << integral << ", chi2 " << chi.chi2 << " dof " << chi.dof << " p "
      << chi.pValue << ", bad directions " << badDirections << ", zero-pdf samples " << zeroPdf
      << ", pdf mismatches " << pdfMismatches << " (worst rel " << worstMismatch << ", at edges "
      << edgeMismatches << "), edge spills " << edgeSpills << (chi.failure.empty() ? "" : ", ")
      << chi.failure;
    return s.str();
  }
};

inline SamplerReport RunSamplerTest(
  const SampleFn& sample, const PdfFn& pdf, const SamplerTestOptions& o)
{
  SamplerReport r;
  std::vector<double> prob = IntegratePdfOverBins(pdf, o.bins, o.sub);
  for (double p : prob)
  {
    r.integral += p;
  }
  std::vector<double> observed(prob.size(), 0.0);
  vs::shared::VsRng rng = vs::shared::vs_rng_init(glm::uvec2(17u, 29u), 3u, o.seed);
  for (int i = 0; i < o.samples; ++i)
  {
    float pdfSampled = 0.0f;
    glm::vec3 d = sample(vs::shared::vs_rng_vec2(rng), pdfSampled);
    float len = glm::length(d);
    if (!std::isfinite(len) || std::abs(len - 1.0f) > 1e-4f)
    {
      ++r.badDirections;
      continue;
    }
    if (!(pdfSampled > 0.0f) || !std::isfinite(pdfSampled))
    {
      ++r.zeroPdf;
      continue;
    }
    glm::vec2 uv = vs::shared::vs_dir_to_octa(d);
    double mismatch = std::abs(double(pdf(d)) - pdfSampled) / pdfSampled;
    if (mismatch > o.pdfTolerance)
    {
      bool atEdge = o.edgeResolution > 0 && NearTexelEdge(uv, o.edgeResolution);
      (atEdge ? r.edgeMismatches : r.pdfMismatches) += 1;
      if (!atEdge)
      {
        r.worstMismatch = std::max(r.worstMismatch, mismatch);
      }
    }
    int bin = SphereBin(d, o.bins);
    if (prob[bin] <= 0.0 && NearTexelEdge(uv, o.bins))
    {
      ++r.edgeSpills;
      continue;
    }
    observed[bin] += 1.0;
  }
  std::vector<double> expected(prob.size());
  for (size_t i = 0; i < prob.size(); ++i)
  {
    expected[i] = prob[i] * o.samples;
  }
  r.chi = ChiSquare(observed, expected);
  return r;
}

// A gtest predicate: the sampler draws from the density it reports.
inline testing::AssertionResult SamplerMatchesPdf(
  const SampleFn& sample, const PdfFn& pdf, const SamplerTestOptions& o = SamplerTestOptions())
{
  SamplerReport r = RunSamplerTest(sample, pdf, o);
  if (std::getenv("VSTEST_VERBOSE"))
  {
    std::cout << "  [chi-square] " << r.Summary() << "\n";
  }
  const int edgeBudget = 2 + o.samples / 1000;
  bool ok = std::abs(r.integral - 1.0) <= o.integralTolerance && r.badDirections == 0 &&
            r.zeroPdf == 0 && r.pdfMismatches == 0 && r.edgeMismatches <= edgeBudget &&
            r.edgeSpills <= edgeBudget && r.chi.failure.empty() && r.chi.pValue >= o.significance;
  return (ok ? testing::AssertionSuccess() : testing::AssertionFailure()) << r.Summary();
}

// ------------------------------------------------------ environment quadtree

// The flat env mip array of warp.h from N x N leaves (N = 2^finestLevel,
// row-major): level l at (4^l - 1)/3, each node the mean of its 4 children.
inline std::vector<float> BuildEnvMips(const std::vector<float>& leaves, unsigned finestLevel)
{
  std::vector<float> mips(((size_t(1) << (2 * (finestLevel + 1))) - 1) / 3, 0.0f);
  std::copy(
    leaves.begin(), leaves.end(), mips.begin() + vs::shared::vs_env_level_offset(finestLevel));
  for (int level = int(finestLevel) - 1; level >= 0; --level)
  {
    const size_t n = size_t(1) << level, base = vs::shared::vs_env_level_offset(level);
    const size_t child = vs::shared::vs_env_level_offset(level + 1);
    for (size_t y = 0; y < n; ++y)
    {
      for (size_t x = 0; x < n; ++x)
      {
        const float* c0 = &mips[child + 2 * y * 2 * n + 2 * x];
        const float* c1 = c0 + 2 * n;
        mips[base + y * n + x] = 0.25f * ((c0[0] + c1[0]) + (c0[1] + c1[1]));
      }
    }
  }
  return mips;
}

} // namespace vstest

#endif
