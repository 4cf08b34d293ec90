// cig: command-line driver of the C model. One struct per command, each in its own file
// (render_, raster_, polys_, compare_, sweep_, arch_command); `cig cosim` runs the co-simulation
// executable. Input errors print "cig: error: FILE: PLACE: RULE" and exit with status 2 before any
// output file is written (cli_main.hpp).
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/cli_main.hpp"
#include "cli/commands.hpp"
#include "common/provenance.hpp"

namespace cig {
namespace {

// `cig cosim ...` runs the co-simulation executable cig-cosim from cig's own folder (built with the
// RTL, -DCIG_WITH_RTL=ON): the product binary links no Verilated model. Returns only on failure.
int forward_to_cosim(int argc, char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path cosim = (ec ? std::filesystem::path(argv[0]) : self).parent_path() / "cig-cosim";
  if (!std::filesystem::exists(cosim))
    throw InputError("", "cosim",
                     "this cig has no co-simulation: " + cosim.string() +
                         " is missing (build with -DCIG_WITH_RTL=ON, which needs Verilator)");
  // argv[0] stays the name the user typed, so cig-cosim records "that/cig cosim ..." in its reports.
  std::vector<char*> args{argv[0]};
  for (int k = 2; k < argc; ++k) args.push_back(argv[k]);
  args.push_back(nullptr);
  ::execv(cosim.c_str(), args.data());
  throw std::runtime_error("cannot run " + cosim.string());
}

int run(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "cosim") return forward_to_cosim(argc, argv);
  CLI::App app{"cig: computer image generator C model (float reference, bit-accurate engines)"};
  app.name("cig");
  app.set_version_flag("--version", version_line("cig"), "print the version and the git commit it was built from");
  cli::Commands commands;
  commands.add_to(app);
  if (argc < 2) {  // a bare `cig`: what it can do, as an error (no command, no work)
    std::cerr << app.help() << "cig: error: no command given (`cig COMMAND --help` for a command's options)\n";
    return 2;
  }
  cli::Commands::check_command_name(app, argc, argv);
  int status = 0;
  if (!cli::parse_command_line(app, argc, argv, status)) return status;
  return commands.run();
}

}  // namespace
}  // namespace cig

int main(int argc, char** argv) {
  return cig::cli::guarded_main("cig", argc, argv, [&] { return cig::run(argc, argv); });
}
