// `cig cosim` (the executable cig-cosim, cosim_main.cpp, with the Verilated RTL; `cig cosim`
// forwards to it): runs the same input through the quadtree RTL and through the kernels +
// architecture model, and reports the records compared, the mismatches, the cycles of both and the
// simulation speed.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct CosimCommand {
  std::string input, arch, frames_text, trace_file, report_file;
  int frame_k = -1, channel = -1;
  unsigned stall_seed = 1;
  int input_gaps = 0, output_stalls = 0;
  std::string start_window = "screen";  // --start-window screen|bbox (ArchConfig::start_window)
  CLI::Option* frame_opt = nullptr;
  ModelLimitArgs model_limit;
  void add_options(CLI::App& app);  // the options, on cig-cosim's own command line
  int run();
};

}  // namespace cig::cli
