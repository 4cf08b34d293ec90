// A Verilated model as both co-simulations hold it: its context, its top, the optional FST trace
// and the clock edges. The wrappers (qt_raster_cosim_tb.sv, ip_array_cosim_tb.sv) register every
// stimulus input, so only the rising edge evaluates the design. Include after the generated
// headers, inside the diagnostics push that silences them.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include <verilated.h>
#include <verilated_fst_c.h>

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
  void open_trace(const std::string& file) {
    if constexpr (kTrace) {
      fst_ = std::make_unique<VerilatedFstC>();
      top_->trace(fst_.get(), 99);
      fst_->open(file.c_str());
    } else {
      throw std::runtime_error("cosim: this model was built without tracing (" + file + ")");
    }
  }
  void rise() {
    top_->clk_i = 1;
    top_->eval();
    if (fst_) fst_->dump(time_++);
  }
  void fall() {
    top_->clk_i = 0;
    top_->eval();
    if (fst_) fst_->dump(time_++);
  }

  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Top> top_;
  std::unique_ptr<VerilatedFstC> fst_;
  std::uint64_t time_ = 0;
};

}  // namespace cig::cosim::detail
