// The segment processor's arithmetic (hls/segment/segment_arith.hpp, zfloat_ops.hpp) and its
// table- and counter-driven kernels (light_segments.hpp, overload.hpp), ac_math style: exhaustive
// where the input space allows, otherwise dense sweeps plus seeded random values, every result
// against an exact reference in 128-bit integer rationals (not against the kernel's own formula).
// Bounds are stated in LSB of the formats beside each assertion. The same file runs in the native
// and the SystemC-typed build; SegmentArith.Digest prints a digest of every output computed here.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/segment/light_segments.hpp"
#include "hls/segment/overload.hpp"
#include "hls/segment/segment_arith.hpp"
#include "hls/types/zfloat_ops.hpp"
#include "reference/sample_lattice.hpp"
#include "segment_test_support.hpp"

namespace cig::hls {
namespace {

using namespace segtest;
using kernel_test::Digest;

#ifdef CIG_HLS_SYSTEMC
constexpr int kScale = 1;  // random-sample counts (the SystemC types are slower)
#else
constexpr int kScale = 2;
#endif
// The random counts of a run: kScale in the tests, 1 in the digest, so that the native and the
// SystemC-typed builds digest the same values (kernel_bits_identical compares the lines).
int scale_of(const kernel_test::Digest* dg) { return dg ? 1 : kScale; }

// ---- e8m7 interpolation (zfloat_ops.hpp) ------------------------------------------------------------

// judge_lerp (segment_test_support.hpp) holds the exact reference and the derivation of its bound.

struct Fraction {
  std::int64_t num, den;
};
// Interpolation points: the ends, simple fractions, eq. 4's quarter-unit ratios, extrapolations.
const Fraction kFractions[] = {{0, 1},  {1, 1}, {1, 2},      {1, 3},         {2, 3},         {1, 4},
                               {3, 4},  {5, 7}, {1, 16380},  {8190, 16380},  {16379, 16380}, {37, 4092},
                               {-1, 4}, {5, 4}, {-3, 16380}, {16383, 16380}, {6, 4},         {-4, 4}};

int lerp_code(int ca, int cb, std::int64_t num, std::int64_t den) {
  return code_of(zfloat_lerp(zcode(ca), zcode(cb), Int<18>(num), Int<18>(den)));
}

// All 128 x 128 mantissa pairs at equal exponents (every tie of the final rounding appears at
// t = 1/2 and must go to even) and at exponent differences around the guard-bit limits (12: last
// exact alignment; 20: the smaller operand vanishes), both orders; random pairs at every other
// difference up to 255, and at both ends of the exponent range (saturation to codes 0 and 0x7FFF).
void work_zfloat_lerp(Digest* dg) {
  long aligned_exactly = 0, exact = 0, double_rounded = 0;
  bool failed = false;
  auto run = [&](int ca, int cb, const Fraction& f) {
    if (failed) return;
    const int r = lerp_code(ca, cb, f.num, f.den);
    const LerpVerdict v = judge_lerp(ca, cb, f.num, f.den, r);
    failed = !v.ok;
    ASSERT_TRUE(v.ok) << "codes " << ca << ", " << cb << " t = " << f.num << "/" << f.den << ": got " << r
                      << ", correctly rounded " << v.rne << ", admissible " << v.lo << ".." << v.hi;
    exact += v.must_be_exact ? 1 : 0;
    if (std::abs((ca >> 7) - (cb >> 7)) <= 12) {  // no alignment loss: only the quotient's rounding
      ++aligned_exactly;
      double_rounded += r != v.rne ? 1 : 0;
    }
    if (dg) dg->add(std::uint64_t(r));
  };
  for (int d : {0, 1, -1, 12, -12, 13, -13, 19, -19, 20, -20}) {
    const int ea = 127, eb = 127 + d;
    for (int ma = 0; ma < 128; ++ma)
      for (int mb = 0; mb < 128; ++mb) {
        const int ca = ea * 128 + ma, cb = eb * 128 + mb;
        if (d == 0) {
          for (const Fraction& f : kFractions) run(ca, cb, f);
        } else {
          run(ca, cb, kFractions[(ma * 7 + mb) % std::size(kFractions)]);
        }
      }
  }
  Rng rng(0x2E8);
  for (int t = 0; t < 60000 * scale_of(dg); ++t) {
    int ea = 0, eb = 0;
    switch (t % 4) {
      case 0:
        ea = int(below(rng, 256));
        eb = int(std::clamp<std::int64_t>(ea + between(rng, -25, 25), 0, 255));
        break;
      case 1:
        ea = int(below(rng, 256));
        eb = int(below(rng, 256));
        break;
      case 2:
        ea = int(below(rng, 4));
        eb = int(below(rng, 4));
        break;  // near the smallest code
      default:
        ea = int(between(rng, 252, 255));
        eb = int(between(rng, 252, 255));
        break;  // the largest
    }
    const int ca = ea * 128 + int(below(rng, 128)), cb = eb * 128 + int(below(rng, 128));
    Fraction f = kFractions[below(rng, std::int64_t(std::size(kFractions)))];
    if (below(rng, 2)) {
      f.den = between(rng, 1, 16380);
      f.num = between(rng, -f.den / 2, f.den + f.den / 2);
    }
    run(ca, cb, f);
  }
  // The extremes themselves.
  EXPECT_EQ(lerp_code(0, 0, 1, 2), 0);
  EXPECT_EQ(lerp_code(0, 5, -4, 4), 0);  // below the smallest value: code 0
  EXPECT_EQ(lerp_code(0x7FFF, 0x7FFF, 1, 2), 0x7FFF);
  EXPECT_EQ(lerp_code(0x7F00, 0x7FFF, 6, 4), 0x7FFF);                   // beyond the largest: saturates
  EXPECT_EQ(lerp_code(127 * 128, 127 * 128 + 3, 1, 2), 127 * 128 + 2);  // 129.5 -> 130 (even)
  EXPECT_EQ(lerp_code(127 * 128, 127 * 128 + 1, 1, 2), 127 * 128 + 0);  // 128.5 -> 128 (even)
  EXPECT_GT(exact, 100000);
  // Results that differ from the correctly rounded code (double rounding, or an absolute error
  // of U/2 after cancellation in an extrapolation) are admissible only within the bound above;
  // recorded for information.
  if (!dg) {
    ::testing::Test::RecordProperty("zfloat_lerp_not_correctly_rounded", std::to_string(double_rounded));
    ::testing::Test::RecordProperty("zfloat_lerp_cases_without_alignment_loss", std::to_string(aligned_exactly));
  }
  std::printf("zfloat_lerp: %ld of %ld results without alignment loss differ from the correctly rounded code\n",
              double_rounded, aligned_exactly);
}

TEST(ZFloatOps, LerpAgainstExactRationalReference) { work_zfloat_lerp(nullptr); }

// zfloat_lerp_ratio: the same with t = t_raw / 2^16 (the video channel's multiply), t in [0, 1].
void work_zfloat_lerp_ratio(Digest* dg) {
  using Ratio = UFixed<17, 1, Quant::kRound, Overflow::kSat>;
  bool failed = false;
  auto run = [&](int ca, int cb, std::int64_t traw) {
    if (failed) return;
    const int r = code_of(zfloat_lerp_ratio(zcode(ca), zcode(cb), Ratio::from_raw_value(std::uint64_t(traw))));
    const LerpVerdict v = judge_lerp(ca, cb, traw, 65536, r);
    failed = !v.ok;
    ASSERT_TRUE(v.ok) << "codes " << ca << ", " << cb << " t_raw " << traw << ": got " << r << ", correctly rounded "
                      << v.rne << ", admissible " << v.lo << ".." << v.hi;
    if (dg) dg->add(std::uint64_t(r));
  };
  const std::int64_t ts[] = {0, 1, 2, 16384, 32768, 32769, 49152, 65535, 65536};
  for (int d : {0, 5, -5, 13, -13, 20, -20})
    for (int ma = 0; ma < 128; ma += (d == 0 ? 1 : 3))
      for (int mb = 0; mb < 128; mb += (d == 0 ? 1 : 3))
        for (std::int64_t t : ts) run(127 * 128 + ma, (127 + d) * 128 + mb, t);
  Rng rng(0xA710);
  for (int k = 0; k < 40000 * scale_of(dg); ++k) {
    const int ea = int(below(rng, 256)), eb = int(std::clamp<std::int64_t>(ea + between(rng, -22, 22), 0, 255));
    run(ea * 128 + int(below(rng, 128)), eb * 128 + int(below(rng, 128)), between(rng, 0, 65536));
  }
}

TEST(ZFloatOps, LerpRatioAgainstExactRationalReference) { work_zfloat_lerp_ratio(nullptr); }

// ---- Light points: the coding table against the float reference's disc -------------------------------

// The table itself: w[D][dy] is the largest w with w^2 + dy^2 <= D^2 (half units), -1 when dy > D.
TEST(LightSegments, CodingTableIsTheLargestChord) {
  for (int d = 0; d < 8; ++d)
    for (int dy = 0; dy < 8; ++dy) {
      const int w = kLightCodingTable.w[d][dy];
      if (dy > d) {
        EXPECT_EQ(w, -1) << d << " " << dy;
      } else {
        EXPECT_GE(w, 0);
        EXPECT_LE(w * w + dy * dy, d * d) << d << " " << dy;
        EXPECT_GT((w + 1) * (w + 1) + dy * dy, d * d) << d << " " << dy;
      }
    }
}

// Every D 0..7, every centre position within a pixel at N = 256, 512 and 1024 (16 x 16, 8 x 8 and
// 4 x 4 grid positions: every sub-pixel position and hence every row offset), one whole sample
// period (u/4 x u/4 positions; the lattice repeats with it) at N = 16..128, and centres on the screen border at every N: the samples the
// kernel's segments cover (columns by the video channel's rule, left X <= X_i < right X) must be
// IDENTICAL to the float reference's disc: sample (i, j) is covered when its distance to the
// centre, in the reference's sample coordinates (cmodel/reference/sample_lattice.hpp), is at most
// the radius D/2 (grid units). All of these are dyadic, so the reference's test is exact in double.
template <class P>
void light_case(int log2, int cx, int cy, int d, long& lights, long& samples, Digest* dg) {
  const int n = 1 << log2, m = 4 * n;
  const LatticeGeometry g = LatticeGeometry::for_raster(log2);
  cig::SampleLattice lattice;
  lattice.raster = n;
  FormattedPrimitive l;
  l.is_light = true;
  l.n = UInt<5>(1);
  l.v[0].x = UInt<12>(cx);
  l.v[0].y = UInt<12>(cy);
  l.v[0].i = UInt<8>((cx * 7 + cy) & 255);
  l.v[0].z = zcode(127 * 128 + (cx & 127));
  l.d = UInt<3>(d);
  l.id = UInt<16>(cx ^ cy);
  Segment<P> out[kMaxLightSegments];
  const int count = generate_light_segments<P>(l, log2, UInt<3>(5), out);
  ASSERT_GE(count, 0);
  ASSERT_LE(count, kMaxLightSegments);
  // The kernel's covered samples, row by row.
  std::vector<std::pair<int, int>> kernel, reference;
  int prev_row = -1;
  for (int s = 0; s < count; ++s) {
    const Segment<P>& seg = out[s];
    ASSERT_EQ(seg.type.value(), kSegWhole);
    ASSERT_EQ(seg.row_first.value(), seg.row_last.value());
    ASSERT_TRUE(seg.is_light);
    ASSERT_TRUE(seg.opaque);
    ASSERT_EQ(seg.channel.value(), 5u);
    ASSERT_EQ(seg.source.value(), l.id.value());
    ASSERT_EQ(seg.il.raw().value(), typename P::Intensity(l.v[0].i).raw().value());
    ASSERT_EQ(seg.ir.raw().value(), seg.il.raw().value());
    ASSERT_EQ(code_of(seg.zl), code_of(l.v[0].z));
    ASSERT_EQ(code_of(seg.zr), code_of(l.v[0].z));
    const int r = int(seg.row_first.value());
    const int row = 4 * int(seg.line.value()) + r;
    ASSERT_GT(row, prev_row);  // one segment per row, top to bottom
    prev_row = row;
    int i0 = P::first_column_at_or_after(g, seg.xl[r]);
    int i1 = P::first_column_at_or_after(g, seg.xr[r]) - 1;
    if (i0 < 0) i0 = 0;
    if (i1 > m - 1) i1 = m - 1;
    for (int i = i0; i <= i1; ++i) kernel.push_back({row, i});
    if (dg) {
      dg->add(seg.line.value());
      dg->add(std::uint64_t(r));
      dg->add_signed(raw_of(seg.xl[r]));
      dg->add_signed(raw_of(seg.xr[r]));
    }
  }
  const double fx = lattice.from_grid(cx), fy = lattice.from_grid(cy), rad = lattice.length_from_grid(0.5 * d);
  const int j0 = std::max(0, int(std::ceil(fy - rad))), j1 = std::min(m - 1, int(std::floor(fy + rad)));
  const int k0 = std::max(0, int(std::ceil(fx - rad))), k1 = std::min(m - 1, int(std::floor(fx + rad)));
  for (int j = j0; j <= j1; ++j)
    for (int i = k0; i <= k1; ++i) {
      const double dx = i - fx, dy = j - fy;
      if (dx * dx + dy * dy <= rad * rad) reference.push_back({j, i});
    }
  ASSERT_EQ(kernel, reference) << "N " << n << " centre (" << cx << ", " << cy << ") D " << d;
  ++lights;
  samples += long(reference.size());
}

template <class P>
void work_light_segments(Digest* dg) {
  long lights = 0, samples = 0;
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    const int u = 4096 >> log2;
    const int span = log2 >= 8 ? u : u / 4;    // a pixel at N >= 256; one sample period (u/4) below
    const int x0 = 2047 - (2047 % u) - 1 + u;  // a pixel's first grid unit: u*p - 1
    std::vector<int> xs, ys;
    for (int k = 0; k < span; ++k) xs.push_back(x0 + k);
    for (int k = 0; k < span; ++k) ys.push_back(x0 + 3 * u + k);
    for (int b : {0, 1, 2, 3, 4, 5, 6, 7, 4088, 4089, 4090, 4091, 4092, 4093, 4094, 4095}) {
      xs.push_back(b);
      ys.push_back(b);
    }
    for (int d = 0; d < 8; ++d)
      for (int cy : ys)
        for (int cx : xs) {
          light_case<P>(log2, cx, cy, d, lights, samples, dg);
          if (::testing::Test::HasFatalFailure()) return;
        }
  }
  EXPECT_GT(lights, 90000);
  std::printf("light segments: %ld lights, %ld covered samples\n", lights, samples);
  EXPECT_GT(samples, 50000);
}

TEST(LightSegments, CoverageEqualsTheReferenceDiscFine) {
  work_light_segments<FixedSegmentArith<SegmentFormatFine>>(nullptr);
}
TEST(LightSegments, CoverageEqualsTheReferenceDiscCoarse) {
  work_light_segments<FixedSegmentArith<SegmentFormatCoarse>>(nullptr);
}

// ---- Row and column geometry ------------------------------------------------------------------------

// Half-unit position of sample row (or column) k by multiplication (valid for negative k too).
int row_pos(const LatticeGeometry& g, int k) { return k * (1 << g.log2_half_spacing) + g.offset_half; }

// For every raster 16..1024: row k (line L = k/4, sample row r = k%4) lies at grid Y = u*L - 1 +
// (2r + 1) u/8 (records.hpp, the reference's lattice): sample_half(k) = 2Y exactly, and the reference's
// sample coordinate of that Y is k. first_sample_at_or_after_half(h) is the smallest k with
// sample_half(k) >= h for every h (brute force, including h before the first and after the last row);
// the fixed and the twin's first_row_at_or_after agree on every grid Y 0..4095.
void work_row_geometry(Digest* dg) {
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    const int n = 1 << log2, u = 4096 / n, rows = 4 * n;
    const LatticeGeometry g = LatticeGeometry::for_raster(log2);
    cig::SampleLattice lattice;
    lattice.raster = n;
    for (int k = 0; k < rows; ++k) {
      const int L = k / 4, r = k % 4;
      const int twice_y = 2 * (u * L - 1) + (2 * r + 1) * u / 4;
      ASSERT_EQ(g.sample_half(k), twice_y) << n << " " << k;
      ASSERT_EQ(lattice.from_grid(0.5 * g.sample_half(k)), double(k));
    }
    int k = -3 * (rows + 8);  // brute-force pointer: smallest k with sample_half(k) >= h
    for (int h = -2 * u - 8; h <= 8192 + 2 * u; ++h) {
      while (row_pos(g, k) < h) ++k;
      ASSERT_LT(row_pos(g, k - 1), h);
      ASSERT_EQ(g.first_sample_at_or_after_half(h), k) << "N " << n << " h " << h;
      if (dg && (h & 7) == 0) dg->add_signed(k);
    }
    for (int y = 0; y < 4096; ++y) {
      const int f = DefaultSegmentArith::first_row_at_or_after(g, UInt<12>(y));
      ASSERT_EQ(f, g.first_sample_at_or_after_half(2 * y));
      ASSERT_EQ(Twin::first_row_at_or_after(g, double(y)), f) << n << " " << y;
    }
  }
}

