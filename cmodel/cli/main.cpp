// cig: command-line driver of the C model. One struct per command, each in its own file
// (render_, raster_, polys_, compare_, sweep_, arch_command); `cig cosim` runs the co-simulation
// executable. Input errors print "cig: error: FILE: PLACE: RULE" and exit with status 2 before any
// output file is written (cli_main.hpp).
#include <unistd.h>

#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/arch_command.hpp"
#include "cli/cli_main.hpp"
#include "cli/compare_command.hpp"
#include "cli/polys_command.hpp"
#include "cli/raster_command.hpp"
#include "cli/render_command.hpp"
#include "cli/sweep_command.hpp"

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
  std::vector<char*> args{const_cast<char*>(cosim.c_str())};
  for (int k = 2; k < argc; ++k) args.push_back(argv[k]);
  args.push_back(nullptr);
  ::execv(cosim.c_str(), args.data());
  throw std::runtime_error("cannot run " + cosim.string());
}

int run(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "cosim") return forward_to_cosim(argc, argv);
  CLI::App app{"cig: computer image generator C model (float reference, bit-accurate engines)"};
  app.require_subcommand(1);
  cli::RenderCommand render;
  cli::RasterCommand raster;
  cli::PolysCommand polys;
  cli::CompareCommand compare;
  cli::SweepCommand sweep;
  cli::ArchCommand arch;
  render.add_to(app);
  raster.add_to(app);
  polys.add_to(app);
  compare.add_to(app);
  sweep.add_to(app);
  arch.add_to(app);
  // Listed for --help; `cig cosim ...` never reaches the parser (forward_to_cosim).
  app.add_subcommand("cosim",
                     "co-simulate the quadtree RTL against the kernels and the architecture model (runs cig-cosim; "
                     "`cig cosim --help` for its options)")
      ->allow_extras();

  // A first word that names no command is answered with the commands, not with CLI11's "A
  // subcommand is required".
  if (argc >= 2 && argv[1][0] != '-') {
    try {
      app.get_subcommand(std::string(argv[1]));
    } catch (const CLI::OptionNotFound&) {
      std::string names;
      for (const CLI::App* c : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + c->get_name();
      throw InputError("", "", "unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")");
    }
  }
  int status = 0;
  if (!cli::parse_command_line(app, argc, argv, status)) return status;
  if (*render.sub) return render.run();
  if (*raster.sub) return raster.run();
  if (*polys.sub) return polys.run();
  if (*compare.sub) return compare.run();
  if (*sweep.sub) return sweep.run();
  if (*arch.sub) return arch.run();
  return 0;
}

}  // namespace
}  // namespace cig

int main(int argc, char** argv) {
  return cig::cli::guarded_main("cig", [&] { return cig::run(argc, argv); });
}
