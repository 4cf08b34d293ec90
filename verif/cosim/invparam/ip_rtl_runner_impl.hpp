// The runner of a Verilated configuration of rtl/invparam/ip_array.sv inside its co-simulation
// wrapper (ip_array_cosim_tb.sv, registered stimulus): a template over the generated classes,
// shared by the co-simulation's models (ip_rtl_runner.cpp, FST tracing compiled in) and the
// benchmark's (rtl_runner_fast.cpp). Include after the generated headers, inside the diagnostics
// push that silences them. Words of W = Tb::W bits (the register width, 73 and 80 here: the ports
// are VlWide; verilator_ports.hpp serves any width) cross the interface as IpWord.
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
  static constexpr int kW = int(Tb::W);

 public:
  IpRtlImpl() { reset(0, rtl_word_max(kW)); }
  int register_bits() const override { return kW; }
  int n_pp() const override { return int(Tb::N_PP); }

  void reset(IpWord eps, IpWord tau_near) override {
    begin_cycle(-1);  // outside a frame: not traced
    top_->clk_i = 0;
    top_->rst_ni = 0;
    top_->cfg_valid_i = 0;
    set_port_word(top_->cfg_eps_i, kW, 0);
    set_port_word(top_->cfg_near_i, kW, 0);
    top_->in_valid_i = 0;
    top_->in_start_i = 0;
    set_port_word(top_->in_word_i, kW, 0);
    top_->vt_ready_i = 1;
    fall();
    rise();  // the wrapper's registers take the idle stimulus
    fall();
    top_->rst_ni = 1;
    fall();
    // The configuration write (not registered by the wrapper): at this edge, before the first
    // cycle (a bubble in it changes nothing after the reset).
    configure(eps, tau_near);
    rise();
    top_->cfg_valid_i = 0;
    fall();
  }
  void configure(IpWord eps, IpWord tau_near) override {
    top_->cfg_valid_i = 1;
    set_port_word(top_->cfg_eps_i, kW, eps);
    set_port_word(top_->cfg_near_i, kW, tau_near);
  }

  void cycle(std::int64_t t, bool in_valid, bool in_start, IpWord in_word, bool vt_ready) override {
    begin_cycle(t);
    top_->in_valid_i = in_valid;
    top_->in_start_i = in_start;
    set_port_word(top_->in_word_i, kW, in_word);
    top_->vt_ready_i = vt_ready;
    rise();
    top_->cfg_valid_i = 0;  // a configuration write (configure) lands at this edge only
    fall();
  }
  bool in_ready() const override { return top_->in_ready_o; }
  bool vt_valid() const override { return top_->vt_valid_o; }
  int vt_pp() const override { return int(top_->vt_pp_o); }
  std::uint32_t vt_par() const override { return std::uint32_t(top_->vt_par_o); }
  IpWord vt_obj() const override { return port_word(top_->vt_obj_o, 0, kW); }
  bool col_done() const override { return top_->col_done_o; }
  IpWord pp_word(int k) const override { return port_word(top_->pp_word_o, k * kW, kW); }
  bool pp_start(int k) const override { return port_bit(top_->pp_start_o, k); }
  bool pp_valid(int k) const override { return port_bit(top_->pp_valid_o, k); }

  void end_frame() override { Model::end_image(); }
  using IpRtl::trace_to;
  void trace_to(const TraceSettings& trace) override { Model::open_trace(trace); }
};

}  // namespace cig::cosim::detail
