// vsBenchOutput.h — the benchmarks' output files (--json, --plot, --csv, --contact-sheet): every path
// is checked before the run (a bad path used to be found after minutes of measuring, or never), and
// every write is checked and made under a temporary name (vsPendingFile.h): a failure is an error,
// exit status 2, never "wrote" over nothing.
#ifndef vsBenchOutput_h
#define vsBenchOutput_h

#include "vsPendingFile.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vstool
{
/** Throws std::runtime_error (naming the option) unless every given path (empty or "-": none) can be
 *  written. Call first thing in a benchmark's Run(). */
inline void CheckBenchOutputs(const std::vector<std::pair<std::string, std::string>>& outputs)
{
  for (const auto& [option, path] : outputs)
  {
    if (!path.empty() && path != "-")
    {
      CheckWritable(option, path);
    }
  }
}

/** Writes `text` to `path` whole or not at all; throws std::runtime_error naming `option`. */
inline void WriteBenchText(const std::string& option, const std::string& path, const std::string& text)
{
  PendingFile file(path);
  {
    std::ofstream out(file.Path());
    out << text;
    out.close();
    if (!out)
    {
      throw std::runtime_error(option + " " + path + ": cannot write");
    }
  }
  file.Commit();
}

/** Runs a plot script (matplotlib) that reads `json` and draws `png`; throws when it fails. */
inline void RunBenchPlot(const std::string& script, const std::string& json, const std::string& png)
{
  const std::string cmd = "/usr/bin/python3 '" + script + "' '" + json + "' '" + png + "'";
  if (std::system(cmd.c_str()) != 0)
  {
    throw std::runtime_error("--plot " + png + ": plotting failed: " + cmd);
  }
}
}

#endif
