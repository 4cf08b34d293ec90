// `cig stress` (stress_command.cpp): writes a stress polygon list of one class (stress_lists.hpp)
// from a seed, as a cig-polys file for `cig raster`, `cig compare` and `cig sweep`.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace cig::cli {

struct StressCommand {
  CLI::App* sub = nullptr;
  std::string class_name, out_file;
  std::uint64_t seed = 1;
  int raster = 256;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
