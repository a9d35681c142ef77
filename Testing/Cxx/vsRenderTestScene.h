// A small scene for core-level Monte Carlo tests: a volume, a transfer function with
// sigma_t = scalar * sigmaAtOne and a constant albedo, an environment, the visibility
// grid, and an orthographic camera looking along +z.
#ifndef vsRenderTestScene_h
#define vsRenderTestScene_h

#include "vsVisibilityTestScene.h"

#include "vsDeviceEnvironment.h"
#include "vsEnvironmentMap.h"
#include "vsMonteCarloPass.h"
#include "vsVolumeParams.h"
#include "vsError.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace vstest
{
/** A heterogeneous phantom for a 24^3 box: a ball of density falling off from its centre, with a
 *  denser off-centre lobe and a thin shell: optical depths from ~0 to ~12 across it, and gradients of
 *  every strength (and their direction) across the image. */
inline float Phantom(int x, int y, int z)
{
  const glm::vec3 p(x, y, z);
  const float r = glm::length(p - glm::vec3(11.5f));
  const float lobe = glm::length(p - glm::vec3(15.0f, 9.0f, 12.0f));
  float s = std::max(0.0f, 1.0f - r / 10.0f) * 0.6f + (lobe < 4.0f ? 0.4f : 0.0f);
  if (std::abs(r - 9.0f) < 0.8f)
    s += 0.3f;
  return std::min(s, 1.0f);
}

struct RenderScene : VisibilityScene
{
  std::unique_ptr<vs::DeviceEnvironment> Environment;
  std::unique_ptr<vs::VisibilityGrid> Grid;
  glm::vec3 Albedo;

  RenderScene(std::array<uint32_t, 3> dims, const std::function<float(int, int, int)>& scalar, double sigmaAtOne,
    glm::vec3 albedo, const vs::EnvironmentMap& env, std::shared_ptr<vs::Context> context = {})
    : VisibilityScene(dims, scalar, sigmaAtOne, vs::VolumeGeometry(), std::move(context))
    , Albedo(albedo)
  {
    auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 1025,
      [&](double s) { return 1.0 - std::exp(-s * sigmaAtOne); },
      [&](double, double c[3]) {
        c[0] = albedo.x;
        c[1] = albedo.y;
        c[2] = albedo.z;
      },
      1.0, 1.0);
    this->TF = std::make_unique<vs::TransferFunctionTable>(this->Context, samples);
    this->Environment = std::make_unique<vs::DeviceEnvironment>(this->Context, env);
    this->Grid = std::make_unique<vs::VisibilityGrid>(this->Context);
    vs::VisibilityGridParameters p;
    this->Grid->Compute(*this->Volume, *this->TF, *this->Majorants, this->Geometry, {}, p);
  }

  /** Orthographic camera along +z covering world x, y in [lo, hi]; `visibleEnvironment` for escaping rays. */
  vs::shared::VsMonteCarloParams Params(uint32_t w, uint32_t h, float lo, float hi, uint32_t strategy,
    uint32_t spp, uint32_t seed, bool visibleEnvironment = false) const
  {
    vs::shared::VsMonteCarloParams p{};
    glm::mat4 m(1.0f);
    m[0][0] = 0.5f * (hi - lo);
    m[1][1] = 0.5f * (hi - lo);
    m[2][2] = 100.0f;
    m[3] = glm::vec4(0.5f * (hi + lo), 0.5f * (hi + lo), 0.0f, 1.0f);
    p.camera.invViewProj = m;
    p.camera.width = w;
    p.camera.height = h;
    p.camera.seed = seed;
    p.volume = vs::MakeVolumeParams(this->Geometry, *this->TF, vs::shared::VS_INTERPOLATION_LINEAR, {}, this->Majorants.get());
    p.background = visibleEnvironment ? vs::shared::VS_BACKGROUND_ENVIRONMENT : vs::shared::VS_BACKGROUND_TRANSPARENT;
    p.strategy = strategy;
    p.samplesPerFrame = spp;
    p.cellMode = vs::shared::VS_CELL_STOCHASTIC;
    p.environmentLevels = uint32_t(this->Environment->FinestLevel());
    p.visibilityEpsilon = 0.01f;
    p.environmentIntensity = 1.0f;
    auto c = this->Grid->Cells();
    p.grid.cells = glm::uvec3(c[0], c[1], c[2]);
    p.grid.side = this->Grid->Side();
    p.grid.cellSize = this->Grid->CellSize();
    return p;
  }

  /** Renders `frames` x params.samplesPerFrame samples; returns (mean, variance) per pixel and channel. */
  std::pair<std::vector<float>, std::vector<double>> Render(vs::shared::VsMonteCarloParams p, int frames)
  {
    vs::MonteCarloPass pass(this->Context);
    pass.SetDirectionTable(this->DirectionTable);
    pass.SetEmptySpaceSkipping(this->EmptySpaceSkipping);
    pass.SetVolumeQuads(this->VolumeQuads);
    pass.SetCountLookups(this->CountLookups);
    pass.Reset(p.camera.width, p.camera.height);
    for (int f = 0; f < frames; ++f)
    {
      pass.Render(*this->Volume, *this->TF, *this->Majorants, this->Grid.get(), *this->Environment, p, {});
    }
    this->LastSamples = pass.Samples();
    this->LastUsedDirectionTable = pass.LastUsedDirectionTable();
    this->LastLookups = pass.LastLookups();
    this->LastUsedVolumeQuads = pass.LastUsedVolumeQuads();
    this->LastPipelineName = pass.LastPipelineName();
    return { pass.Mean(), pass.Variance() };
  }
  std::string LastPipelineName;
  uint32_t LastSamples = 0;
  /** Whether Render lets the grid strategies read the cells' direction table (the pass's default). */
  bool DirectionTable = true;
  bool LastUsedDirectionTable = false;
  /** Whether the trackers cross empty space a cube of bricks at a time (the pass's default). */
  bool EmptySpaceSkipping = true;
  /** Whether trilinear samples may read an integer-coded volume's 8-bit quads (the pass's default). */
  bool VolumeQuads = true;
  bool LastUsedVolumeQuads = false;
  /** Whether Render uses the counting kernel; LastLookups are its counts of the last frame. */
  bool CountLookups = false;
  std::array<uint64_t, 3> LastLookups{};
};

