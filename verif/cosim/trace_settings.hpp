// What a co-simulation's FST trace holds (`cig cosim --trace FILE.fst [--trace-cycles A:B]
// [--trace-depth N]`), for both processors: one image (the next run after trace_to), its cycles
// first..last (inclusive, in the image's own numbering: the quadtree's cycles 0..C, stage F's
// 1..C), each cycle one clock period of the architecture model on the FST's time axis (the rising
// edge that starts cycle c at c x period, the falling edge half a period later), the signals down
// to `depth` scope levels below the model's TOP.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace cig::cosim {

struct TraceSettings {
  std::string file;
  long long first = 0;
  long long last = std::numeric_limits<long long>::max();
  std::int64_t period_ps = 10000;  // the clock period, in ps (the quadtree model's 100 MHz)
  int depth = 0;                   // 0: every scope; N: N levels below TOP (Verilator's dumpvars)
};

// The FST's time unit and the edges in it: ns when the period is a whole number of ns (2 or more),
// else ps. The falling edge is drawn half a period after the rising one, rounded down to the unit
// (3 ns: at 1 ns); the design uses only rising edges.
struct TraceTimeScale {
  const char* unit = "1ns";
  std::uint64_t period = 10, fall = 5;  // in `unit`
  explicit TraceTimeScale(std::int64_t period_ps) {
    const bool ns = period_ps % 1000 == 0 && period_ps >= 2000;
    unit = ns ? "1ns" : "1ps";
    period = std::uint64_t(ns ? period_ps / 1000 : period_ps < 2 ? 2 : period_ps);
    fall = period / 2;
  }
};

// Cycles between two calls of a run's progress callback (RtlRunner::on_cycles).
constexpr long long kProgressCycles = 4096;

}  // namespace cig::cosim
