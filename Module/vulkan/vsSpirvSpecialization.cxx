#include "vsSpirvSpecialization.h"

#include <spirv-tools/optimizer.hpp>

#include <unordered_map>

namespace vs
{
std::vector<uint32_t> SpecializeSpirv(
  const uint32_t* spirv, size_t bytes, const std::vector<uint32_t>& constants, std::string& problem)
{
  problem.clear();
  if (!spirv || bytes == 0 || bytes % sizeof(uint32_t) != 0)
  {
    problem = "the module is not a whole number of 32-bit words";
    return {};
  }
  std::unordered_map<uint32_t, std::vector<uint32_t>> values;
  for (uint32_t id = 0; id < constants.size(); ++id)
  {
    values[id] = { constants[id] };
  }
  spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_1);
  optimizer.SetMessageConsumer(
    [&problem](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
      if (level <= SPV_MSG_ERROR && problem.empty())
      {
        problem = message ? message : "the optimizer failed";
      }
    });
  // The constants' values, frozen into ordinary constants; the expressions of them folded
  // (VS_SPEC_PATH == 0u); constants propagated into the branches they decide; those branches and
  // the functions only they called removed. No inlining (the driver does that, on what is left),
  // no merging of returns, no arithmetic simplification: the code that runs is the code written.
  optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values))
    .RegisterPass(spvtools::CreateFreezeSpecConstantValuePass())
    .RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass())
    .RegisterPass(spvtools::CreateUnifyConstantPass())
    .RegisterPass(spvtools::CreateCCPPass())
    .RegisterPass(spvtools::CreateDeadBranchElimPass())
    .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
    .RegisterPass(spvtools::CreateAggressiveDCEPass())
    .RegisterPass(spvtools::CreateDeadBranchElimPass())
    .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
  spvtools::OptimizerOptions options;
  options.set_run_validator(false); // the module was validated when glslang built it
  std::vector<uint32_t> out;
  try
  {
    if (!optimizer.Run(spirv, bytes / sizeof(uint32_t), &out, options) || out.empty())
    {
      if (problem.empty())
      {
        problem = "the optimizer failed";
      }
      return {};
    }
  }
  catch (const std::exception& e)
  {
    problem = e.what();
    return {};
  }
  return out;
}
}
