// The one table of the kernel's options (vsKernelOptions, issue 34 item 6): every specialization
// constant set by id, none twice, none left unset; words and API names unique and found again;
// the spec ids named in kernel_spec.h are exactly those the kernel declares.
#include "sampling/kernel_spec.h"
#include "sampling/mc_params.h"
#include "sampling/strategies.h"
#include "vsError.h"
#include "vsKernelOptions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

using namespace vs;

TEST(KernelOptions, SpecializationRefusesAnIdUnsetOrSetTwice)
{
  KernelSpecialization spec;
  for (uint32_t id = 0; id + 1 < shared::VS_SPEC_ID_COUNT; ++id)
  {
    spec.Set(id, id * 10u);
  }
  EXPECT_THROW(spec.Values(), std::logic_error); // the last id unset
  spec.Set(shared::VS_SPEC_ID_COUNT - 1, 7u);
  const std::vector<uint32_t> v = spec.Values();
  ASSERT_EQ(v.size(), size_t(shared::VS_SPEC_ID_COUNT));
  EXPECT_EQ(v[shared::VS_SPEC_ID_CAMERA], shared::VS_SPEC_ID_CAMERA * 10u);
  EXPECT_EQ(v.back(), 7u);
  EXPECT_THROW(spec.Set(0, 1u), std::logic_error);
  EXPECT_THROW(spec.Set(shared::VS_SPEC_ID_COUNT, 1u), std::logic_error);
}

TEST(KernelOptions, WordsAndNamesAreUniqueAndFoundAgain)
{
  std::set<int> specIds;
  for (auto id : { KernelOptionId::Strategy, KernelOptionId::CellMode, KernelOptionId::CameraEstimator,
         KernelOptionId::Sampler, KernelOptionId::ControlExtinction, KernelOptionId::Transmittance,
         KernelOptionId::Mis })
  {
    const KernelOption& option = GetKernelOption(id);
    if (option.SpecializationId >= 0)
    {
      EXPECT_LT(option.SpecializationId, int(shared::VS_SPEC_ID_COUNT)) << option.Setting;
      EXPECT_TRUE(specIds.insert(option.SpecializationId).second) << option.Setting << " shares its id";
    }
    std::set<std::string> words, names;
    for (const auto& v : option.Values)
    {
      EXPECT_TRUE(words.insert(v.Word).second) << option.Setting << ": " << v.Word;
      EXPECT_TRUE(names.insert(v.ApiName).second) << option.Setting << ": " << v.ApiName;
      EXPECT_EQ(KernelOptionValueOf(id, v.Word), int(v.Value));
      EXPECT_EQ(KernelOptionValueOf(id, v.ApiName), int(v.Value));
      EXPECT_STREQ(KernelOptionWord(id, v.Value), v.Word);
      EXPECT_STREQ(KernelOptionApiName(id, v.Value), v.ApiName);
    }
    EXPECT_EQ(KernelOptionValueOf(id, "no-such-word"), -1);
    EXPECT_STREQ(KernelOptionApiName(id, 1000u), "Unknown");
  }
  EXPECT_EQ(KernelOptionValueOf(KernelOptionId::Strategy, "Two_Step"), int(shared::VS_STRATEGY_TWO_STEP));
}

// The GLSL declares one constant per id of kernel_spec.h, each by its name, no literal ids.
TEST(KernelOptions, TheKernelDeclaresEveryIdByName)
{
  std::ifstream in(VISSWEEP_TEST_DATA "/../../Module/render/mc_resources.glsl");
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  const std::string glsl = text.str();
  EXPECT_FALSE(std::regex_search(glsl, std::regex(R"(constant_id\s*=\s*[0-9])"))) << "a literal constant_id";
  std::ifstream hin(VISSWEEP_TEST_DATA "/../../Module/sampling/kernel_spec.h");
  std::stringstream header;
  header << hin.rdbuf();
  const std::string h = header.str();
  std::regex idName(R"(VS_CONST uint (VS_SPEC_ID_[A-Z_]+) = )");
  int declared = 0;
  for (auto it = std::sregex_iterator(h.begin(), h.end(), idName); it != std::sregex_iterator(); ++it)
  {
    const std::string name = (*it)[1];
    if (name == "VS_SPEC_ID_COUNT")
    {
      continue;
    }
    ++declared;
    EXPECT_NE(glsl.find("constant_id = " + name + ")"), std::string::npos) << name << " is not declared";
  }
  EXPECT_EQ(declared, int(shared::VS_SPEC_ID_COUNT));
}

TEST(KernelOptions, ScatteringSettingsOutOfRangeAreErrors)
{
  EXPECT_NO_THROW(CheckScatteringSettings(1, 0.0));
  EXPECT_NO_THROW(CheckScatteringSettings(shared::VS_MAX_SCATTERING_EVENTS, -0.99));
  EXPECT_THROW(CheckScatteringSettings(0, 0.0), InputError);
  EXPECT_THROW(CheckScatteringSettings(shared::VS_MAX_SCATTERING_EVENTS + 1.0, 0.0), InputError);
  EXPECT_THROW(CheckScatteringSettings(4, 1.0), InputError);
  EXPECT_THROW(CheckScatteringSettings(4, std::nan("")), InputError);
}
