// Smoke and unit tests of the quadtree RTL (rtl/), Verilated, against the bit-accurate kernels:
//   * qt_pixel_lane (with qt_e8m7_code inside): the e8m7 code of 1/Z and the sample colour of
//     random and directed inputs (ties to even, the rounding carry, the clamp at 2^41, values
//     below -2^41 that the kernel's Int<42> wraps, exponents out of range, fog factors > 256)
//     against QuadFixedArith::inverse_depth_code and sample_colour;
//   * qt_pe alone (a middle level of N = 512 and the pixel level of N = 16): random windows
//     (extreme edge values, gradients, parameters) with random mask words and random output
//     back-pressure: the children it emits, their order, full flags and mask set requests against
//     evaluate_child;
//   * qt_window_fields: every field of random windows at the offset of the C++ field table
//     (cosim/record_bits.hpp), i.e. rtl/quadtree/qt_pkg.sv's layout and the table agree field by field;
// Whole architectures (qt_raster) are compared with the kernels and the architecture model, record
// for record and cycle for cycle, by verif/cosim.
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

// Verilator's headers and the generated ones are not ours to keep -Wextra-clean.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <verilated.h>

#include "Vqt_pe_n4_l4.h"
#include "Vqt_pe_n9_l5.h"
#include "Vqt_pixel_lane.h"
#include "Vqt_window_fields.h"
#pragma GCC diagnostic pop
#include "cosim/record_bits.hpp"
#include "cosim/verilator_ports.hpp"
#include "hls/quadtree/mask_memory.hpp"
#include "hls/quadtree/pe.hpp"
#include "hls/quadtree/pixel_processor.hpp"
#include "hls/quadtree/setup.hpp"

