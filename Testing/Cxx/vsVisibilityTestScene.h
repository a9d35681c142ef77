// Small volumes with known visibility for the visibility-grid tests.
#ifndef vsVisibilityTestScene_h
#define vsVisibilityTestScene_h

#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsMajorantGrid.h"
#include "vsTransferFunctionTable.h"
#include "vsVisibilityGrid.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace vstest
{
/** Distance from p along w to the exit of box [lo, hi] (0 outside it). */
inline double ExitDistance(glm::dvec3 p, glm::dvec3 w, glm::dvec3 lo, glm::dvec3 hi)
{
  double t = 1e300;
  for (int i = 0; i < 3; ++i)
  {
    if (w[i] > 0)
      t = std::min(t, (hi[i] - p[i]) / w[i]);
    else if (w[i] < 0)
      t = std::min(t, (lo[i] - p[i]) / w[i]);
  }
  return std::max(0.0, t);
}

/** A volume, a linear transfer function (sigma_t = scalar * sigmaPerUnit, white albedo) and its majorants. */
struct VisibilityScene
{
  std::shared_ptr<vs::Context> Context;
  vs::VolumeGeometry Geometry;
  std::unique_ptr<vs::DeviceVolume> Volume;
  std::unique_ptr<vs::TransferFunctionTable> TF;
  std::unique_ptr<vs::MajorantGrid> Majorants;

  /** On `context`, or the process's default context when none is given. */
  VisibilityScene(std::array<uint32_t, 3> dims, const std::function<float(int, int, int)>& scalar,
    double sigmaAtOne, vs::VolumeGeometry geometry = vs::VolumeGeometry(), std::shared_ptr<vs::Context> context = {})
    : Context(context ? std::move(context) : vs::Context::Default())
  {
    this->Geometry = geometry.Dims[0] ? geometry : vs::VolumeGeometry::Axis(dims);
    std::vector<float> v(size_t(dims[0]) * dims[1] * dims[2]);
    for (uint32_t z = 0; z < dims[2]; ++z)
      for (uint32_t y = 0; y < dims[1]; ++y)
        for (uint32_t x = 0; x < dims[0]; ++x)
          v[(size_t(z) * dims[1] + y) * dims[0] + x] = scalar(int(x), int(y), int(z));
    this->Volume = std::make_unique<vs::DeviceVolume>(this->Context, v.data(), dims);
    // opacity(s) chosen so that sigma_t(s) = s * sigmaAtOne exactly at the LUT entries (s in [0, 1]).
    auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 1025,
      [&](double s) { return 1.0 - std::exp(-s * sigmaAtOne); },
      [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0, 1.0);
    this->TF = std::make_unique<vs::TransferFunctionTable>(this->Context, samples);
    this->Majorants = std::make_unique<vs::MajorantGrid>(this->Context);
    this->Majorants->UpdateRanges(*this->Volume);
    this->Majorants->UpdateMajorants(samples);
  }

  /** Replaces the transfer function by a hat of extinction sigmaPeak at scalar 0.5, 0 at and beyond
   *  0.25 and 0.75 (so 0 at the scalars 0 and 1 a label map of two labels holds): under trilinear
   *  interpolation the medium is between voxels of different labels, under nearest nowhere. */
  void UseHatTransferFunction(double sigmaPeak)
  {
    auto samples = vs::TransferFunctionSamples::FromFunctions(0.0f, 1.0f, 1025,
      [&](double s) { return 1.0 - std::exp(-sigmaPeak * std::max(0.0, 1.0 - 4.0 * std::abs(s - 0.5))); },
      [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0, 1.0);
    this->TF = std::make_unique<vs::TransferFunctionTable>(this->Context, samples);
    this->Majorants->UpdateMajorants(samples);
  }

  /** Scales the extinction by factor(x, y, z) per voxel (the gradient opacity's factor volume,
   *  vsDeviceVolume.h SetFactor), with the majorants that bound it. */
  void ScaleExtinction(const std::function<float(int, int, int)>& factor)
  {
    const auto dims = this->Volume->Dims();
    std::vector<float> g(size_t(dims[0]) * dims[1] * dims[2]);
    for (uint32_t z = 0; z < dims[2]; ++z)
      for (uint32_t y = 0; y < dims[1]; ++y)
        for (uint32_t x = 0; x < dims[0]; ++x)
          g[(size_t(z) * dims[1] + y) * dims[0] + x] = factor(int(x), int(y), int(z));
    this->Volume->SetFactor(g.data());
    this->Majorants->SetFactor(g.data());
    this->Majorants->UpdateMajorants(this->TF->Samples());
  }

  std::vector<float> Grid(vs::VisibilityGrid& grid, const vs::VisibilityGridParameters& p,
    const std::vector<glm::dvec4>& planes = {})
  {
    grid.Compute(*this->Volume, *this->TF, *this->Majorants, this->Geometry, planes, p);
    return grid.Download();
  }
};
}

#endif
