// `cig sweep` (sweep_command.cpp): run time against image error over every combination of the
// values of one or more engine options, with the Pareto frontier and an optional plot.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct SweepCommand {
  CLI::App* sub = nullptr;
  std::string input, report_file, plot_file, frames_text, reference = "float";
  std::string html_dir;  // --html DIR: DIR/index.html
  std::vector<std::string> vary;
  int frame_k = -1, channel = -1, repeat = 3, reference_spp = 16;
  CLI::Option* frame_opt = nullptr;
  EngineArgs engine;
  ModelLimitArgs model_limit;
  ManagerUnitArgs manager_unit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
