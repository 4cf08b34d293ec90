// libFuzzer target: cig's option parser. The input is a command line, one argument per line (at
// most 24 arguments); it is parsed with every command registered (cmodel/cli/commands.hpp) and
// the chosen command's engine options validated. Nothing runs: a fuzzer must not write files.
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_main.hpp"
#include "cli/commands.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return cig::fuzz::run_input(data, size, [](const std::string& text) {
    std::vector<std::string> words{"cig"};
    std::istringstream lines(text);
    for (std::string w; std::getline(lines, w) && words.size() < 25;) words.push_back(w);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    if (words.size() >= 2 && words[1] == "cosim") return;  // forwarded to another program
    CLI::App app{"cig"};
    cig::cli::Commands commands;
    commands.add_to(app);
    cig::cli::Commands::check_command_name(app, int(argv.size()), argv.data());
    std::ostringstream quiet;  // --help output
    int status = 0;
    auto* saved = std::cout.rdbuf(quiet.rdbuf());
    try {
      const bool parsed = cig::cli::parse_command_line(app, int(argv.size()), argv.data(), status);
      std::cout.rdbuf(saved);
      if (!parsed) return;
    } catch (...) {
      std::cout.rdbuf(saved);
      throw;
    }
    if (*commands.render.sub) commands.render.engine.options();
    if (*commands.raster.sub) commands.raster.engine.options();
    if (*commands.compare.sub) commands.compare.engine.options();
    if (*commands.sweep.sub) commands.sweep.engine.options();
  });
}
