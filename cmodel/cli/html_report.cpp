#include "cli/html_report.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include "common/provenance.hpp"
#include "image/image.hpp"

namespace cig::cli {

namespace {

namespace fs = std::filesystem;

// The length of the UTF-8 sequence starting at s[i], 0 when it is not valid UTF-8.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const unsigned char c = (unsigned char)s[i];
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if (((unsigned char)s[i + k] >> 6) != 0x2) return 0;
  return n;
}

const char* const kStyle =
    "body{font-family:sans-serif;margin:1.5em;color:#222;background:#fafafa}"
    "h1{font-size:1.4em}h2{font-size:1.15em;margin-top:1.6em;border-bottom:1px solid #ccc}"
    "table{border-collapse:collapse;margin:0.5em 0}"
    "th,td{border:1px solid #ccc;padding:2px 8px;text-align:right;font-size:0.9em}"
    "th{background:#eee}td.text{text-align:left}"
    "figure{display:inline-block;margin:0 12px 12px 0;vertical-align:top}"
    "figcaption{font-size:0.85em;max-width:100%}img{border:1px solid #999;image-rendering:pixelated}"
    "pre{background:#f0f0f0;padding:0.5em;overflow-x:auto}code{word-break:break-all}";

// The width a PNG declares in its header (IHDR), 0 when the file is not a readable PNG.
int png_width(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char h[24] = {};
  if (!in.read(reinterpret_cast<char*>(h), sizeof h) || h[1] != 'P' || h[2] != 'N' || h[3] != 'G') return 0;
  const unsigned long w = (unsigned long)h[16] << 24 | (unsigned long)h[17] << 16 | (unsigned long)h[18] << 8 | h[19];
  return w > 100000 ? 0 : int(w);
}

bool is_number_text(const std::string& t) {
  return !t.empty() && t.find_first_not_of("0123456789.-+ e") == std::string::npos;
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_length(text, i);
    if (n == 0) {
      out += "\xEF\xBF\xBD";  // U+FFFD for a byte that is not UTF-8
      ++i;
      continue;
    }
    const char c = text[i];
    if (n == 1 && c == '&') out += "&amp;";
    else if (n == 1 && c == '<') out += "&lt;";
    else if (n == 1 && c == '>') out += "&gt;";
    else if (n == 1 && c == '"') out += "&quot;";
    else if (n == 1 && c == '\'') out += "&#39;";
    else out.append(text, i, n);
    i += n;
  }
  return out;
}

std::string url_path(const std::string& relative_path) {
  static const char* const hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : relative_path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') out += char(c);
    else out += std::string("%") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}

std::string relative_path(const std::string& file, const std::string& dir) {
  std::error_code ec;
  // Both resolved the same way (symbolic links of existing folders included), so that the path
  // goes from the one to the other as the file system sees them.
  const fs::path f = fs::weakly_canonical(fs::absolute(file), ec), d = fs::weakly_canonical(fs::absolute(dir), ec);
  const fs::path rel = f.lexically_relative(d);
  return rel.empty() ? fs::path(file).filename().string() : rel.generic_string();
}

std::string json_cell_text(const nlohmann::ordered_json& value, int decimals) {
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
  if (value.is_number_float()) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(decimals) << value.get<double>();
    return s.str();
  }
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array()) {
    std::string s;
    for (const auto& v : value) s += (s.empty() ? "" : " ") + json_cell_text(v, decimals);
    return s;
  }
  return value.is_null() ? "" : value.dump();
}

HtmlPage::HtmlPage(std::string dir, std::string title) : dir_(std::move(dir)), title_(std::move(title)) {}

std::string HtmlPage::index_file(const std::string& dir) { return (fs::path(dir) / "index.html").string(); }

std::string HtmlPage::href(const std::string& file) const { return html_escape(url_path(relative_path(file, dir_))); }

void HtmlPage::heading(const std::string& text) { body_ << "<h2>" << html_escape(text) << "</h2>\n"; }

