// `cig arch` (arch_command.cpp): the architecture analysis of seed 004 (eq. 2-10), measured with
// the project's setup and PE kernels and its cycle model (cmodel/studies/arch_analysis.hpp);
// with --processor invparam, seed 002's frame time and faces/s (arch_invparam.cpp).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"
#include "invparam/invparam_engine.hpp"

namespace cig::cli {

struct ArchCommand {
  CLI::App* sub = nullptr;
  int raster_log2 = 9, raster = 0, perf_log2 = 10;
  std::vector<double> aspects{1, 5, 10}, areas{1, 10, 100, 1000};
  std::vector<std::string> archs;
  int positions = 256, stream = 1024, fifo = 2, threads = 0;
  double perf_aspect = 5;
  int perf_rotation = 45;
  unsigned seed = 1;
  std::string table = "all", report_file;
  // --processor invparam (seed 002): m, n, P, N_n, t_t and the mean object widths (columns).
  std::string processor = "quadtree";
  int faces_per_object = 6, columns = 512, pps = 512;
  std::vector<long long> objects{100, 1000, 10000, 100000};
  std::vector<double> widths{10, 50, 100, 250, 500};
  double clock_ns = kInvparamDefaultClockNs;
  void add_to(CLI::App& app);
  int run();

 private:
  void check_options();
  void check_invparam_options();
  int run_invparam();
};

}  // namespace cig::cli
