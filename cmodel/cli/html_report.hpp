// The index.html that `cig render --html`, `cig compare --html` and `cig sweep --html` write
// (docs/review_outputs.md): one plain HTML page (inline CSS, no JavaScript) gathering a run's
// images as thumbnails linking to the full files, its tables, a link to its report.json and its
// provenance. Every string from the user (paths, scene names, the command line) is escaped; links
// are relative to the page's folder, so the folder can be moved or served as it is.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cig::cli {

// Text for HTML content and attribute values: & < > " ' as entities; bytes that are not UTF-8 as
// U+FFFD (a path may hold any bytes).
std::string html_escape(const std::string& text);
// A relative path as a URL path: every byte but letters, digits, - . _ ~ and / percent-encoded.
std::string url_path(const std::string& relative_path);
// `file` relative to the folder `dir` (both as given on the command line).
std::string relative_path(const std::string& file, const std::string& dir);

struct HtmlCell {
  std::string text;
  std::string file;  // "" = plain text; else a link to this file (a path as given)
};

struct HtmlFigure {
  std::string file;     // the image (a path as given)
  std::string caption;  // under the thumbnail
  int width = 256;      // thumbnail width in the page (at most the image's)
};

class HtmlPage {
 public:
  // The page dir/index.html, titled `title`.
  HtmlPage(std::string dir, std::string title);

  static std::string index_file(const std::string& dir);  // dir/index.html

  void heading(const std::string& text);
  void paragraph(const std::string& text);
  void preformatted(const std::string& text);
  void link(const std::string& label, const std::string& file);  // "label: <file>" as a link
  // No header row when `header` is empty.
  void table(const std::vector<std::string>& header, const std::vector<std::vector<HtmlCell>>& rows);
  // The scalar members of a JSON object as a two-column table (nested values skipped).
  void key_values(const nlohmann::ordered_json& object);
  // A JSON array of objects as a table, the columns the first object's keys.
  void json_table(const nlohmann::ordered_json& rows);
  void figures(const std::vector<HtmlFigure>& figures);

  // The whole page, with the run's provenance (common/provenance.hpp) as its last section.
  std::string html() const;
  // Writes it to index_file(dir) (atomically: write_text_file).
  void write() const;

 private:
  std::string href(const std::string& file) const;
  std::string dir_, title_;
  std::ostringstream body_;
};

// A JSON value as table text: numbers with `decimals` decimals when not integers, arrays joined by
// spaces, booleans yes / no.
std::string json_cell_text(const nlohmann::ordered_json& value, int decimals = 2);

}  // namespace cig::cli
