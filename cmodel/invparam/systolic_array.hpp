// Seed 002's systolic array, clock by clock (SPEC F; digest notes/seed002_digest.md): N_n pixel
// processors (hls/invparam/pixel_processor.hpp) in a chain, one per sample of a column, fed the
// token chains of P columns one after the other, the VT results collected per column and PP.
//
// The frame's stream (build_frame_stream), the reading of the seed that makes its frame time
//     t = (max(N_K, ceil(N_n/4)*4) (P - 1) + N_K + N_n + 3) t_t,   N_K = 4((m + 1) n + 1)
// exact:
//   * one initialising T_Col (the seed: "at the start every PP is initialised by a T_Col"; 4 codes,
//     marked First so that it puts nothing on VT);
//   * per column i: the T_Pln tokens of object 1, T_Obj, ..., of object n, T_Obj, then the T_Col
//     that sends column i's results down VT and initialises column i + 1 (N_K codes); then empty
//     codes up to L = max(N_K, ceil(N_n/4)*4) codes (the seed's padding "so that the chain is not
//     shorter than the number of PPs", in 4-code empty tokens): PP k puts its result on VT k + 1
//     clocks after the T_Col entered PP 0, so N_n results take N_n clocks of the one VT bus, and
//     the next T_Col may not come sooner (ArrayRun::vt_conflicts counts clocks that break this);
//   * the last column gets N_n - 1 empty codes instead: they push its T_Col through the chain
//     until the last PP has done the T_Col's clock 4.
// So the stream is 4 + (P - 1) L + N_K + N_n - 1 codes: the formula's "+ 3" is the initial T_Col's
// 4 codes and the N_n - 1 pushing codes. The frame ends when the last PP finishes the last token:
// exactly at the last code in, the clock the simulation counts (ArrayRun::clocks). The last VT
// result leaves 2 clocks earlier (clock 2 of the last PP's last T_Col; ArrayRun::last_vt_clock).
//
// Covered-columns streaming (StreamMode::kCoveredColumns): an object's tokens go only to the
// columns of its (conservative) column range; each column's chain has its own length
// N_K(i) = 4 (sum over the objects covering i of (m_k + 1) + 1). Chains now differ, so the padding
// after column i's T_Col is sized by column i + 1's chain: the next T_Col still comes at least
// ceil(N_n/4)*4 codes later (in full streaming this is the seed's padding, code for code). An
// object that passes no sample test in a column changes nothing there (RGparP only matters with
// the RGtin it was written with), so conservative ranges give full streaming's results exactly.
// Clocks: covered_columns_clocks.
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/stall_pattern.hpp"
#include "hls/invparam/pixel_processor.hpp"
#include "hls/invparam/records.hpp"
#include "invparam/face_setup.hpp"

