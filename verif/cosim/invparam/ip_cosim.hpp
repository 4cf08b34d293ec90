// Lock-step co-simulation of the inverse-parameter array RTL (rtl/invparam/ip_array.sv, Verilated
// inside ip_array_cosim_tb.sv) against the clock-level model (cmodel/invparam/systolic_array.hpp,
// run_array_frame with the PP of hls/invparam/pixel_processor.hpp): the same frame stream, with the
// same input gaps and VT back-pressure (ArrayPacing, stall_hit), goes through both, and every cycle
// is compared while the model runs (its observer steps the RTL):
//   * every PP's Output word (RGres) and delayed Ctrl lines (start, valid): every token at every PP;
//   * the VT bus: which PP drives it (or none), its par and obj, in advancing and in held cycles;
//   * the handshake: in_ready_o low exactly in the cycles the model holds (then vt_valid_o high);
//   * col_done_o (the last PP does clock 4 of a T_Col) and the frame's cycle count.
// The RTL's stimulus is computed from the RTL's own in_ready_o (host_offer: a word not taken stays
// offered), not copied from the model. Frames run back to back without reset: the model keeps its
// chain (run_array_frame's `pp`), the RTL its registers; a configuration write between two frames
// (configure: RGeps and RGnear) changes both sides' before the next frame's first cycle. The first
// mismatch is reported with the frame, the cycle, the PP, the signal, the expected and the
// obtained value.
//
// Widths: the harness templates on the seed's word W (hls Word<W>); the RTL's registers, and its
// parameter W, have hls::word_bits(W) = W + 16 bits (the guard bits, hls/invparam/word.hpp), 80
// for the seed's 64-bit word. Words cross the interface below as IpWord, 128 bits.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/screen_frame.hpp"
#include "invparam/face_setup.hpp"
#include "invparam/systolic_array.hpp"
#include "trace_settings.hpp"

