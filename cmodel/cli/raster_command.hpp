// `cig raster` (raster_command.cpp): one polygon list through one engine, to a PNG, an id buffer and
// a report.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct RasterCommand {
  CLI::App* sub = nullptr;
  std::string polys_file, out_file = "out/raster.png", ids_file, report_file;
  EngineArgs engine;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
