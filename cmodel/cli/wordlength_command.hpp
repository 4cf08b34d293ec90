// `cig wordlength` (wordlength_command.cpp): seed 002's word-length claims tested
// (cmodel/studies/word_length_study.hpp): per range, method (a inverse parameter, b Z-buffer,
// c inverse Z-buffer, d exact Z rounded) and word length W, the samples with a wrong visible face,
// with a depth error over 1 mm, the largest depth error; the smallest clean W beside the seed's.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cli/cli_common.hpp"

namespace cig::cli {

struct WordLengthCommand {
  CLI::App* sub = nullptr;
  std::string ranges_text = "10000,100000", bits_text = "40:72", plot_file, report_file;
  int views = 16, lattice = 256;
  unsigned long long seed = 2;
  void add_to(CLI::App& app);
  int run();
};

}  // namespace cig::cli
