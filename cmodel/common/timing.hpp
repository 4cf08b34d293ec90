// The one wall-clock helper of the C model: every "ms" and "seconds" in the reports is measured
// with it (steady_clock, so a clock adjustment never makes a stage take negative time).
#pragma once

#include <chrono>

namespace cig {

using Clock = std::chrono::steady_clock;

inline double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace cig
