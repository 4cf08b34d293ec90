// `cig timing` (timing_command.cpp): the whole machine in time over a run of frames. Each frame
// goes through stages A and B and the engine as `cig render` does (no image is written); each
// stage's modelled time (studies/frame_timing.hpp) per frame, the limiting stage, the frame time
// and the transport delay; then p50 / p99 / max and the frames over budget; a plot and a report.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct TimingCommand {
  CLI::App* sub = nullptr;
  std::string scene_file, frames_text, report_file, plot_file;
  int channel = -1, threads = 1, pipelines = 1;
  double budget_ms = 0;  // 0: not given (the default budget, no governor)
  bool quiet = false;
  EngineArgs engine;
  ModelLimitArgs model_limit;
  ManagerUnitArgs manager_unit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
