#include "cli/commands.hpp"

#include <string>

namespace cig::cli {

void Commands::add_to(CLI::App& app) {
  app.require_subcommand(1);
  render.add_to(app);
  raster.add_to(app);
  polys.add_to(app);
  compare.add_to(app);
  sweep.add_to(app);
  arch.add_to(app);
  stress.add_to(app);
  cull.add_to(app);
  manager.add_to(app);
  wordlength.add_to(app);
  engines.add_to(app);
  import.add_to(app);
  temporal.add_to(app);
  timing.add_to(app);
  // Listed for --help; `cig cosim ...` never reaches the parser (main.cpp forwards it to cig-cosim).
  app.add_subcommand("cosim",
                     "co-simulate the quadtree RTL against the kernels and the architecture model, or with "
                     "--processor invparam the inverse-parameter array RTL against its model (runs cig-cosim; "
                     "`cig cosim --help` for its options)")
      ->allow_extras();
}

void Commands::check_command_name(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  try {
    app.get_subcommand(std::string(argv[1]));
  } catch (const CLI::OptionNotFound&) {
    std::string names;
    for (const CLI::App* c : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + c->get_name();
    throw InputError("", "", "unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")");
  }
}

int Commands::run() {
  if (*render.sub) return render.run();
  if (*raster.sub) return raster.run();
  if (*polys.sub) return polys.run();
  if (*compare.sub) return compare.run();
  if (*sweep.sub) return sweep.run();
  if (*arch.sub) return arch.run();
  if (*stress.sub) return stress.run();
  if (*cull.sub) return cull.run();
  if (*manager.sub) return manager.run();
  if (*wordlength.sub) return wordlength.run();
  if (*engines.sub) return engines.run();
  if (*import.sub) return import.run();
  if (*temporal.sub) return temporal.run();
  if (*timing.sub) return timing.run();
  return 0;
}

}  // namespace cig::cli
