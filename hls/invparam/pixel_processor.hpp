// The inverse-parameter pixel processor (PP) of seed 002, chapter 4, one clock at a time (SPEC F;
// digest notes/seed002_digest.md). A PP is one sample of a column; N_n PPs in a chain make the
// systolic array (cmodel/invparam/systolic_array.hpp). The token stream and its coding:
// tokens.hpp.
//
// State: the seed's registers and flip-flops, named as in the seed, plus the control unit's
// clock-within-token counter and the Ctrl flip-flops. Per clock the PP puts RGres on Output (the
// word it took one clock before: tokens pass with a delay of one clock), Ctrl's lines one clock
// delayed, and the VT bus (valid while a T_Col's clock 2 passes: RGpar and RGobj of the column
// just finished). A bubble on Input (Ctrl valid low) is not a clock of any token: every register
// holds (RGres too: a Pln's clock 4 still reads the sum of its clock 3) and only the delayed valid
// line falls, so the PP below sees the bubble one clock later. Every register transfer follows the
// seed's clock-by-clock text:
//   clock 1 (all): Input -> RGres, its top 5 bits -> RGI.
//   Col  2: Input -> RGparP (background); RGpar, RGobj on VT.   3: RGtin = MAX, RGtout = RGobj =
//        the minimal code, RGpar = RGparP.   4: nothing.
//   Pln  2: Input -> RGh.   3: RGres = Input + RGh (SM), z, s -> Tz, Ts.   4: by Az, As, s (below).
//   Obj  2: c = RGtin > RGtout.   3: if c': c = RGnear > RGtin.   4: if c': c = RGtin > RGobj, if c:
//        RGobj = RGtin, RGpar = RGparP; then RGtin = MAX, RGtout = the minimal code.
// Choices where the seed is silent or ambiguous:
//  * "The minimal code" that RGtout and RGobj start from is the word 0 (tau = 0, a point at
//    infinity), not word_min(): Fig. 1 starts tau_out and tau_hit at 0, and a missed object marks
//    RGtin = 0, which must then fail "RGtin > RGtout" (else an object the ray misses and whose exit
//    planes all lie behind the eye would win with tau = 0 and a face colour over the background).
//    A sample no object covers ends with RGobj = 0: the background is at infinity.
//  * Cm's output c is 0 in a clock where the control unit does not enable a comparison (Obj clock
//    3 with c' = 0), so Tc (c') carries "every test so far held" into Obj clock 4.
//  * Flag z (Tz) is kept as the seed's flip-flop; no rule of the seed's clock 4 reads it.
//  * Ties: Pln clock 4 with Az = 1, As = 0, s = 0 takes the face when c = 0, i.e. RGres <= RGtin,
//    so of two entry faces at the same tau the later one gives the colour (the seed's rule).
//  * RGeps is loaded once (pp_reset), a configuration register: the seed does not say how.
//  * RGnear (ours, issue 29): Obj clock 3 compares RGtin with RGnear = 1/near, a configuration
//    register loaded with RGeps, where the seed puts its constant MAX on bus A; RGnear = MAX is the
//    seed's PP. The near plane cuts away what lies nearer (visibility.hpp).
#pragma once

#include "hls/invparam/tokens.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <int W>
struct PpState {
  Word<W> RGres, RGh, RGtin, RGtout, RGobj, RGeps, RGnear;
  ParCode RGpar, RGparP;
  Command RGI;
  bool Tz = false, Ts = false, Tc = false;  // z, s, c delayed one clock
  bool Tctrl = false;                       // Ctrl's start line, delayed with RGres
  bool Tvalid = false;                      // Ctrl's valid line, delayed with RGres
  UInt<3> clock;                            // clock within the token: 0 idle, 1..4
};

template <int W>
struct VtBus {
  bool valid = false;
  ParCode par;  // RGpar: the visible face's code (or the background)
  Word<W> obj;  // RGobj: its tau (0: nothing hit)
};

template <int W>
struct PpOutputs {
  Word<W> output;  // RGres before this clock's edge
  PpCtrl ctrl;
  VtBus<W> vt;
  bool ends_column = false;  // this clock is a T_Col's clock 4 (pp_ends_column)
};

// A configuration write: RGeps = eps (< 0) and RGnear = tau_near (1/near; MAX: no near plane),
// every other register as it is (between frames, without reset).
template <int W>
CIG_HLS_INLINE void pp_configure(PpState<W>& st, const Word<W>& eps, const Word<W>& tau_near) {
  st.RGeps = eps;
  st.RGnear = tau_near;
}

// Power-on, then the configuration write: every register 0 except RGtin = MAX, RGeps, RGnear.
template <int W>
CIG_HLS_INLINE void pp_reset(PpState<W>& st, const Word<W>& eps, const Word<W>& tau_near) {
  st = PpState<W>();
  st.RGres = st.RGh = st.RGtout = st.RGobj = word_zero<W>();
  st.RGtin = word_max<W>();
  pp_configure(st, eps, tau_near);
}

// The control unit's counter: start restarts it; a 4-word token counts 1..4; an empty code is
// one clock; otherwise the PP idles (0).
template <int W>
CIG_HLS_INLINE UInt<3> pp_next_clock(const PpState<W>& st, const PpCtrl& ctrl) {
  const unsigned c = unsigned(st.clock.value());
  if (ctrl.start) return UInt<3>(1);
  if (c >= 1 && c <= 3 && command_kind(st.RGI) != kKindEmpty) return UInt<3>(c + 1);
  return UInt<3>(0);
}

