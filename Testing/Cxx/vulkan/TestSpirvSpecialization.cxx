// The render kernel's specialization constants folded into its module before the driver compiles it
// (vsSpirvSpecialization.h): the features not selected leave the module, a module the optimizer
// cannot read is refused with a reason, pipelines say whether they were folded, and every variant of
// the kernel renders the same bits as the driver's own specialization of the whole module.
#include "vsRenderTestScene.h"
#include "vsContext.h"
#include "vsMonteCarloPass.h"
#include "vsPipeline.h"
#include "vsSceneLightParams.h"
#include "vsSpirvSpecialization.h"
#include "vsSurfaceScattering.h"

#include "sampling/kernel_spec.h"
#include "sampling/mc_params.h"
#include "sampling/strategies.h"

#include "vs_spirv_loop_probe.h"
#include "vs_spirv_mc_render_env.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

using namespace vs::shared;
using vstest::Phantom;
using vstest::RenderScene;

namespace
{
// Whether the module's debug names hold `name` (glslang names each function "name(args;").
bool Names(const std::vector<uint32_t>& words, const std::string& name)
{
  const char* begin = reinterpret_cast<const char*>(words.data());
  const char* end = begin + words.size() * sizeof(uint32_t);
  return std::search(begin, end, name.begin(), name.end()) != end;
}

std::vector<uint32_t> Words(const uint32_t* spirv, size_t bytes)
{
  return std::vector<uint32_t>(spirv, spirv + bytes / sizeof(uint32_t));
}

// The Environment kernel's constants (kernel_spec.h ids) for full transport (path 1) or single scattering.
std::vector<uint32_t> EnvironmentKernel(uint32_t path)
{
  std::vector<uint32_t> c(VS_SPEC_ID_COUNT, 0u);
  c[VS_SPEC_ID_STRATEGY] = VS_STRATEGY_ENVIRONMENT;
  c[VS_SPEC_ID_CELL_MODE] = VS_CELL_STOCHASTIC;
  c[VS_SPEC_ID_SKIP] = 1u;
  c[VS_SPEC_ID_PATH] = path;
  c[VS_SPEC_ID_LOOP_BUDGET] = VS_LOOP_BUDGET;
  return c;
}
}

// Full transport leaves single scattering's sample out of the module and single scattering the path's
// segment; the camera's reservoir estimator and the lights leave with them when not selected. What is
// left is much smaller: the driver inlines and compiles only that.
TEST(SpirvSpecialization, FoldsAwayTheFeaturesNotSelected)
{
  const std::vector<uint32_t> whole = Words(VS_SPIRV(vs_spirv_mc_render_env));
  ASSERT_TRUE(Names(whole, "render_sample(") && Names(whole, "path_segment(") && Names(whole, "camera_reservoir("));
  std::string problem;
  const std::vector<uint32_t> path =
    vs::SpecializeSpirv(whole.data(), whole.size() * sizeof(uint32_t), EnvironmentKernel(1u), problem);
  ASSERT_FALSE(path.empty()) << problem;
  EXPECT_TRUE(Names(path, "path_segment("));
  EXPECT_FALSE(Names(path, "render_sample("));
  EXPECT_FALSE(Names(path, "camera_reservoir("));
  EXPECT_LT(path.size(), whole.size() * 3 / 4);
  const std::vector<uint32_t> single =
    vs::SpecializeSpirv(whole.data(), whole.size() * sizeof(uint32_t), EnvironmentKernel(0u), problem);
  ASSERT_FALSE(single.empty()) << problem;
  EXPECT_TRUE(Names(single, "render_sample("));
  EXPECT_FALSE(Names(single, "path_segment("));
  // The SPIR-V magic number, and no specialization constant left (OpSpecConstant* are opcodes 48-52).
  for (const auto* m : { &path, &single })
  {
    EXPECT_EQ((*m)[0], 0x07230203u);
    for (size_t i = 5; i < m->size();)
    {
      const uint32_t count = (*m)[i] >> 16, opcode = (*m)[i] & 0xffffu;
      ASSERT_GT(count, 0u) << "a malformed instruction at word " << i;
      EXPECT_FALSE(opcode >= 48u && opcode <= 52u) << "a specialization constant left at word " << i;
      i += count;
    }
  }
}

// A module the optimizer cannot read gives no words and a reason (the pipeline then hands the driver
// the module as it is).
TEST(SpirvSpecialization, BadModuleSaysWhy)
{
  std::string problem;
  const std::vector<uint32_t> whole = Words(VS_SPIRV(vs_spirv_mc_render_env));
  EXPECT_TRUE(vs::SpecializeSpirv(whole.data(), whole.size() * sizeof(uint32_t) - 2, { 1u }, problem).empty());
  EXPECT_NE(problem.find("whole number"), std::string::npos) << problem;
  std::vector<uint32_t> garbage(whole.begin(), whole.begin() + 64);
  garbage[0] = 0xdeadbeefu;
  problem.clear();
  EXPECT_TRUE(vs::SpecializeSpirv(garbage.data(), garbage.size() * sizeof(uint32_t), { 1u }, problem).empty());
  EXPECT_FALSE(problem.empty());
  problem.clear();
  EXPECT_TRUE(vs::SpecializeSpirv(nullptr, 0, { 1u }, problem).empty());
  EXPECT_FALSE(problem.empty());
}

