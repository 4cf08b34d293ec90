#include "cli/review_outputs.hpp"

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "cli/cli_common.hpp"
#include "cli/gnuplot_plot.hpp"
#include "cli/html_report.hpp"
#include "common/error.hpp"
#include "image/image.hpp"
#include "image/review_image.hpp"

namespace cig::cli {

namespace {

namespace fs = std::filesystem;

std::string fixed2(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// The comparison's numbers as one line (the side image's caption, the gallery's).
std::string comparison_caption(const Comparison& c) {
  const ImageError& e = c.error;
  return "frame " + std::to_string(c.frame) + " channel " + std::to_string(c.channel) + ": PSNR " + fixed2(e.psnr()) +
         " dB, SSIM " + ssim_text(e.ssim()) + ", max |error| R " + std::to_string(e.max_abs[0]) + " G " +
         std::to_string(e.max_abs[1]) + " B " + std::to_string(e.max_abs[2]) + ", " +
         std::to_string(e.pixels_over_2lsb) + " px > 2 LSB, " + std::to_string(c.ids_differ) + " ids differ";
}

const char* const kHeatMapLegend =
    "Side-by-side images: engine | reference | error map. The error of a pixel is the largest absolute "
    "difference of its R, G and B in 8-bit LSB, coloured by bins 0 (dark grey), 1, 2-3, 4-7, 8-15, 16-31, "
    "32-63, 64-127, 128+ (dark blue, blue, cyan, green, yellow, orange, red, white); magenta marks a pixel "
    "whose polygon id differs from the reference's, whatever its colour error. diff: |error| x 8 per channel.";

}  // namespace

std::string compare_image_file(const std::string& dir, int frame, int channel, const std::string& kind) {
  return (fs::path(dir) / (frame_name(frame) + "_ch" + std::to_string(channel) + "_" + kind + ".png")).string();
}

void write_side_image(const std::string& dir, const Comparison& c, const std::string& engine,
                      const std::string& reference, const RasterImage& got, const RasterImage& want) {
  write_png(compare_image_file(dir, c.frame, c.channel, "side"),
            review_image(got, want, {engine, reference, comparison_caption(c)}));
}

void prepare_render_html(const std::string& out_dir) { check_output_file(HtmlPage::index_file(out_dir), "--html"); }

void prepare_compare_html(const std::string& out_dir, std::string& report_file) {
  if (out_dir.empty())
    throw InputError("", "--html", "needs --out DIR: the page is written to DIR/index.html beside the images");
  check_output_file(HtmlPage::index_file(out_dir), "--html");
  if (report_file.empty()) report_file = (fs::path(out_dir) / "report.json").string();
}

void prepare_sweep_html(const std::string& html_dir, std::string& report_file, std::string& plot_file) {
  check_output_dir(html_dir, "--html");
  check_output_file(HtmlPage::index_file(html_dir), "--html");
  if (report_file.empty()) report_file = (fs::path(html_dir) / "report.json").string();
  if (plot_file.empty()) {
    plot_file = (fs::path(html_dir) / "plot.png").string();
    check_plot_output(plot_file, "--html");  // the page's plot needs gnuplot, though --plot was not given
  }
}

namespace {

// A number at `pointer` in `j`, as table text ("" when absent: engines report different counts).
HtmlCell at(const nlohmann::ordered_json& j, const char* pointer, int decimals = 2) {
  const nlohmann::ordered_json::json_pointer p(pointer);
  return {j.contains(p) ? json_cell_text(j[p], decimals) : "", ""};
}

// One row per frame and channel: what stages A, B and the engine counted, and their times.
void render_table(HtmlPage& page, const nlohmann::ordered_json& frames) {
  std::vector<std::vector<HtmlCell>> rows;
  for (const auto& fr : frames)
    for (const auto& ch : fr["channels"]) {
      const std::string image = ch.value("image", std::string());
      rows.push_back({at(fr, "/frame"),
                      at(ch, "/channel"),
                      at(ch, "/name"),
                      at(ch, "/scene_manager/objects_visible"),
                      at(ch, "/geometry/polygons_out"),
                      at(ch, "/geometry/light_points_out"),
                      at(ch, "/scene_manager/ms", 3),
                      at(ch, "/geometry/ms", 3),
                      at(ch, "/raster/ms", 3),
                      at(fr, "/render_ms", 1),
                      {image.empty() ? "" : fs::path(image).filename().string(), image}});
    }
  page.table({"frame", "channel", "name", "objects visible", "polygons", "light points", "manager ms", "geometry ms",
              "raster ms", "frame ms", "image"},
             rows);
}

}  // namespace

void write_render_html(const std::string& out_dir, const std::string& report_file,
                       const nlohmann::ordered_json& report) {
  HtmlPage page(out_dir, "cig render: " + report.value("scene", std::string()));
  page.heading("Run");
  page.key_values(report);
  const nlohmann::ordered_json& frames = report["frames"];
  page.heading("Images");
  std::vector<HtmlFigure> figures;
  for (const auto& fr : frames) {
    const std::string frame = "frame " + json_cell_text(fr["frame"]);
    for (const auto& ch : fr["channels"])
      if (ch.contains("image"))
        figures.push_back({ch["image"].get<std::string>(),
                           frame + " channel " + json_cell_text(ch["channel"]) + " (" + ch.value("name", "") + ")",
                           256});
    if (fr.contains("panorama")) figures.push_back({fr["panorama"].get<std::string>(), frame + " panorama", 768});
  }
  page.figures(figures);
  page.heading("Frames and channels");
  render_table(page, frames);
  page.heading("Report");
  page.link("report", report_file);
  page.write();
}

void write_compare_html(const std::string& out_dir, const std::string& report_file,
                        const nlohmann::ordered_json& report, const std::vector<Comparison>& rows,
                        const ComparisonTotals& totals) {
  HtmlPage page(out_dir, "cig compare: engine " + report.value("engine", std::string()) + " against " +
                             report.value("reference", std::string()) + " on " + report.value("input", std::string()));
  page.heading("Totals");
  nlohmann::ordered_json summary = report;
  summary["images"] = totals.images;
  summary["max_abs"] = {totals.all.max_abs[0], totals.all.max_abs[1], totals.all.max_abs[2]};
  summary["worst_image"] =
      "frame " + std::to_string(totals.worst_frame) + " channel " + std::to_string(totals.worst_channel);
  page.key_values(summary);
  page.heading("Images");
  std::vector<std::vector<HtmlCell>> table;
  std::vector<HtmlFigure> figures;
  for (const Comparison& c : rows) {
    const std::string side = compare_image_file(out_dir, c.frame, c.channel, "side");
    const std::string diff = compare_image_file(out_dir, c.frame, c.channel, "diff");
    table.push_back({{std::to_string(c.frame), ""},
                     {std::to_string(c.channel), ""},
                     {fixed2(c.error.psnr()), ""},
                     {ssim_text(c.error.ssim()), ""},
                     {std::to_string(c.error.max_abs[0]), ""},
                     {std::to_string(c.error.max_abs[1]), ""},
                     {std::to_string(c.error.max_abs[2]), ""},
                     {std::to_string(c.error.pixels_over_2lsb), ""},
                     {std::to_string(c.ids_differ), ""},
                     {"side", side},
                     {"diff", diff}});
    figures.push_back({side, comparison_caption(c), 768});
  }
  page.table({"frame", "ch", "PSNR", "SSIM", "max R", "max G", "max B", "> 2 LSB", "ids differ", "side by side",
              "|error| x 8"},
             table);
  page.paragraph(kHeatMapLegend);
  page.figures(figures);
  page.heading("Report");
  page.link("report", report_file);
  page.write();
}

void write_sweep_html(const std::string& html_dir, const std::string& report_file, const std::string& plot_file,
                      const nlohmann::ordered_json& report, const std::string& table_text) {
  HtmlPage page(html_dir, "cig sweep: engine " + report.value("engine", std::string()) + " on " +
                              report.value("input", std::string()));
  page.heading("Run");
  page.key_values(report);
  page.heading("Combinations");
  page.json_table(report["rows"]);
  page.preformatted(table_text);
  page.heading("Plot");
  page.figures({{plot_file, "PSNR against time per frame; the Pareto frontier joined", 800}});
  page.heading("Report");
  page.link("report", report_file);
  page.write();
}

}  // namespace cig::cli
