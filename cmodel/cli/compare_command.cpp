// cig compare INPUT --engine E [--reference float|float-snap] [--frame K | --frames A:B]
//                   [--channel C] [--out DIR [--html]] [--report FILE]
// Renders INPUT (a scene or a polygon list) with engine E and with the reference, and prints per
// frame and channel the PSNR, the SSIM (image/ssim.hpp), the maximum absolute error per colour
// channel, the pixels off by more than 2 LSB and the pixels whose polygon id differs; writes difference images (x8) and
// side-by-side review images to DIR, and with --html DIR/index.html (review_outputs.hpp).
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <set>
#include <thread>

#include "cli/compare_command.hpp"
#include "cli/frame_jobs.hpp"
#include "cli/output_plan.hpp"
#include "cli/review_outputs.hpp"
#include "common/progress.hpp"
#include "image/image_compare.hpp"
#include "registry/engine_registry.hpp"

namespace cig::cli {

void CompareCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("compare", "an engine's image error against the float reference");
  sub->add_option("input", input, "scene or polygon list")->required();
  frame_opt = sub->add_option("--frame", frame_k, "frame number (scenes; default 0)");
  sub->add_option("--frames", frames_text, "inclusive frame range A:B (scenes)")->excludes(frame_opt);
  sub->add_option("--channel", channel, "only this channel (scenes)")->check(CLI::Range(0, kMaxChannelIndex));
  sub->add_option(
      "--reference", reference,
      "float (default), float-snap (vertices snapped to the formatter grid) or float-snap-priority (snapped, visibility by list order as the engines)");
  add_reference_spp(sub, reference_spp);
  sub->add_option("--out", out_dir,
                  "write per image frame_KKKK_chC_diff.png (|error| x 8) and frame_KKKK_chC_side.png: engine | "
                  "reference | error map, the largest |error| of R, G, B in bins 0 (grey), 1, 2, 4, ..., 64, 128+ LSB, "
                  "magenta where the polygon id differs (docs/review_outputs.md)");
  sub->add_option("--report", report_file, "write a JSON report (with --html: default DIR/report.json)");
  sub->add_option("--pipelines", pipelines,
                  "rendering pipelines per channel (seed 000; scenes, priority engines): the engine renders the "
                  "lists and merges them, the reference renders them one after another")
      ->check(CLI::Range(1, 16));
  sub->add_flag("--html", html,
                "also write DIR/index.html (needs --out): the images, the table, the report, provenance");
  engine.add_to(sub, true);
  model_limit.add_to(sub);
  manager_unit.add_to(sub);
}

namespace {

void print_row(const Comparison& r) {
  std::cout << std::setw(6) << r.frame << std::setw(4) << r.channel << std::fixed << std::setprecision(2)
            << std::setw(9) << r.error.psnr() << std::setw(8) << ssim_text(r.error.ssim()) << std::setw(6)
            << r.error.max_abs[0] << std::setw(5) << r.error.max_abs[1] << std::setw(5) << r.error.max_abs[2]
            << std::setw(9) << r.error.pixels_over_2lsb << std::setw(11) << r.ids_differ << "\n";
}

}  // namespace

