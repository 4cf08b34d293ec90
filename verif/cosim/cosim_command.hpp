// `cig cosim` (the executable cig-cosim, cosim_main.cpp, with the Verilated RTL; `cig cosim`
// forwards to it): runs the same input through the quadtree RTL and through the kernels +
// architecture model (--processor quadtree, the default), or a scene's polyhedra through the
// inverse-parameter array RTL and its clock-level model (--processor invparam), and reports the
// comparisons, the mismatches, the cycles of both and the simulation speed.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct CosimCommand {
  std::string input, arch, frames_text, trace_file, report_file;
  std::string processor = "quadtree";  // --processor quadtree|invparam
  int frame_k = -1, channel = -1;
  unsigned stall_seed = 1;
  int input_gaps = 0, output_stalls = 0;
  int vt_stalls = 0, word_bits = 64, pps = 64;  // invparam: VT back-pressure, the configuration (W, N_PP)
  std::string start_window = "screen";          // --start-window screen|bbox (ArchConfig::start_window)
  CLI::Option* frame_opt = nullptr;
  // Options of one processor only (an error with the other).
  std::vector<CLI::Option*> quadtree_only, invparam_only;
  ModelLimitArgs model_limit;
  void add_options(CLI::App& app);  // the options, on cig-cosim's own command line
  int run();

 private:
  int run_quadtree();
  int run_invparam();  // cosim_invparam.cpp
};

}  // namespace cig::cli
