// Seed 002's pixel processor and systolic array (cmodel/invparam/systolic_array.hpp): the frame's
// clock count from the simulation equals the seed's formula exactly; the array's per-sample results
// equal a direct per-sample evaluation of Fig. 1 on the same words; covered-columns streaming gives
// the same results with fewer clocks, as its closed form says.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "invparam/systolic_array.hpp"
#include "support/invparam_scenes.hpp"

namespace {

using namespace cig::invparam;
using namespace cig::invparam::scenes;
using cig::hls::ParCode;
using cig::hls::Word;

// ---- The reference: Fig. 1 per sample, on the same words ----------------------------------------
// v = start + column step_x + (row + 1) step_y with the PP's adder (word_add: W-bit wrap). Per face,
// the seed's clock-4 rules decide by the sign of v (= tau, or Den when Az = 0) and Num's sign (As):
// Fig. 1's "Den < 0: not visible" with Den = Num tau; they differ from Fig. 1's text only at
// tau = 0 (taken as non-negative, the adder's s flag) and at ties (the later entry face wins).
template <int W>
Word<W> face_value(const FaceSetup<W>& f, int column, int row) {
  Word<W> v = f.start;
  for (int i = 0; i < column; ++i) v = cig::hls::word_add(v, f.step_x);
  for (int j = 0; j <= row; ++j) v = cig::hls::word_add(v, f.step_y);
  return v;
}

template <int W>
struct ObjectTest {
  bool hit = false;
  Word<W> tau_in;
  ParCode face;
};

template <int W>
ObjectTest<W> reference_object(const InvparamScene<W>& s, const ObjectSpan& o, int column, int row) {
  using namespace cig::hls;
  const Word<W> zero = word_zero<W>(), max = word_max<W>();
  Word<W> tau_in = max, tau_out = zero;
  ParCode hit_pl;
  for (int f = o.first_face; f < o.first_face + o.face_count; ++f) {
    const FaceSetup<W>& fs = s.faces[std::size_t(f)];
    const Word<W> v = face_value(fs, column, row);
    if (!fs.az) {  // Num = 0: tau = Den / 0; Den <= eps (below the tolerance): not visible, miss
      if (!word_greater(v, s.eps)) tau_in = zero;
      continue;
    }
    const bool tau_ahead = !word_negative(v);             // tau >= 0
    const bool visible = fs.as ? !tau_ahead : tau_ahead;  // Den = Num tau >= 0 (tau = 0: by As)
    if (!visible) {
      if (tau_ahead && word_greater(v, tau_out)) tau_out = v;  // Num < 0 here: an exit plane ahead
      if (!tau_ahead) tau_in = zero;                           // the ray left it behind the eye: miss
    } else if (tau_ahead && !word_greater(v, tau_in)) {        // an entry plane ahead, nearest so far
      tau_in = v;
      hit_pl = fs.colour;
    }
  }
  ObjectTest<W> r;
  r.hit = word_greater(tau_in, tau_out) && word_greater(max, tau_in);
  r.tau_in = tau_in;
  r.face = hit_pl;
  return r;
}

template <int W>
VtResult<W> reference_sample(const InvparamScene<W>& s, int column, int row) {
  VtResult<W> r{s.background, cig::hls::word_zero<W>()};  // tau_hit = 0: nothing hit
  for (const ObjectSpan& o : s.objects) {
    const ObjectTest<W> t = reference_object(s, o, column, row);
    if (t.hit && cig::hls::word_greater(t.tau_in, r.obj)) r = {t.face, t.tau_in};
  }
  return r;
}

template <int W>
void expect_reference(const InvparamScene<W>& s, const ArrayRun<W>& run, int columns, int n_pp, const char* what) {
  int bad = 0;
  for (int i = 0; i < columns; ++i)
    for (int j = 0; j < n_pp; ++j) {
      const VtResult<W> ref = reference_sample(s, i, j);
      const VtResult<W>& got = run.at(i, j, n_pp);
      if ((got.par.value() != ref.par.value() || got.obj.low_limb() != ref.obj.low_limb()) && ++bad <= 3)
        ADD_FAILURE() << what << ": column " << i << " row " << j << ": array (" << got.par.value() << ", "
                      << got.obj.low_limb() << "), Fig. 1 (" << ref.par.value() << ", " << ref.obj.low_limb() << ")";
    }
  EXPECT_EQ(bad, 0) << what;
}

template <int W>
void expect_same_results(const ArrayRun<W>& a, const ArrayRun<W>& b, const char* what) {
  ASSERT_EQ(a.results.size(), b.results.size());
  for (std::size_t k = 0; k < a.results.size(); ++k)
    ASSERT_TRUE(a.results[k].par.value() == b.results[k].par.value() &&
                a.results[k].obj.low_limb() == b.results[k].obj.low_limb())
        << what << ": result " << k;
}

// ---- Tests ----------------------------------------------------------------------------------------

TEST(InvparamTokens, FieldsRoundTrip) {
  using namespace cig::hls;
  for (unsigned c = 0; c < 32; ++c) {
    EXPECT_EQ(word_command<63>(command_word<63>(Command(c))).value(), c);
    EXPECT_EQ(word_command<40>(command_word<40>(Command(c))).value(), c);
    // The command in the register's top 5 bits (word_bits(63) = 79: bits 78..74, the high limb's 14..10;
    // the limb above bit 78 is the sign's extension).
    EXPECT_EQ(command_word<63>(Command(c)).high_limb() & 0x7fffu, std::uint64_t(c)
                                                                      << (cig::hls::word_bits(63) - 64 - 5));
    EXPECT_EQ(command_word<63>(Command(c)).low_limb(), 0u);
  }
  for (unsigned p : {0u, 1u, 0x800000u, 0xffffffu, 0x123456u}) {
    EXPECT_EQ(word_par<63>(par_word<63>(ParCode(p))).value(), p);
    EXPECT_EQ(par_word<63>(ParCode(p)).low_limb(), std::uint64_t(p));
    EXPECT_EQ(word_par<57>(Word<57>(std::int64_t(p) - (std::int64_t(1) << 40))).value(), p);  // low bits only
  }
  EXPECT_EQ(command_kind(pln_command(true, false)), kKindPln);
  EXPECT_TRUE(command_az(pln_command(true, false)));
  EXPECT_TRUE(command_as(pln_command(false, true)));
}

// The HLS top (64-bit words): a token leaves one clock later, unchanged except T_Pln's word 3,
// which gains step_y; the T_Col's clock 2 drives VT with the previous column's result.
TEST(InvparamPixelProcessor, TopPassesTokensOneClockLater) {
  using namespace cig::hls;
  constexpr int W = kPpTopWordBits;
  PpState<W> st;
  pp_reset(st, Word<W>(-4), word_max<W>());
  const Word<W> zero = word_zero<W>();
  const Word<W> codes[] = {command_word<W>(pln_command(true, false)),
                           Word<W>(5),
                           Word<W>(100),
                           par_word<W>(ParCode(0x42)),
                           command_word<W>(Command(kCmdObj)),
                           zero,
                           zero,
                           zero,
                           command_word<W>(Command(kCmdCol)),
                           par_word<W>(ParCode(0x99)),
                           zero,
                           zero};
  Word<W> previous = zero;
  int vt = 0;
  for (int t = 0; t < 13; ++t) {
    const Word<W> in = t < 12 ? codes[t] : zero;
    const PpOutputs<W> o = invparam_pixel_processor_top(st, in, PpCtrl{t % 4 == 0});
    EXPECT_EQ(o.output.low_limb(), t == 3 ? 105 : previous.low_limb()) << "clock " << t;
    EXPECT_EQ(o.ctrl.start, t > 0 && (t - 1) % 4 == 0) << "clock " << t;
    if (o.vt.valid) {
      ++vt;
      EXPECT_EQ(t, 9);
      EXPECT_EQ(o.vt.par.value(), 0x42u);  // the face seen at tau = 105
      EXPECT_EQ(o.vt.obj.low_limb(), 105);
    }
    previous = in;
  }
  EXPECT_EQ(vt, 1);
  EXPECT_EQ(st.RGpar.value(), 0x99u);  // the next column starts on its background
}

// The frame's clocks from the simulation: the seed's formula exactly, over random m, n, N_n, P.
TEST(InvparamArray, FrameClocksEqualSeedFormula) {
  std::mt19937_64 rng(2002);
  int cases = 0, nk_below = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int m = int(uniform(rng, 1, 8));
    const int n = trial < 30 ? int(uniform(rng, 0, 1)) : int(uniform(rng, 0, 6));  // the first: N_K < N_n
    const int n_pp = trial < 30 ? int(uniform(rng, 33, 64)) : int(uniform(rng, 1, 64));
    const int columns = int(uniform(rng, 1, 16));
    std::mt19937_64 scene_rng(rng());
    InvparamScene<63> s = random_scene<63>(scene_rng, n, 1, 20);
    for (ObjectSpan& o : s.objects) {  // m faces each
      o.first_face = int(&o - s.objects.data()) * m;
      o.face_count = m;
    }
    s.faces.resize(std::size_t(n) * std::size_t(m), s.faces.empty() ? FaceSetup<63>() : s.faces.front());
    const ArrayRun<63> run = run_systolic_array(s, columns, n_pp);
    const std::int64_t formula = seed_frame_clocks(m, n, n_pp, columns);
    EXPECT_EQ(run.clocks, formula) << "m " << m << " n " << n << " N_n " << n_pp << " P " << columns;
    EXPECT_EQ(run.codes_in, formula);
    EXPECT_EQ(run.last_vt_clock, formula - 2);
    EXPECT_EQ(run.vt_conflicts, 0);
    nk_below += chain_codes(m, n) < n_pp;
    ++cases;
  }
  EXPECT_GE(nk_below, 20);  // the max() of the formula picked the PPs' side
  EXPECT_EQ(cases, 300);
}

