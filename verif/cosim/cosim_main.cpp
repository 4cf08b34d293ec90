// cig-cosim: the co-simulation front end (`cig cosim` forwards here). A separate executable so
// that the product binary `cig` links no Verilated model and builds without Verilator.
#include <CLI/CLI.hpp>

#include "cli/cli_main.hpp"
#include "cosim_command.hpp"

int main(int argc, char** argv) {
  return cig::cli::guarded_main("cig", [&] {
    CLI::App app{
        "cig cosim: co-simulate the quadtree RTL against the kernels and the architecture model, or the inverse-parameter array RTL against its clock-level model (--processor invparam)"};
    app.name("cig cosim");
    cig::cli::CosimCommand cosim;
    cosim.add_options(app);
    int status = 0;
    if (!cig::cli::parse_command_line(app, argc, argv, status)) return status;
    return cosim.run();
  });
}
