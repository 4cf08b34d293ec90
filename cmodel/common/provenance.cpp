#include "common/provenance.hpp"

#include <ctime>
#include <mutex>

namespace cig {
namespace {

struct Recorded {
  std::mutex lock;
  std::string command_line;
  std::string date;
};

Recorded& recorded() {
  static Recorded r;
  return r;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

std::string shell_quote(const std::string& arg) {
  if (arg.empty()) return "''";
  bool plain = true;
  for (char c : arg) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      std::string("-_./:=,+@%").find(c) != std::string::npos;
    plain = plain && safe;
  }
  if (plain) return arg;
  std::string q = "'";
  for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void record_command_line(int argc, const char* const* argv) {
  record_command_line(argc > 0 ? shell_quote(argv[0]) : std::string(), argc, argv);
}

void record_command_line(const std::string& program_words, int argc, const char* const* argv) {
  std::string line = program_words;
  for (int k = 1; k < argc; ++k) line += " " + shell_quote(argv[k]);
  Recorded& r = recorded();
  std::lock_guard<std::mutex> guard(r.lock);
  r.command_line = line;
  r.date = utc_now();
}

std::string command_line() {
  Recorded& r = recorded();
  std::lock_guard<std::mutex> guard(r.lock);
  return r.command_line;
}

std::string run_date() {
  Recorded& r = recorded();
  std::lock_guard<std::mutex> guard(r.lock);
  if (r.date.empty()) r.date = utc_now();
  return r.date;
}

std::string version_line(const std::string& program) {
  return program + " " + build_version() + " (commit " + build_commit() + ")";
}

nlohmann::ordered_json provenance_json(const std::string& program) {
  return {{"program", program},
          {"version", build_version()},
          {"commit", build_commit()},
          {"command_line", command_line()},
          {"date", run_date()}};
}

}  // namespace cig
