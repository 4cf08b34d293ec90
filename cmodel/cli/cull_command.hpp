// `cig cull` (cull_command.cpp): seed 003's culling table: for each method (line of sight, the
// hierarchical sphere-and-box test, the ground-plane projection, brute force) over the chosen
// frames and channels, the quadtree nodes visited and kept, the objects kept and visible, the time
// per channel, and the false negatives against brute force.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct CullCommand {
  CLI::App* sub = nullptr;
  CLI::Option* frame_opt = nullptr;
  std::string scene_file, frames_text, report_file;
  int frame_k = -1, repeat = 3;
  double near_distance = 2000, far_distance = 8000;
  ModelLimitArgs model_limit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