// Without the padding to N_n codes the VT bus would be driven twice in one clock: the padding's
// reason. (Column chains of 8 codes for 16 PPs, the empty codes between columns removed.)
TEST(InvparamArray, PaddingKeepsVtBusFree) {
  std::mt19937_64 rng(5);
  const InvparamScene<63> s = random_scene<63>(rng, 1, 1, 12);
  const int n_pp = 16, columns = 3;
  const std::vector<StreamCode<63>> stream = build_frame_stream(s, columns, n_pp, StreamMode::kFull);
  ASSERT_EQ(std::int64_t(stream.size()), seed_frame_clocks(1, 1, n_pp, columns));
  EXPECT_EQ(run_array_stream(stream, s.eps, s.tau_near, columns, n_pp).vt_conflicts, 0);
  std::vector<StreamCode<63>> unpadded;  // keep the last column's N_n - 1 pushing codes
  const std::size_t tail = stream.size() - std::size_t(n_pp - 1);
  for (std::size_t k = 0; k < stream.size(); ++k)
    if (k >= tail || !stream[k].start || word_nonzero(stream[k].word)) unpadded.push_back(stream[k]);
  ASSERT_LT(unpadded.size(), stream.size());
  const ArrayRun<63> run = run_array_stream(unpadded, s.eps, s.tau_near, columns, n_pp);
  EXPECT_GT(run.vt_conflicts, 0);
}

