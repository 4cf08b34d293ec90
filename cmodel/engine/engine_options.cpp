#include "engine/engine_options.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/error.hpp"
#include "formatter/formatter_twin.hpp"
#include "hls/formatter/sample_lattice.hpp"

namespace cig {

namespace {

// "%g" without its exponent's plus sign and leading zeros: 1e6, not 1e+06.
std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  std::string s = buf;
  const auto e = s.find("e+");
  if (e != std::string::npos) s.erase(e + 1, s.find_first_not_of("+0", e + 1) - (e + 1));
  return s;
}

// "a, b or c" (or "a|b|c" with a separator).
std::string joined(const std::vector<std::string>& items, const std::string& sep, const std::string& last_sep) {
  std::string s;
  for (std::size_t k = 0; k < items.size(); ++k) s += (k == 0 ? "" : k + 1 == items.size() ? last_sep : sep) + items[k];
  return s;
}

// A whole decimal integer (optional sign), nothing else.
bool parse_integer(const std::string& text, long& value) {
  if (text.empty()) return false;
  errno = 0;
  char* end = nullptr;
  value = std::strtol(text.c_str(), &end, 10);
  return errno == 0 && *end == '\0' && !std::isspace(static_cast<unsigned char>(text[0]));
}

bool parse_real(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0' && std::isfinite(value);
}

bool in_range(const EngineOptionSpec& spec, const std::string& value) {
  using Kind = EngineOptionSpec::Kind;
  long i = 0;
  double r = 0;
  switch (spec.kind) {
    case Kind::kChoice:
      return std::find(spec.choices.begin(), spec.choices.end(), value) != spec.choices.end();
    case Kind::kInteger:
      return parse_integer(value, i) && double(i) >= spec.min && double(i) <= spec.max;
    case Kind::kReal:
      return parse_real(value, r) && r > spec.min && r <= spec.max;
    case Kind::kSyntax:
      spec.check(value);
      return true;  // the syntax's own InputError
  }
  return false;
}

}  // namespace

std::string EngineOptionSpec::range() const {
  switch (kind) {
    case Kind::kChoice:
      return joined(choices, "|", "|");
    case Kind::kInteger:
      return number_text(min) + ".." + number_text(max);
    case Kind::kReal:
      return "(" + number_text(min) + ", " + number_text(max) + "]";
    case Kind::kSyntax:
      return syntax;
  }
  return "";
}

std::string EngineOptionSpec::range_in_words() const {
  if (kind == Kind::kChoice) return joined(choices, ", ", " or ");
  if (kind == Kind::kReal) return "> " + number_text(min) + " and <= " + number_text(max);
  return range();
}

namespace {

// The fields every kind of setting has.
EngineOptionSpec option_of(EngineOptionSpec::Kind kind, std::string key, std::string default_value, std::string help,
                           std::string shorthand = "") {
  EngineOptionSpec s;
  s.kind = kind;
  s.key = std::move(key);
  s.default_value = std::move(default_value);
  s.help = std::move(help);
  s.shorthand = std::move(shorthand);
  return s;
}

}  // namespace

EngineOptionSpec choice_option(std::string key, std::vector<std::string> choices, std::string default_value,
                               std::string help, std::string shorthand) {
  EngineOptionSpec s = option_of(EngineOptionSpec::Kind::kChoice, std::move(key), std::move(default_value),
                                 std::move(help), std::move(shorthand));
  s.choices = std::move(choices);
  return s;
}

EngineOptionSpec integer_option(std::string key, int min, int max, std::string default_value, std::string help) {
  EngineOptionSpec s =
      option_of(EngineOptionSpec::Kind::kInteger, std::move(key), std::move(default_value), std::move(help));
  s.min = min;
  s.max = max;
  return s;
}

EngineOptionSpec real_option(std::string key, double above, double max, std::string default_value, std::string help) {
  EngineOptionSpec s =
      option_of(EngineOptionSpec::Kind::kReal, std::move(key), std::move(default_value), std::move(help));
  s.min = above;
  s.max = max;
  return s;
}

EngineOptionSpec real_option(std::string key, double above, double max, double default_value, std::string help) {
  return real_option(std::move(key), above, max, number_text(default_value), std::move(help));
}

EngineOptionSpec syntax_option(std::string key, std::string syntax, void (*check)(const std::string&),
                               std::string default_value, std::string help, std::string shorthand) {
  EngineOptionSpec s = option_of(EngineOptionSpec::Kind::kSyntax, std::move(key), std::move(default_value),
                                 std::move(help), std::move(shorthand));
  s.syntax = std::move(syntax);
  s.check = check;
  return s;
}

EngineOptionSpec samples_per_pixel_option(int max_side_log2) {
  std::vector<std::string> values;
  for (int t = 0; t <= max_side_log2; ++t) values.push_back(std::to_string(1 << (2 * t)));
  return choice_option("spp", values, std::to_string(1 << (2 * hls::kDefaultSideLog2)), "samples per pixel");
}

EngineOptionSpec subpixel_option(bool float_reference) {
  const std::string grid = "the formatter grid at 1/2^B pixel, log2(raster) + B bits";
  return integer_option("subpixel", 0, kMaxSubpixelBits, "",
                        float_reference ? grid + ", up to " + std::to_string(kMaxGridBits) +
                                              ", the grid --snap snaps to (with --snap only); unset: eq. 1's " +
                                              std::to_string(kSeedGridBits) + " bits"
                                        : grid + ", up to eq. 1's " + std::to_string(kSeedGridBits) + " (B <= " +
                                              std::to_string(kSeedGridBits - 9) + " at 512 lines); unset: eq. 1's");
}

int EngineSettings::integer(const std::string& key) const { return std::stoi(text(key)); }
double EngineSettings::real(const std::string& key) const { return std::stod(text(key)); }

int EngineSettings::side_log2() const {
  const int spp = integer("spp");
  int t = 0;
  while ((1 << (2 * t)) < spp) ++t;
  return t;
}

EngineSettings parse_engine_options(const std::string& engine, const std::vector<EngineOptionSpec>& specs,
                                    const std::map<std::string, std::string>& params) {
  EngineSettings settings;
  for (const EngineOptionSpec& spec : specs) settings.values()[spec.key] = spec.default_value;
  for (const auto& param : params) {
    const std::string& key = param.first;  // a named reference: a lambda may not capture a binding (C++17)
    const std::string& value = param.second;
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const EngineOptionSpec& s) { return s.key == key; });
    if (spec == specs.end()) {
      std::vector<std::string> takes;
      for (const EngineOptionSpec& s : specs) takes.push_back(s.key + "=" + s.range());
      throw InputError("", "--engine-opt",
                       "engine '" + engine + "' takes no option '" + key + "' (it takes " +
                           (takes.empty() ? std::string("none") : joined(takes, ", ", ", ")) + ")");
    }
    if (!in_range(*spec, value))
      throw InputError("", spec->shorthand.empty() ? "--engine-opt" : spec->shorthand,
                       "engine '" + engine + "': " + key + "='" + value + "' is not " + spec->range_in_words() + " (" +
                           spec->help + ")");
    settings.values()[key] = value;
  }
  return settings;
}

}  // namespace cig
