// The runner of a Verilated configuration of rtl/quadtree/qt_raster.sv inside its co-simulation
// wrapper (qt_raster_cosim_tb.sv): table configuration, frame start, the polygon stream with the
// verification stalls, the trace ports read every cycle, the read-out of the final pixels. A
// template over the generated classes, shared by the co-simulation's models (rtl_runner.cpp, FST
// tracing compiled in) and the benchmark's (rtl_runner_fast.cpp, built for speed, no tracing).
// Include after the generated headers, inside the diagnostics push that silences them.
#pragma once

#include <cstring>
#include <memory>
#include <stdexcept>

#include <verilated.h>

#include "common/timing.hpp"
#include "cosim.hpp"
#include "verilated_model.hpp"
#include "verilator_ports.hpp"

namespace cig::cosim::detail {

// The public parameters of a model's wrapper module (class Tb: V<prefix>_qt_raster_cosim_tb).
template <class Tb>
RtlModelParams model_params() {
  return {int(Tb::NE),  int(Tb::NP),   int(Tb::EW),          int(Tb::AW),    int(Tb::PW),
          int(Tb::GW),  int(Tb::G),    int(Tb::WIN_W),       int(Tb::PIX_W), int(Tb::MASK_SET_W),
          int(Tb::NPE), int(Tb::NPIX), int(Tb::LIGHT_COVERS)};
}

// kTrace: the model was Verilated with --trace-fst (trace_to works).
template <class Top, class Tb, bool kTrace = true>
class RtlRunnerImpl final : public RtlRunner, private VerilatedModel<Top, kTrace> {
  using Model = VerilatedModel<Top, kTrace>;
  using Model::begin_cycle;
  using Model::end_image;
  using Model::fall;
  using Model::rise;
  using Model::top_;

 public:
  explicit RtlRunnerImpl(int raster_log2)
      : n_(raster_log2), params_(model_params<Tb>()), npe_(params_.npe), npix_(params_.npix), L_(rtl_layout()) {
    top_->clk_i = 0;
    top_->rst_ni = 0;
    top_->frame_start_i = 0;
    top_->start_window_i = 0;
    top_->cfg_valid_i = 0;
    top_->poly_valid_i = 0;
    top_->pixel_stall_i = 0;
    fall();
    edge();
    edge();
    top_->rst_ni = 1;
    edge();
  }

  const RtlModelParams& params() const override { return params_; }

  using RtlRunner::trace_to;
  void trace_to(const TraceSettings& trace) override { Model::open_trace(trace); }

  Trace run(const std::vector<hls::QuadWindow<RtlArith>>& roots, const quad::PixelFrame<RtlArith>& pixels,
            const StallConfig& stalls, long long max_cycles) override {
    Trace t = frame(roots, pixels, stalls, max_cycles, -1);
    end_image();
    read_out(t);
    return t;
  }

  Trace run_cut(const std::vector<hls::QuadWindow<RtlArith>>& roots, const quad::PixelFrame<RtlArith>& pixels,
                const StallConfig& stalls, long long cycles, int hold) override {
    Trace t = frame(roots, pixels, stalls, cycles + 1, cycles);
    // The input idle and every pixel processor stalled: the records back up until the frame start.
    top_->poly_valid_i = 0;
    top_->pixel_stall_i = port_value_t<decltype(top_->pixel_stall_i)>(~std::uint64_t(0) >> (64 - npix_));
    for (int k = 0; k < hold; ++k) {
      begin_cycle(cycles + k);
      edge();
    }
    end_image();
    t.busy_at_cut = top_->busy_o;
    return t;
  }