TEST(LatticeGeometry, EveryRasterRowsAndFirstRowMatchTheFormula) { work_row_geometry(nullptr); }

// first_column_at_or_after: the smallest sample column i with X_i >= x, X_i = sample_half(i) / 2. Checked
// by its definition on the raw value (sample_half(i) * 2^(F-1) >= raw > sample_half(i - 1) * 2^(F-1)),
// exhaustively over every raw value of the coarse X format at every raster and, for the medium and
// fine formats, over every raw value within 4 LSB of every column position plus random values; the
// twin's double version gives the same column for the same (dyadic) value.
template <class Fmt>
void work_columns(Digest* dg) {
  using P = FixedSegmentArith<Fmt>;
  using X = typename P::X;
  constexpr int F = X::frac_bits;
  const std::int64_t lo = -(std::int64_t(1) << (X::width - 1)), hi = (std::int64_t(1) << (X::width - 1)) - 1;
  Rng rng(0xC01);
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    const LatticeGeometry g = LatticeGeometry::for_raster(log2);
    auto check = [&](std::int64_t raw) {
      const X x = X::from_raw_value(raw);
      const int i = P::first_column_at_or_after(g, x);
      const i128 at = mul2k(row_pos(g, i), F - 1), before = mul2k(row_pos(g, i - 1), F - 1);
      ASSERT_TRUE(at >= raw && before < raw) << "N 2^" << log2 << " raw " << raw << " -> " << i;
      ASSERT_EQ(Twin::first_column_at_or_after(g, value_of(x)), i) << raw;
      if (dg) dg->add_signed(i);
    };
    if (X::width <= 16) {
      for (std::int64_t raw = lo; raw <= hi; ++raw) check(raw);
    } else {
      for (int i = -2; i <= (4 << log2) + 2; i += (log2 >= 9 ? 3 : 1)) {
        const std::int64_t c = std::int64_t(row_pos(g, i)) * (std::int64_t(1) << (F - 1));
        for (std::int64_t dr = -4; dr <= 4; ++dr) check(c + dr);
      }
      for (int t = 0; t < 5000 * scale_of(dg); ++t) check(between(rng, lo, hi));
    }
  }
}

