// vsTestPaths.h — where the unit tests find their data: the source tree's paths compiled in, or
// the environment's VISSWEEP_TEST_DATA_DIR (Data/: envmaps/, smoke/) and VISSWEEP_TEST_CH2 (Colin27),
// with which the device bundle (scripts/device-bundle.sh) runs the tests away from the source tree.
#ifndef vsTestPaths_h
#define vsTestPaths_h

#include <cstdlib>
#include <string>

namespace vstest
{
inline std::string FromEnvironment(const char* name, const char* compiledIn)
{
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : std::string(compiledIn);
}

/** The repository's Data/ folder (envmaps/, smoke/). */
inline std::string DataDir()
{
  return FromEnvironment("VISSWEEP_TEST_DATA_DIR", VISSWEEP_DATA);
}

/** Colin27 (mricron-data's ch2.nii.gz). */
inline std::string Ch2Path()
{
  return FromEnvironment("VISSWEEP_TEST_CH2", VISSWEEP_CH2);
}
}

#endif
