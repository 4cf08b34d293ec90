// The runner of a Verilated configuration of rtl/ip_array.sv inside its co-simulation wrapper
// (ip_array_cosim_tb.sv, registered stimulus): a template over the generated classes, shared by the
// co-simulation's models (ip_rtl_runner.cpp, FST tracing compiled in) and the benchmark's
// (rtl_runner_fast.cpp). Include after the generated headers, inside the diagnostics push that
// silences them.
#pragma once

#include <memory>
#include <stdexcept>

#include <verilated.h>

#include "ip_cosim.hpp"
#include "verilated_model.hpp"
#include "verilator_ports.hpp"

namespace cig::cosim::detail {

// kTrace: the model was Verilated with --trace-fst (trace_to works).
template <class Top, class Tb, bool kTrace = true>
class IpRtlImpl final : public IpRtl, private VerilatedModel<Top, kTrace> {
  using Model = VerilatedModel<Top, kTrace>;
  using Model::begin_cycle;
  using Model::fall;
  using Model::rise;
  using Model::top_;

 public:
  IpRtlImpl() { reset(0); }
  int w() const override { return int(Tb::W); }
  int n_pp() const override { return int(Tb::N_PP); }

  void reset(std::uint64_t eps) override {
    begin_cycle(-1);  // outside a frame: not traced
    top_->clk_i = 0;
    top_->rst_ni = 0;
    top_->cfg_eps_valid_i = 0;
    top_->cfg_eps_i = 0;
    top_->in_valid_i = 0;
    top_->in_start_i = 0;
    top_->in_word_i = 0;
    top_->vt_ready_i = 1;
    fall();
    rise();  // the wrapper's registers take the idle stimulus
    fall();
    top_->rst_ni = 1;
    fall();
    // The configuration cycle: latched by the wrapper at this edge, written at the next, the
    // first cycle's (a bubble in it changes nothing after the reset).
    top_->cfg_eps_valid_i = 1;
    top_->cfg_eps_i = eps;
    rise();
    fall();
    top_->cfg_eps_valid_i = 0;
  }

  void cycle(std::int64_t t, bool in_valid, bool in_start, std::uint64_t in_word, bool vt_ready) override {
    begin_cycle(t);
    top_->in_valid_i = in_valid;
    top_->in_start_i = in_start;
    top_->in_word_i = in_word;
    top_->vt_ready_i = vt_ready;
    rise();
    fall();
  }
  bool in_ready() const override { return top_->in_ready_o; }
  bool vt_valid() const override { return top_->vt_valid_o; }
  int vt_pp() const override { return int(top_->vt_pp_o); }
  std::uint32_t vt_par() const override { return std::uint32_t(top_->vt_par_o); }
  std::uint64_t vt_obj() const override { return std::uint64_t(top_->vt_obj_o); }
  bool col_done() const override { return top_->col_done_o; }
  std::uint64_t pp_word(int k) const override { return port_field(top_->pp_word_o, k * int(Tb::W), int(Tb::W)); }
  bool pp_start(int k) const override { return port_bit(top_->pp_start_o, k); }
  bool pp_valid(int k) const override { return port_bit(top_->pp_valid_o, k); }

  void end_frame() override { Model::end_image(); }
  using IpRtl::trace_to;
  void trace_to(const TraceSettings& trace) override { Model::open_trace(trace); }
};

}  // namespace cig::cosim::detail
