// rtl/ip_pe.sv (stage F's pixel processor) against the kernel it implements,
// hls/invparam/pixel_processor.hpp pp_clock, cycle by cycle: random token streams (every kind and
// command bit, words drawn so that the comparator goes both ways and ties occur), bubbles inside
// tokens, stray start lines and clock enables low; every cycle the PP's Output, Ctrl, VT and
// column-clock-4 lines against the kernel's state, at the seed's 64-bit word and at 57 bits.
#include <cstdint>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <verilated.h>

#include "Vip_pe_w57.h"
#include "Vip_pe_w64.h"
#pragma GCC diagnostic pop

#include "hls/invparam/pixel_processor.hpp"

namespace {

using namespace cig;
using Rng = std::mt19937_64;

template <int W>
std::uint64_t word_bits(const hls::Word<W>& w) {
  return w.low_limb() & (W >= 64 ? ~0ull : (1ull << W) - 1);
}

// A word the comparator finds interesting: a few small values (ties), extremes, random magnitudes.
template <int W>
hls::Word<W> random_word(Rng& r) {
  switch (r() % 6) {
    case 0:
      return hls::Word<W>(std::int64_t(r() % 7) - 3);
    case 1:
      return (r() & 1) ? hls::word_max<W>() : hls::word_min<W>();
    case 2:
      return hls::word_zero<W>();
    default: {
      const int bits = 1 + int(r() % std::uint64_t(W - 1));
      const std::int64_t v = std::int64_t(r() >> (64 - std::min(bits, 63)));
      return hls::Word<W>((r() & 1) ? -v : v);
    }
  }
}

// Word 1 of a random token: any kind, any command bits.
template <int W>
hls::Word<W> random_command_word(Rng& r) {
  return hls::command_word<W>(hls::Command(unsigned(r() % 32)));
}

struct PeStimulus {
  std::uint64_t word = 0;
  bool start = false, valid = false, en = false;
};

template <class Model, int W>
void check_pe_cycle(Model& m, const hls::PpState<W>& st, const hls::PpCtrl& ctrl, long cycle) {
  const std::uint64_t mask = W >= 64 ? ~0ull : (1ull << W) - 1;
  ASSERT_EQ(std::uint64_t(m.out_word_o) & mask, word_bits(st.RGres)) << "cycle " << cycle << ": RGres on Output";
  ASSERT_EQ(bool(m.out_start_o), st.Tctrl) << "cycle " << cycle << ": Ctrl start";
  ASSERT_EQ(bool(m.out_valid_o), st.Tvalid) << "cycle " << cycle << ": Ctrl valid";
  const bool vt = hls::pp_drives_vt(st, ctrl);
  ASSERT_EQ(bool(m.vt_valid_o), vt) << "cycle " << cycle << ": VT valid";
  if (vt) {
    ASSERT_EQ(std::uint64_t(m.vt_par_o), std::uint64_t(st.RGpar.value())) << "cycle " << cycle << ": VT RGpar";
    ASSERT_EQ(std::uint64_t(m.vt_obj_o) & mask, word_bits(st.RGobj)) << "cycle " << cycle << ": VT RGobj";
  }
  ASSERT_EQ(bool(m.col_clock4_o), hls::pp_ends_column(st, ctrl)) << "cycle " << cycle << ": T_Col clock 4";
}

template <class Model, int W>
void ip_pe_random_test(std::uint64_t seed, long cycles, long* vt_seen) {
  Rng r(seed);
  auto ctx = std::make_unique<VerilatedContext>();
  auto m = std::make_unique<Model>(ctx.get());
  const hls::Word<W> eps(-std::int64_t(1 + r() % 4096));
  hls::PpState<W> st;
  hls::pp_reset(st, eps);
  m->clk_i = 0;
  m->rst_ni = 0;
  m->en_i = 0;
  m->in_valid_i = 0;
  m->eval();
  m->rst_ni = 1;
  m->eps_we_i = 1;
  m->eps_i = word_bits(eps);
  m->clk_i = 1;
  m->eval();
  m->clk_i = 0;
  m->eps_we_i = 0;
  m->eval();
  int word_in_token = 0;  // 0: the next valid word starts a token
  for (long t = 0; t < cycles; ++t) {
    PeStimulus in;
    in.valid = r() % 5 != 0;
    in.en = r() % 7 != 0;
    if (word_in_token == 0) {
      in.word = word_bits(random_command_word<W>(r));
      in.start = true;
    } else {
      in.word = word_bits(random_word<W>(r));
      in.start = r() % 40 == 0;  // a stray start restarts the counter
    }
    m->in_word_i = in.word;
    m->in_start_i = in.start;
    m->in_valid_i = in.valid;
    m->en_i = in.en;
    m->eval();
    const hls::PpCtrl ctrl{in.start, in.valid};
    check_pe_cycle<Model, W>(*m, st, ctrl, t);
    if (::testing::Test::HasFatalFailure()) return;
    *vt_seen += m->vt_valid_o;
    if (in.en) {
      hls::pp_clock(st, hls::Word<W>::from_limbs(0, in.word), ctrl);
      if (in.valid) word_in_token = in.start ? 1 : (word_in_token + 1) % 4;
    }
    m->clk_i = 1;
    m->eval();
    m->clk_i = 0;
    m->eval();
  }
}

TEST(RtlIpPe, Word64MatchesPpClock) {
  long vt = 0;
  ip_pe_random_test<Vip_pe_w64, 64>(31, 200000, &vt);
  EXPECT_GT(vt, 1000);
}

TEST(RtlIpPe, Word57MatchesPpClock) {
  long vt = 0;
  ip_pe_random_test<Vip_pe_w57, 57>(32, 200000, &vt);
  EXPECT_GT(vt, 1000);
}

}  // namespace
