// vsFuzzUtilities.h — helpers shared by the libFuzzer targets in Testing/Fuzz.
#ifndef vsFuzzUtilities_h
#define vsFuzzUtilities_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace vsfuzz
{
/* A per-process scratch file (the readers take file names): <tmp>/vissweep_fuzz_<pid><ext>,
 * rewritten for every input and removed at exit. */
inline const std::string& ScratchFile(const char* ext)
{
  static const std::string path = [ext] {
    std::string p = (std::filesystem::temp_directory_path() /
      ("vissweep_fuzz_" + std::to_string(::getpid()) + ext)).string();
    static std::string copy;
    copy = p;
    std::atexit([] { std::remove(copy.c_str()); });
    return p;
  }();
  return path;
}

inline void WriteFile(const std::string& path, const uint8_t* data, size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out)
  {
    std::fprintf(stderr, "fuzz harness: cannot write %s\n", path.c_str());
    std::abort();
  }
}

/* A broken invariant: print it and abort, so libFuzzer saves the input as a crash. */
[[noreturn]] inline void Fail(const std::string& what)
{
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what.c_str());
  std::abort();
}
}

#endif
