// What the commands write for a person to review a run (docs/review_outputs.md): the side-by-side
// image of `cig compare --out` (image/review_image.hpp) and the index.html of `--html` on
// `cig render`, `cig compare` and `cig sweep` (html_report.hpp). Each command calls these at three
// points: the checks before any work (prepare_*), while it writes its images, and at its end.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/frame_jobs.hpp"
#include "image/raster_image.hpp"

namespace cig::cli {

// DIR/frame_KKKK_chC_KIND.png: the file names of `cig compare --out` (KIND diff or side).
std::string compare_image_file(const std::string& dir, int frame, int channel, const std::string& kind);

// `cig compare --out DIR`: DIR/frame_KKKK_chC_side.png, engine | reference | error map, the
// comparison's numbers in its title strip.
void write_side_image(const std::string& dir, const Comparison& c, const std::string& engine,
                      const std::string& reference, const RasterImage& got, const RasterImage& want);

// Before any work. render: DIR/index.html can be written (DIR checked by the command).
void prepare_render_html(const std::string& out_dir);
// compare: --html needs --out (InputError otherwise); the report goes to DIR/report.json unless
// --report names a file.
void prepare_compare_html(const std::string& out_dir, std::string& report_file);
// sweep: --html DIR; the report and the plot go to DIR/report.json and DIR/plot.png unless --report
// and --plot name files (the command then checks those, gnuplot included).
void prepare_sweep_html(const std::string& html_dir, std::string& report_file, std::string& plot_file);

// At the end, after the report is written: DIR/index.html.
void write_render_html(const std::string& out_dir, const std::string& report_file,
                       const nlohmann::ordered_json& report);
void write_compare_html(const std::string& out_dir, const std::string& report_file,
                        const nlohmann::ordered_json& report, const std::vector<Comparison>& rows,
                        const ComparisonTotals& totals);
void write_sweep_html(const std::string& html_dir, const std::string& report_file, const std::string& plot_file,
                      const nlohmann::ordered_json& report, const std::string& table_text);

}  // namespace cig::cli