// Whether the PP drives VT in this clock: a valid word that is clock 2 of a T_Col other than the
// frame's initialising one. A function of the state and Input's Ctrl only (the array's VT
// handshake needs it before the clock edge).
template <int W>
CIG_HLS_INLINE bool pp_drives_vt(const PpState<W>& st, const PpCtrl& ctrl) {
  return ctrl.valid && pp_next_clock(st, ctrl).value() == 2 && command_kind(st.RGI) == kKindCol &&
         !command_first(st.RGI);
}

// Whether this clock is a T_Col's clock 4, the last of a column at this PP: at the chain's last PP
// the column has left the array (the array's column-done).
template <int W>
CIG_HLS_INLINE bool pp_ends_column(const PpState<W>& st, const PpCtrl& ctrl) {
  return ctrl.valid && pp_next_clock(st, ctrl).value() == 4 && command_kind(st.RGI) == kKindCol;
}

template <int W>
CIG_HLS_INLINE void pp_col_clock(PpState<W>& st, unsigned clock, const Word<W>& input, VtBus<W>& vt) {
  if (clock == 2) {
    vt.valid = !command_first(st.RGI);
    vt.par = st.RGpar;
    vt.obj = st.RGobj;
    st.RGparP = word_par<W>(input);
  } else if (clock == 3) {
    st.RGtin = word_max<W>();
    st.RGtout = word_zero<W>();
    st.RGobj = word_zero<W>();
    st.RGpar = st.RGparP;
  }
}

// Pln clock 4: RGres holds tau (or Den) of this sample, Ts its sign; Input is the face's code.
template <int W>
CIG_HLS_INLINE bool pp_pln_decide(PpState<W>& st, const Word<W>& input) {
  bool c = false;
  if (!command_az(st.RGI)) {  // the eye in the plane: Den <= eps is a miss
    c = word_greater(st.RGres, st.RGeps);
    if (!c) st.RGtin = word_zero<W>();
  } else if (command_as(st.RGI)) {  // Num < 0: tau >= 0 is an exit plane ahead
    if (!st.Ts) {
      c = word_greater(st.RGres, st.RGtout);
      if (c) st.RGtout = st.RGres;
    }
  } else if (!st.Ts) {  // Num > 0, tau >= 0: an entry plane ahead
    c = word_greater(st.RGres, st.RGtin);
    if (!c) {
      st.RGtin = st.RGres;
      st.RGparP = word_par<W>(input);
    }
  } else {  // Num > 0, tau < 0: the ray leaves the half-space behind the eye: miss
    st.RGtin = word_zero<W>();
  }
  return c;
}

// One Pln clock; returns Cm's c. *sum is the SM output (Input, or Input + RGh in clock 3).
template <int W>
CIG_HLS_INLINE bool pp_pln_clock(PpState<W>& st, unsigned clock, const Word<W>& input, Word<W>* sum) {
  if (clock == 2) st.RGh = input;
  if (clock == 3) {
    *sum = word_add(input, st.RGh);
    st.Tz = word_nonzero(*sum);
    st.Ts = word_negative(*sum);
  }
  if (clock == 4) return pp_pln_decide(st, input);
  return false;
}

// One Obj clock; returns Cm's c.
template <int W>
CIG_HLS_INLINE bool pp_obj_clock(PpState<W>& st, unsigned clock) {
  bool c = false;
  if (clock == 2) c = word_greater(st.RGtin, st.RGtout);
  if (clock == 3 && st.Tc) c = word_greater(st.RGnear, st.RGtin);
  if (clock == 4) {
    if (st.Tc) {
      c = word_greater(st.RGtin, st.RGobj);
      if (c) {
        st.RGobj = st.RGtin;
        st.RGpar = st.RGparP;
      }
    }
    st.RGtin = word_max<W>();
    st.RGtout = word_zero<W>();
  }
  return c;
}

// One clock of the PP.
template <int W>
CIG_HLS_INLINE PpOutputs<W> pp_clock(PpState<W>& st, const Word<W>& input, const PpCtrl& ctrl) {
  PpOutputs<W> out;
  out.output = st.RGres;
  out.ctrl.start = st.Tctrl;
  out.ctrl.valid = st.Tvalid;
  out.ends_column = pp_ends_column(st, ctrl);
  if (!ctrl.valid) {  // a bubble: nothing but the delayed Ctrl lines moves
    st.Tctrl = false;
    st.Tvalid = false;
    return out;
  }
  const UInt<3> next = pp_next_clock(st, ctrl);
  const unsigned clock = unsigned(next.value());
  Word<W> sum = input;  // SM passes Input unless a Pln's clock 3 adds RGh
  bool c = false;
  if (clock == 1) {
    st.RGI = word_command<W>(input);
  } else if (clock >= 2) {
    const unsigned kind = command_kind(st.RGI);
    if (kind == kKindCol) pp_col_clock(st, clock, input, out.vt);
    if (kind == kKindPln) c = pp_pln_clock(st, clock, input, &sum);
    if (kind == kKindObj) c = pp_obj_clock(st, clock);
  }
  st.RGres = sum;
  st.Tc = c;
  st.Tctrl = ctrl.start;
  st.Tvalid = true;
  st.clock = next;
  return out;
}

// The top function's width: the seed's PP has six 64-bit registers (its word for 100 km); here
// 80 bits with the guard bits (word.hpp).
constexpr int kPpTopWordBits = 64;

// Top function (HLS): one clock of one pixel processor.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_invparam_pixel_processor_top(PORT, ARRAY, RESULT) \
  RESULT(PpOutputs<kPpTopWordBits>)                                     \
  PORT(st, inout, ap_ovld, PpState<kPpTopWordBits>&)                    \
  PORT(input, in, ap_none, const Word<kPpTopWordBits>&)                 \
  PORT(ctrl, in, ap_none, const PpCtrl&)
inline CIG_HLS_TOP(invparam_pixel_processor_top) { return pp_clock(st, input, ctrl); }

CIG_HLS_END_NAMESPACE