template <int W>
void check_random_results(std::uint64_t seed, int trials) {
  std::mt19937_64 rng(seed);
  std::int64_t hits = 0, samples = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const int range_log2 = std::vector<int>{6, 20, W - 4}[std::size_t(trial % 3)];
    const InvparamScene<W> s = random_scene<W>(rng, int(uniform(rng, 0, 6)), 7, range_log2);
    const int n_pp = int(uniform(rng, 1, 20)), columns = int(uniform(rng, 1, 8));
    const ArrayRun<W> run = run_systolic_array(s, columns, n_pp);
    expect_reference(s, run, columns, n_pp, "random words");
    for (const VtResult<W>& r : run.results) hits += word_nonzero(r.obj) ? 1 : 0;
    samples += std::int64_t(run.results.size());
  }
  EXPECT_GT(hits, samples / 50) << "too few samples hit an object to test anything";
}

TEST(InvparamArray, ResultsEqualFig1RandomWords63) { check_random_results<63>(11, 400); }
TEST(InvparamArray, ResultsEqualFig1RandomWords40) { check_random_results<40>(12, 200); }

// Counts the array's held cycles and the bubbles PP 0 passed down (its output in every advancing
// clock but the first, which is the reset state's).
struct PacingCounter {
  std::int64_t freezes = 0, bubbles = 0, clocks = 0;
  template <class Outputs>
  void on_clock(std::int64_t, int k, const Outputs& o) {
    if (k != 0) return;
    bubbles += clocks > 0 && !o.ctrl.valid;
    ++clocks;
  }
  void on_freeze(std::int64_t) { ++freezes; }
};

