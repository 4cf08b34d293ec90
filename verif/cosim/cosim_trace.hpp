// `cig cosim --trace FILE.fst [--trace-cycles A:B] [--trace-depth N]` for both processors: the
// trace holds the first image run (the quadtree's cycles 0..C, stage F's 1..C; the window A:B of
// them), one clock period of the architecture model per cycle on the FST's time axis; before it a
// warning on stderr when the trace would be large (estimated from the image's cycles, which the
// model counts first, and the measured bytes and seconds per traced cycle of the configuration);
// after it the save file FILE.gtkw (gtkw_save.hpp) and a summary line. Bad requests (a window
// without --trace, B < A, beyond the image's cycles) are input errors before any trace is written.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "gtkw_save.hpp"
#include "trace_settings.hpp"

namespace cig::cli {

// What tracing one cycle costs in a configuration (measured: verif/cosim/README.md "Tracing").
struct TraceCost {
  double bytes_per_cycle = 0;
  double seconds_per_cycle = 0;
};
// The configurations' costs: the quadtree's by architecture ("7p2t"), stage F's by "W=64, N_PP=64".
TraceCost trace_cost(const std::string& configuration);

class OutputPlan;

class CosimTrace {
 public:
  // The options as given; the window's syntax and the option pairing checked (InputError).
  CosimTrace(std::string file, const std::string& cycles_text, int depth, bool cycles_given, bool depth_given);
  bool on() const { return !file_.empty(); }
  const std::string& file() const { return file_; }
  std::string save_file() const { return file_ + ".gtkw"; }
  // Before any work: the trace and its save file among the run's outputs (checked with the rest).
  void declare_outputs(OutputPlan& plan) const;
  // The traced image's cycles known (first_cycle..last_cycle): the window checked against them
  // (InputError), the warning for a large trace, the trace's folder made, the settings to trace
  // with.
  cosim::TraceSettings plan(long long first_cycle, long long last_cycle, std::int64_t period_ps, const TraceCost& cost,
                            const std::string& image);
  // After the traced image: the save file written, the summary line (stdout), the report's entry.
  nlohmann::ordered_json finish(cosim::TracedDesign design, double image_seconds) const;
  // An input error after the trace began: the trace and its save file removed.
  void discard() const;

 private:
  std::string file_;
  long long first_ = -1, last_ = -1;  // the window asked for (-1: the whole image)
  int depth_ = 0;
  cosim::TraceSettings settings_;
  std::string image_;
};

}  // namespace cig::cli