// Two independent renders of the same expectation, pixel by pixel: the sum of z^2 over the pixels
// and channels with variance (each ~ chi-square(1)), their count, and the summed rgb variance of
// one sample of each render (what splitting and the reservoir should lower).
struct Agreement
{
  double chi2 = 0.0, varA = 0.0, varB = 0.0;
  int dof = 0;
  // Rejects beyond dof + 4 sd + 20, past the chi-square's 1e-4 quantile.
  double Bound() const { return dof + 4.0 * std::sqrt(2.0 * dof) + 20.0; }
};

inline Agreement Compare(const std::vector<float>& a, const std::vector<double>& va, const std::vector<float>& b,
  const std::vector<double>& vb, double n)
{
  Agreement r;
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double se2 = (va[i] + vb[i]) / n;
    if (se2 > 0.0)
    {
      r.chi2 += (a[i] - b[i]) * (a[i] - b[i]) / se2;
      ++r.dof;
    }
    if (i % 4 < 3)
    {
      r.varA += va[i];
      r.varB += vb[i];
    }
  }
  return r;
}

// Every pixel's mean against one `expected` value for every pixel and colour channel (alpha left
// out): the sum of z^2 over those with variance, their count, and the largest |mean - expected|.
// A pixel without variance must be exact (within 1e-5).
struct Against
{
  double chi2 = 0.0, maxError = 0.0;
  int dof = 0;
  double Bound() const { return dof + 4.0 * std::sqrt(2.0 * dof) + 20.0; }
};

inline Against AgainstConstant(const std::vector<float>& mean, const std::vector<double>& var, double n, double expected)
{
  Against r;
  for (size_t i = 0; i < mean.size(); ++i)
  {
    if (i % 4 == 3)
      continue;
    r.maxError = std::max(r.maxError, std::abs(double(mean[i]) - expected));
    const double se2 = var[i] / n;
    if (se2 > 0.0)
    {
      r.chi2 += (mean[i] - expected) * (mean[i] - expected) / se2;
      ++r.dof;
    }
    else if (std::abs(double(mean[i]) - expected) > 1e-5)
    {
      r.chi2 += 1e9;
    }
  }
  return r;
}

// Bad settings: rendering `p` throws an InputError whose message contains `words`, and the pass
// keeps no sample.
inline void ExpectInputError(RenderScene& scene, const vs::shared::VsMonteCarloParams& p, const std::string& words)
{
  vs::MonteCarloPass pass(scene.Context);
  pass.Reset(4, 4);
  try
  {
    pass.Render(*scene.Volume, *scene.TF, *scene.Majorants, scene.Grid.get(), *scene.Environment, p, {});
    ADD_FAILURE() << "no error for " << words;
  }
  catch (const vs::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
  EXPECT_EQ(pass.Samples(), 0u);
}
}

#endif
