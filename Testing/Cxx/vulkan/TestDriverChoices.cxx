// The choices made for a driver come from what the device reports (issue 37): which features the
// kernels need (named when missing), whether the driver has a loop limiter (llvmpipe's, keyed on
// its driver id), and the width of the row kernels (the subgroup size).
#include "vsContext.h"

#include <gtest/gtest.h>

#include <vulkan/vulkan.h>

namespace
{
// A device as a GPU driver reports it: Vulkan 1.3, subgroups of 32 with every operation the kernels use.
vs::DeviceInfo Gpu()
{
  vs::DeviceInfo info;
  info.Name = "a GPU";
  info.ApiVersion = "1.3.0";
  info.ApiVersionNumber = VK_MAKE_API_VERSION(0, 1, 3, 0);
  info.DriverId = VK_DRIVER_ID_NVIDIA_PROPRIETARY;
  info.SubgroupSize = 32;
  info.SubgroupStages = VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  info.SubgroupOperations = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_VOTE_BIT |
    VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_SHUFFLE_BIT;
  return info;
}
}

TEST(DriverChoices, TheDefaultDeviceHasWhatTheKernelsNeed)
{
  const vs::DeviceInfo& info = vs::Context::Default()->Info();
  EXPECT_EQ(info.MissingFeatures(), "");
  EXPECT_NE(info.DriverId, 0u);
  // lavapipe here: its loop limiter is known from its driver id, not from its name.
  if (info.DriverId == VK_DRIVER_ID_MESA_LLVMPIPE)
  {
    EXPECT_TRUE(info.LoopLimited());
  }
  EXPECT_EQ(info.RowWorkgroupWidth(), std::min(64u, std::max(8u, info.SubgroupSize)));
  EXPECT_NE(info.Describe().find("driver loop limiter"), std::string::npos);
}

TEST(DriverChoices, MissingFeaturesAreNamed)
{
  EXPECT_EQ(Gpu().MissingFeatures(), "");
  vs::DeviceInfo old = Gpu();
  old.ApiVersion = "1.0.68";
  old.ApiVersionNumber = VK_MAKE_API_VERSION(0, 1, 0, 68);
  EXPECT_EQ(old.MissingFeatures(), "Vulkan 1.1 (the device reports 1.0.68)");
  vs::DeviceInfo noArithmetic = Gpu();
  noArithmetic.SubgroupOperations &= ~uint32_t(VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_VOTE_BIT);
  EXPECT_EQ(noArithmetic.MissingFeatures(),
    "subgroup vote operations in compute shaders, subgroup arithmetic operations in compute shaders");
  vs::DeviceInfo fragmentOnly = Gpu();
  fragmentOnly.SubgroupStages = VK_SHADER_STAGE_FRAGMENT_BIT;
  EXPECT_EQ(fragmentOnly.MissingFeatures(), "subgroup operations in compute shaders");
  EXPECT_NE(fragmentOnly.Describe().find("MISSING for VisSweep:    subgroup operations in compute shaders"),
    std::string::npos);
}

TEST(DriverChoices, OnlyLlvmpipeHasALoopLimiter)
{
  vs::DeviceInfo gpu = Gpu();
  EXPECT_FALSE(gpu.LoopLimited());
  vs::DeviceInfo lavapipe = Gpu();
  lavapipe.DriverId = VK_DRIVER_ID_MESA_LLVMPIPE;
  lavapipe.SubgroupSize = 8;
  EXPECT_TRUE(lavapipe.LoopLimited());
  // A driver that does not say which it is keeps the budget (it costs little where not needed).
  vs::DeviceInfo unknown = Gpu();
  unknown.DriverId = 0;
  EXPECT_TRUE(unknown.LoopLimited());
}

TEST(DriverChoices, RowWorkgroupsAreOneSubgroupWide)
{
  vs::DeviceInfo info = Gpu();
  EXPECT_EQ(info.RowWorkgroupWidth(), 32u); // NVIDIA
  info.SubgroupSize = 8;                    // lavapipe on AVX2
  EXPECT_EQ(info.RowWorkgroupWidth(), 8u);
  info.SubgroupSize = 64;                   // AMD wave64
  EXPECT_EQ(info.RowWorkgroupWidth(), 64u);
  info.SubgroupSize = 4;                    // lavapipe on SSE: still a workgroup of 8
  EXPECT_EQ(info.RowWorkgroupWidth(), 8u);
  info.SubgroupSize = 128;
  EXPECT_EQ(info.RowWorkgroupWidth(), 64u);
}