namespace cig::cosim {

// ---- The Verilated configurations (ip_rtl_runner.cpp) -------------------------------------------

// A word of the RTL, LSB first: its register_bits() low bits (the rest zero). 128 bits hold hls
// WideInt's widest register.
__extension__ typedef unsigned __int128 IpWord;

// The register of hls Word<W> as the RTL carries it: its word_bits(W) bits, two's complement.
template <int W>
IpWord rtl_word(const hls::Word<W>& w) {
  constexpr int kBits = hls::word_bits(W);
  static_assert(kBits <= 128, "the harness carries words in 128 bits");
  const IpWord mask = kBits >= 128 ? ~IpWord(0) : (IpWord(1) << (kBits % 128)) - 1;
  return (IpWord(w.high_limb()) << 64 | IpWord(w.low_limb())) & mask;
}
// The largest code of a `bits`-bit register (RGnear's reset value, the seed's MAX).
inline IpWord rtl_word_max(int bits) { return (IpWord(1) << (bits - 1)) - 1; }
// "0x..." without leading zeros.
std::string ip_hex(IpWord v);

// A configuration, named by the seed's word w (hls Word<w>, the harness's template parameter): the
// Verilated ip_array's W is the register width, register_bits() = hls word_bits(w) = w + 16.
struct IpRtlConfig {
  int w = 64, n_pp = 64;
  int register_bits() const { return hls::word_bits(w); }
  std::string text() const { return "W=" + std::to_string(w) + ", N_PP=" + std::to_string(n_pp); }
};
std::vector<IpRtlConfig> ip_rtl_configs();

// One Verilated ip_array: words of register_bits() bits (IpWord).
class IpRtl {
 public:
  virtual ~IpRtl() = default;
  // The model's public parameters (ip_array_cosim_tb): W, the register width, and N_PP.
  virtual int register_bits() const = 0;
  virtual int n_pp() const = 0;
  // Asynchronous reset, then a configuration write of RGeps and RGnear of every PP (at the edge
  // before the first cycle).
  virtual void reset(IpWord eps, IpWord tau_near) = 0;
  // A configuration write of RGeps and RGnear of every PP with the next cycle's stimulus: it
  // lands at the edge that starts that cycle, so that the cycle sees the new values (between two
  // frames: the next frame's first cycle), whatever the handshake.
  virtual void configure(IpWord eps, IpWord tau_near) = 0;
  // Cycle t of the frame (from 1): its stimulus, then the edge that starts it; the outputs below
  // then show this cycle, before its own clock edge (the next call's).
  virtual void cycle(std::int64_t t, bool in_valid, bool in_start, IpWord in_word, bool vt_ready) = 0;
  // The frame is over (the trace of the next frame, trace_to, ends here).
  virtual void end_frame() = 0;
  virtual bool in_ready() const = 0;
  virtual bool vt_valid() const = 0;
  virtual int vt_pp() const = 0;
  virtual std::uint32_t vt_par() const = 0;
  virtual IpWord vt_obj() const = 0;
  virtual bool col_done() const = 0;
  virtual IpWord pp_word(int k) const = 0;
  virtual bool pp_start(int k) const = 0;
  virtual bool pp_valid(int k) const = 0;
  // FST of the next frame (trace_settings.hpp: its cycles 1..C, or the window first..last).
  virtual void trace_to(const TraceSettings& trace) = 0;
  void trace_to(const std::string& fst_file) { trace_to(TraceSettings{fst_file}); }
};
// nullptr when this build has no such configuration.
std::unique_ptr<IpRtl> make_ip_rtl(int w, int n_pp);
// The benchmark's model (w = 64, N_PP = 64, Verilated for speed, no tracing); in cig_cosim_fast.
std::unique_ptr<IpRtl> make_fast_ip_rtl(int w, int n_pp);

// ---- One frame's result -----------------------------------------------------------------------

struct IpFrameResult {
  std::int64_t samples = 0, codes = 0, tokens = 0, faces = 0;
  std::int64_t model_cycles = 0, rtl_cycles = 0;
  std::int64_t held_cycles = 0, vt_results = 0;
  std::int64_t vt_hits = 0;  // VT results with an object (RGobj != 0)
  std::int64_t checks = 0, mismatches = 0;
  std::string first;  // the first mismatch ("" if none)
  double seconds = 0;
  bool ok() const { return mismatches == 0 && model_cycles == rtl_cycles; }
};

// Tokens of a stream: codes that start a T_Pln, T_Obj or T_Col (the empty codes, word 0, are not
// counted; the command lies in the register's top bits).
template <int W>
std::int64_t stream_tokens(const std::vector<invparam::StreamCode<W>>& s) {
  std::int64_t n = 0;
  for (const auto& c : s) n += c.start && hls::word_nonzero(c.word) ? 1 : 0;
  return n;
}

namespace detail {

// The comparisons' bookkeeping: counts, and the first mismatch in words.
class IpChecker {
 public:
  IpChecker(IpFrameResult& r, int frame) : r_(r), frame_(frame) {}
  void expect(std::int64_t cycle, int pp, const char* signal, IpWord expected, IpWord got) {
    ++r_.checks;
    if (expected == got) return;
    if (r_.mismatches++ == 0) {
      std::ostringstream o;
      o << "frame " << frame_ << ", cycle " << cycle << (pp >= 0 ? ", PP " + std::to_string(pp) : std::string()) << ", "
        << signal << ": expected " << ip_hex(expected) << ", got " << ip_hex(got);
      r_.first = o.str();
    }
  }