// Input bubbles (anywhere, also inside tokens) and VT back-pressure change the clocks, never the
// results: each held cycle adds one clock, each bubble at most one (a bubble behind the last
// T_Col's last word adds none: the frame ends when that word has passed the last PP), and nothing
// drives VT twice.
TEST(InvparamArray, BubblesAndBackPressureOnlyAddClocks) {
  std::mt19937_64 rng(21);
  std::int64_t freezes = 0, bubbles = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const InvparamScene<63> s = random_scene<63>(rng, int(uniform(rng, 0, 5)), 7, 20);
    const int n_pp = int(uniform(rng, 1, 20)), columns = int(uniform(rng, 1, 8));
    const std::vector<StreamCode<63>> stream = build_frame_stream(s, columns, n_pp, StreamMode::kFull);
    const ArrayRun<63> plain = run_array_stream(stream, s.eps, s.tau_near, columns, n_pp);
    const ArrayPacing pacing{std::uint32_t(trial + 1), int(uniform(rng, 0, 60)), int(uniform(rng, 0, 60))};
    PacingCounter count;
    const ArrayRun<63> paced = run_array_stream(stream, s.eps, s.tau_near, columns, n_pp, pacing, count);
    ASSERT_EQ(paced.results.size(), plain.results.size());
    for (std::size_t r = 0; r < plain.results.size(); ++r) {
      EXPECT_EQ(paced.results[r].par.value(), plain.results[r].par.value()) << "trial " << trial << " result " << r;
      EXPECT_EQ(paced.results[r].obj.low_limb(), plain.results[r].obj.low_limb())
          << "trial " << trial << " result " << r;
    }
    EXPECT_EQ(paced.vt_conflicts, 0);
    EXPECT_EQ(paced.clocks, count.clocks + count.freezes);
    EXPECT_GE(paced.clocks - plain.clocks, count.freezes) << "trial " << trial;
    EXPECT_LE(paced.clocks - plain.clocks, count.freezes + count.bubbles + 1) << "trial " << trial;
    if (pacing.input_gap_percent + pacing.vt_stall_percent == 0) { EXPECT_EQ(paced.clocks, plain.clocks); }
    freezes += count.freezes;
    bubbles += count.bubbles;
  }
  EXPECT_GT(freezes, 100);  // the pacing did hold the array and did put bubbles in
  EXPECT_GT(bubbles, 100);
}

// Frames back to back on one chain, no reset between them: each frame's initialising T_Col starts
// every PP afresh, so results and clocks equal those of a chain fresh from power-on (also paced,
// and after an empty scene).
TEST(InvparamArray, ConsecutiveFramesNeedNoReset) {
  std::mt19937_64 rng(23);
  const int n_pp = 9, columns = 5;
  std::vector<PpState<63>> chain(n_pp);
  for (int frame = 0; frame < 12; ++frame) {
    const InvparamScene<63> s = random_scene<63>(rng, frame % 4 == 0 ? 0 : int(uniform(rng, 1, 5)), 7, 20);
    if (frame == 0)
      for (PpState<63>& st : chain) cig::hls::pp_reset(st, s.eps, s.tau_near);
    const std::vector<StreamCode<63>> stream = build_frame_stream(s, columns, n_pp, StreamMode::kFull);
    const ArrayPacing pacing{std::uint32_t(frame + 3), frame % 2 ? 30 : 0, frame % 3 ? 30 : 0};
    const ArrayRun<63> fresh = run_array_stream(stream, s.eps, s.tau_near, columns, n_pp, pacing);
    const ArrayRun<63> kept = run_array_frame(chain, stream, columns, pacing);
    EXPECT_EQ(kept.clocks, fresh.clocks) << "frame " << frame;
    for (std::size_t r = 0; r < fresh.results.size(); ++r) {
      EXPECT_EQ(kept.results[r].par.value(), fresh.results[r].par.value()) << "frame " << frame << " result " << r;
      EXPECT_EQ(kept.results[r].obj.low_limb(), fresh.results[r].obj.low_limb())
          << "frame " << frame << " result " << r;
    }
  }
}

TEST(InvparamArray, ResultsEqualFig1Boxes) {
  std::mt19937_64 rng(13);
  int hits = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const int n_pp = int(uniform(rng, 4, 24)), columns = int(uniform(rng, 2, 12));
    const InvparamScene<57> s = box_scene<57>(rng, int(uniform(rng, 1, 5)), columns, n_pp);
    const ArrayRun<57> run = run_systolic_array(s, columns, n_pp);
    expect_reference(s, run, columns, n_pp, "boxes");
    for (const VtResult<57>& r : run.results) hits += r.par.value() != s.background.value();
  }
  EXPECT_GT(hits, 100);  // the boxes are seen
}

