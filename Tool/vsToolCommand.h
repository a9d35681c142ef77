// vsToolCommand.h — how every `vissweep` subcommand runs: its function returns the exit
// status, and any exception becomes one line "vissweep <name>: error: <what>" on stderr
// and exit status 2 (CLI11 carries the status out of the parse).
#ifndef vsToolCommand_h
#define vsToolCommand_h

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>

namespace vstool
{
/** The tool's data (example scenes, benchmark scenes and plot scripts, environment maps):
 *  <folder of the executable>/../share/vissweep, in the build tree (links to the sources) as
 *  in an install. No source-tree path is compiled in, so an installed tool works where it lands. */
inline std::filesystem::path DataRoot()
{
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path("share/vissweep") : exe.parent_path().parent_path() / "share" / "vissweep";
}

/** A scene of Examples/Scenes (the benchmarks' defaults), by file name. */
inline std::string ExampleScene(const std::string& name)
{
  return (DataRoot() / "Examples" / "Scenes" / name).string();
}

/** The Benchmarks folder (benchmark scenes, plot scripts, the references' default cache). */
inline std::string BenchmarksDir()
{
  return (DataRoot() / "Benchmarks").string();
}

/** A validator for options of floating-point numbers: CLI11 parses "nan", "inf" and "1e999" as
 *  doubles, and its PositiveNumber lets NaN and +inf through (NaN fails no comparison), so a
 *  --time-budget of nan was accepted and ignored. Checked before the other validators. */
inline CLI::Validator FiniteNumber()
{
  return CLI::Validator(
    [](std::string& text) -> std::string {
      const char* begin = text.c_str();
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end != begin && !std::isfinite(v))
      {
        return "Value " + text + " is not a finite number";
      }
      return std::string();
    },
    "FINITE", "FINITE");
}

template <class Run>
void SetCommandRun(CLI::App* command, Run run)
{
  const std::string name = command->get_parent() && command->get_parent()->get_parent()
    ? command->get_parent()->get_name() + " " + command->get_name()
    : command->get_name();
  command->callback([name, run]() {
    int status = 2;
    try
    {
      status = run();
    }
    catch (const std::exception& e)
    {
      std::fprintf(stderr, "vissweep %s: error: %s\n", name.c_str(), e.what());
    }
    throw CLI::RuntimeError(status);
  });
}
}

#endif
