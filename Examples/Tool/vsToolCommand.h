// vsToolCommand.h — how every `vissweep` subcommand runs: its function returns the exit
// status, and any exception becomes one line "vissweep <name>: error: <what>" on stderr
// and exit status 2 (CLI11 carries the status out of the parse).
#ifndef vsToolCommand_h
#define vsToolCommand_h

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#ifndef VISSWEEP_EXAMPLE_SCENES
#define VISSWEEP_EXAMPLE_SCENES ""
#endif

namespace vstool
{
/** A scene of Examples/Scenes (the benchmarks' defaults), by file name. */
inline std::string ExampleScene(const std::string& name)
{
  return std::string(VISSWEEP_EXAMPLE_SCENES) + "/" + name;
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
