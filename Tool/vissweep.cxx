// vissweep — the command-line tool: `vissweep info` prints the Vulkan device and its limits.
#include "vsBenchConvergence.h"
#include "vsBenchFrames.h"
#include "vsBenchStress.h"
#include "vsBenchOverhead.h"
#include "vsBenchAnimation.h"
#include "vsBenchLightVolume.h"
#include "vsBenchPreview.h"
#include "vsBenchDenoise.h"
#include "vsBenchKernels.h"
#include "vsBenchSweeps.h"
#include "vsRenderCommand.h"
#include "vsContext.h"
#include "vsError.h"
#include "vsToolCommand.h"

#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv)
{
  CLI::App app{ "VisSweep: physically based volume rendering with visibility sweeps (Vulkan compute)" };
  app.set_version_flag("--version", std::string("vissweep ") + VISSWEEP_VERSION);
  app.require_subcommand(1);
  bool all = false;
  auto* info = app.add_subcommand("info", "print the Vulkan device VisSweep uses and the limits that matter");
  info->add_flag("--all", all, "list every device the loader reports");
  auto* bench = app.add_subcommand("bench", "benchmarks that print what they measure");
  bench->require_subcommand(1);
  vstool::AddBenchSweeps(*bench);
  vstool::AddBenchOverhead(*bench);
  vstool::AddBenchFrames(*bench);
  vstool::AddBenchConvergence(*bench);
  vstool::AddBenchStress(*bench);
  vstool::AddBenchAnimation(*bench);
  vstool::AddBenchLightVolume(*bench);
  vstool::AddBenchPreview(*bench);
  vstool::AddBenchDenoise(*bench);
  vstool::AddBenchKernels(*bench);
  vstool::AddRender(app);
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::RuntimeError& e)
  {
    return e.get_exit_code(); // a subcommand ran and returned its status
  }
  catch (const CLI::ParseError& e)
  {
    // --help and --version exit 0; a command line CLI11 rejects exits 2, like every other error.
    return app.exit(e) == 0 ? 0 : 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "vissweep: " << e.what() << std::endl;
    return 2;
  }

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
      std::cout << "vissweep " << VISSWEEP_VERSION << ", data in " << vstool::DataRoot().string() << "\n";
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
