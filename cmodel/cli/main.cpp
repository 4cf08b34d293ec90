// cig: command-line driver of the C model.
//   cig render SCENE [--frame K | --frames A:B] [--channel C] [--out DIR] [--report FILE]
//   cig raster POLYS.json [--out FILE.png] [--ids FILE] [--report FILE]
//   cig polys SCENE --frame K --channel C --out FILE.json
// All commands take --engine NAME [--engine-opt KEY=VALUE ...] [--snap]. Input errors print
// "cig: error: FILE: PLACE: RULE" and exit with status 2 before any output file is written.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "cli/arch_command.hpp"
#include "cli/cli_common.hpp"
#include "cli/cli_main.hpp"
#include "cli/sweep_command.hpp"
#include "common/error.hpp"
#include "image/image.hpp"
#include "pipeline/scene_pipeline.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

using namespace cli;

// `cig cosim ...` runs the co-simulation executable cig-cosim from cig's own folder (built with the
// RTL, -DCIG_WITH_RTL=ON): the product binary links no Verilated model. Returns only on failure.
int forward_to_cosim(int argc, char** argv) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path cosim = (ec ? std::filesystem::path(argv[0]) : self).parent_path() / "cig-cosim";
  if (!std::filesystem::exists(cosim))
    throw InputError("", "cosim", "this cig has no co-simulation: " + cosim.string() +
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

  // render
  auto* render = app.add_subcommand("render", "render frames of a scene, one PNG per channel plus a panorama");
  std::string scene_file, out_dir = "out", report_file, frames_text;
  int frame_k = -1, channel = -1, threads = int(std::max(1u, std::thread::hardware_concurrency()));
  bool write_ids_files = false;
  EngineArgs render_engine;
  render->add_option("scene", scene_file, "scene file (JSON, scenes/README.md)")->required();
  auto* fopt = render->add_option("--frame", frame_k, "frame number (default 0)");
  render->add_option("--frames", frames_text, "inclusive frame range A:B")->excludes(fopt);
  render->add_option("--channel", channel, "render only this channel");
  render->add_option("--out", out_dir, "output directory (default out)");
  render->add_option("--report", report_file, "report file (default DIR/report.json)");
  render->add_option("--threads", threads, "worker threads over channels (default: cores)")->check(CLI::Range(1, 64));
  render->add_flag("--ids", write_ids_files, "also write per-channel id buffers (CIGIDS1)");
  render_engine.add_to(render);

  // raster
  auto* raster = app.add_subcommand("raster", "rasterise a screen-space polygon list (cig-polys)");
  std::string polys_file, raster_out = "out/raster.png", ids_file, raster_report;
  EngineArgs raster_engine;
  raster->add_option("polys", polys_file, "polygon list (JSON, scenes/README.md)")->required();
  raster->add_option("--out", raster_out, "output PNG (default out/raster.png)");
  raster->add_option("--ids", ids_file, "write the per-pixel polygon index (CIGIDS1 format)");
  raster->add_option("--report", raster_report, "write a JSON report");
  raster_engine.add_to(raster);

  // polys
  auto* polys = app.add_subcommand("polys", "write the geometric processor's polygon list for one channel");
  std::string polys_scene, polys_out;
  int polys_frame = 0, polys_channel = 0;
  polys->add_option("scene", polys_scene, "scene file")->required();
  polys->add_option("--frame", polys_frame, "frame number")->required();
  polys->add_option("--channel", polys_channel, "channel")->required();
  polys->add_option("--out", polys_out, "output polygon list (JSON)")->required();

  CompareCommand compare;
  compare.add_to(app);
  SweepCommand sweep;
  sweep.add_to(app);
  ArchCommand arch;
  arch.add_to(app);
  // Listed for --help; `cig cosim ...` never reaches the parser (forward_to_cosim).
  app.add_subcommand("cosim", "co-simulate the quadtree RTL against the kernels and the architecture model (runs cig-cosim; "
                              "`cig cosim --help` for its options)")
      ->allow_extras();

  int status = 0;
  if (!parse_command_line(app, argc, argv, status)) return status;

  if (*render) {
    // Everything that can be wrong with the input is checked before anything is written.
    EngineOptions eo = render_engine.options();
    auto t_load = Clock::now();
    Scene scene = load_scene(scene_file);
    const double load_ms = ms_since(t_load);
    int a = 0, b = 0;
    frame_range(frames_text, frame_k, fopt->count() > 0, scene.frame_count(), scene_file, a, b);
    std::vector<int> channels;
    if (channel >= 0) {
      if (channel >= int(scene.channels.size()))
        throw InputError("", "--channel", "channel " + std::to_string(channel) + " does not exist (scene has " +
                                              std::to_string(scene.channels.size()) + ")");
      channels.push_back(channel);
    } else {
      for (int c = 0; c < int(scene.channels.size()); ++c) channels.push_back(c);
    }
    make_engine(render_engine.engine, eo)->check_raster(scene.raster);
    std::filesystem::create_directories(out_dir);
    if (report_file.empty()) report_file = (std::filesystem::path(out_dir) / "report.json").string();

    ScenePipeline pipeline(scene);
    nlohmann::ordered_json report;
    report["command"] = "render";
    report["scene"] = scene_file;
    report["engine"] = render_engine.engine;
    report["snap"] = eo.snap;
    report["raster"] = scene.raster;
    report["threads"] = threads;
    report["scene_polygons"] = scene.polygon_count();
    report["scene_light_points"] = scene.light_point_count();
    report["load_ms"] = load_ms;
    report["frames"] = nlohmann::ordered_json::array();
    const auto t_all = Clock::now();
    for (int frame = a; frame <= b; ++frame) {
      const auto t_frame = Clock::now();
      std::vector<ChannelOutput> outs = pipeline.render(frame, channels, render_engine.engine, eo, threads);
      const double render_ms = ms_since(t_frame);
      const auto t_out = Clock::now();
      nlohmann::ordered_json fr;
      fr["frame"] = frame;
      for (auto& co : outs) {
        const std::string base = (std::filesystem::path(out_dir) / (frame_name(frame) + "_ch" +
                                  std::to_string(co.channel) + "_" +
                                  safe_name(scene.channels[std::size_t(co.channel)].name))).string();
        write_png(base + ".png", co.out.image);
        if (write_ids_files) write_ids(base + ".ids", co.out.ids);
        co.report["image"] = base + ".png";
      }
      if (outs.size() > 1) {
        // Panorama: channels left to right by yaw offset.
        std::vector<const ChannelOutput*> order;
        for (const auto& co : outs) order.push_back(&co);
        std::stable_sort(order.begin(), order.end(), [&](const ChannelOutput* x, const ChannelOutput* y) {
          return scene.channels[std::size_t(x->channel)].yaw_deg < scene.channels[std::size_t(y->channel)].yaw_deg;
        });
        std::vector<const Image*> parts;
        for (const auto* co : order) parts.push_back(&co->out.image);
        const std::string pano = (std::filesystem::path(out_dir) / (frame_name(frame) + "_panorama.png")).string();
        write_png(pano, concatenate_horizontally(parts));
        fr["panorama"] = pano;
      }
      fr["render_ms"] = render_ms;
      fr["output_ms"] = ms_since(t_out);
      fr["channels"] = nlohmann::ordered_json::array();
      for (auto& co : outs) fr["channels"].push_back(std::move(co.report));
      report["frames"].push_back(std::move(fr));
      if (b > a)
        std::cerr << "cig: frame " << frame << " (" << (frame - a + 1) << "/" << (b - a + 1) << ") "
                  << channels.size() << " channel(s) in " << int(render_ms) << " ms\n";
    }
    report["total_ms"] = ms_since(t_all);
    write_text_file(report_file, report.dump(2) + "\n");
    std::cout << "cig: rendered " << (b - a + 1) << " frame(s) x " << channels.size() << " channel(s) of "
              << scene_file << " to " << out_dir << " in " << int(ms_since(t_all)) << " ms (report "
              << report_file << ")\n";
    return 0;
  }

  if (*raster) {
    EngineOptions eo = raster_engine.options();
    ScreenFrame frame = load_polygon_list(polys_file);
    auto eng = make_engine(raster_engine.engine, eo);
    eng->check_raster(frame.raster);
    const auto t0 = Clock::now();
    EngineRun run = eng->render(frame);
    run.report["ms"] = ms_since(t0);
    auto parent = std::filesystem::path(raster_out).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    write_png(raster_out, run.out.image);
    if (!ids_file.empty()) write_ids(ids_file, run.out.ids);
    if (!raster_report.empty()) {
      nlohmann::ordered_json r;
      r["command"] = "raster";
      r["polys"] = polys_file;
      r["raster"] = frame.raster;
      r["polygons"] = frame.polygons.size();
      r["light_points"] = frame.light_points.size();
      r["engine_report"] = run.report;
      write_text_file(raster_report, r.dump(2) + "\n");
    }
    std::cout << "cig: rasterised " << frame.polygons.size() << " polygon(s), " << frame.light_points.size()
              << " light point(s) with engine " << raster_engine.engine << " to " << raster_out << "\n";
    return 0;
  }

  if (*compare.sub) return compare.run();
  if (*sweep.sub) return sweep.run();
  if (*arch.sub) return arch.run();

  if (*polys) {
    Scene scene = load_scene(polys_scene);
    if (polys_frame < 0 || polys_frame >= scene.frame_count())
      throw InputError("", "--frame", "frame " + std::to_string(polys_frame) + " lies outside the observer path (0.." +
                                          std::to_string(scene.frame_count() - 1) + ")");
    if (polys_channel < 0 || polys_channel >= int(scene.channels.size()))
      throw InputError("", "--channel", "channel " + std::to_string(polys_channel) + " does not exist");
    ScenePipeline pipeline(scene);
    nlohmann::ordered_json rep;
    ScreenFrame f = pipeline.geometry(polys_frame, polys_channel, rep);
    write_text_file(polys_out, polygon_list_json(f));
    std::cout << "cig: wrote " << f.polygons.size() << " polygon(s), " << f.light_points.size()
              << " light point(s) to " << polys_out << "\n";
    return 0;
  }
  return 0;
}

}  // namespace
}  // namespace cig

int main(int argc, char** argv) {
  return cig::cli::guarded_main("cig", [&] { return cig::run(argc, argv); });
}
