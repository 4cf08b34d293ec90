// `cig compare` (compare_command.cpp): an engine's image error against the float reference, per
// frame and channel.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct CompareCommand {
  CLI::App* sub = nullptr;
  std::string input, out_dir, report_file, frames_text, reference = "float";
  int frame_k = -1, channel = -1, reference_spp = 16;
  int pipelines = 1;  // --pipelines: the engine renders the channel's rendering pipelines and merges them
  bool html = false;  // --html: DIR/index.html
  CLI::Option* frame_opt = nullptr;
  EngineArgs engine;
  ModelLimitArgs model_limit;
  ManagerUnitArgs manager_unit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
