// Every cig command (one struct and file each), registered on one CLI11 application: main.cpp
// parses and runs them; the option-parser fuzz target (verif/fuzz) parses them.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/arch_command.hpp"
#include "cli/compare_command.hpp"
#include "cli/cull_command.hpp"
#include "cli/engines_command.hpp"
#include "cli/import_command.hpp"
#include "cli/manager_command.hpp"
#include "cli/polys_command.hpp"
#include "cli/raster_command.hpp"
#include "cli/render_command.hpp"
#include "cli/stress_command.hpp"
#include "cli/sweep_command.hpp"
#include "cli/temporal_command.hpp"
#include "cli/timing_command.hpp"
#include "cli/wordlength_command.hpp"

namespace cig::cli {

struct Commands {
  RenderCommand render;
  RasterCommand raster;
  PolysCommand polys;
  CompareCommand compare;
  SweepCommand sweep;
  ArchCommand arch;
  StressCommand stress;
  CullCommand cull;
  ManagerCommand manager;
  WordLengthCommand wordlength;
  EnginesCommand engines;
  ImportCommand import;
  TemporalCommand temporal;
  TimingCommand timing;

  void add_to(CLI::App& app);
  // Throws InputError naming the commands when argv[1] names none (instead of CLI11's "A
  // subcommand is required").
  static void check_command_name(const CLI::App& app, int argc, const char* const* argv);
  int run();  // the parsed command
};

}  // namespace cig::cli