TEST(LatticeGeometry, FirstColumnExactCoarse) { work_columns<SegmentFormatCoarse>(nullptr); }
TEST(LatticeGeometry, FirstColumnExactMedium) { work_columns<SegmentFormatMedium>(nullptr); }
TEST(LatticeGeometry, FirstColumnExactFine) { work_columns<SegmentFormatFine>(nullptr); }

// ---- Area code (eq. 6) ------------------------------------------------------------------------------

// The definition (segment_arith.hpp): area = |twice| / 2 units^2; code c in 2..14 holds areas in
// [2^(20-c), 2^(21-c)), code 1 areas >= 2^19, code 15 areas < 2^6 (and zero). At every octave
// boundary of the twice-area (2^k - 1, 2^k, 2^k + 1 for k = 0..30, both signs, and the extremes of
// Area) the fixed and the twin's codes are that code. Twice-areas are integers, so the twin's
// log2 sees the same octave: the codes must be EQUAL, never one apart.
int area_code_by_definition(std::int64_t twice) {
  const std::int64_t m = twice < 0 ? -twice : twice;  // 2 * area
  for (int c = 1; c <= 14; ++c)
    if (m >= (std::int64_t(1) << (21 - c))) return c;  // area >= 2^(20 - c)
  return 15;
}

