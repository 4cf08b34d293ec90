// A Verilated model as both co-simulations hold it: its context, its top, the optional FST trace
// and the clock edges. The wrappers (qt_raster_cosim_tb.sv, ip_array_cosim_tb.sv) register every
// stimulus input, so only the rising edge evaluates the design. Include after the generated
// headers, inside the diagnostics push that silences them.
//
// The trace (trace_settings.hpp) holds one image: the runner numbers its cycles (begin_cycle
// before the rising edge that starts cycle c) and ends it (end_image closes the file); edges
// outside an image (reset, table writes, the frame start) and outside the window first..last are
// not dumped. Cycle c's rising edge is at c x period on the FST's time axis.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include <verilated.h>
#include <verilated_fst_c.h>

#include "trace_settings.hpp"

namespace cig::cosim::detail {

// kTrace: the model was Verilated with --trace-fst (open_trace works).
template <class Top, bool kTrace>
class VerilatedModel {
 public:
  VerilatedModel() : ctx_(std::make_unique<VerilatedContext>()) {
    ctx_->traceEverOn(kTrace);
    top_ = std::make_unique<Top>(ctx_.get());
  }
  ~VerilatedModel() {
    if (fst_) fst_->close();
    top_->final();
  }
  VerilatedModel(const VerilatedModel&) = delete;
  VerilatedModel& operator=(const VerilatedModel&) = delete;

 protected:
  void open_trace(const TraceSettings& s) {
    if constexpr (kTrace) {
      const TraceTimeScale scale(s.period_ps);
      fst_ = std::make_unique<VerilatedFstC>();
      // $dumpvars(depth, TOP): only the signals down to `depth` scope levels below TOP are declared.
      if (s.depth > 0) fst_->dumpvars(s.depth, "TOP");
      top_->trace(fst_.get(), 99);  // Verilator 5.006 ignores the levels argument
      fst_->set_time_unit(scale.unit);
      fst_->set_time_resolution(scale.unit);
      fst_->open(s.file.c_str());
      first_ = s.first;
      last_ = s.last;
      period_ = scale.period;
      fall_ = scale.fall;
      cycle_ = -1;
    } else {
      throw std::runtime_error("cosim: this model was built without tracing (" + s.file + ")");
    }
  }
  // The rising edge that comes next starts cycle c of the traced image.
  void begin_cycle(long long c) { cycle_ = c; }
  // The traced image is over: the file is complete (the following runs are not traced).
  void end_image() {
    if (fst_) {
      fst_->close();
      fst_.reset();
    }
    cycle_ = -1;
  }
  void rise() {
    top_->clk_i = 1;
    top_->eval();
    if (dumping()) fst_->dump(std::uint64_t(cycle_) * period_);
  }
  void fall() {
    top_->clk_i = 0;
    top_->eval();
    if (dumping()) fst_->dump(std::uint64_t(cycle_) * period_ + fall_);
  }

  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Top> top_;
  std::unique_ptr<VerilatedFstC> fst_;

 private:
  bool dumping() const { return fst_ && cycle_ >= first_ && cycle_ <= last_; }
  long long cycle_ = -1, first_ = 0, last_ = 0;
  std::uint64_t period_ = 10, fall_ = 5;
};

}  // namespace cig::cosim::detail