 private:
  IpFrameResult& r_;
  int frame_;
};

// The host's side of the RTL (the model's host_offer on the RTL's own handshake): the stream with
// the pacing's input gaps, a word not taken offered again, idle empty codes after the stream; the
// col_done_o pulses counted up to the frame's end (the (columns + 1)-th, counting the initialising
// T_Col).
template <int W>
class IpHost {
 public:
  IpHost(IpRtl& rtl, const std::vector<invparam::StreamCode<W>>& stream, int columns,
         const invparam::ArrayPacing& pacing)
      : rtl_(rtl), stream_(stream), columns_(columns), pacing_(pacing) {}
  // Runs cycle t (t = cycles() + 1); returns what was offered.
  invparam::ArrayInput<W> step(std::int64_t t) {
    if (t != t_ + 1) throw std::logic_error("ip cosim: the RTL and the model are out of step");
    const invparam::ArrayInput<W> in = invparam::host_offer(stream_, next_, holding_, t, pacing_);
    const bool vt_ready = !stall_hit(pacing_.seed, std::uint64_t(t), 1, pacing_.vt_stall_percent);
    rtl_.cycle(t, in.ctrl.valid, in.ctrl.start, rtl_word<W>(in.word), vt_ready);
    t_ = t;
    if (rtl_.in_ready()) {
      if (in.ctrl.valid && next_ < stream_.size()) ++next_;
      holding_ = false;
    } else {
      holding_ = in.ctrl.valid;
    }
    if (rtl_.col_done() && ++col_done_ == columns_ + 1) end_ = t;
    return in;
  }
  std::int64_t cycles() const { return t_; }
  std::int64_t end() const { return end_; }  // the frame's last cycle, 0 while it runs

 private:
  IpRtl& rtl_;
  const std::vector<invparam::StreamCode<W>>& stream_;
  int columns_;
  invparam::ArrayPacing pacing_;
  std::size_t next_ = 0;
  bool holding_ = false;
  std::int64_t t_ = 0, end_ = 0;
  int col_done_ = 0;
};

// The model's observer: steps the RTL through each cycle the model runs and compares.
template <int W>
class IpLockstep {
 public:
  IpLockstep(IpRtl& rtl, IpHost<W>& host, const std::vector<hls::PpState<W>>& chain, IpChecker& check, IpFrameResult& r)
      : rtl_(rtl), host_(host), chain_(chain), check_(check), r_(r), n_(int(chain.size())) {}

  // A held cycle: the RTL must hold too, with a result on VT; every PP shows its registers.
  void on_freeze(std::int64_t t) {
    const invparam::ArrayInput<W> in = host_.step(t);
    ++r_.held_cycles;
    check_.expect(t, -1, "in_ready_o (held cycle)", 0, rtl_.in_ready());
    check_.expect(t, -1, "vt_valid_o (held cycle)", 1, rtl_.vt_valid());
    hls::PpCtrl ctrl = in.ctrl;
    for (int k = 0; k < n_; ++k) {
      const hls::PpState<W>& st = chain_[std::size_t(k)];
      compare_pp(t, k, st.RGres, hls::PpCtrl{st.Tctrl, st.Tvalid});
      compare_vt(t, k, hls::pp_drives_vt(st, ctrl), st.RGpar, st.RGobj);
      ctrl = hls::PpCtrl{st.Tctrl, st.Tvalid};
    }
    check_.expect(t, -1, "col_done_o (held cycle)", 0, rtl_.col_done());
  }

  // An advancing cycle, PP k (0 first): its outputs before the edge; the last PP's tell whether it
  // did clock 4 of a T_Col (col_done_o).
  void on_clock(std::int64_t t, int k, const hls::PpOutputs<W>& o) {
    if (k == 0) {
      host_.step(t);
      check_.expect(t, -1, "in_ready_o", 1, rtl_.in_ready());
      if (rtl_.vt_valid()) check_.expect(t, -1, "vt_pp_o < N_PP", 1, rtl_.vt_pp() < n_ ? 1 : 0);
    }
    compare_pp(t, k, o.output, o.ctrl);
    compare_vt(t, k, o.vt.valid, o.vt.par, o.vt.obj);
    r_.vt_results += o.vt.valid ? 1 : 0;
    r_.vt_hits += o.vt.valid && hls::word_nonzero(o.vt.obj) ? 1 : 0;
    if (k == n_ - 1) check_.expect(t, -1, "col_done_o", o.ends_column, rtl_.col_done());
  }