void work_area_code(Digest* dg) {
  std::vector<std::int64_t> values = {0, Int<32>::max_value, Int<32>::min_value + 1};
  for (int k = 0; k <= 30; ++k)
    for (std::int64_t dv : {-1, 0, 1}) values.push_back((std::int64_t(1) << k) + dv);
  for (std::int64_t v : values)
    for (std::int64_t s : {1, -1}) {
      const std::int64_t t = v * s;
      const int c = DefaultSegmentArith::area_code(Int<32>(t));
      ASSERT_EQ(c, area_code_by_definition(t)) << t;
      ASSERT_EQ(Twin::area_code(double(t)), c) << t;
      ASSERT_EQ(FixedSegmentArith<SegmentFormatCoarse>::area_code(Int<32>(t)), c);
      if (dg) dg->add(std::uint64_t(c));
    }
  // Monotone: a larger area never gets a larger code.
  std::vector<std::int64_t> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k + 1 < sorted.size(); ++k) {
    if (sorted[k] >= 0) {
      ASSERT_GE(DefaultSegmentArith::area_code(Int<32>(sorted[k])),
                DefaultSegmentArith::area_code(Int<32>(sorted[k + 1])));
    }
  }
}

TEST(AreaCode, EveryOctaveBoundary) { work_area_code(nullptr); }

