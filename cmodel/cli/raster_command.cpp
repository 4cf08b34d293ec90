// cig raster POLYS.json [--out FILE.png] [--ids FILE] [--report FILE] + the engine options
#include "cli/raster_command.hpp"

#include <filesystem>
#include <iostream>

#include "cli/frame_jobs.hpp"
#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "image/image.hpp"

namespace cig::cli {

void RasterCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("raster", "rasterise a screen-space polygon list (cig-polys)");
  sub->add_option("polys", polys_file, "polygon list (JSON, scenes/README.md)")->required();
  sub->add_option("--out", out_file, "output PNG (default out/raster.png)");
  sub->add_option("--ids", ids_file, "write the per-pixel polygon index (CIGIDS1 format)");
  sub->add_option("--report", report_file, "write a JSON report");
  engine.add_to(sub);
}

int RasterCommand::run() {
  const EngineOptions eo = engine.options();
  auto eng = make_engine(engine.engine, eo);
  // The raster and the counts as soon as the list is parsed (a list of 1 M polygons is refused
  // before its polygons are read), then the frame as the engine draws it (split into fans).
  const ScreenFrame frame = load_polygon_list(polys_file, FrameJobs::list_capacity(polys_file, *eng));
  try {
    eng->check_raster(frame.raster);
    eng->check_frame(frame);
  } catch (const InputError& e) {  // the engine's capability checks name no file: this one
    throw InputError(e.file().empty() ? polys_file : e.file(), e.where(), e.rule());
  }
  OutputPlan plan;
  plan.input(polys_file, "the polygon list this run reads");
  plan.file(out_file, "--out");
  if (!ids_file.empty()) plan.file(ids_file, "--ids");
  if (!report_file.empty()) plan.file(report_file, "--report");
  plan.check();
  const auto t0 = Clock::now();
  EngineRun run = eng->render(frame);
  run.report["ms"] = ms_since(t0);
  std::cerr << drop_warning(run.report, polys_file);
  const auto parent = std::filesystem::path(out_file).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  write_png(out_file, run.out.image);
  if (!ids_file.empty()) write_ids(ids_file, run.out.ids);
  if (!report_file.empty()) {
    nlohmann::ordered_json r;
    r["command"] = "raster";
    r["polys"] = polys_file;
    r["raster"] = frame.raster;
    r["polygons"] = frame.polygons.size();
    r["light_points"] = frame.light_points.size();
    r["engine_report"] = run.report;
    write_text_file(report_file, report_text(r));
  }
  std::cout << "cig: rasterised " << frame.polygons.size() << " polygon(s), " << frame.light_points.size()
            << " light point(s) with engine " << engine.engine << " to " << out_file << "\n";
  return 0;
}

}  // namespace cig::cli
