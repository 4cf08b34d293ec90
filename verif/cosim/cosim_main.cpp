// cig-cosim: the co-simulation front end (`cig cosim` forwards here). A separate executable so
// that the product binary `cig` links no Verilated model and builds without Verilator.
#include <filesystem>

#include <CLI/CLI.hpp>

#include "cli/cli_main.hpp"
#include "cosim_command.hpp"

int main(int argc, char** argv) {
  return cig::cli::guarded_main("cig", argc, argv, [&] {
    CLI::App app{
        "cig cosim: co-simulate the quadtree RTL against the kernels and the architecture model, or the inverse-parameter array RTL against its clock-level model (--processor invparam)"};
    app.name("cig cosim");
    // The command the user typed: `cig cosim ...` (cig runs this executable from its own folder).
    const std::string folder = std::filesystem::path(argv[0]).parent_path().string();
    cig::record_command_line(cig::shell_quote(folder.empty() ? "cig" : folder + "/cig") + " cosim", argc, argv);
    app.set_version_flag("--version", cig::version_line("cig cosim"), "print the version and the git commit");
    cig::cli::CosimCommand cosim;
    cosim.add_options(app);
    int status = 0;
    if (!cig::cli::parse_command_line(app, argc, argv, status)) return status;
    return cosim.run();
  });
}
