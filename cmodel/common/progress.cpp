#include "common/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace cig {

bool Progress::stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, long long steps)
    : Progress(std::move(label), steps, std::cerr, Style{stderr_is_terminal()}) {}

Progress::Progress(std::string label, long long steps, std::ostream& os, Style style)
    : label_(std::move(label)), steps_(steps), os_(os), style_(style), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  std::lock_guard<std::mutex> guard(lock_);
  if (line_open_) os_ << "\n" << std::flush;
}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::show(const std::string& line) {
  if (style_.terminal) {
    os_ << "\r" << line << "\x1b[K";  // erase what a longer line left
    line_open_ = true;
  } else {
    os_ << line << "\n";
  }
  os_ << std::flush;
}

void Progress::within(long long done, long long total, const char* unit) {
  std::lock_guard<std::mutex> guard(lock_);
  const double t = elapsed();
  const double interval = style_.terminal ? style_.terminal_interval_s : style_.log_interval_s;
  if (t - last_shown_ < interval || (style_.terminal && t < style_.first_after_s)) return;
  if (!style_.terminal && t < style_.log_interval_s) return;  // a log hears of a step when it is over
  last_shown_ = t;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s: step %lld/%lld: %lld/%lld %s (%.0f %%), %.1f s", label_.c_str(), done_steps_ + 1,
                steps_, done, total, unit, total > 0 ? 100.0 * double(done) / double(total) : 0.0, t);
  show(buf);
}

void Progress::note(const std::string& line) {
  if (line.empty()) return;
  std::lock_guard<std::mutex> guard(lock_);
  if (line_open_) os_ << "\r\x1b[K";
  line_open_ = false;
  os_ << line << std::flush;
}

void Progress::step(const std::string& text) {
  std::lock_guard<std::mutex> guard(lock_);
  ++done_steps_;
  const double t = elapsed();
  const bool last = done_steps_ >= steps_;
  if (style_.terminal) {
    if (t < style_.first_after_s && !line_open_) return;  // a quick run prints nothing
    if (!last && t - last_shown_ < style_.terminal_interval_s) return;
  }
  last_shown_ = t;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%lld/%lld", done_steps_, steps_);
  char when[32];
  std::snprintf(when, sizeof when, " (%.1f s)", t);
  show(label_ + ": " + buf + " " + text + when);
}

}  // namespace cig
