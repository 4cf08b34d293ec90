// `cig sweep` (sweep_command.cpp): run time against image error for the values of one engine
// option.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct SweepCommand {
  CLI::App* sub = nullptr;
  std::string input, vary, report_file, frames_text, reference = "float";
  int frame_k = -1, channel = -1, repeat = 3;
  CLI::Option* frame_opt = nullptr;
  EngineArgs engine;
  ModelLimitArgs model_limit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
