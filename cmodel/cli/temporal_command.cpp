#include "cli/temporal_command.hpp"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/gnuplot_plot.hpp"
#include "cli/output_plan.hpp"
#include "cli/temporal_study.hpp"
#include "common/error.hpp"
#include "image/image.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

void TemporalCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("temporal",
                           "temporal quality over frames: light-point scintillation, edge crawl, popping, per engine "
                           "and spp, against the sample lattice's bounds");
  sub->add_option("scene", scene_file, "scene file")->required();
  sub->add_option("--frames", frames_text, "inclusive frame range A:B")->required();
  sub->add_option("--channel", channel, "the channel (default: the middle one)")
      ->check(CLI::Range(0, kMaxChannelIndex));
  sub->add_option("--engines", engines_text,
                  "engines, comma-separated (default float,segment,quadtree); float-snap: the reference on the "
                  "formatter grid");
  sub->add_option("--spp", spp_text, "samples per pixel, comma-separated (default 16)");
  sub->add_option("--pipelines", pipelines,
                  "rendering pipelines per channel: the priority engines render them and merge them, the float "
                  "reference their concatenation")
      ->check(CLI::Range(1, 16));
  sub->add_option("--edge-object", edge_object,
                  "the object whose surface's outline is measured (default: the first runway_*)");
  sub->add_option("--pop-pixels", pop_pixels, "an object popping covers at least this many pixels (default 4)")
      ->check(CLI::Range(1.0, 1e6));
  sub->add_option("--report", report_file, "write the table and the per-frame series as JSON");
  sub->add_option("--plot", plot_file, "write a PNG: per frame, RMS change of scintillation and crawl, and pops");
  model_limit.add_to(sub);
}

namespace {

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  std::string w;
  while (std::getline(s, w, ','))
    if (!w.empty()) out.push_back(w);
  return out;
}

void print_table(const TemporalStudy& st, int frames) {
  std::cout << "temporal quality over " << frames << " frames; edges of '" << st.edge_object << "'\n"
            << "engine     spp  lights  scint rms  max Δ   > bound |  rows  crawl rms  max Δ  bound px  > bound |"
               "  pops  dropped\n";
  for (const TemporalSeries& s : st.series)
    std::cout << std::left << std::setw(10) << s.engine << std::right << std::setw(4) << s.spp << std::setw(8)
              << s.light_frames << std::fixed << std::setprecision(4) << std::setw(11) << s.light_rms_delta
              << std::setw(7) << std::setprecision(3) << s.light_max_delta << std::setw(10) << s.light_bound_violations
              << " |" << std::setw(6) << s.edge_rows << std::setprecision(4) << std::setw(11) << s.edge_rms_delta
              << std::setw(7) << std::setprecision(3) << s.edge_max_delta << std::setw(10) << s.edge_bound
              << std::setw(9) << s.edge_bound_violations << " |" << std::setw(6) << s.pops << std::setw(9) << s.dropped
              << "\n";
}

nlohmann::ordered_json series_json(const TemporalSeries& s) {
  return {{"engine", s.engine},
          {"spp", s.spp},
          {"scintillation",
           {{"light_frames", s.light_frames},
            {"deltas", s.light_deltas},
            {"rms_error", s.light_rms_error},
            {"max_error", s.light_max_error},
            {"rms_delta", s.light_rms_delta},
            {"max_delta", s.light_max_delta},
            {"bound_violations", s.light_bound_violations},
            {"rms_delta_per_frame", s.light_delta_frame}}},
          {"crawl",
           {{"rows", s.edge_rows},
            {"deltas", s.edge_deltas},
            {"rms_error_px", s.edge_rms_error},
            {"max_error_px", s.edge_max_error},
            {"rms_delta_px", s.edge_rms_delta},
            {"max_delta_px", s.edge_max_delta},
            {"bound_px", s.edge_bound},
            {"bound_violations", s.edge_bound_violations},
            {"rms_delta_per_frame", s.edge_delta_frame}}},
          {"popping", {{"pops", s.pops}, {"dropped", s.dropped}, {"pops_per_frame", s.pops_frame}}},
          {"ms", s.ms}};
}