namespace {

using namespace cig;
using P = hls::QuadFixedArith<hls::QuadFormatFine>;  // the RTL's default widths (rtl/quadtree/README.md)
using cosim::Bits;
using cosim::MaskSetLayout;
using cosim::RecordField;
using Layout = cosim::RecordLayout<P>;
using Rng = std::mt19937_64;

using cosim::port_bits;
using cosim::port_field;
using cosim::set_port_bits;
using cosim::set_port_field;

std::int64_t random_signed(Rng& r, int bits) {  // uniform over a random magnitude class
  const int w = 1 + int(r() % std::uint64_t(bits - 1));
  const std::int64_t v = std::int64_t(r() & ((1ull << (w - 1)) - 1));
  return (r() & 1) ? -v : v;
}

// ---- qt_pixel_lane / qt_e8m7_code ---------------------------------------------------------------

struct LaneCase {
  int sample;  // 4 dj + di
  std::int64_t f_i, f_w, di_i, dj_i, di_w, dj_w;
  int w_exponent;
  int colour[3], fog[3];
  int fog_factor;
};

// The kernel's colour of the sample and the code of its 1/Z (quad_pixel_process, one sample).
void lane_expected(const LaneCase& c, unsigned& code, unsigned (&colour)[3]) {
  const int di = c.sample & 3, dj = c.sample >> 2;
  const P::Param vi = P::at_sample(P::Param(c.f_i), P::Gradient(c.di_i), P::Gradient(c.dj_i), di, dj);
  const P::Param vw = P::at_sample(P::Param(c.f_w), P::Gradient(c.di_w), P::Gradient(c.dj_w), di, dj);
  code = unsigned(P::inverse_depth_code(vw, hls::Int<10>(c.w_exponent)).bits.value());
  const P::Intensity in = P::intensity(vi);
  const hls::FogFactor f = hls::FogFactor::from_raw_value(std::uint64_t(c.fog_factor));
  for (int k = 0; k < 3; ++k)
    colour[k] = unsigned(P::sample_colour(hls::UInt<8>(c.colour[k]), in, f, hls::UInt<8>(c.fog[k])).raw().value());
}

void lane_check(Vqt_pixel_lane& m, const LaneCase& c) {
  const int pw = hls::QuadFormatFine::kParamWidth, gw = hls::QuadFormatFine::kGradientWidth;
  m.sample_i = std::uint8_t(c.sample);
  set_port_field(m.f_intensity_i, 0, pw, std::uint64_t(c.f_i));
  set_port_field(m.f_depth_i, 0, pw, std::uint64_t(c.f_w));
  set_port_field(m.di_intensity_i, 0, gw, std::uint64_t(c.di_i));
  set_port_field(m.dj_intensity_i, 0, gw, std::uint64_t(c.dj_i));
  set_port_field(m.di_depth_i, 0, gw, std::uint64_t(c.di_w));
  set_port_field(m.dj_depth_i, 0, gw, std::uint64_t(c.dj_w));
  m.w_exponent_i = std::uint16_t(c.w_exponent & 1023);
  m.colour_i = std::uint32_t(c.colour[0] | (c.colour[1] << 8) | (c.colour[2] << 16));
  m.fog_colour_i = std::uint32_t(c.fog[0] | (c.fog[1] << 8) | (c.fog[2] << 16));
  m.fog_factor_i = std::uint16_t(c.fog_factor);
  m.eval();
  unsigned code = 0, colour[3];
  lane_expected(c, code, colour);
  ASSERT_EQ(unsigned(m.code_o), code) << "f_w " << c.f_w << " w_exponent " << c.w_exponent;
  for (int k = 0; k < 3; ++k)
    ASSERT_EQ(unsigned(port_field(m.colour_o, 16 * k, 16)), colour[k])
        << "channel " << k << " f_i " << c.f_i << " fog factor " << c.fog_factor;
}

TEST(RtlPixelLane, RandomInputsMatchTheKernel) {
  auto ctx = std::make_unique<VerilatedContext>();
  Vqt_pixel_lane m(ctx.get());
  Rng r(11);
  for (int k = 0; k < 200000; ++k) {
    LaneCase c{};
    c.sample = int(r() % 16);
    c.f_i = random_signed(r, hls::QuadFormatFine::kParamWidth);
    c.f_w = random_signed(r, hls::QuadFormatFine::kParamWidth);
    c.di_i = random_signed(r, hls::QuadFormatFine::kGradientWidth);
    c.dj_i = random_signed(r, hls::QuadFormatFine::kGradientWidth);
    c.di_w = random_signed(r, hls::QuadFormatFine::kGradientWidth);
    c.dj_w = random_signed(r, hls::QuadFormatFine::kGradientWidth);
    if (k % 3 == 0) c.di_i = c.dj_i = c.di_w = c.dj_w = 0;  // the value itself at the sample
    c.w_exponent = int(r() % 1024) - 512;
    if (k % 2 == 0) c.w_exponent = int(r() % 200) - 150;  // the codes a scene produces
    for (int j = 0; j < 3; ++j) {
      c.colour[j] = int(r() % 256);
      c.fog[j] = int(r() % 256);
    }
    c.fog_factor = (k % 4 == 0) ? int(r() % 512) : int(r() % 257);
    lane_check(m, c);
    if (HasFatalFailure()) return;
  }
}

// Directed values of 1/Z: exact halves (ties to even both ways), the carry into the next binade,
// the clamp at 2^41, the wrap of the kernel's Int<42> below -2^41, zero and negatives, and
// exponents that leave the code's range at both ends.
TEST(RtlPixelLane, InverseDepthCodeCornerCases) {
  auto ctx = std::make_unique<VerilatedContext>();
  Vqt_pixel_lane m(ctx.get());
  std::vector<std::int64_t> values = {0,
                                      1,
                                      -1,
                                      2,
                                      127,
                                      128,
                                      255,
                                      256,
                                      257,
                                      (1ll << 41) - 1,
                                      1ll << 41,
                                      (1ll << 41) + 5,
                                      (1ll << 52) - 1,
                                      -(1ll << 41),
                                      -(1ll << 41) - 1,
                                      -(1ll << 41) - 12345,
                                      -(1ll << 42) + 3,
                                      -(1ll << 52)};
  for (int drop = 1; drop <= 33; ++drop)
    for (std::int64_t sig : {128ll, 129ll, 200ll, 201ll, 254ll, 255ll}) {
      const std::int64_t base = sig << drop, half = 1ll << (drop - 1);
      for (std::int64_t v : {base, base + half, base + half - 1, base + half + 1, base - 1})
        if (v > 0 && v < (1ll << 41)) values.push_back(v);
    }
  for (std::int64_t v : values)
    for (int we : {-512, -300, -140, -111, -100, -20, 0, 16, 100, 111, 140, 200, 511}) {
      LaneCase c{};
      c.f_w = v;
      c.w_exponent = we;
      c.fog_factor = 100;
      lane_check(m, c);
      if (HasFatalFailure()) return;
    }
}

// ---- qt_pe --------------------------------------------------------------------------------------

// A random window of level `level - 1` (x, y in range), polygon constants random over their widths.
hls::QuadWindow<P> random_window(Rng& r, int level, int n) {
  hls::QuadWindow<P> w;
  w.level = hls::UInt<4>(level - 1);
  const int span = 1 << (level - 1);
  w.x = hls::UInt<10>(int(r() % std::uint64_t(span)));
  w.y = hls::UInt<10>(int(r() % std::uint64_t(span)));
  const int k = n - level + 2;
  // Active edges as the setup leaves them (the rest A = B = C = 0, d = 0: never reject); d relative
  // to the edge's reach over the window, (|A| + |B|) 2^k: anywhere around it, or mostly inside so
  // that children are covered and fully covered too.
  const int active = 3 + int(r() % 6);
  const bool inside = r() % 2 == 0;
  for (int e = 0; e < hls::kQuadMaxEdges; ++e) {
    w.poly.a[e] = hls::EdgeGradient(0);
    w.poly.b[e] = hls::EdgeGradient(0);
    w.d[e] = hls::EdgeValue(0);
    if (e >= active) continue;
    // Gradients within the setup's range (|A|, |B| < 2^20) or anywhere in 22 bits.
    const bool wide = r() % 8 == 0;
    const std::int64_t a = wide ? random_signed(r, 22) : std::int64_t(r() % 2001) - 1000;
    const std::int64_t b = wide ? random_signed(r, 22) : std::int64_t(r() % 2001) - 1000;
    w.poly.a[e] = hls::EdgeGradient(a);
    w.poly.b[e] = hls::EdgeGradient(b);
    const std::int64_t reach = ((a < 0 ? -a : a) + (b < 0 ? -b : b)) << k;
    std::int64_t d = inside ? reach / 2 + std::int64_t(r() % std::uint64_t(2 * reach + 1))
                            : std::int64_t(r() % std::uint64_t(3 * reach + 3)) - reach;
    if (r() % 16 == 0) d = random_signed(r, 32);
    w.d[e] = hls::EdgeValue(d);
  }
  for (int p = 0; p < hls::kQuadParams; ++p) {
    w.f[p] = P::Param(random_signed(r, hls::QuadFormatFine::kParamWidth));
    w.poly.dp_di[p] = P::Gradient(random_signed(r, hls::QuadFormatFine::kGradientWidth));
    w.poly.dp_dj[p] = P::Gradient(random_signed(r, hls::QuadFormatFine::kGradientWidth));
  }
  w.poly.id = hls::UInt<16>(int(r() % 65536));
  w.poly.opaque = r() % 4 != 0;
  for (int c = 0; c < 3; ++c) w.poly.colour[c] = hls::UInt<8>(int(r() % 256));
  w.poly.edge_count = hls::UInt<4>(int(r() % 9));
  w.poly.w_exponent = hls::Int<10>(int(r() % 1024) - 512);
  return w;
}

struct Emitted {
  int child;
  bool full;
  Bits record;
};

// One window through a stand-alone PE: load, then every child with random output back-pressure.
// Returns the children pushed and the set requests; checks the stall and load timing on the way.
template <class M>
void pe_run(M& m, const hls::QuadWindow<P>& w, unsigned mask, Rng& r, int level, std::vector<Emitted>& out,
            std::vector<int>& sets) {
  const Layout L;
  m.in_valid_i = 1;
  set_port_bits(m.in_data_i, cosim::pack_record(L, w, 0), L.pix_w);
  m.mask_word_i = std::uint8_t(mask);
  m.out_ready_i = 1;
  m.eval();
  ASSERT_TRUE(m.in_ready_o);
  ASSERT_TRUE(m.load_valid_o);
  ASSERT_EQ(unsigned(m.mask_level_o), unsigned(level - 1));
  ASSERT_EQ(unsigned(m.mask_x_o), unsigned(w.x.value()));
  ASSERT_EQ(unsigned(m.mask_y_o), unsigned(w.y.value()));
  m.clk_i = 1;
  m.eval();
  m.clk_i = 0;
  m.in_valid_i = 0;
  m.eval();
  ASSERT_EQ(bool(m.busy_o), mask != 0xF);
  for (int cycle = 0; cycle < 64 && m.busy_o; ++cycle) {
    const bool ready = r() % 3 != 0;
    m.out_ready_i = ready ? 1 : 0;
    m.eval();
    if (m.emit_valid_o) {
      ASSERT_TRUE(ready);
      out.push_back({int(m.emit_child_o), bool(m.emit_full_o), port_bits(m.out_data_o, 0, L.pix_w)});
    }
    if (m.set_valid_o) {
      const MaskSetLayout::Fields set = MaskSetLayout::decode(port_field(m.set_o, 0, MaskSetLayout::width));
      ASSERT_EQ(set.level, level - 1);
      ASSERT_EQ(std::uint64_t(set.x), w.x.value());
      ASSERT_EQ(std::uint64_t(set.y), w.y.value());
      sets.push_back(set.child);
    }
    m.clk_i = 1;
    m.eval();
    m.clk_i = 0;
    m.eval();
  }
  ASSERT_FALSE(m.busy_o);
}

template <class M>
void pe_random_test(int n, int level, int windows, std::uint64_t seed) {
  auto ctx = std::make_unique<VerilatedContext>();
  M m(ctx.get());
  m.clk_i = 0;
  m.rst_ni = 0;
  m.clear_i = 0;
  m.in_valid_i = 0;
  m.eval();
  m.rst_ni = 1;
  m.eval();
  const Layout L;
  Rng r(seed);
  long covered = 0, full = 0;
  for (int k = 0; k < windows; ++k) {
    const hls::QuadWindow<P> w = random_window(r, level, n);
    const unsigned mask = r() % 4 == 0 ? unsigned(r() % 16) : 0u;
    std::vector<Emitted> got;
    std::vector<int> sets;
    pe_run(m, w, mask, r, level, got, sets);
    if (::testing::Test::HasFatalFailure()) return;
    std::vector<Emitted> want;
    std::vector<int> want_sets;
    for (int q = 0; q < 4; ++q) {
      if ((mask >> q) & 1u) continue;
      hls::QuadChild<P> c;
      hls::evaluate_child(w, q, n, false, c);
      if (c.covered) want.push_back({q, c.full, cosim::pack_record(L, c.window, unsigned(c.samples.value()))});
      if (c.full && w.poly.opaque) want_sets.push_back(q);
    }
    ASSERT_EQ(got.size(), want.size()) << "window " << k;
    for (std::size_t i = 0; i < want.size(); ++i) {
      ASSERT_EQ(got[i].child, want[i].child) << "window " << k;
      ASSERT_EQ(got[i].full, want[i].full) << "window " << k << " child " << want[i].child;
      ASSERT_TRUE(got[i].record == want[i].record) << "window " << k << " child " << want[i].child << ": "
                                                   << cosim::first_field_difference(L, want[i].record, got[i].record);
      covered += 1;
      full += want[i].full;
    }
    ASSERT_EQ(sets, want_sets) << "window " << k;
  }
  // The random windows exercise both outcomes of both tests.
  EXPECT_GT(covered, windows / 4);
  EXPECT_GT(full, 0);
}

TEST(RtlPe, MiddleLevelMatchesEvaluateChild) { pe_random_test<Vqt_pe_n9_l5>(9, 5, 3000, 21); }
TEST(RtlPe, PixelLevelMatchesEvaluateChild) { pe_random_test<Vqt_pe_n4_l4>(4, 4, 3000, 22); }

// ---- qt_window_fields ---------------------------------------------------------------------------

// Random windows packed by the C++ field table read back through qt_window_fields, whose slices are
// rtl/quadtree/qt_pkg.sv's offsets: each port against the bits the table puts the field in. A field
// moved, resized or added on one side only fails here, with its name.
TEST(RtlWindowFields, EveryFieldAtTheTablesOffset) {
  auto ctx = std::make_unique<VerilatedContext>();
  Vqt_window_fields m(ctx.get());
  const Layout L;
  Rng r(31);
  for (int k = 0; k < 300; ++k) {
    Bits window(L.win_w);
    for (int lo = 0; lo < L.win_w; lo += 32) window.put(lo, std::min(32, L.win_w - lo), r());
    set_port_bits(m.window_i, window, L.win_w);
    m.eval();
    auto field = [&](int lo, int width) {
      Bits b;
      b.load(window.words(), lo, width);
      return b;
    };
    auto check = [&](RecordField f, const Bits& port, const char* name) {
      ASSERT_TRUE(port == field(L.field_lo(f), L.field_width(f)))
          << name << " (table: bits " << L.field_lo(f) << " +: " << L.field_width(f) << ", port width " << port.width()
          << ")";
    };
    check(RecordField::kLevel, port_bits(m.level_o, 0, L.field_width(RecordField::kLevel)), "level_o");
    check(RecordField::kX, port_bits(m.x_o, 0, L.field_width(RecordField::kX)), "x_o");
    check(RecordField::kY, port_bits(m.y_o, 0, L.field_width(RecordField::kY)), "y_o");
    check(RecordField::kD, port_bits(m.d_o, 0, L.field_width(RecordField::kD)), "d_o");
    check(RecordField::kF, port_bits(m.f_o, 0, L.field_width(RecordField::kF)), "f_o");
    check(RecordField::kId, port_bits(m.id_o, 0, L.field_width(RecordField::kId)), "id_o");
    check(RecordField::kOpaque, port_bits(m.opaque_o, 0, L.field_width(RecordField::kOpaque)), "opaque_o");
    check(RecordField::kColour, port_bits(m.colour_o, 0, L.field_width(RecordField::kColour)), "colour_o");
    check(RecordField::kEdgeCount, port_bits(m.edge_count_o, 0, L.field_width(RecordField::kEdgeCount)),
          "edge_count_o");
    check(RecordField::kA, port_bits(m.a_o, 0, L.field_width(RecordField::kA)), "a_o");
    check(RecordField::kB, port_bits(m.b_o, 0, L.field_width(RecordField::kB)), "b_o");
    check(RecordField::kDpDi, port_bits(m.dp_di_o, 0, L.field_width(RecordField::kDpDi)), "dp_di_o");
    check(RecordField::kDpDj, port_bits(m.dp_dj_o, 0, L.field_width(RecordField::kDpDj)), "dp_dj_o");
    check(RecordField::kWExponent, port_bits(m.w_exponent_o, 0, L.field_width(RecordField::kWExponent)),
          "w_exponent_o");
    check(RecordField::kStartLevel, port_bits(m.start_level_o, 0, L.field_width(RecordField::kStartLevel)),
          "start_level_o");
    check(RecordField::kStartX, port_bits(m.start_x_o, 0, L.field_width(RecordField::kStartX)), "start_x_o");
    check(RecordField::kStartY, port_bits(m.start_y_o, 0, L.field_width(RecordField::kStartY)), "start_y_o");
    // The polygon's constants: id up to the end of the window.
    const int poly_lo = L.field_lo(RecordField::kId);
    ASSERT_TRUE(port_bits(m.poly_o, 0, L.win_w - poly_lo) == field(poly_lo, L.win_w - poly_lo)) << "poly_o";
    if (HasFatalFailure()) return;
  }
}

// ---- qt_raster ----------------------------------------------------------------------------------

}  // namespace
