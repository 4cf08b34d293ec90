// rtl/invparam/ip_pe.sv (stage F's pixel processor) against the kernel it implements,
// hls/invparam/pixel_processor.hpp pp_clock, cycle by cycle: random token streams (every kind and
// command bit, words drawn so that the comparator goes both ways and ties occur), bubbles inside
// tokens, stray start lines and clock enables low, configuration writes of RGeps and RGnear at
// random clocks (RGnear random, MAX among them); every cycle the PP's Output, Ctrl, VT and
// column-clock-4 lines against the kernel's state, for the seed's 64-bit word and 57 bits (the
// models' W is the register width, word_bits: 80 and 73 bits, VlWide ports).
#include <algorithm>
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

#include "cosim/verilator_ports.hpp"
#include "hls/invparam/pixel_processor.hpp"

namespace {

using namespace cig;
using cosim::PortWord;
using Rng = std::mt19937_64;

// The register of hls Word<W>: its word_bits(W) bits.
template <int W>
PortWord reg_bits(const hls::Word<W>& w) {
  constexpr int kBits = hls::word_bits(W);
  static_assert(kBits < 128, "");
  return (PortWord(w.high_limb()) << 64 | PortWord(w.low_limb())) & ((PortWord(1) << kBits) - 1);
}
template <int W>
hls::Word<W> word_of_bits(PortWord x) {
  return hls::Word<W>::from_limbs(std::uint64_t(x >> 64), std::uint64_t(x));
}

// A word the comparator finds interesting: a few small values (ties), extremes, random magnitudes
// up to the register's (word_bits(W) bits).
template <int W>
hls::Word<W> random_word(Rng& r) {
  constexpr int kBits = hls::word_bits(W);
  switch (r() % 6) {
    case 0:
      return hls::Word<W>(std::int64_t(r() % 7) - 3);
    case 1:
      return (r() & 1) ? hls::word_max<W>() : hls::word_min<W>();
    case 2:
      return hls::word_zero<W>();
    default: {
      const int bits = 1 + int(r() % std::uint64_t(kBits - 1));
      const PortWord raw = PortWord(r()) << 64 | PortWord(r());
      const PortWord v = raw >> (128 - bits);  // 0 <= v < 2^bits
      return word_of_bits<W>((r() & 1) ? PortWord(0) - v : v);
    }
  }
}

// RGnear: MAX (the seed's PP) one time in three, else a random word.
template <int W>
hls::Word<W> random_near(Rng& r) {
  return r() % 3 == 0 ? hls::word_max<W>() : random_word<W>(r);
}

// Word 1 of a random token: any kind, any command bits.
template <int W>
hls::Word<W> random_command_word(Rng& r) {
  return hls::command_word<W>(hls::Command(unsigned(r() % 32)));
}

struct PeStimulus {
  PortWord word = 0;
  bool start = false, valid = false, en = false;
};

template <class Model, int W>
void check_pe_cycle(Model& m, const hls::PpState<W>& st, const hls::PpCtrl& ctrl, long cycle) {
  constexpr int kBits = hls::word_bits(W);
  ASSERT_TRUE(cosim::port_word(m.out_word_o, 0, kBits) == reg_bits<W>(st.RGres))
      << "cycle " << cycle << ": RGres on Output";
  ASSERT_EQ(bool(m.out_start_o), st.Tctrl) << "cycle " << cycle << ": Ctrl start";
  ASSERT_EQ(bool(m.out_valid_o), st.Tvalid) << "cycle " << cycle << ": Ctrl valid";
  const bool vt = hls::pp_drives_vt(st, ctrl);
  ASSERT_EQ(bool(m.vt_valid_o), vt) << "cycle " << cycle << ": VT valid";
  if (vt) {
    ASSERT_EQ(std::uint64_t(m.vt_par_o), std::uint64_t(st.RGpar.value())) << "cycle " << cycle << ": VT RGpar";
    ASSERT_TRUE(cosim::port_word(m.vt_obj_o, 0, kBits) == reg_bits<W>(st.RGobj)) << "cycle " << cycle << ": VT RGobj";
  }
  ASSERT_EQ(bool(m.col_clock4_o), hls::pp_ends_column(st, ctrl)) << "cycle " << cycle << ": T_Col clock 4";
}

// Counts of what the run exercised: VT results, Obj clocks 3 whose compare ran (Tc) and, of those,
// the ones that RGnear decided otherwise than MAX would have (RGtin >= RGnear).
struct PeCounts {
  long vt = 0, obj3 = 0, near_cut = 0;
};

template <class Model, int W>
void ip_pe_random_test(std::uint64_t seed, long cycles, PeCounts* counts) {
  constexpr int kBits = hls::word_bits(W);
  Rng r(seed);
  auto ctx = std::make_unique<VerilatedContext>();
  auto m = std::make_unique<Model>(ctx.get());
  hls::Word<W> eps(-std::int64_t(1 + r() % 4096)), tau_near = random_near<W>(r);
  hls::PpState<W> st;
  hls::pp_reset(st, eps, tau_near);
  m->clk_i = 0;
  m->rst_ni = 0;
  m->en_i = 0;
  m->in_valid_i = 0;
  m->cfg_we_i = 0;
  m->eval();
  m->rst_ni = 1;
  m->cfg_we_i = 1;
  cosim::set_port_word(m->eps_i, kBits, reg_bits<W>(eps));
  cosim::set_port_word(m->near_i, kBits, reg_bits<W>(tau_near));
  m->clk_i = 1;
  m->eval();
  m->clk_i = 0;
  m->cfg_we_i = 0;
  m->eval();
  int word_in_token = 0;  // 0: the next valid word starts a token
  for (long t = 0; t < cycles; ++t) {
    PeStimulus in;
    in.valid = r() % 5 != 0;
    in.en = r() % 7 != 0;
    if (word_in_token == 0) {
      in.word = reg_bits<W>(random_command_word<W>(r));
      in.start = true;
    } else {
      in.word = reg_bits<W>(random_word<W>(r));
      in.start = r() % 40 == 0;  // a stray start restarts the counter
    }
    // Now and then a configuration write (whatever en_i): new RGeps and RGnear from the next clock.
    const bool cfg = r() % 50 == 0;
    hls::Word<W> new_eps = eps, new_near = tau_near;
    if (cfg) {
      new_eps = random_word<W>(r);
      new_near = random_near<W>(r);
    }
    cosim::set_port_word(m->in_word_i, kBits, in.word);
    m->in_start_i = in.start;
    m->in_valid_i = in.valid;
    m->en_i = in.en;
    m->cfg_we_i = cfg;
    cosim::set_port_word(m->eps_i, kBits, reg_bits<W>(new_eps));
    cosim::set_port_word(m->near_i, kBits, reg_bits<W>(new_near));
    m->eval();
    const hls::PpCtrl ctrl{in.start, in.valid};
    check_pe_cycle<Model, W>(*m, st, ctrl, t);
    if (::testing::Test::HasFatalFailure()) return;
    counts->vt += m->vt_valid_o;
    if (in.en) {
      // Obj clock 3 with its compare enabled: does RGnear cut what MAX would keep?
      const hls::PpState<W> before = st;
      hls::pp_clock(st, word_of_bits<W>(in.word), ctrl);
      if (in.valid && hls::pp_next_clock(before, ctrl).value() == 3 && hls::command_kind(before.RGI) == hls::kKindObj &&
          before.Tc) {
        ++counts->obj3;
        const bool with_max = hls::word_greater(hls::word_max<W>(), before.RGtin);
        counts->near_cut += with_max != hls::word_greater(before.RGnear, before.RGtin) ? 1 : 0;
      }
      if (in.valid) word_in_token = in.start ? 1 : (word_in_token + 1) % 4;
    }
    if (cfg) {
      eps = new_eps;
      tau_near = new_near;
      hls::pp_configure(st, eps, tau_near);
    }
    m->clk_i = 1;
    m->eval();
    m->clk_i = 0;
    m->cfg_we_i = 0;
    m->eval();
  }
}

TEST(RtlIpPe, Word64MatchesPpClock) {
  PeCounts c;
  ip_pe_random_test<Vip_pe_w64, 64>(31, 200000, &c);
  EXPECT_GT(c.vt, 1000);
  EXPECT_GT(c.near_cut, 50) << "of " << c.obj3 << " Obj clocks 3";
}

TEST(RtlIpPe, Word57MatchesPpClock) {
  PeCounts c;
  ip_pe_random_test<Vip_pe_w57, 57>(32, 200000, &c);
  EXPECT_GT(c.vt, 1000);
  EXPECT_GT(c.near_cut, 50) << "of " << c.obj3 << " Obj clocks 3";
}

}  // namespace