void plot(const TemporalStudy& st, int first, const std::string& file) {
  const GnuplotJob job("temporal");
  std::string lines_scint, lines_crawl, lines_pops;
  for (std::size_t k = 0; k < st.series.size(); ++k) {
    const TemporalSeries& s = st.series[k];
    const std::string data = job.file("s" + std::to_string(k) + ".dat"),
                      title = s.engine + " spp " + std::to_string(s.spp);
    std::ofstream out(data);
    for (std::size_t i = 0; i < s.pops_frame.size(); ++i)
      out << first + int(i) << " " << s.light_delta_frame[i] << " " << s.edge_delta_frame[i] << " " << s.pops_frame[i]
          << "\n";
    const std::string sep = k ? ", " : "";
    lines_scint += sep + "'" + data + "' using 1:2 with lines title '" + title + "'";
    lines_crawl += sep + "'" + data + "' using 1:3 with lines title '" + title + "'";
    lines_pops += sep + "'" + data + "' using 1:4 with steps title '" + title + "'";
  }
  const std::string script =
      "set multiplot layout 3,1\nset grid\nset key outside right\n"
      "set ylabel 'scintillation: RMS change of E/A'\nplot " +
      lines_scint + "\nset ylabel 'crawl: RMS change, px'\nplot " + lines_crawl +
      "\nset ylabel 'pops'\nset xlabel 'frame'\nplot " + lines_pops + "\nunset multiplot\n";
  job.draw(script, 1000, 900, file, "--plot");
}

}  // namespace

int TemporalCommand::run() {
  const Scene scene = load_scene(scene_file, model_limit.limits());
  TemporalOptions o;
  frame_range(frames_text, -1, false, scene.frame_count(), scene_file, o.first, o.last);
  if (o.last <= o.first) throw InputError("", "--frames", "temporal quality needs at least two frames");
  o.channel = channel >= 0 ? channel : int(scene.channels.size()) / 2;
  if (o.channel >= int(scene.channels.size()))
    throw InputError("", "--channel", "the scene has " + std::to_string(scene.channels.size()) + " channel(s)");
  o.engines = split_list(engines_text);
  o.spp.clear();
  for (const std::string& v : split_list(spp_text)) {
    if (v != "1" && v != "4" && v != "16" && v != "64")
      throw InputError("", "--spp", "'" + v + "' is not one of 1, 4, 16, 64");
    o.spp.push_back(std::stoi(v));
  }
  o.pipelines = pipelines;
  o.edge_object = edge_object;
  o.pop_pixels = pop_pixels;
  for (const std::string& e : o.engines)
    for (int spp : o.spp) {  // every engine and setting before any work
      EngineOptions eo;
      eo.params["spp"] = std::to_string(spp);
      eo.snap = e == "float-snap";
      make_engine(eo.snap ? "float" : e, eo);
    }
  OutputPlan plan;
  plan.scene_inputs(scene);
  plan.report_and_plot(report_file, plot_file);
  plan.check();
  const TemporalStudy st = run_temporal_study(scene, o);
  print_table(st, o.last - o.first + 1);
  if (!report_file.empty()) {
    nlohmann::ordered_json rep = {{"scene", scene_file},           {"frames", {o.first, o.last}},
                                  {"channel", o.channel},          {"raster", st.raster},
                                  {"edge_object", st.edge_object}, {"series", nlohmann::ordered_json::array()}};
    for (const TemporalSeries& s : st.series) rep["series"].push_back(series_json(s));
    write_text_file(report_file, report_text(rep));
  }
  if (!plot_file.empty()) plot(st, o.first, plot_file);
  return 0;
}

}  // namespace cig::cli