// ---- Overload threshold (eq. 6 bucket counts) ------------------------------------------------------

// Brute force: the largest T in 1..15 such that, in both fields, the segments of codes 0..T fit the
// bank; 0 when none does (protected polygons are always kept, even when they alone overflow).
int threshold_brute(const OverloadCounts& c, long cap) {
  for (int t = 15; t >= 1; --t) {
    long s0 = 0, s1 = 0;
    for (int k = 0; k <= t; ++k) {
      s0 += long(c.segments[0][k].value());
      s1 += long(c.segments[1][k].value());
    }
    if (s0 <= cap && s1 <= cap) return t;
  }
  return 0;
}

void work_overload(Digest* dg) {
  Rng rng(0x0F1);
  for (int t = 0; t < 20000 * scale_of(dg); ++t) {
    OverloadCounts c;
    overload_reset(c);
    const long cap = t % 5 == 0 ? kSegmentBankWords : long(between(rng, 0, 1 << 20));
    const int mode = int(below(rng, 4));
    for (int f = 0; f < 2; ++f)
      for (int k = 0; k < kAreaCodes; ++k) {
        std::int64_t v = 0;
        switch (mode) {
          case 0:
            v = between(rng, 0, cap / 8 + 1);
            break;
          case 1:
            v = below(rng, 3) == 0 ? 0 : between(rng, 0, cap / 3 + 1);
            break;
          case 2:
            v = below(rng, 8) == 0 ? (std::int64_t(1) << 24) - 1 : between(rng, 0, 64);
            break;
          default:
            v = between(rng, 0, 2 * cap / kAreaCodes + 1);
            break;
        }
        c.segments[f][k] = UInt<24>(std::uint64_t(v));
      }
    // Make some sums hit the capacity exactly.
    if (t % 3 == 0) {
      const int k = int(below(rng, kAreaCodes)), f = int(below(rng, 2));
      long s = 0;
      for (int j = 0; j < k; ++j) s += long(c.segments[f][j].value());
      if (s <= cap && cap - s < (1 << 24)) c.segments[f][k] = UInt<24>(std::uint64_t(cap - s));
    }
    const int got = overload_threshold_top(c, int(cap));
    ASSERT_EQ(got, threshold_brute(c, cap)) << "case " << t;
    if (dg) dg->add(std::uint64_t(got));
  }
  // overload_count accumulates the headers' per-field counts into their code's bucket.
  OverloadCounts c;
  overload_reset(c);
  long expect[2][kAreaCodes] = {};
  for (int t = 0; t < 3000; ++t) {
    PolygonHeader<DefaultSegmentArith> h;
    h.area_code = UInt<4>(std::uint64_t(below(rng, 16)));
    h.segments_even = UInt<11>(std::uint64_t(below(rng, 1025)));
    h.segments_odd = UInt<11>(std::uint64_t(below(rng, 1025)));
    overload_count(h, c);
    expect[0][h.area_code.value()] += long(h.segments_even.value());
    expect[1][h.area_code.value()] += long(h.segments_odd.value());
  }
  for (int f = 0; f < 2; ++f)
    for (int k = 0; k < kAreaCodes; ++k) {
      ASSERT_EQ(long(c.segments[f][k].value()), expect[f][k]);
      if (dg) dg->add(c.segments[f][k].value());
    }
}

