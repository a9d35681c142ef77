#include "vsKernelOptions.h"
#include "sampling/kernel_spec.h"
#include "sampling/mc_params.h"
#include "sampling/strategies.h"
#include "vsError.h"

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace vs
{
namespace
{
using namespace shared;

// The table. Words are what users type (scene file, command line); API names are the mapper's enums.
const std::vector<KernelOption>& Table()
{
  static const std::vector<KernelOption> table{
    { "SamplingStrategy", "strategy", int(VS_SPEC_ID_STRATEGY),
      { { VS_STRATEGY_UNIFORM, "uniform", "Uniform" }, { VS_STRATEGY_ENVIRONMENT, "environment", "Environment" },
        { VS_STRATEGY_VISIBILITY, "visibility", "Visibility" }, { VS_STRATEGY_COMBINED, "combined", "Combined" },
        { VS_STRATEGY_TWO_STEP, "two-step", "TwoStep" }, { kAutoStrategy, "auto", "Auto" } } },
    { "CellMode", "", int(VS_SPEC_ID_CELL_MODE),
      { { VS_CELL_TRILINEAR, "trilinear", "TrilinearCells" }, { VS_CELL_STOCHASTIC, "stochastic", "StochasticCell" } } },
    { "CameraEstimator", "", int(VS_SPEC_ID_CAMERA),
      { { VS_CAMERA_COLLISION, "collision", "CollisionCamera" }, { VS_CAMERA_RESERVOIR, "reservoir", "ReservoirCamera" } } },
    { "Sampler", "sampler", int(VS_SPEC_ID_SAMPLER),
      { { VS_SAMPLER_INDEPENDENT, "independent", "IndependentSampler" }, { VS_SAMPLER_SOBOL, "sobol", "SobolSampler" } } },
    { "ControlExtinction", "control_extinction", int(VS_SPEC_ID_CONTROL),
      { { 0u, "none", "NoControl" }, { VS_CONTROL_SHADOW, "shadow", "ShadowRayControl" },
        { VS_CONTROL_CAMERA, "camera", "CameraRayControl" }, { VS_CONTROL_SHADOW | VS_CONTROL_CAMERA, "both", "FullControl" } } },
    { "TransmittanceEstimator", "transmittance_estimator", int(VS_SPEC_ID_TRANSMITTANCE),
      { { VS_TRANSMITTANCE_RATIO_TRACKING, "ratio-tracking", "RatioTracking" },
        { VS_TRANSMITTANCE_RAY_MARCHING, "ray-marching", "RayMarching" } } },
    { "MultipleImportanceSampling", "", -1,
      { { VS_MIS_POWER, "power", "PowerHeuristic" }, { VS_MIS_LIGHT_ONLY, "light-only", "LightSamplingOnly" },
        { VS_MIS_PHASE_ONLY, "phase-only", "PhaseSamplingOnly" }, { VS_MIS_BALANCE, "balance", "BalanceHeuristic" } } },
  };
  return table;
}

const KernelOptionValue* Find(KernelOptionId id, uint32_t value)
{
  for (const auto& v : GetKernelOption(id).Values)
  {
    if (v.Value == value)
    {
      return &v;
    }
  }
  return nullptr;
}

std::string Folded(const std::string& name)
{
  std::string f;
  for (const char c : name)
  {
    if (c != '-' && c != '_')
    {
      f += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  return f;
}
}

const KernelOption& GetKernelOption(KernelOptionId id)
{
  return Table().at(size_t(id));
}

const char* KernelOptionApiName(KernelOptionId id, uint32_t value)
{
  const KernelOptionValue* v = Find(id, value);
  return v ? v->ApiName : "Unknown";
}

const char* KernelOptionWord(KernelOptionId id, uint32_t value)
{
  const KernelOptionValue* v = Find(id, value);
  return v ? v->Word : "?";
}

std::vector<std::string> KernelOptionWords(KernelOptionId id)
{
  std::vector<std::string> words;
  for (const auto& v : GetKernelOption(id).Values)
  {
    words.emplace_back(v.Word);
  }
  return words;
}

int KernelOptionValueOf(KernelOptionId id, const std::string& name)
{
  const std::string f = Folded(name);
  for (const auto& v : GetKernelOption(id).Values)
  {
    if (f == Folded(v.Word) || f == Folded(v.ApiName))
    {
      return int(v.Value);
    }
  }
  return -1;
}

void CheckScatteringSettings(double maxEvents, double anisotropy)
{
  if (!(maxEvents >= 1.0 && maxEvents <= double(VS_MAX_SCATTERING_EVENTS)))
  {
    throw InputError("MaximumScatteringEvents must be in [1, " + std::to_string(VS_MAX_SCATTERING_EVENTS) +
      "], got " + std::to_string(int64_t(std::isfinite(maxEvents) ? maxEvents : -1.0)));
  }
  if (!(anisotropy > -1.0 && anisotropy < 1.0))
  {
    throw InputError(
      "ScatteringAnisotropy (the Henyey-Greenstein anisotropy g) must be in (-1, 1), got " + std::to_string(anisotropy));
  }
}

KernelSpecialization::KernelSpecialization()
  : Values_(VS_SPEC_ID_COUNT, 0u)
  , Set_(VS_SPEC_ID_COUNT, false)
{
}

KernelSpecialization& KernelSpecialization::Set(uint32_t id, uint32_t value)
{
  if (id >= VS_SPEC_ID_COUNT || this->Set_[id])
  {
    throw std::logic_error("kernel specialization constant " + std::to_string(id) +
      (id >= VS_SPEC_ID_COUNT ? " is out of range" : " is set twice"));
  }
  this->Values_[id] = value;
  this->Set_[id] = true;
  return *this;
}

std::vector<uint32_t> KernelSpecialization::Values() const
{
  for (uint32_t id = 0; id < VS_SPEC_ID_COUNT; ++id)
  {
    if (!this->Set_[id])
    {
      throw std::logic_error("kernel specialization constant " + std::to_string(id) + " was not set");
    }
  }
  return this->Values_;
}
}
