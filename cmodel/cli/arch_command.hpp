// `cig arch` (arch_command.cpp): the architecture analysis of seed 004 (eq. 2-10), measured with
// the project's setup and PE kernels and its cycle model (cmodel/quadtree/arch_analysis.hpp).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

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
  void add_to(CLI::App& app);
  int run();

 private:
  void check_options();
};

}  // namespace cig::cli