 private:
  void compare_pp(std::int64_t t, int k, const hls::Word<W>& word, const hls::PpCtrl& ctrl) {
    check_.expect(t, k, "pp_word_o (RGres)", rtl_word<W>(word), rtl_.pp_word(k));
    check_.expect(t, k, "pp_start_o (Tctrl)", ctrl.start, rtl_.pp_start(k));
    check_.expect(t, k, "pp_valid_o (Tvalid)", ctrl.valid, rtl_.pp_valid(k));
  }
  void compare_vt(std::int64_t t, int k, bool drives, const hls::ParCode& par, const hls::Word<W>& obj) {
    const bool rtl_drives = rtl_.vt_valid() && rtl_.vt_pp() == k;
    check_.expect(t, k, "VT driven by this PP (vt_valid_o && vt_pp_o == k)", drives, rtl_drives);
    if (!drives || !rtl_drives) return;
    check_.expect(t, k, "vt_par_o (RGpar)", par.value(), rtl_.vt_par());
    check_.expect(t, k, "vt_obj_o (RGobj)", rtl_word<W>(obj), rtl_.vt_obj());
  }

  IpRtl& rtl_;
  IpHost<W>& host_;
  const std::vector<hls::PpState<W>>& chain_;
  IpChecker& check_;
  IpFrameResult& r_;
  int n_;
};

}  // namespace detail

// The co-simulation of one configuration: the RTL and the model's chain, frames back to back. W is
// the seed's word; the RTL's registers must have hls::word_bits(W) bits.
template <int W>
class IpCosim {
 public:
  IpCosim(IpRtl& rtl, const hls::Word<W>& eps, const hls::Word<W>& tau_near)
      : rtl_(rtl), chain_(std::size_t(rtl.n_pp())) {
    if (rtl.register_bits() != hls::word_bits(W))
      throw std::logic_error("ip cosim: a W=" + std::to_string(W) + " harness (" + std::to_string(hls::word_bits(W)) +
                             "-bit registers) on a model of W=" + std::to_string(rtl.register_bits()) + " bits");
    reset(eps, tau_near);
  }
  // Power-on of both sides: every register 0 (RGtin = MAX), RGeps = eps, RGnear = tau_near.
  void reset(const hls::Word<W>& eps, const hls::Word<W>& tau_near) {
    rtl_.reset(rtl_word<W>(eps), rtl_word<W>(tau_near));
    for (hls::PpState<W>& st : chain_) hls::pp_reset(st, eps, tau_near);
    eps_ = eps;
    tau_near_ = tau_near;
  }
  // A configuration write between two frames, no reset: RGeps and RGnear of every PP on both
  // sides, in place from the next frame's first cycle (the other registers keep their values).
  void configure(const hls::Word<W>& eps, const hls::Word<W>& tau_near) {
    rtl_.configure(rtl_word<W>(eps), rtl_word<W>(tau_near));
    for (hls::PpState<W>& st : chain_) hls::pp_configure(st, eps, tau_near);
    eps_ = eps;
    tau_near_ = tau_near;
  }
  const hls::Word<W>& eps() const { return eps_; }
  const hls::Word<W>& tau_near() const { return tau_near_; }
  int n_pp() const { return int(chain_.size()); }