 private:
  // One frame from the frame start: until it is done (cut < 0; more than max_cycles throws), or
  // until cycle `cut` starts (its stimulus not applied: the trace ends with cycle cut - 1).
  Trace frame(const std::vector<hls::QuadWindow<RtlArith>>& roots, const quad::PixelFrame<RtlArith>& pixels,
              const StallConfig& stalls, long long max_cycles, long long cut) {
    configure(pixels);
    top_->start_window_i = stalls.start_window ? 1 : 0;  // registered by the wrapper with the frame start
    // Frame start: latched by the wrapper at this edge, applied by the design at the next one,
    // the loop's first, which starts cycle 0.
    top_->frame_start_i = 1;
    edge();
    top_->frame_start_i = 0;

    const auto t0 = Clock::now();
    Trace t;
    t.pe.assign(std::size_t(npe_), {});
    t.pixel.assign(std::size_t(npix_), {});
    // The input records, packed once (a root may be offered for many cycles).
    using PolyPort = port_value_t<decltype(top_->poly_i)>;
    std::vector<PolyPort> packed(roots.size());
    for (std::size_t k = 0; k < roots.size(); ++k) set_port_bits(packed[k], pack_record(L_, roots[k], 0), L_.win_w);
    std::size_t next = 0;
    for (long long cycle = 0;; ++cycle) {
      if (cycle == cut) {
        t.cycles = cycle;
        break;
      }
      if (cycle >= max_cycles)
        throw std::runtime_error("cosim: the RTL did not finish the frame within " + std::to_string(max_cycles) +
                                 " cycles");
      const bool offer =
          next < roots.size() && !quad::stall_hit(stalls.seed, std::uint64_t(cycle), 0, stalls.input_gap_percent);
      top_->poly_valid_i = offer ? 1 : 0;
      if (offer) top_->poly_i = packed[next];
      std::uint64_t stall_bits = 0;
      for (int u = 0; u < npix_; ++u)
        if (quad::stall_hit(stalls.seed, std::uint64_t(cycle), std::uint32_t(1 + u), stalls.output_stall_percent))
          stall_bits |= 1ull << u;
      top_->pixel_stall_i = port_value_t<decltype(top_->pixel_stall_i)>(stall_bits);
      // The rising edge that starts this cycle: the design's registers take the previous cycle's
      // results, the wrapper latches this cycle's stimulus (qt_raster_cosim_tb.sv).
      if (on_cycles_ && cycle % kProgressCycles == 0) on_cycles_(cycle);
      begin_cycle(cycle);
      rise();
      // The frame's cycle count: the first cycle that starts with all input in and nothing busy.
      if (cycle > 0 && next >= roots.size() && !top_->busy_o) {
        t.cycles = cycle;
        fall();
        break;
      }
      // What the cycle does (combinational from the registers and this cycle's inputs); a PE that
      // finishes its window emits its last child before it loads the next one, as in the model.
      for (int p = 0; p < npe_; ++p) {
        if (port_bit(top_->pe_emit_valid_o, p))
          t.pe[std::size_t(p)].push_back({EventKind::kEmit, cycle, int(port_field(top_->pe_emit_child_o, 2 * p, 2)), 0,
                                          port_bit(top_->pe_emit_full_o, p),
                                          port_bits(top_->pe_emit_data_o, p * L_.pix_w, L_.pix_w)});
        if (port_bit(top_->pe_load_valid_o, p))
          t.pe[std::size_t(p)].push_back(
              {EventKind::kLoad, cycle, 0, unsigned(port_field(top_->pe_load_mask_o, 4 * p, 4)), false, Bits()});
      }
      for (int u = 0; u < npix_; ++u)
        if (port_bit(top_->px_valid_o, u))
          t.pixel[std::size_t(u)].push_back(
              {EventKind::kPixel, cycle, 0, unsigned(port_field(top_->px_fresh_o, 16 * u, 16)),
               port_bit(top_->px_full_o, u), port_bits(top_->px_data_o, u * L_.pix_w, L_.pix_w)});
      for (int s = 0; s < npe_ + npix_; ++s)
        if (port_bit(top_->mask_set_valid_o, s)) {
          const auto m =
              MaskSetLayout::decode(port_field(top_->mask_set_o, MaskSetLayout::width * s, MaskSetLayout::width));
          t.mask_sets.push_back({cycle, m.level, m.x, m.y, m.child});
        }
      if (offer && top_->poly_ready_o) ++next;
      fall();
    }
    t.seconds = seconds_since(t0);
    begin_cycle(-1);  // what follows is outside the image
    top_->poly_valid_i = 0;
    std::sort(t.mask_sets.begin(), t.mask_sets.end());
    return t;
  }

