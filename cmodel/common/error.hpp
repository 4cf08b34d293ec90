// Errors of the C model. An InputError is a rule broken by an input (scene file, polygon list,
// OBJ model, command-line option): it names the file, the place in it and the rule, so that the
// CLI can print it and exit non-zero before writing any output.
#pragma once

#include <stdexcept>
#include <string>

namespace cig {

class InputError : public std::runtime_error {
 public:
  // file: the input's path ("" for command-line options); where: JSON path, "line N", option name.
  InputError(std::string file, std::string where, std::string rule)
      : std::runtime_error(format(file, where, rule)),
        file_(std::move(file)),
        where_(std::move(where)),
        rule_(std::move(rule)) {}

  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& rule() const { return rule_; }

 private:
  static std::string format(const std::string& file, const std::string& where, const std::string& rule) {
    std::string s = file;
    if (!where.empty()) s += (s.empty() ? "" : ": ") + where;
    return s + (s.empty() ? "" : ": ") + rule;
  }
  std::string file_, where_, rule_;
};

}  // namespace cig
