// cig wordlength [--ranges 10000,100000] [--bits 40:72] [--views N] [--lattice L] [--seed S]
//                [--plot FILE.png] [--report FILE.json]
#include "cli/wordlength_command.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/gnuplot_plot.hpp"
#include "cli/output_plan.hpp"
#include "common/error.hpp"
#include "studies/word_length_study.hpp"

namespace cig::cli {

void WordLengthCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("wordlength",
                           "seed 002's word-length claims: visibility and depth errors against W for the inverse "
                           "parameter, a Z-buffer, an inverse Z-buffer and exact Z");
  sub->add_option("--ranges", ranges_text, "eye depths R of the views, metres, comma-separated (default 10000,100000)");
  sub->add_option("--bits", bits_text, "word lengths A:B, inclusive (default 40:72)");
  sub->add_option("--views", views, "views per range (default 16)");
  sub->add_option("--lattice", lattice, "samples a side L (default 256; 2048 = 512 lines at 16 spp)");
  sub->add_option("--seed", seed, "seed of the views (default 2)");
  sub->add_option("--plot", plot_file, "write the errors against W as a PNG (gnuplot)");
  sub->add_option("--report", report_file, "write the table as JSON");
}

namespace {

std::vector<double> parse_ranges(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::size_t used = 0;
    double r = 0;
    try {
      r = std::stod(item, &used);
    } catch (const std::logic_error&) { used = 0; }
    if (item.empty() || used != item.size() || !std::isfinite(r))
      throw InputError("", "--ranges", "'" + text + "' is not a comma-separated list of ranges in metres");
    out.push_back(r);
  }
  if (out.empty() || text.back() == ',')
    throw InputError("", "--ranges", "'" + text + "' is not a comma-separated list of ranges in metres");
  return out;
}

void parse_bits(const std::string& text, int& a, int& b) {
  const auto colon = text.find(':');
  auto bad = [&] { throw InputError("", "--bits", "'" + text + "' is not of the form A:B (word lengths, A <= B)"); };
  if (colon == std::string::npos) bad();
  try {
    std::size_t u1 = 0, u2 = 0;
    a = std::stoi(text.substr(0, colon), &u1);
    b = std::stoi(text.substr(colon + 1), &u2);
    if (u1 != colon || u2 != text.size() - colon - 1) bad();
  } catch (const std::logic_error&) { bad(); }
}

// The seed's figure for a range (57 bits to 10 km, 64 to 100 km), 0 for other ranges.
int seed_bits(double range) { return range == 10000 ? 57 : range == 100000 ? 64 : 0; }

std::string range_name(double r) {
  std::ostringstream s;
  if (r >= 1000 && std::fmod(r, 1000) == 0) s << r / 1000 << " km";
  else s << r << " m";
  return s.str();
}

std::string bits_name(int w) { return w < 0 ? "none" : std::to_string(w); }

const WordLengthRow* find_row(const WordLengthStudy& s, double range, DepthMethod m) {
  for (const WordLengthRow& r : s.rows)
    if (r.range == range && r.method == m) return &r;
  return nullptr;
}

void print_table(const WordLengthStudy& s) {
  const WordLengthOptions& o = s.options;
  std::cout << "cig wordlength: " << o.views << " view(s) per range of an L x L lattice, L = " << o.lattice << " ("
            << s.samples << " samples per range, " << s.uncertain
            << " on an edge within binary128's margin left out), seed " << o.seed << "; Z-buffer words: " << kZIntBits
            << " integer bits, inverse parameter and 1/Z: 8\n"
            << "range    method         W  wrong faces  edge ties  depth > 1 mm  max depth error (m)\n";
  for (const WordLengthRow& r : s.rows)
    for (const WordLengthCell& c : r.cells)
      std::cout << std::left << std::setw(9) << range_name(r.range) << depth_method_letter(r.method) << " "
                << std::setw(12) << depth_method_name(r.method) << std::right << std::setw(3) << c.bits << std::setw(13)
                << c.wrong_faces << std::setw(11) << c.edge_ties << std::setw(14) << c.depth_errors << std::setw(21)
                << std::scientific << std::setprecision(3) << c.max_depth_error << std::defaultfloat << "\n";
}

