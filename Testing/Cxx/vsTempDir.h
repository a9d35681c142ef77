// A temporary folder for one test, removed with everything in it when the test ends. Named by the
// test's suite and name and the run's random seed, so tests running side by side (ctest -j) never
// share one.
#ifndef vsTempDir_h
#define vsTempDir_h

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace vstest
{
struct TempDir
{
  std::filesystem::path Path;
  TempDir()
  {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    Path = std::filesystem::temp_directory_path() /
      ("vissweep_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
        test->test_suite_name() + "_" + test->name());
    std::filesystem::create_directories(Path);
  }
  ~TempDir()
  {
    std::error_code ec;
    std::filesystem::remove_all(Path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string File(const std::string& name) const { return (Path / name).string(); }
};
}

#endif
