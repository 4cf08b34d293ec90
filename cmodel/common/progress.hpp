// Progress of a long run on stderr (frames, sweep points, word-length ranges, co-simulated frames
// and cycles). On a terminal: one line rewritten in place, at most 5 times a second, shown only
// once the run has taken a second (a quick run prints nothing). Elsewhere (a log, CI): one line per
// finished step, and within a long step a line at most every 10 s, so that a log shows the run is
// alive without flooding it. Nothing goes to stdout: tables and results stay clean.
#pragma once

#include <chrono>
#include <iosfwd>
#include <mutex>
#include <string>

namespace cig {

class Progress {
 public:
  struct Style {
    bool terminal = false;
    double first_after_s = 1.0;  // terminal: nothing before this
    double terminal_interval_s = 0.2;
    double log_interval_s = 10.0;  // not a terminal: a line within a step at most this often
  };
  // On stderr; terminal when stderr is one (isatty).
  Progress(std::string label, long long steps);
  Progress(std::string label, long long steps, std::ostream& os, Style style);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();  // ends a terminal line

  // Within the current step: `done` of `total` units ("cycles", "samples"). Cheap when nothing is
  // due, but it reads the clock: call it every few thousand units, not every unit.
  void within(long long done, long long total, const char* unit);
  // One more step finished; `text` says which ("frame 3 channel 1: 124845 cycles").
  void step(const std::string& text);
  // A line of its own (a warning, ending in a newline) between progress lines: on a terminal the
  // open progress line is cleared first and shown again at the next update. "" prints nothing.
  void note(const std::string& line);
  long long steps_done() const { return done_steps_; }
  static bool stderr_is_terminal();

 private:
  double elapsed() const;
  void show(const std::string& line);

  std::string label_;
  long long steps_;
  std::ostream& os_;
  Style style_;
  std::chrono::steady_clock::time_point start_;
  double last_shown_ = -1e9;
  long long done_steps_ = 0;
  bool line_open_ = false;
  std::mutex lock_;
};

}  // namespace cig
