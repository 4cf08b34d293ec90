// cig polys SCENE --frame K --channel C --out FILE.json
#include "cli/polys_command.hpp"

#include <iostream>

#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "generator/image_generator.hpp"
#include "image/image.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

void PolysCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("polys", "write the geometric processor's polygon list for one channel");
  sub->add_option("scene", scene_file, "scene file")->required();
  sub->add_option("--frame", frame, "frame number")->required();
  sub->add_option("--channel", channel, "channel")->check(CLI::Range(0, kMaxChannelIndex))->required();
  sub->add_option("--out", out_file, "output polygon list (JSON)")->required();
  model_limit.add_to(sub);
  manager_unit.add_to(sub);
}

int PolysCommand::run() {
  const Scene scene = load_scene(scene_file, model_limit.limits());
  if (frame < 0 || frame >= scene.frame_count())
    throw InputError(scene_file, "--frame",
                     "frame " + std::to_string(frame) + " lies outside the observer path (0.." +
                         std::to_string(scene.frame_count() - 1) + ")");
  if (channel < 0 || channel >= int(scene.channels.size()))
    throw InputError(scene_file, "--channel", "channel " + std::to_string(channel) + " does not exist");
  OutputPlan plan;
  plan.scene_inputs(scene);
  plan.file(out_file, "--out");
  plan.check();
  const ImageGenerator generator(scene, {}, manager_unit.arith());
  nlohmann::ordered_json rep;
  const ScreenFrame f = generator.geometry(frame, channel, rep);
  write_text_file(out_file, polygon_list_json(f));
  std::cout << "cig: wrote " << f.polygons.size() << " polygon(s), " << f.light_points.size() << " light point(s) to "
            << out_file << "\n";
  return 0;
}

}  // namespace cig::cli
