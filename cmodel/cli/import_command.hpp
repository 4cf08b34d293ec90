// `cig import flightgear ICAO` (import_command.cpp): a scene from FlightGear's data for an airport
// (import/flightgear_import.hpp), written to --out with its import statistics printed and, with
// --report, written as JSON.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct ImportCommand {
  CLI::App* sub = nullptr;
  CLI::App* flightgear = nullptr;
  std::string icao, out_file, report_file, fg_root, approach, time = "dusk";
  double radius_km = 20, cell_m = 2000, from_nm = 10, to_nm = 0, speed_kt = 140, rate = 50, glide_slope = 3;
  double max_model_seconds = 60;
  int raster = 512;
  bool no_objects = false;
  void add_to(CLI::App& app);
  int run();
};

// The data folder `cig import flightgear` reads by default: $CIG_FLIGHTGEAR_ROOT, else the cache
// tools/fetch_flightgear.sh fills ($CIG_FLIGHTGEAR_CACHE or ~/.cache/cig/flightgear, then fgdata),
// else Debian's installed package (/usr/share/games/flightgear).
std::string default_flightgear_root();

}  // namespace cig::cli