void print_summary(const WordLengthStudy& s) {
  const WordLengthOptions& o = s.options;
  std::cout << "\nsmallest W with no wrong face and no depth error > 1 mm from there to " << o.max_bits
            << " bits (L = " << o.lattice << "):\nrange    invparam  z-buffer  inverse-z  exact-z  bound (a)  seed\n";
  for (double range : o.ranges) {
    std::cout << std::left << std::setw(9) << range_name(range) << std::right;
    const int widths[4] = {10, 10, 11, 9};
    for (int m = 0; m < 4; ++m)
      std::cout << std::setw(widths[m]) << bits_name(find_row(s, range, kDepthMethods[m])->smallest_bits());
    std::cout << std::setw(9) << word_length_bound_bits(range, o.lattice) << std::setw(6)
              << (seed_bits(range) ? std::to_string(seed_bits(range)) : "-") << "\n";
  }
  std::cout << "bound (a): W >= 8 + log2(2 L R^2 / 1 mm) (word_length_study.hpp)\n";
}

// The seed's claims, one line each: reproduced or refuted, with the numbers.
std::vector<std::string> verdicts(const WordLengthStudy& s) {
  std::vector<std::string> out;
  const WordLengthOptions& o = s.options;
  for (double range : o.ranges) {
    const int want = seed_bits(range);
    if (want == 0) continue;
    const WordLengthRow* a = find_row(s, range, DepthMethod::kInverseParameter);
    std::ostringstream v;
    v << "claim \"" << want << " bits to " << range_name(range) << "\" (inverse parameter, L = " << o.lattice << "): ";
    if (want < o.min_bits || want > o.max_bits) {
      v << "not measured (W = " << want << " outside " << o.min_bits << ":" << o.max_bits << ")";
    } else {
      const WordLengthCell& c = a->cells[std::size_t(want - o.min_bits)];
      const int smallest = a->smallest_bits();
      if (c.clean() && smallest >= 0 && smallest <= want)
        v << "reproduced: " << want << " bits give 0 wrong faces and 0 depth errors > 1 mm (max " << std::scientific
          << std::setprecision(2) << c.max_depth_error << std::defaultfloat << " m); the smallest clean W here is "
          << smallest << " (bound " << word_length_bound_bits(range, o.lattice) << "; at L = 2048 the bound is "
          << word_length_bound_bits(range, 2048) << ")";
      else
        v << "refuted: " << want << " bits give " << c.wrong_faces << " wrong faces and " << c.depth_errors
          << " depth errors > 1 mm; the smallest clean W is " << bits_name(smallest);
    }
    out.push_back(v.str());
  }
  for (double range : o.ranges) {
    const WordLengthCell& a = find_row(s, range, DepthMethod::kInverseParameter)->cells.back();
    const WordLengthCell& b = find_row(s, range, DepthMethod::kZBuffer)->cells.back();
    const WordLengthCell& c = find_row(s, range, DepthMethod::kInverseZBuffer)->cells.back();
    const bool reproduced = b.wrong_faces > 0 && a.wrong_faces == 0 && c.wrong_faces == 0;
    std::ostringstream v;
    v << "claim \"a direct Z-buffer makes visibility errors that 1/t avoids\" at " << range_name(range)
      << ", W = " << o.max_bits << ": " << (reproduced ? "reproduced" : "refuted for the visible face") << ": z-buffer "
      << b.wrong_faces << " wrong faces, inverse parameter " << a.wrong_faces << ", inverse Z-buffer " << c.wrong_faces
      << "; the z-buffer's depth is off by up to " << std::scientific << std::setprecision(2) << b.max_depth_error
      << " m (" << b.depth_errors << " samples > 1 mm), the inverse parameter's by " << a.max_depth_error
      << std::defaultfloat << " m";
    out.push_back(v.str());
  }
  return out;
}