namespace {

// The files --out receives: per image its difference and side-by-side images (compare_all writes
// them), and with --html the page (the report's default place is --report's to check).
std::set<std::string> compare_output_names(const FrameJobs& jobs, bool html) {
  std::set<std::string> names;
  for (std::size_t k = 0; k < jobs.size(); ++k)
    for (const char* kind : {"diff", "side"})
      names.insert(compare_image_file("", jobs.frame(k), jobs.channel(k), kind));
  if (html) names.insert("index.html");
  return names;
}

// Renders every image with the engine and the reference on all cores; one Comparison per image.
std::vector<Comparison> compare_all(const CompareCommand& c, const FrameJobs& jobs, const EngineOptions& eo,
                                    const EngineOptions& ro, bool classify) {
  std::vector<Comparison> rows(jobs.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex mutex;
  Progress progress("cig compare", (long long)jobs.size());
  auto worker = [&] {
    try {
      auto eng = make_engine(c.engine.engine, eo);
      auto ref = make_engine(reference_engine_name(), ro);
      // The same reference with visibility by priority, to attribute the error that comes from
      // the engines' visibility by list order (only for a z-buffered reference).
      EngineOptions po = ro;
      po.params["visibility"] = "priority";
      auto priority_ref = make_engine(reference_engine_name(), po);
      for (std::size_t k; (k = next++) < jobs.size();) {
        // With pipelines the engine merges their lists; the reference renders them one after another.
        const std::vector<ScreenFrame> parts = jobs.screen_frame_parts(k);
        const ScreenFrame f = parts.size() > 1 ? concatenate_parts(parts) : parts[0];
        const EngineRun got = parts.size() > 1 ? eng->render_parts(parts) : eng->render(f);
        const EngineRun want = ref->render(f);
        rows[k] = compare_run(jobs.frame(k), jobs.channel(k), got.out, want.out);
        const std::string image =
            "frame " + std::to_string(jobs.frame(k)) + " channel " + std::to_string(jobs.channel(k));
        progress.note(drop_warning(got.report, image));
        if (classify && rows[k].error.sum_squared > 0)
          attribute_priority(rows[k], got.out, want.out, priority_ref->render(f).out);
        if (!c.out_dir.empty())
          write_png(compare_image_file(c.out_dir, jobs.frame(k), jobs.channel(k), "diff"),
                    difference_image(got.out.image, want.out.image, 8));
        if (!c.out_dir.empty()) write_side_image(c.out_dir, rows[k], c.engine.engine, c.reference, got.out, want.out);
        progress.step(image);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  };
  const int threads = int(std::max(1u, std::min<unsigned>(std::thread::hardware_concurrency(), unsigned(jobs.size()))));
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return rows;
}

// The squared error in three parts: pixels showing another polygon; pixels showing the same
// polygon whose colour the reference changes under visibility by priority (light points and
// minority samples ordered against the z-buffer); the rest.
void print_totals(const ComparisonTotals& totals, std::size_t images, bool classify, double& ids_share,
                  double& priority_share) {
  const ImageError& all = totals.all;
  std::cout << "all:  " << images << " image(s), PSNR " << std::fixed << std::setprecision(2) << all.psnr()
            << " dB over all pixels, lowest " << totals.min_psnr << " dB (frame " << totals.worst_frame << " channel "
            << totals.worst_channel << "), mean SSIM " << ssim_text(all.ssim());
  if (all.has_ssim())
    std::cout << ", lowest " << ssim_text(totals.min_ssim) << " (frame " << totals.worst_ssim_frame << " channel "
              << totals.worst_ssim_channel << ")";
  std::cout << ", max abs error R " << all.max_abs[0] << " G " << all.max_abs[1] << " B " << all.max_abs[2] << ", "
            << all.pixels_over_2lsb << " of " << all.pixels << " pixels off by more than 2 LSB, " << totals.ids_differ
            << " pixels with another polygon id\n"
            << "      of those, " << totals.ids_differ_off_edges
            << " at an edge in neither image (another surface away from any boundary)\n"
            << "      of those, " << totals.priority.ids_priority_vs_depth
            << " where the reference itself shows another polygon with visibility by priority order instead of"
               " the z-buffer (priority order against the z-buffer)\n";
  auto share = [&](double part) { return all.sum_squared > 0 ? 100.0 * part / all.sum_squared : 0.0; };
  ids_share = share(all.sum_squared_ids_differ);
  priority_share = share(totals.priority.sum_squared_priority_colour);
  std::cout << "      error attribution: " << std::setprecision(1) << ids_share
            << " % of the squared error lies in the " << all.pixels_ids_differ
            << " pixels whose visible polygon differs (visibility, coverage), ";
  if (classify)
    std::cout << priority_share << " % in the " << totals.priority.pixels_priority_colour
              << " pixels showing the same polygon whose colour visibility by priority order changes in the reference"
                 " (light points, partly covered pixels), ";
  std::cout << 100.0 - ids_share - (classify ? priority_share : 0.0)
            << " % in the other pixels (shading, fog, quantization)\n";
}

nlohmann::ordered_json to_json(const ComparisonTotals& totals, double ids_share, double priority_share) {
  const ImageError& all = totals.all;
  return {{"psnr_all", all.psnr()},
          {"psnr_min", totals.min_psnr},
          {"ssim_mean", ssim_json(all.ssim())},
          {"ssim_min", ssim_json(all.has_ssim() ? totals.min_ssim : all.ssim())},
          {"pixels", all.pixels},
          {"pixels_over_2lsb", all.pixels_over_2lsb},
          {"ids_differ", totals.ids_differ},
          {"ids_differ_off_edges", totals.ids_differ_off_edges},
          {"ids_priority_vs_depth", totals.priority.ids_priority_vs_depth},
          {"pixels_priority_colour", totals.priority.pixels_priority_colour},
          {"squared_error_share_ids_differ", ids_share / 100.0},
          {"squared_error_share_priority_colour", priority_share / 100.0}};
}

}  // namespace

int CompareCommand::run() {
  const EngineOptions eo = engine.options();
  EngineOptions ro = reference_options(reference, reference_spp);
  ro.fan_split = eo.fan_split;  // the reference follows the engine's polygon split
  const auto probe = make_engine(engine.engine, eo);
  FrameJobs jobs = FrameJobs::load(input, frames_text, frame_k, frame_opt->count() > 0, channel, model_limit.limits(),
                                   manager_unit.arith(), FrameJobs::list_capacity(input, *probe));
  if (pipelines > 1) {
    if (!jobs.is_scene())
      throw InputError(input, "--pipelines", "rendering pipelines split a scene's lists; this is a polygon list");
    probe->check_renders_parts();
    jobs.set_pipelines(pipelines);
  }
  jobs.check_capacity(*probe);
  if (html) prepare_compare_html(out_dir, report_file);
  OutputPlan plan;
  jobs.declare_inputs(plan);
  if (!out_dir.empty()) plan.folder(out_dir, "--out", compare_output_names(jobs, html));
  if (!report_file.empty()) plan.file(report_file, "--report");
  plan.check();
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);
  const bool classify = ro.params.count("visibility") == 0;  // a z-buffered reference
  const std::vector<Comparison> rows = compare_all(*this, jobs, eo, ro, classify);

  std::cout << "engine " << engine.engine << " against " << reference << " on " << input << "\n"
            << " frame  ch     PSNR    SSIM  maxR maxG maxB  >2 LSB  ids differ\n";
  ComparisonTotals totals;
  nlohmann::ordered_json rep;
  rep["engine"] = engine.engine;
  rep["reference"] = reference;
  rep["input"] = input;
  rep["pipelines"] = pipelines;
  rep["rows"] = nlohmann::ordered_json::array();
  for (const Comparison& r : rows) {
    if (rows.size() <= 30) print_row(r);
    totals.add(r);
    rep["rows"].push_back(comparison_json(r));
  }
  double ids_share = 0, priority_share = 0;
  print_totals(totals, rows.size(), classify, ids_share, priority_share);
  rep.update(to_json(totals, ids_share, priority_share));
  if (!report_file.empty()) write_text_file(report_file, report_text(rep));
  if (html) write_compare_html(out_dir, report_file, rep, rows, totals);
  return 0;
}

}  // namespace cig::cli