TEST(Overload, ThresholdEqualsBruteForceSearch) { work_overload(nullptr); }

// ---- The fixed-point operations of the policy, against exact rationals ----------------------------

// Every operation below is one exact computation followed by one rounding half up (Quant::kRound)
// and saturation, so each result must equal floor(exact * 2^F + 1/2), clamped to the format: a
// bound of 1/2 LSB that is met with equality, checked bit for bit.
template <class Fmt>
void work_policy_ops(Digest* dg) {
  using P = FixedSegmentArith<Fmt>;
  using X = typename P::X;
  using S = typename P::Slope;
  using I = typename P::Intensity;
  constexpr int Fx = X::frac_bits, Fs = S::frac_bits, Fi = I::frac_bits;
  const i128 xmin = -(i128(1) << (X::width - 1)), xmax = (i128(1) << (X::width - 1)) - 1;
  const i128 imax = (i128(1) << I::width) - 1;
  auto clampi = [](i128 v, i128 lo, i128 hi) { return v < lo ? lo : v > hi ? hi : v; };
  auto add = [&](std::int64_t v) {
    if (dg) dg->add_signed(v);
  };
  Rng rng(0x5EED + Fx);
  const int n = 20000 * scale_of(dg);
  for (int t = 0; t < n; ++t) {
    const int log2 = int(between(rng, kMinRasterLog2, kMaxRasterLog2));
    const LatticeGeometry g = LatticeGeometry::for_raster(log2);
    const int s = g.log2_half_spacing;
    const int ya = int(below(rng, 4095)), yb = int(between(rng, ya + 1, 4095));
    const int xa = int(below(rng, 4096)), xb = t % 7 == 0 ? xa : int(below(rng, 4096));
    const UInt<12> cxa(xa), cya(ya), cxb(xb), cyb(yb);
    const i128 dx = xb - xa, dy = yb - ya;
    // Eq. 2: slope per sample row = dx / dy * 2^(s - 1) grid units.
    const S slope = P::slope_per_row(g, cxa, cya, cxb, cyb);
    ASSERT_TRUE(raw_of(slope) == round_half_up(mul2k(dx, s + Fs), 2 * dy)) << xa << " " << ya << " " << xb << " " << yb;
    add(raw_of(slope));
    // The crossing at a row k whose Y lies in [ya, yb): xa + dx * (Y_k - ya) / dy, one rounding,
    // to the slope's fractional bits (it loads the stepping accumulator).
    const int kf = g.first_sample_at_or_after_half(2 * ya), kl = g.first_sample_at_or_after_half(2 * yb) - 1;
    if (kf <= kl) {
      const int k = int(between(rng, kf, kl));
      const S x = P::crossing(g, cxa, cya, cxb, cyb, k);
      const i128 t2 = g.sample_half(k) - 2 * ya;
      ASSERT_TRUE(raw_of(x) == (i128(xa) << Fs) + round_half_up(mul2k(dx * t2, Fs), 2 * dy));
      add(raw_of(x));
      // Stepping: x + rows * slope, exact in the accumulator, rounded once into X.
      const int rows = int(between(rng, 0, 4095));
      const X st = P::step(x, slope, rows);
      ASSERT_TRUE(
          raw_of(st) ==
          clampi(round_half_up(i128(raw_of(x)) + i128(rows) * raw_of(slope), i128(1) << (Fs - Fx)), xmin, xmax));
      add(raw_of(st));
    }
    // Eq. 3 at a quarter-unit Y (anywhere within a row spacing of the edge; beyond its ends t is
    // clamped to them): ib + (ie - ib) * (yt - yb) / (ye - yb), one rounding, clamped to the
    // Intensity format.
    const int ib = int(below(rng, 256)), ie = t % 5 == 0 ? 255 : int(below(rng, 256));
    const int ytq = int(between(rng, 4 * ya - (1 << s), 4 * yb + (1 << s)));
    const I in = P::intensity_at(UInt<8>(ib), UInt<8>(ie), cya, cyb, ytq);
    const i128 t4 = std::clamp<i128>(ytq - 4 * ya, 0, 4 * dy);
    const i128 along = round_half_up(mul2k(i128(ie - ib) * t4, Fi), 4 * dy);
    ASSERT_TRUE(raw_of(in) == clampi((i128(ib) << Fi) + along, 0, imax)) << ib << " " << ie << " " << ytq;
    add(raw_of(in));
    // Midpoint: (a + b) / 2, one rounding.
    const X a = X::from_raw_value(between(rng, std::int64_t(xmin), std::int64_t(xmax)));
    const X b = X::from_raw_value(between(rng, std::int64_t(xmin), std::int64_t(xmax)));
    ASSERT_TRUE(raw_of(P::midpoint(a, b)) == round_half_up(i128(raw_of(a)) + raw_of(b), 2));
    add(raw_of(P::midpoint(a, b)));
    // Seed quadrilateral interpolation: x0 + (x1 - x0) * num / den, den 1..3, on X values of the
    // screen (-1..4096 grid units: the step (x1 - x0) * num / den is held in the X format, which
    // saturates beyond +-2^(I-1), far outside the screen).
    const int den = int(between(rng, 1, 3)), num = int(between(rng, 0, den));
    const X la = X::from_raw_value(between(rng, -(std::int64_t(1) << Fx), std::int64_t(4096) << Fx));
    const X lb = X::from_raw_value(between(rng, -(std::int64_t(1) << Fx), std::int64_t(4096) << Fx));
    const X lx = P::lerp_x(la, lb, num, den);
    ASSERT_TRUE(raw_of(lx) == raw_of(la) + round_half_up((i128(raw_of(lb)) - raw_of(la)) * num, den))
        << raw_of(la) << " " << raw_of(lb) << " " << num << "/" << den << " -> " << raw_of(lx);
    add(raw_of(lx));
    // Video channel: 1/span (24 fractional bits, saturating), t = along / span (16 fractional bits,
    // at most 1), I along the segment, colour x I, fog mix, box filter.
    const X span = X::from_raw_value(t % 9 == 0 ? between(rng, -3, 3) : between(rng, 1, std::int64_t(xmax)));
    const typename P::Reciprocal inv = P::reciprocal(span);
    const i128 inv_expect =
        raw_of(span) > 0 ? clampi(round_half_up(i128(1) << (Fx + 24), raw_of(span)), 0, (i128(1) << 32) - 1) : 0;
    ASSERT_TRUE(i128(inv.raw().value()) == inv_expect) << raw_of(span);
    const X alongx = X::from_raw_value(t % 11 == 0 ? between(rng, -3, 3) : between(rng, 1, std::int64_t(xmax)));
    const typename P::Ratio ratio = P::ratio(alongx, inv);
    i128 r_expect = 0;
    if (raw_of(alongx) > 0) {
      r_expect = clampi(round_half_up(i128(raw_of(alongx)) * inv_expect, i128(1) << (Fx + 8)), 0, (i128(1) << 17) - 1);
      if (r_expect > 65536) r_expect = 65536;
    }
    ASSERT_TRUE(i128(ratio.raw().value()) == r_expect);
    add(std::int64_t(inv.raw().value()));
    add(std::int64_t(ratio.raw().value()));
    const I il = I::from_raw_value(std::uint64_t(below(rng, std::int64_t(imax) + 1)));
    const I ir = I::from_raw_value(std::uint64_t(below(rng, std::int64_t(imax) + 1)));
    const I li = P::lerp_intensity(il, ir, ratio);
    ASSERT_TRUE(raw_of(li) ==
                clampi(raw_of(il) + round_half_up((i128(raw_of(ir)) - raw_of(il)) * r_expect, 65536), 0, imax));
    add(raw_of(li));
    const int c = int(below(rng, 256)), fog = int(below(rng, 256));
    const typename P::Sample sh = P::shade(UInt<8>(c), li);
    ASSERT_TRUE(raw_of(sh) == clampi(round_half_up(i128(c) * raw_of(li), i128(1) << Fi), 0, 65535));
    const typename P::FogFactor f = P::FogFactor::from_raw_value(std::uint64_t(below(rng, 257)));
    const typename P::Sample mx = P::mix(sh, UInt<8>(fog), f);
    ASSERT_TRUE(
        raw_of(mx) ==
        clampi(round_half_up(i128(raw_of(sh)) * (256 - raw_of(f)) + i128(fog) * 256 * raw_of(f), 256), 0, 65535));
    add(raw_of(sh));
    add(raw_of(mx));
  }
  // The box filter: the mean of the 4^t samples rounded half up, saturated to 255, for every
  // lattice t = 0..3 (the digest takes the seeds' 4 x 4 only, first: its draws are unchanged).
  for (const int side_log2 : {kDefaultSideLog2, 0, 1, 3}) {
    const int count = 1 << (2 * side_log2);
    for (int t = 0; t < 4000 * scale_of(dg); ++t) {
      typename P::Sample samples[kMaxSamplesPerPixel];
      i128 sum = 0;
      const int mode = t % 3;
      for (int k = 0; k < count; ++k) {
        const std::int64_t v = mode == 0   ? below(rng, 65536)
                               : mode == 1 ? between(rng, 65280, 65535)
                                           : between(rng, 0, 300);
        samples[k] = P::Sample::from_raw_value(std::uint64_t(v));
        sum += v;
      }
      const UInt<8> px = P::resolve(samples, side_log2);
      ASSERT_TRUE(i128(px.value()) == clampi(round_half_up(sum, 256 * count), 0, 255));
      if (side_log2 == kDefaultSideLog2) add(std::int64_t(px.value()));
    }
  }
  for (int c = 0; c < 256; ++c) ASSERT_EQ(raw_of(P::level_sample(UInt<8>(c))), 256 * c);
}

