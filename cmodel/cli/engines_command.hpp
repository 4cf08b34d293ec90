// `cig engines` (engines_command.cpp): every raster engine, what it models and draws, its settings
// (--engine-opt keys with their values and defaults, and the shorthands that set them) and what it
// can drop, from the engine registry's tables, the ones the engines' parsers use.
#pragma once

#include <CLI/CLI.hpp>

namespace cig::cli {

struct EnginesCommand {
  CLI::App* sub = nullptr;
  bool json = false;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