  // One frame's stream (columns columns) through both, from where the last frame left them.
  IpFrameResult run_frame(const std::vector<invparam::StreamCode<W>>& stream, int columns,
                          const invparam::ArrayPacing& pacing = {}) {
    IpFrameResult r;
    const int frame = frames_++;
    r.samples = std::int64_t(columns) * n_pp();
    r.codes = std::int64_t(stream.size());
    r.tokens = stream_tokens(stream);
    const auto t0 = std::chrono::steady_clock::now();
    detail::IpChecker check(r, frame);
    detail::IpHost<W> host(rtl_, stream, columns, pacing);
    detail::IpLockstep<W> lockstep(rtl_, host, chain_, check, r);
    try {
      run_ = invparam::run_array_frame(chain_, stream, columns, pacing, lockstep);
      r.model_cycles = run_.clocks;
    } catch (const std::logic_error& e) {  // the model did not drain: a broken stream
      check.expect(host.cycles(), -1, e.what(), 0, 1);
    }
    // The RTL's side up to its own frame end (if the model's came first).
    const std::int64_t limit = 8 * (r.codes + 4 * std::int64_t(n_pp()) + 16);
    while (host.end() == 0 && host.cycles() < limit) {
      host.step(host.cycles() + 1);
      check.expect(host.cycles(), -1, "col_done_o: the frame goes on after the model's end", 0, 1);
    }
    r.rtl_cycles = host.end();
    rtl_.end_frame();
    check.expect(host.cycles(), -1, "frame cycles (the (columns + 1)-th col_done_o)", std::uint64_t(r.model_cycles),
                 std::uint64_t(r.rtl_cycles));
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }
  // The model alone on a frame's stream from the chain's present state, RGeps and RGnear written
  // as configure(eps, tau_near) would (both sides untouched).
  std::int64_t model_cycles(const std::vector<invparam::StreamCode<W>>& stream, int columns,
                            const invparam::ArrayPacing& pacing, const hls::Word<W>& eps,
                            const hls::Word<W>& tau_near) const {
    std::vector<hls::PpState<W>> chain = chain_;
    for (hls::PpState<W>& st : chain) hls::pp_configure(st, eps, tau_near);
    return invparam::run_array_frame(chain, stream, columns, pacing).clocks;
  }
  // The same with the present configuration.
  std::int64_t model_cycles(const std::vector<invparam::StreamCode<W>>& stream, int columns,
                            const invparam::ArrayPacing& pacing = {}) const {
    return model_cycles(stream, columns, pacing, eps_, tau_near_);
  }
  // The model's run of the last frame (its VT results per column and PP).
  const invparam::ArrayRun<W>& last_run() const { return run_; }

 private:
  IpRtl& rtl_;
  std::vector<hls::PpState<W>> chain_;
  hls::Word<W> eps_, tau_near_;
  invparam::ArrayRun<W> run_;
  int frames_ = 0;
};

// The RTL alone on a stream (bench_rtl): its frame's cycles.
template <int W>
std::int64_t ip_rtl_run_frame(IpRtl& rtl, const std::vector<invparam::StreamCode<W>>& stream, int columns,
                              const invparam::ArrayPacing& pacing = {}) {
  detail::IpHost<W> host(rtl, stream, columns, pacing);
  const std::int64_t limit = 8 * (std::int64_t(stream.size()) + 4 * std::int64_t(rtl.n_pp()) + 16);
  while (host.end() == 0 && host.cycles() < limit) host.step(host.cycles() + 1);
  rtl.end_frame();
  return host.end();
}

// ---- Frames of a scene (ip_cosim.cpp) ---------------------------------------------------------

// Frames (ScreenFrame, stage B's polyhedra) through one configuration, back to back: each set up on
// an N_PP x N_PP lattice (L = N_PP: a PP per sample of a column, N_PP columns). W from the model.
class IpFrameCosim {
 public:
  virtual ~IpFrameCosim() = default;
  virtual IpFrameResult run(const ScreenFrame& frame, const invparam::ArrayPacing& pacing) = 0;
  // The model alone on the frame from where the last frame left the chain (the RTL untouched): the
  // cycles run() will count (a trace window is checked against them; the progress's total).
  virtual std::int64_t model_cycles(const ScreenFrame& frame, const invparam::ArrayPacing& pacing) const = 0;
};
std::unique_ptr<IpFrameCosim> make_ip_frame_cosim(IpRtl& rtl);

}  // namespace cig::cosim
