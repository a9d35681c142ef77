// vissweep — the command-line tool: `vissweep info` prints the Vulkan device and its limits.
#include "vsContext.h"
#include "vsError.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv)
{
  CLI::App app{ "VisSweep: physically based volume rendering with visibility sweeps (Vulkan compute)" };
  app.require_subcommand(1);
  bool all = false;
  auto* info = app.add_subcommand("info", "print the Vulkan device VisSweep uses and the limits that matter");
  info->add_flag("--all", all, "list every device the loader reports");
  CLI11_PARSE(app, argc, argv);

  try
  {
    if (*info)
    {
      if (all)
      {
        for (const auto& d : vs::Context::ListDevices())
        {
          std::cout << d.Describe();
        }
      }
      auto ctx = vs::Context::Default();
      std::cout << "VisSweep computes on:\n" << ctx->Info().Describe();
      std::cout << "  validation layers:       " << (ctx->ValidationEnabled() ? "on" : "off") << "\n";
      return 0;
    }
  }
  catch (const vs::Error& e)
  {
    std::cerr << "vissweep: " << e.what() << std::endl;
    return 2;
  }
  return 0;
}
