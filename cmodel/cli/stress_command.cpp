// cig stress CLASS [--seed S] [--raster N] --out FILE.json
#include "cli/stress_command.hpp"

#include <iostream>

#include "cli/cli_common.hpp"
#include "cli/output_plan.hpp"
#include "cli/stress_lists.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

namespace cig::cli {

void StressCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("stress", "write a stress polygon list of one class (cig-polys)");
  std::string names;
  for (const auto& n : stress_class_names()) names += (names.empty() ? "" : ", ") + n;
  sub->add_option("class", class_name, "class: " + names)->required();
  sub->add_option("--seed", seed, "seed (default 1)");
  sub->add_option("--raster", raster, "raster lines of the list (default 256)");
  sub->add_option("--out", out_file, "output polygon list (JSON)")->required();
}

int StressCommand::run() {
  if (!valid_raster_size(raster))
    throw InputError("", "--raster",
                     "raster size " + std::to_string(raster) + " is not a power of two in [" +
                         std::to_string(kMinRaster) + ", " + std::to_string(kMaxRaster) + "]");
  const ScreenFrame f = make_stress_list(class_name, seed, raster);
  OutputPlan plan;
  plan.file(out_file, "--out");
  plan.check();
  write_text_file(out_file, polygon_list_json(f));
  std::cout << "cig: wrote " << f.polygons.size() << " polygon(s) of class " << class_name << " (seed " << seed
            << (stress_class_on_grid(class_name) ? ", vertices on the formatter grid" : ", vertices off the grid")
            << ") to " << out_file << "\n";
  return 0;
}

}  // namespace cig::cli