  // The read-out of every pixel (the port is combinational: no clock).
  void read_out(Trace& t) {
    const int size = 1 << n_;
    t.image = Image(size, size);
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        top_->rd_x_i = port_value_t<decltype(top_->rd_x_i)>(x);
        top_->rd_y_i = port_value_t<decltype(top_->rd_y_i)>(y);
        top_->eval();
        const std::uint32_t rgb = std::uint32_t(top_->rd_rgb_o);
        std::uint8_t* dst = t.image.at(x, y);
        dst[0] = std::uint8_t(rgb & 255);
        dst[1] = std::uint8_t((rgb >> 8) & 255);
        dst[2] = std::uint8_t((rgb >> 16) & 255);
      }
  }

  // A clock (VerilatedModel: only the rising edge evaluates the design; the falling edge's eval
  // is cheap, the read-out address is the only input logic left).
  void edge() {
    rise();
    fall();
  }

  void write_cfg(int target, std::uint32_t addr, std::uint64_t lo, std::uint32_t hi = 0) {
    top_->cfg_valid_i = 1;
    top_->cfg_target_i = std::uint8_t(target);
    top_->cfg_addr_i = addr;
    top_->cfg_data_i[0] = std::uint32_t(lo);
    top_->cfg_data_i[1] = std::uint32_t(lo >> 32);
    top_->cfg_data_i[2] = hi;
    edge();  // latched by the wrapper; the design writes it at the next edge
    top_->cfg_valid_i = 0;
  }

  void configure(const quad::PixelFrame<RtlArith>& pixels) {
    const hls::QuadPixelTables<RtlArith>& tb = pixels.tables();
    for (int code = 0; code < hls::kFogTableSize; ++code) {
      const std::uint64_t f = tb.fog.f[code].raw().value();
      if (f != fog_loaded_[std::size_t(code)] || !fog_valid_) write_cfg(0, std::uint32_t(code), f);
      fog_loaded_[std::size_t(code)] = f;
    }
    fog_valid_ = true;
    for (int c = 0; c < 3; ++c) {
      write_cfg(1, std::uint32_t(c), tb.fog_colour[c].value());
      write_cfg(1, std::uint32_t(3 + c), tb.background[c].value());
    }
    // Light covers: clear last frame's index entries, write this frame's.
    for (std::uint32_t pix : light_pixels_) write_cfg(2, pix, 0);
    light_pixels_.clear();
    const std::vector<int>& index = pixels.cover_index();
    for (std::size_t pix = 0; pix < index.size(); ++pix)
      if (index[pix] >= 0) {
        write_cfg(2, std::uint32_t(pix), std::uint64_t(index[pix]) + 1);
        light_pixels_.push_back(std::uint32_t(pix));
      }
    const auto& covers = pixels.covers();
    for (std::size_t e = 0; e < covers.size(); ++e) {
      const hls::QuadLightCover<RtlArith>& cv = covers[e];
      write_cfg(3, std::uint32_t(e), cv.mask.value());
      for (int s = 0; s < 16; ++s) {
        if (!cv.mask.bit(s)) continue;
        const std::uint64_t r = cv.colour[s][0].raw().value(), g = cv.colour[s][1].raw().value(),
                            b = cv.colour[s][2].raw().value();
        const std::uint64_t prio = cv.priority[s].value();
        // {priority[16:0], R, G, B}: B in bits 15:0, G 31:16, R 47:32, priority 64:48.
        const std::uint64_t lo = b | (g << 16) | (r << 32) | ((prio & 0xFFFF) << 48);
        write_cfg(4, std::uint32_t(e * 16 + std::size_t(s)), lo, std::uint32_t(prio >> 16));
      }
    }
  }

  int n_;
  RtlModelParams params_;
  int npe_, npix_;
  RtlLayout L_;
  std::vector<std::uint64_t> fog_loaded_ = std::vector<std::uint64_t>(hls::kFogTableSize, 0);
  bool fog_valid_ = false;
  std::vector<std::uint32_t> light_pixels_;
};

}  // namespace cig::cosim::detail