TEST(SegmentArith, PolicyOpsExactCoarse) { work_policy_ops<SegmentFormatCoarse>(nullptr); }
TEST(SegmentArith, PolicyOpsExactMedium) { work_policy_ops<SegmentFormatMedium>(nullptr); }
TEST(SegmentArith, PolicyOpsExactFine) { work_policy_ops<SegmentFormatFine>(nullptr); }

// Eq. 2 exhaustively in dy: every dy 1..4095 against a set of dx at every raster (the quotient's
// rounding half up is exact: raw = floor(dx * 2^(s + F) / (2 dy) + 1/2)).
void work_slope_sweep(Digest* dg) {
  using P = DefaultSegmentArith;
  constexpr int Fs = P::Slope::frac_bits;
  const int dxs[] = {-4095, -4094, -2048, -1365, -7, -1, 0, 1, 3, 5, 1024, 2047, 2731, 4095};
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    const LatticeGeometry g = LatticeGeometry::for_raster(log2);
    for (int dy = 1; dy <= 4095; ++dy)
      for (int dx : dxs) {
        const int xa = dx < 0 ? 4095 : 0;
        const auto s = P::slope_per_row(g, UInt<12>(xa), UInt<12>(0), UInt<12>(xa + dx), UInt<12>(dy));
        ASSERT_TRUE(raw_of(s) == round_half_up(mul2k(dx, g.log2_half_spacing + Fs), 2 * dy)) << dx << "/" << dy;
        if (dg && (dy & 15) == 0) dg->add_signed(raw_of(s));
      }
  }
}

TEST(SegmentArith, SlopeEveryDy) { work_slope_sweep(nullptr); }

// ---- Digest -------------------------------------------------------------------------------------------

TEST(SegmentArith, Digest) {
  Digest d;
  work_zfloat_lerp(&d);
  work_zfloat_lerp_ratio(&d);
  work_light_segments<FixedSegmentArith<SegmentFormatFine>>(&d);
  work_light_segments<FixedSegmentArith<SegmentFormatCoarse>>(&d);
  work_row_geometry(&d);
  work_columns<SegmentFormatCoarse>(&d);
  work_columns<SegmentFormatMedium>(&d);
  work_columns<SegmentFormatFine>(&d);
  work_area_code(&d);
  work_overload(&d);
  work_policy_ops<SegmentFormatCoarse>(&d);
  work_policy_ops<SegmentFormatMedium>(&d);
  work_policy_ops<SegmentFormatFine>(&d);
  work_slope_sweep(&d);
  kernel_test::print_digest("segment_arith", d);
}

}  // namespace
}  // namespace cig::hls
