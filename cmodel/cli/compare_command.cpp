// cig compare INPUT --engine E [--reference float|float-snap] [--frame K | --frames A:B]
//                   [--channel C] [--out DIR] [--report FILE]
// Renders INPUT (a scene or a polygon list) with engine E and with the reference, and prints per
// frame and channel the PSNR, the maximum absolute error per colour channel, the pixels off by
// more than 2 LSB and the pixels whose polygon id differs; writes difference images (x8) to DIR.
#include <algorithm>
#include <atomic>
#include <mutex>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <thread>

#include "cli/cli_common.hpp"
#include "common/json_reader.hpp"
#include "image/image_compare.hpp"
#include "pipeline/scene_pipeline.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cli {

void CompareCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("compare", "an engine's image error against the float reference");
  sub->add_option("input", input, "scene or polygon list")->required();
  frame_opt = sub->add_option("--frame", frame_k, "frame number (scenes; default 0)");
  sub->add_option("--frames", frames_text, "inclusive frame range A:B (scenes)")->excludes(frame_opt);
  sub->add_option("--channel", channel, "only this channel (scenes)");
  sub->add_option("--reference", reference, "float (default) or float-snap (vertices snapped to the formatter grid)");
  sub->add_option("--out", out_dir, "write difference images (|error| x 8) here");
  sub->add_option("--report", report_file, "write a JSON report");
  engine.add_to(sub);
}

namespace {

struct Row {
  int frame, channel;
  ImageError error;
  long ids_differ;
};

void print_row(const Row& r) {
  std::cout << std::setw(6) << r.frame << std::setw(4) << r.channel << std::fixed << std::setprecision(2)
            << std::setw(9) << r.error.psnr() << std::setw(6) << r.error.max_abs[0] << std::setw(5)
            << r.error.max_abs[1] << std::setw(5) << r.error.max_abs[2] << std::setw(9) << r.error.pixels_over_2lsb
            << std::setw(11) << r.ids_differ << "\n";
}

}  // namespace

int CompareCommand::run() {
  EngineOptions eo = engine.options();
  if (reference != "float" && reference != "float-snap")
    throw InputError("", "--reference", "'" + reference + "' is neither float nor float-snap");
  EngineOptions ro;
  ro.snap = reference == "float-snap";
  const std::string text = read_text_file(input);
  const bool is_polys = text.find("\"cig-polys\"") != std::string::npos;
  std::vector<ScreenFrame> frames;  // polygon-list input: one frame
  std::unique_ptr<Scene> scene;
  std::vector<std::pair<int, int>> jobs;  // (frame, channel)
  if (is_polys) {
    frames.push_back(parse_polygon_list(text, input));
    jobs.push_back({frames[0].frame, frames[0].channel});
  } else {
    scene = std::make_unique<Scene>(parse_scene(text, input));
    int a, b;
    frame_range(frames_text, frame_k, frame_opt->count() > 0, scene->frame_count(), input, a, b);
    if (channel >= int(scene->channels.size()))
      throw InputError("", "--channel", "channel " + std::to_string(channel) + " does not exist");
    for (int f = a; f <= b; ++f)
      for (int c = 0; c < int(scene->channels.size()); ++c)
        if (channel < 0 || c == channel) jobs.push_back({f, c});
  }
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);

  std::unique_ptr<ScenePipeline> pipeline = scene ? std::make_unique<ScenePipeline>(*scene) : nullptr;
  std::vector<Row> rows(jobs.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex mutex;
  auto worker = [&] {
    try {
      auto eng = make_engine(engine.engine, eo);
      auto ref = make_engine("float", ro);
      for (std::size_t k; (k = next++) < jobs.size();) {
        nlohmann::ordered_json unused;
        const ScreenFrame f = pipeline ? pipeline->geometry(jobs[k].first, jobs[k].second, unused) : frames[0];
        const EngineRun got = eng->render(f);
        const EngineRun want = ref->render(f);
        rows[k] = {jobs[k].first, jobs[k].second,
                   compare_images(got.out.image, want.out.image, got.out.ids, want.out.ids),
                   differing_ids(got.out.ids, want.out.ids)};
        if (!out_dir.empty())
          write_png((std::filesystem::path(out_dir) / (frame_name(jobs[k].first) + "_ch" + std::to_string(jobs[k].second) +
                                                       "_diff.png")).string(),
                    difference_image(got.out.image, want.out.image, 8));
        if (jobs.size() > 3) {
          std::lock_guard<std::mutex> lock(mutex);
          std::cerr << "\rcig: compared " << k + 1 << "/" << jobs.size() << std::flush;
        }
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
  if (jobs.size() > 3) std::cerr << "\n";
  if (error) std::rethrow_exception(error);

  std::cout << "engine " << engine.engine << " against " << reference << " on " << input << "\n"
            << " frame  ch     PSNR  maxR maxG maxB  >2 LSB  ids differ\n";
  ImageError all;
  double min_psnr = 1e9;
  const Row* worst = nullptr;
  long ids = 0, pixels = 0;
  nlohmann::ordered_json rep;
  rep["engine"] = engine.engine;
  rep["reference"] = reference;
  rep["input"] = input;
  rep["rows"] = nlohmann::ordered_json::array();
  for (const Row& r : rows) {
    if (rows.size() <= 30) print_row(r);
    all.add(r.error);
    ids += r.ids_differ;
    pixels += r.error.pixels;
    if (r.error.psnr() < min_psnr) {
      min_psnr = r.error.psnr();
      worst = &r;
    }
    rep["rows"].push_back({{"frame", r.frame}, {"channel", r.channel}, {"psnr", r.error.psnr()},
                           {"max_abs", {r.error.max_abs[0], r.error.max_abs[1], r.error.max_abs[2]}},
                           {"pixels_over_2lsb", r.error.pixels_over_2lsb}, {"ids_differ", r.ids_differ}});
  }
  std::cout << "all:  " << rows.size() << " image(s), PSNR " << std::fixed << std::setprecision(2) << all.psnr()
            << " dB over all pixels, lowest " << min_psnr << " dB (frame " << worst->frame << " channel " << worst->channel
            << "), max abs error R " << all.max_abs[0] << " G " << all.max_abs[1] << " B " << all.max_abs[2] << ", "
            << all.pixels_over_2lsb << " of " << pixels << " pixels off by more than 2 LSB, " << ids
            << " pixels with another polygon id\n";
  const double share = all.sum_squared > 0 ? 100.0 * all.sum_squared_ids_differ / all.sum_squared : 0.0;
  std::cout << "      error attribution: " << std::setprecision(1) << share
            << " % of the squared error lies in the " << all.pixels_ids_differ
            << " pixels whose visible polygon differs (visibility, coverage), " << 100.0 - share
            << " % in pixels showing the same polygon (shading, fog, quantization)\n";
  rep["psnr_all"] = all.psnr();
  rep["psnr_min"] = min_psnr;
  rep["pixels"] = pixels;
  rep["pixels_over_2lsb"] = all.pixels_over_2lsb;
  rep["ids_differ"] = ids;
  rep["squared_error_share_ids_differ"] = all.sum_squared > 0 ? all.sum_squared_ids_differ / all.sum_squared : 0.0;
  if (!report_file.empty()) write_text_file(report_file, rep.dump(2) + "\n");
  return 0;
}

}  // namespace cig::cli
