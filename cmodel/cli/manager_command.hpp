// `cig manager` (manager_command.cpp): the scene manager of seed 000 as a counted model
// (cmodel/studies/operation_counts.hpp). `--capacity`: for each number of occluded objects and each
// object shape (Npl planes of Np points), the largest number of objects one frame holds at a clock,
// a frame rate and a cost per operation kind; then whether the seed's "about 1000 objects, 60 of
// them occluded, at 100 MHz and 25 Hz" holds, and under which assumptions.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct ManagerCommand {
  CLI::App* sub = nullptr;
  bool capacity = false;
  double clock_ns = 10, rate_hz = 25;  // the seed's 100 MHz
  std::string cost_text, schedule = "sequence", pairs = "neighbours";
  std::vector<long long> occluded{0, 20, 60, 100, 200}, planes, points;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