nlohmann::ordered_json to_json(const WordLengthStudy& s, const std::vector<std::string>& claims) {
  const WordLengthOptions& o = s.options;
  nlohmann::ordered_json j;
  j["command"] = "wordlength";
  j["ranges_m"] = o.ranges;
  j["bits"] = {o.min_bits, o.max_bits};
  j["views"] = o.views;
  j["lattice"] = o.lattice;
  j["seed"] = o.seed;
  j["samples_per_range"] = s.samples;
  j["uncertain_samples"] = s.uncertain;
  j["z_int_bits"] = kZIntBits;
  j["rows"] = nlohmann::ordered_json::array();
  for (const WordLengthRow& r : s.rows) {
    nlohmann::ordered_json row = {{"range_m", r.range},
                                  {"method", depth_method_name(r.method)},
                                  {"smallest_bits", r.smallest_bits()},
                                  {"bound_bits", word_length_bound_bits(r.range, o.lattice)},
                                  {"seed_bits", seed_bits(r.range)}};
    for (const WordLengthCell& c : r.cells)
      row["cells"].push_back({{"bits", c.bits},
                              {"wrong_faces", c.wrong_faces},
                              {"edge_ties", c.edge_ties},
                              {"depth_errors", c.depth_errors},
                              {"max_depth_error_m", c.max_depth_error}});
    j["rows"].push_back(row);
  }
  j["verdicts"] = claims;
  return j;
}

// Two panels: samples in error (log y; a clean W is left out) and the largest depth error (log y,
// the 1 mm line), against W, one line per range x method.
void write_plot(const std::string& plot_file, const WordLengthStudy& s) {
  const GnuplotJob job("wordlength");
  std::ostringstream errors, depth;
  errors
      << "set multiplot layout 1,2 title \"cig wordlength: L = " << s.options.lattice << ", " << s.options.views
      << " views per range\" noenhanced\nset grid\nset logscale y\nset xlabel 'word length W (bits)'\n"
      << "set key top right font ',9' noenhanced\nset ylabel 'samples with a wrong face or depth error > 1 mm'\nplot ";
  depth << "set ylabel 'largest depth error (m)'\nset format y '10^{%L}'\nset key bottom left\nplot " << 1e-3
        << " with lines dt 2 lw 2 lc rgb 'black' title '1 mm', ";
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    const WordLengthRow& r = s.rows[k];
    const std::string data = job.file("row" + std::to_string(k) + ".dat");
    std::ofstream out(data);
    for (const WordLengthCell& c : r.cells)
      out << c.bits << " " << (c.in_error > 0 ? std::to_string(c.in_error) : "NaN") << " " << std::scientific
          << c.max_depth_error << std::defaultfloat << "\n";  // a zero (no error) is left out by log y
    const std::string title =
        range_name(r.range) + " " + depth_method_letter(r.method) + " " + depth_method_name(r.method);
    const std::string style = std::string(" with linespoints lw ") +
                              (r.method == DepthMethod::kInverseParameter ? "5" : "2") + " dt " +
                              std::string(r.range == s.options.ranges[0] ? "1 pt 6" : "3 pt 7") + " lc " +
                              std::to_string(int(r.method) + 1) + " title '" + title + "'";
    errors << (k ? ", " : "") << "'" << data << "' using 1:2" << style;
    depth << (k ? ", " : "") << "'" << data << "' using 1:3" << style;
  }
  job.draw(errors.str() + "\n" + depth.str() + "\nunset multiplot\n", 1400, 620, plot_file, "--plot");
}

}  // namespace

int WordLengthCommand::run() {
  WordLengthOptions o;
  o.ranges = parse_ranges(ranges_text);
  parse_bits(bits_text, o.min_bits, o.max_bits);
  o.views = views;
  o.lattice = lattice;
  o.seed = seed;
  check_word_length_options(o);
  OutputPlan plan;
  if (!report_file.empty()) plan.file(report_file, "--report");
  if (!plot_file.empty()) plan.file(plot_file, "--plot");
  plan.check();
  check_plot_output(plot_file, "--plot");
  WordLengthStudy s;
  {
    Progress progress("cig wordlength", (long long)(o.ranges.size()) * o.views);
    s = run_word_length_study(o, &progress);
  }
  const std::vector<std::string> claims = verdicts(s);
  if (!plot_file.empty()) write_plot(plot_file, s);
  if (!report_file.empty()) write_text_file(report_file, report_text(to_json(s, claims)));
  print_table(s);
  print_summary(s);
  for (const std::string& c : claims) std::cout << c << "\n";
  return 0;
}

}  // namespace cig::cli