void HtmlPage::paragraph(const std::string& text) { body_ << "<p>" << html_escape(text) << "</p>\n"; }

void HtmlPage::preformatted(const std::string& text) { body_ << "<pre>" << html_escape(text) << "</pre>\n"; }

void HtmlPage::link(const std::string& label, const std::string& file) {
  body_ << "<p>" << html_escape(label) << ": <a href=\"" << href(file) << "\"><code>"
        << html_escape(relative_path(file, dir_)) << "</code></a></p>\n";
}

void HtmlPage::table(const std::vector<std::string>& header, const std::vector<std::vector<HtmlCell>>& rows) {
  body_ << "<table>\n";
  if (!header.empty()) {
    body_ << "<tr>";
    for (const std::string& h : header) body_ << "<th>" << html_escape(h) << "</th>";
    body_ << "</tr>\n";
  }
  for (const auto& row : rows) {
    body_ << "<tr>";
    for (const HtmlCell& c : row) {
      body_ << (is_number_text(c.text) ? "<td>" : "<td class=\"text\">");
      if (c.file.empty()) body_ << html_escape(c.text);
      else body_ << "<a href=\"" << href(c.file) << "\">" << html_escape(c.text) << "</a>";
      body_ << "</td>";
    }
    body_ << "</tr>\n";
  }
  body_ << "</table>\n";
}

namespace {

// Decimals of a report value by its key: an SSIM's 4 (its tables' precision), else 2.
int decimals_of(const std::string& key) { return key.rfind("ssim", 0) == 0 ? 4 : 2; }

}  // namespace

void HtmlPage::key_values(const nlohmann::ordered_json& object) {
  std::vector<std::vector<HtmlCell>> rows;
  for (auto it = object.begin(); it != object.end(); ++it)
    if (!it.value().is_object() && !(it.value().is_array() && !it.value().empty() && it.value()[0].is_object()))
      rows.push_back({{it.key(), ""}, {json_cell_text(it.value(), decimals_of(it.key())), ""}});
  table({}, rows);
}

void HtmlPage::json_table(const nlohmann::ordered_json& rows) {
  if (!rows.is_array() || rows.empty()) return;
  std::vector<std::string> header;
  for (auto it = rows[0].begin(); it != rows[0].end(); ++it) header.push_back(it.key());
  std::vector<std::vector<HtmlCell>> cells;
  for (const auto& r : rows) {
    cells.emplace_back();
    for (const std::string& key : header)
      cells.back().push_back({r.contains(key) ? json_cell_text(r[key], decimals_of(key)) : "", ""});
  }
  table(header, cells);
}

void HtmlPage::figures(const std::vector<HtmlFigure>& figures) {
  body_ << "<div>\n";
  for (const HtmlFigure& f : figures) {
    const std::string h = href(f.file);
    const int full = png_width(f.file);  // a thumbnail is never wider than its image
    body_ << "<figure><a href=\"" << h << "\"><img src=\"" << h << "\" width=\""
          << (full > 0 ? std::min(full, f.width) : f.width) << "\" alt=\"" << html_escape(f.caption)
          << "\" loading=\"lazy\"></a><figcaption>" << html_escape(f.caption) << "</figcaption></figure>\n";
  }
  body_ << "</div>\n";
}

std::string HtmlPage::html() const {
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(title_)
       << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>" << html_escape(title_) << "</h1>\n"
       << body_.str() << "<h2>Provenance</h2>\n<table>\n";
  const nlohmann::ordered_json p = provenance_json();
  for (auto it = p.begin(); it != p.end(); ++it)
    page << "<tr><th>" << html_escape(it.key()) << "</th><td class=\"text\"><code>"
         << html_escape(json_cell_text(it.value())) << "</code></td></tr>\n";
  page << "</table>\n</body>\n</html>\n";
  return page.str();
}

void HtmlPage::write() const { write_text_file(index_file(dir_), html()); }

}  // namespace cig::cli