// Covered columns: the same results as full streaming whenever the ranges are conservative, and
// the clocks of its closed form.
TEST(InvparamArray, CoveredColumnsSameResults) {
  std::mt19937_64 rng(14);
  for (int trial = 0; trial < 200; ++trial) {
    const int n_pp = int(uniform(rng, 1, 24)), columns = int(uniform(rng, 1, 12));
    InvparamScene<63> s = trial % 2 ? box_scene<63>(rng, int(uniform(rng, 1, 6)), columns, n_pp)
                                    : random_scene<63>(rng, int(uniform(rng, 0, 6)), 6, 12);
    for (ObjectSpan& o : s.objects) {  // conservative: every column where the object passes, plus slack
      if (trial % 2 == 0) {
        o.first_column = 1 << 20;
        o.last_column = -1;
        for (int i = 0; i < columns; ++i)
          for (int j = 0; j < n_pp; ++j)
            if (reference_object(s, o, i, j).hit) {
              o.first_column = std::min(o.first_column, i);
              o.last_column = std::max(o.last_column, i);
            }
      }
      if (o.first_column <= o.last_column) {
        o.first_column -= int(uniform(rng, 0, 2));
        o.last_column += int(uniform(rng, 0, 2));
      }
    }
    const ArrayRun<63> full = run_systolic_array(s, columns, n_pp, StreamMode::kFull);
    const ArrayRun<63> cov = run_systolic_array(s, columns, n_pp, StreamMode::kCoveredColumns);
    expect_same_results(full, cov, "covered vs full");
    std::vector<std::int64_t> nk(std::size_t(columns), 4);
    for (int i = 0; i < columns; ++i)
      for (const ObjectSpan& o : s.objects)
        if (covers(o, i)) nk[std::size_t(i)] += 4 * (o.face_count + 1);
    EXPECT_EQ(cov.clocks, covered_columns_clocks(nk, n_pp));
    EXPECT_LE(cov.clocks, full.clocks);
    EXPECT_EQ(cov.vt_conflicts, 0);
  }
}

// A range that cuts off a visible object changes the results: the comparison above can fail.
TEST(InvparamArray, CoveredColumnsNonConservativeDiffers) {
  InvparamScene<63> s;
  s.background = ParCode(7);
  s.eps = Word<63>(-16);
  add_box(s, 2, 5, 1, 6, 1 << 20, 100);
  const ArrayRun<63> full = run_systolic_array(s, 8, 8);
  s.objects[0].last_column = 3;
  const ArrayRun<63> cut = run_systolic_array(s, 8, 8, StreamMode::kCoveredColumns);
  EXPECT_EQ(full.at(4, 3, 8).par.value(), 100u);
  EXPECT_EQ(cut.at(4, 3, 8).par.value(), 7u);
}

// The closed form of covered-columns streaming against the model: n objects of width w in layers
// that tile the P columns, so every column is covered by n w / P objects.
TEST(InvparamArray, CoveredColumnsClosedFormMatchesModel) {
  struct Case {
    int m, width, layers, n_pp, columns;
  };
  for (const Case c : {Case{6, 4, 2, 8, 12}, Case{3, 2, 1, 30, 8}, Case{6, 5, 3, 5, 10}, Case{2, 12, 1, 64, 12}}) {
    InvparamScene<63> s;
    s.eps = Word<63>(-16);
    int n = 0;
    for (int l = 0; l < c.layers; ++l)
      for (int a = 0; a + c.width <= c.columns; a += c.width, ++n) {
        add_box(s, a, a + c.width - 1, 0, c.n_pp - 1, (1 << 16) + 1000 * n, unsigned(16 * n));
        s.objects.back().face_count = c.m;  // the first m of the box's faces
      }
    const ArrayRun<63> cov = run_systolic_array(s, c.columns, c.n_pp, StreamMode::kCoveredColumns);
    EXPECT_EQ(double(cov.clocks), covered_columns_clocks_mean(c.m, n, c.width, c.n_pp, c.columns))
        << "m " << c.m << " width " << c.width << " n " << n;
    const Throughput t = invparam_throughput(c.m, n, c.width, c.n_pp, c.columns, 1e-9);
    EXPECT_EQ(t.covered_clocks, double(cov.clocks));
    EXPECT_EQ(t.full_clocks, double(seed_frame_clocks(c.m, n, c.n_pp, c.columns)));
  }
}

TEST(InvparamArray, ThroughputAtSeedSetting) {
  // m = 6, P = N_n = 512, t_t = 3 ns: full streaming is bounded by m / (4 (m + 1) P t_t);
  // covered columns by m / (4 (m + 1) w t_t): 1.43 M faces/s for w = 50 (the seed: > 1.6 M).
  const Throughput t = invparam_throughput(6, 100000, 50, 512, 512, 3e-9);
  EXPECT_NEAR(t.covered_limit_faces_per_s, 6.0 / (28 * 50 * 3e-9), 1);
  EXPECT_LT(t.covered_faces_per_s, t.covered_limit_faces_per_s);
  EXPECT_GT(t.covered_faces_per_s, 0.99 * t.covered_limit_faces_per_s);
  EXPECT_NEAR(t.full_faces_per_s, 6.0 / (28 * 512 * 3e-9), 200);
}

}  // namespace
