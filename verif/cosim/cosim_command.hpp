// `cig cosim` (the executable cig-cosim, cosim_main.cpp, with the Verilated RTL; `cig cosim`
// forwards to it): runs the same input through the quadtree RTL and through the kernels +
// architecture model (--processor quadtree, the default: the stream the quadtree engine runs, its
// fan split included), or a scene's polyhedra through the inverse-parameter array RTL and its
// clock-level model (--processor invparam), and reports the comparisons, the mismatches, the
// cycles of both and the simulation speed; progress on stderr (cig::Progress), the FST trace of
// the first image on request (cosim_trace.hpp).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

class CosimTrace;
class FrameJobs;

// A run's totals over its images, and its last lines (stdout), report keys and exit status, the
// same for both processors; `compared` counts what the processor compares (records or values).
struct CosimTotals {
  long long compared = 0, mismatches = 0, bad_cycles = 0;
  std::string first;  // the first mismatch ("" if none)
  void add(long long n_compared, long long n_mismatches, bool cycles_equal, const std::string& first_mismatch);
  // Prints "all: N <what> compared, M mismatches, K <images> with a cycle mismatch" (and the first
  // mismatch), sets rep[compared_key], "mismatches", "cycle_mismatches"; returns the exit status.
  int finish(nlohmann::ordered_json& rep, const char* what, const char* compared_key, const char* images) const;
};

struct CosimCommand {
  std::string input, arch, frames_text, trace_file, report_file;
  std::string processor = "quadtree";  // --processor quadtree|invparam
  int frame_k = -1, channel = -1;
  unsigned stall_seed = 1;
  int input_gaps = 0, output_stalls = 0;
  int vt_stalls = 0, word_bits = 64, pps = 64;  // invparam: VT back-pressure, the configuration (W, N_PP)
  std::string start_window = "screen";          // --start-window screen|bbox (ArchConfig::start_window)
  std::string fan_split = "on";                 // --fan-split on|off: the quadtree engine's stream
  std::string trace_cycles;                     // --trace-cycles A:B (cosim_trace.hpp)
  int trace_depth = 0;                          // --trace-depth N
  CLI::Option* frame_opt = nullptr;
  CLI::Option *trace_cycles_opt = nullptr, *trace_depth_opt = nullptr;
  // Options of one processor only (an error with the other).
  std::vector<CLI::Option*> quadtree_only, invparam_only;
  ModelLimitArgs model_limit;
  void add_options(CLI::App& app);  // the options, on cig-cosim's own command line
  int run();

 private:
  int run_quadtree();  // quadtree/cosim_quadtree.cpp
  int run_invparam();  // invparam/cosim_invparam.cpp
  // Before any work: the run's inputs and its outputs (the report, the trace) collide nowhere.
  void check_outputs(const FrameJobs& jobs, const CosimTrace& trace) const;
};

}  // namespace cig::cli
