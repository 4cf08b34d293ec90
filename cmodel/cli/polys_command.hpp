// `cig polys` (polys_command.cpp): the geometric processor's polygon list of one channel of one frame,
// written as a cig-polys file that `cig raster` reads back.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct PolysCommand {
  CLI::App* sub = nullptr;
  std::string scene_file, out_file;
  int frame = 0, channel = 0;
  ModelLimitArgs model_limit;
  ManagerUnitArgs manager_unit;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