// A pipeline says whether its module was folded: with constants on a context that folds (the
// default), not without constants, not on a context made with SpecializeModules = 0.
TEST(SpirvSpecialization, PipelinesSayWhetherFolded)
{
  using B = vs::BindingType;
  auto folding = vs::Context::Default();
  ASSERT_TRUE(folding->SpecializesModules()) << "the default (VISSWEEP_SPECIALIZE unset)";
  vs::ContextOptions off;
  off.SpecializeModules = 0;
  auto driver = vs::Context::Create(off);
  EXPECT_FALSE(driver->SpecializesModules());

  const std::vector<B> probe = { B::StorageBuffer };
  vs::ComputePipeline plain(folding, VS_SPIRV(vs_spirv_loop_probe), probe, 8, "loop probe");
  EXPECT_FALSE(plain.SpecializedAhead());
  EXPECT_TRUE(plain.SpecializationProblem().empty());

  const std::vector<B> bindings = vs::MonteCarloPass::KernelBindings();
  vs::ComputePipeline folded(
    folding, VS_SPIRV(vs_spirv_mc_render_env), bindings, sizeof(uint32_t), "folded", EnvironmentKernel(1u));
  EXPECT_TRUE(folded.SpecializedAhead()) << folded.SpecializationProblem();
  vs::ComputePipeline whole(
    driver, VS_SPIRV(vs_spirv_mc_render_env), bindings, sizeof(uint32_t), "whole", EnvironmentKernel(1u));
  EXPECT_FALSE(whole.SpecializedAhead());
}

// Every kind of kernel the pass builds, folded here and by the driver, renders the same bits: the
// folding removes code that cannot run and changes none that can. One case per specialization
// constant that selects code (strategy and grid format, cell mode, camera estimator, sampler,
// transmittance estimator, control extinction, interpolation, full transport, surface lobe, lights).
TEST(SpirvSpecialization, SameImageAsTheDriversSpecialization)
{
  vs::ContextOptions off;
  off.SpecializeModules = 0;
  const auto env = vs::EnvironmentMap::Constant(32, glm::vec3(1.0f, 0.8f, 0.6f));
  RenderScene folded({ { 24, 24, 24 } }, Phantom, 1.2, glm::vec3(0.9f), env);
  RenderScene driver({ { 24, 24, 24 } }, Phantom, 1.2, glm::vec3(0.9f), env, vs::Context::Create(off));
  ASSERT_TRUE(folded.Context->SpecializesModules());
  ASSERT_FALSE(driver.Context->SpecializesModules());

  struct Case
  {
    const char* Name;
    uint32_t Strategy;
    std::function<void(VsMonteCarloParams&)> Set;
  };
  const Case cases[] = {
    { "environment, single scattering", VS_STRATEGY_ENVIRONMENT, [](VsMonteCarloParams&) {} },
    { "environment, full transport, g 0.5", VS_STRATEGY_ENVIRONMENT,
      [](VsMonteCarloParams& p) {
        p.maxEvents = 64;
        p.anisotropy = 0.5f;
      } },
    { "two-step, full transport", VS_STRATEGY_TWO_STEP, [](VsMonteCarloParams& p) { p.maxEvents = 64; } },
    { "combined, trilinear cells", VS_STRATEGY_COMBINED,
      [](VsMonteCarloParams& p) { p.cellMode = VS_CELL_TRILINEAR; } },
    { "reservoir camera, Sobol", VS_STRATEGY_ENVIRONMENT,
      [](VsMonteCarloParams& p) {
        p.cameraEstimator = VS_CAMERA_RESERVOIR;
        p.pixelSampler = VS_SAMPLER_SOBOL;
      } },
    { "ray-marched shadow rays, visibility", VS_STRATEGY_VISIBILITY,
      [](VsMonteCarloParams& p) { p.transmittance = VS_TRANSMITTANCE_RAY_MARCHING; } },
    { "control extinction, nearest", VS_STRATEGY_ENVIRONMENT,
      [](VsMonteCarloParams& p) {
        p.controlExtinction = VS_CONTROL_SHADOW | VS_CONTROL_CAMERA;
        p.volume.interpolation = VS_INTERPOLATION_NEAREST;
      } },
    { "surface lobe, a directional light, full transport", VS_STRATEGY_ENVIRONMENT,
      [](VsMonteCarloParams& p) {
        p.maxEvents = 16;
        vs::SurfaceScattering::Settings s;
        s.Shade = true;
        s.Blending = 1.0;
        s.Diffuse = 0.8;
        s.Specular = 0.3;
        s.SpecularPower = 20.0;
        vs::SurfaceScattering::Set(p, s, 1.0, 1.0, 1.0, 1.0);
        p.lightCount = 1;
        ASSERT_TRUE(vs::SceneLightParams::Make(p.lights[0], false, glm::dvec3(0.3, 0.2, -1.0), glm::dvec3(0.0), 1.5,
          glm::dvec3(1.0), 30.0, 1.0, glm::dvec3(1, 0, 0)));
      } },
  };
  for (const Case& c : cases)
  {
    auto pa = folded.Params(12, 12, -1.0f, 24.0f, c.Strategy, 4, 7u, true);
    auto pb = driver.Params(12, 12, -1.0f, 24.0f, c.Strategy, 4, 7u, true);
    c.Set(pa);
    c.Set(pb);
    const auto [meanA, varA] = folded.Render(pa, 1);
    const auto [meanB, varB] = driver.Render(pb, 1);
    EXPECT_EQ(folded.LastPipelineName, driver.LastPipelineName) << c.Name;
    ASSERT_EQ(meanA.size(), meanB.size()) << c.Name;
    size_t differing = 0;
    double lit = 0.0;
    for (size_t i = 0; i < meanA.size(); ++i)
    {
      differing += std::memcmp(&meanA[i], &meanB[i], sizeof(float)) != 0 ? 1u : 0u;
      lit += meanA[i];
    }
    EXPECT_EQ(differing, 0u) << c.Name << " (" << folded.LastPipelineName << ")";
    EXPECT_GT(lit, 0.0) << c.Name << ": an image to compare";
  }
}