namespace cig::invparam {

using hls::Command;
using hls::FaceSetup;
using hls::ParCode;
using hls::PpCtrl;
using hls::PpState;
using hls::Word;

// An object: its faces are faces[first_face .. first_face + face_count - 1] of the scene; its
// screen extent covers columns first_column .. last_column (first_column > last_column: none).
struct ObjectSpan {
  int first_face = 0, face_count = 0;
  int first_column = 0, last_column = 1 << 30;
};

template <int W>
struct InvparamScene {
  std::vector<FaceSetup<W>> faces;
  std::vector<ObjectSpan> objects;
  ParCode background;
  Word<W> eps;                            // RGeps, a negative tolerance
  Word<W> tau_near = hls::word_max<W>();  // RGnear: 1/near (the largest code: no near plane)
};

enum class StreamMode { kFull, kCoveredColumns };

template <int W>
struct StreamCode {
  Word<W> word;
  bool start = false;  // Ctrl: word 1 of a token
};

template <int W>
struct VtResult {
  ParCode par;  // RGpar: the visible face's code or the background
  Word<W> obj;  // RGobj: its tau, 0 for the background
};

template <int W>
struct ArrayRun {
  std::int64_t clocks = 0;           // first code in .. the last PP done with the last T_Col
  std::int64_t last_vt_clock = 0;    // the clock of the last VT result
  std::int64_t codes_in = 0;         // the stream's length
  std::int64_t vt_conflicts = 0;     // clocks in which more than one PP drove VT
  std::vector<VtResult<W>> results;  // column-major: [column * n_pp + pp]
  const VtResult<W>& at(int column, int pp, int n_pp) const { return results[std::size_t(column) * n_pp + pp]; }
};

inline bool covers(const ObjectSpan& o, int column) { return column >= o.first_column && column <= o.last_column; }

// The seed's padded chain length: max(N_K, ceil(N_n/4)*4) codes.
inline std::int64_t padded_chain_codes(std::int64_t nk, int n_pp) {
  return std::max<std::int64_t>(nk, 4 * ((n_pp + 3) / 4));
}

template <int W>
void append_token(std::vector<StreamCode<W>>& s, const Command& cmd, const Word<W>& w2, const Word<W>& w3,
                  const Word<W>& w4) {
  s.push_back({hls::command_word<W>(cmd), true});
  s.push_back({w2, false});
  s.push_back({w3, false});
  s.push_back({w4, false});
}

// The codes of one column's chain before padding: 4 per T_Pln, T_Obj and the T_Col.
template <int W>
std::int64_t column_chain_codes(const InvparamScene<W>& scene, int column, StreamMode mode) {
  std::int64_t codes = 4;
  for (const ObjectSpan& o : scene.objects)
    if (mode == StreamMode::kFull || covers(o, column)) codes += 4 * (std::int64_t(o.face_count) + 1);
  return codes;
}

// One column's token chain and the empty codes after its T_Col: `running[f]` is face f's value at
// this column, row -1 (start + column * step_x, kept by the host with word_add); `next_codes` is the
// next column's chain length (0: this is the last column). The padding keeps the next T_Col at
// least ceil(N_n/4)*4 codes behind this one (max(N_K, ceil(N_n/4)*4) - N_K empty codes in full
// streaming, the seed's padding); the last column gets N_n - 1.
template <int W>
std::vector<StreamCode<W>> build_column_chain(const InvparamScene<W>& scene, const std::vector<Word<W>>& running,
                                              int column, std::int64_t next_codes, int n_pp, StreamMode mode) {
  std::vector<StreamCode<W>> s;
  const Word<W> zero = hls::word_zero<W>();
  for (const ObjectSpan& o : scene.objects) {
    if (mode == StreamMode::kCoveredColumns && !covers(o, column)) continue;
    for (int f = o.first_face; f < o.first_face + o.face_count; ++f) {
      const FaceSetup<W>& fs = scene.faces[std::size_t(f)];
      append_token<W>(s, hls::pln_command(fs.az, fs.as), fs.step_y, running[std::size_t(f)],
                      hls::par_word<W>(fs.colour));
    }
    append_token<W>(s, Command(hls::kCmdObj), zero, zero, zero);
  }
  append_token<W>(s, Command(hls::kCmdCol), hls::par_word<W>(scene.background), zero, zero);
  const std::int64_t empties = next_codes == 0 ? n_pp - 1 : padded_chain_codes(next_codes, n_pp) - next_codes;
  for (std::int64_t k = 0; k < empties; ++k) s.push_back({zero, true});
  return s;
}

// The frame's stream: the initialising T_Col, then P column chains with their padding.
template <int W>
std::vector<StreamCode<W>> build_frame_stream(const InvparamScene<W>& scene, int columns, int n_pp, StreamMode mode) {
  std::vector<StreamCode<W>> s;
  const Word<W> zero = hls::word_zero<W>();
  append_token<W>(s, Command(hls::kCmdCol | hls::kCmdFirst), hls::par_word<W>(scene.background), zero, zero);
  std::vector<Word<W>> running;
  for (const FaceSetup<W>& f : scene.faces) running.push_back(f.start);
  for (int i = 0; i < columns; ++i) {
    const std::int64_t next = i + 1 < columns ? column_chain_codes(scene, i + 1, mode) : 0;
    const std::vector<StreamCode<W>> chain = build_column_chain(scene, running, i, next, n_pp, mode);
    s.insert(s.end(), chain.begin(), chain.end());
    for (std::size_t f = 0; f < running.size(); ++f) running[f] = hls::word_add(running[f], scene.faces[f].step_x);
  }
  return s;
}

// Verification pacing (the co-simulation applies the same to the RTL): in `input_gap_percent` %
// of the cycles the host has no word ready (a bubble enters PP 0; a word already offered and not
// taken stays offered), in `vt_stall_percent` % the VT consumer is not ready. Drawn by
// stall_hit(seed, cycle, stream 0 / 1). The idle codes after the stream are never gapped.
struct ArrayPacing {
  std::uint32_t seed = 1;
  int input_gap_percent = 0;
  int vt_stall_percent = 0;
};

// The array's handshakes, cycle t (clocks count from 1):
//   vt_valid = some PP drives VT (pp_drives_vt on its state and its Input's Ctrl);
//   advance  = vt_ready || !vt_valid: a result the consumer does not take freezes every PP (the
//              whole array holds: its clock enable), anything else moves the chain;
//   in_ready = advance: the host's word is taken (or its bubble enters) when the array moves.
// Observer: on_clock(t, k, outputs of PP k, drives_vt) for every PP of every advancing clock (the
// word and Ctrl each PP passes down, its VT); on_freeze(t) for a cycle the array holds.
struct NoArrayObserver {
  template <class Outputs>
  void on_clock(std::int64_t, int, const Outputs&) {}
  void on_freeze(std::int64_t) {}
};

template <int W>
struct ArrayInput {  // what the host puts on PP 0's Input and Ctrl in a cycle
  Word<W> word;
  PpCtrl ctrl;
};

// The host's offer in cycle t: the next code, a bubble, or (after the stream) an idle empty code.
template <int W>
ArrayInput<W> host_offer(const std::vector<StreamCode<W>>& stream, std::size_t next, bool holding, std::int64_t t,
                         const ArrayPacing& pacing) {
  if (next >= stream.size()) return {hls::word_zero<W>(), PpCtrl{true, true}};
  const bool gap = !holding && stall_hit(pacing.seed, std::uint64_t(t), 0, pacing.input_gap_percent);
  return {stream[next].word, PpCtrl{stream[next].start, !gap}};
}

// Whether some PP drives VT in this cycle, before the edge (PP k > 0 reads PP k - 1's registers).
template <int W>
bool array_drives_vt(const std::vector<PpState<W>>& pp, const ArrayInput<W>& in) {
  PpCtrl ctrl = in.ctrl;
  for (const PpState<W>& st : pp) {
    if (hls::pp_drives_vt(st, ctrl)) return true;
    ctrl = PpCtrl{st.Tctrl, st.Tvalid};
  }
  return false;
}

// One advancing clock of the chain: every PP takes the word of the one above; VT results recorded.
// Returns whether the last PP ended a column (a T_Col's clock 4) in this clock.
template <int W, class Observer>
bool clock_array(std::vector<PpState<W>>& pp, const ArrayInput<W>& in, std::int64_t t, int columns, ArrayRun<W>& run,
                 std::vector<int>& sent, Observer& observer) {
  Word<W> word = in.word;
  PpCtrl ctrl = in.ctrl;
  int drivers = 0;
  bool ends_column = false;
  const int n_pp = int(pp.size());
  for (int k = 0; k < n_pp; ++k) {
    const hls::PpOutputs<W> o = hls::pp_clock(pp[std::size_t(k)], word, ctrl);
    observer.on_clock(t, k, o);
    if (o.vt.valid) {
      ++drivers;
      int& col = sent[std::size_t(k)];
      if (col >= columns) throw std::logic_error("run_systolic_array: more VT results than columns");
      run.results[std::size_t(col) * n_pp + k] = {o.vt.par, o.vt.obj};
      ++col;
      run.last_vt_clock = t;
    }
    word = o.output;
    ctrl = o.ctrl;
    if (k == n_pp - 1) ends_column = o.ends_column;
  }
  if (drivers > 1) ++run.vt_conflicts;
  return ends_column;
}

// Runs the array clock by clock on the stream until every PP has sent every column's result and
// the last PP has finished the last T_Col (after the stream ends the host idles: empty codes; with
// bubbles the frame may end before the host has sent the last of the N_n - 1 pushing codes). `pp`
// is the chain's state, N_n PPs, kept for the next frame: a frame needs no reset, its initialising
// T_Col starts every PP afresh (clocks count from 1 again; the next frame's first code may come in
// the clock after this frame's last).
template <int W, class Observer = NoArrayObserver>
ArrayRun<W> run_array_frame(std::vector<PpState<W>>& pp, const std::vector<StreamCode<W>>& stream, int columns,
                            const ArrayPacing& pacing = {}, Observer&& observer = Observer{}) {
  if (pacing.input_gap_percent > 75 || pacing.vt_stall_percent > 75)
    throw std::invalid_argument("run_systolic_array: stall percentages above 75 would not drain in time");
  const int n_pp = int(pp.size());
  ArrayRun<W> run;
  run.codes_in = std::int64_t(stream.size());
  run.results.resize(std::size_t(columns) * std::size_t(n_pp));
  std::vector<int> sent(std::size_t(n_pp), 0);  // VT results per PP so far
  const std::int64_t limit = 8 * (run.codes_in + 4 * std::int64_t(n_pp) + 16);
  std::size_t next = 0;  // the next code the host offers
  bool holding = false;  // the host offered it in a cycle the array held
  for (std::int64_t t = 1; t <= limit; ++t) {
    const ArrayInput<W> in = host_offer(stream, next, holding, t, pacing);
    const bool vt_ready = !stall_hit(pacing.seed, std::uint64_t(t), 1, pacing.vt_stall_percent);
    if (!vt_ready && array_drives_vt(pp, in)) {
      holding = in.ctrl.valid;
      observer.on_freeze(t);
      continue;
    }
    holding = false;
    if (in.ctrl.valid && next < stream.size()) ++next;
    const bool column_left = clock_array(pp, in, t, columns, run, sent, observer);
    if (column_left && std::all_of(sent.begin(), sent.end(), [&](int c) { return c == columns; })) {
      run.clocks = t;
      return run;
    }
  }
  throw std::logic_error("run_systolic_array: the array did not drain");
}

// The same from power-on (pp_reset with RGeps = eps, RGnear = tau_near).
template <int W, class Observer = NoArrayObserver>
ArrayRun<W> run_array_stream(const std::vector<StreamCode<W>>& stream, const Word<W>& eps, const Word<W>& tau_near,
                             int columns, int n_pp, const ArrayPacing& pacing = {}, Observer&& observer = Observer{}) {
  std::vector<PpState<W>> pp(static_cast<std::size_t>(n_pp));
  for (PpState<W>& st : pp) hls::pp_reset(st, eps, tau_near);
  return run_array_frame(pp, stream, columns, pacing, std::forward<Observer>(observer));
}

// The same from a scene: its frame's stream (build_frame_stream).
template <int W>
ArrayRun<W> run_systolic_array(const InvparamScene<W>& scene, int columns, int n_pp,
                               StreamMode mode = StreamMode::kFull, const ArrayPacing& pacing = {}) {
  if (columns < 1 || n_pp < 1) throw std::invalid_argument("run_systolic_array: columns and n_pp must be >= 1");
  return run_array_stream(build_frame_stream(scene, columns, n_pp, mode), scene.eps, scene.tau_near, columns, n_pp,
                          pacing);
}

// ---- Frame time and throughput (systolic_array.cpp) ---------------------------------------------

// N_K = 4((m + 1) n + 1): codes of one column's chain, before padding.
std::int64_t chain_codes(int m, std::int64_t n);
// The seed's formula, in clocks.
std::int64_t seed_frame_clocks(int m, std::int64_t n, int n_pp, int columns);
// Covered-columns streaming, exact for given per-column chain lengths nk[i] (codes, incl. T_Col):
// 4 + nk[0] + sum_{0 < i < P} max(nk[i], ceil(N_n/4)*4) + N_n - 1 (full streaming: the formula).
std::int64_t covered_columns_clocks(const std::vector<std::int64_t>& nk, int n_pp);
// The same for n objects of m faces, each covering `width` columns, spread so that every column
// is covered by n * width / P objects (real: the mean; exact when it is an integer).
double covered_columns_clocks_mean(int m, double n, double width, int n_pp, int columns);

struct Throughput {
  double full_clocks = 0, full_seconds = 0, full_faces_per_s = 0;
  double covered_clocks = 0, covered_seconds = 0, covered_faces_per_s = 0;
  double covered_limit_faces_per_s = 0;  // n -> infinity: m / (4 (m + 1) width t_t)
};
Throughput invparam_throughput(int m, double n, double width, int n_pp, int columns, double t_t_seconds);

// The array's scene of a frame's setup (face_setup.hpp): every polyhedron an object, the
// background code 0xffffff (no face: face codes are indices in the setup's face list).
template <int W>
InvparamScene<W> scene_of_setup(const InvparamSetup<W>& setup) {
  InvparamScene<W> s;
  s.eps = setup.eps;
  s.tau_near = setup.tau_near;
  s.background = hls::ParCode(0xffffff);
  int first = 0;
  for (int o = 0; o < setup.faces->objects; ++o) {
    ObjectSpan span;
    span.first_face = first;
    span.face_count = setup.faces->object_faces[o];
    first += span.face_count;
    s.objects.push_back(span);
  }
  for (int f = 0; f < first; ++f) s.faces.push_back(setup.faces->face[f]);
  return s;
}

}  // namespace cig::invparam
