// `cig temporal` (temporal_command.cpp): temporal image quality over a run of frames of one
// channel, per engine and samples per pixel (cli/temporal_study.hpp): light-point
// scintillation, edge crawl, popping; a table, a JSON report and a plot.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct TemporalCommand {
  CLI::App* sub = nullptr;
  std::string scene_file, frames_text, engines_text = "float,segment,quadtree", spp_text = "16", edge_object;
  std::string report_file, plot_file;
  int channel = -1, pipelines = 1;
  double pop_pixels = 4;
  ModelLimitArgs model_limit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
