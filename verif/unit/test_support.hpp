// Shared helpers of the unit tests.
#pragma once

#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace cig::test {

inline std::string source_path(const std::string& relative) { return std::string(CIG_SOURCE_DIR) + "/" + relative; }

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Fenced ```json blocks of a Markdown file, in order.
inline std::vector<std::string> json_blocks(const std::string& markdown) {
  std::vector<std::string> out;
  const std::string open = "```json\n", close = "```";
  for (std::size_t p = markdown.find(open); p != std::string::npos; p = markdown.find(open, p)) {
    p += open.size();
    std::size_t e = markdown.find(close, p);
    out.push_back(markdown.substr(p, e - p));
    p = e + close.size();
  }
  return out;
}

// True when `text` holds the pieces of `pattern` between its '*'s, in order (the corpus's wildcard).
inline bool contains_pattern(const std::string& text, const std::string& pattern) {
  std::size_t at = 0, from = 0;
  for (;;) {
    const std::size_t star = pattern.find('*', from);
    const std::string piece = pattern.substr(from, star == std::string::npos ? std::string::npos : star - from);
    const std::size_t pos = text.find(piece, at);
    if (pos == std::string::npos) return false;
    at = pos + piece.size();
    if (star == std::string::npos) return true;
    from = star + 1;
  }
}

struct BadInputCase {
  std::string name, file, command, message;
};

inline std::vector<BadInputCase> bad_input_cases() {
  std::vector<BadInputCase> cases;
  std::istringstream in(read_file(source_path("verif/bad_input/expected.tsv")));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    BadInputCase c;
    std::istringstream ls(line);
    std::getline(ls, c.name, '\t');
    std::getline(ls, c.file, '\t');
    std::getline(ls, c.command, '\t');
    std::getline(ls, c.message, '\t');
    cases.push_back(c);
  }
  return cases;
}

}  // namespace cig::test
