// The bit-accurate type layer against independent exact references (ac_math style): every
// operation on every value of small widths, random values at large widths. The same file runs in
// the native and the SystemC-typed build (cig_kernel_tests, cig_kernel_tests_systemc).
#include <cstdint>
#include <random>
#include <utility>

#include <gtest/gtest.h>

#include "hls/types/fixed.hpp"

namespace cig::hls {
namespace {

using i128 = __int128;

// Mathematical reference of W-bit two's complement wrap.
i128 wrap_ref(i128 v, int w) {
  const i128 m = i128(1) << w;
  i128 r = ((v % m) + m) % m;
  return r >= (m >> 1) ? r - m : r;
}
i128 sat_ref(i128 v, int w) {
  const i128 lo = -(i128(1) << (w - 1)), hi = (i128(1) << (w - 1)) - 1;
  return v < lo ? lo : v > hi ? hi : v;
}
i128 floor_div(i128 n, i128 d) {  // d > 0
  i128 q = n / d;
  if ((n % d) != 0 && n < 0) q -= 1;
  return q;
}
// Quantizes the rational n / d (d > 0) to an integer with mode q.
i128 quantize_ref(i128 n, i128 d, Quant q) {
  const i128 f = floor_div(n, d);
  const i128 r2 = 2 * (n - f * d);  // twice the remainder, in [0, 2d)
  if (q == Quant::kTrunc) return f;
  if (q == Quant::kRound) return f + (r2 >= d ? 1 : 0);
  return f + ((r2 > d || (r2 == d && (f & 1))) ? 1 : 0);
}

template <int A, int B>
void exhaustive_int_ops() {
  for (i128 x = Int<A>::min_value; x <= Int<A>::max_value; ++x)
    for (i128 y = Int<B>::min_value; y <= Int<B>::max_value; ++y) {
      const Int<A> a(static_cast<std::int64_t>(x));
      const Int<B> b(static_cast<std::int64_t>(y));
      ASSERT_EQ(i128((a + b).value()), x + y);
      ASSERT_EQ(i128((a - b).value()), x - y);
      ASSERT_EQ(i128((a * b).value()), x * y);
      ASSERT_EQ((a < b), x < y);
      ASSERT_EQ((a == b), x == y);
      ASSERT_EQ(i128(wrap<A>(a + b).value()), wrap_ref(x + y, A));
      ASSERT_EQ(i128(saturate<B>(a * b).value()), sat_ref(x * y, B));
      if (y != 0) { ASSERT_EQ(i128(div_trunc(a, b).value()), x / y); }
      // Unsigned views of the same bits.
      const i128 ux = ((x % (i128(1) << A)) + (i128(1) << A)) % (i128(1) << A);
      const i128 uy = ((y % (i128(1) << B)) + (i128(1) << B)) % (i128(1) << B);
      const UInt<A> ua = as_unsigned(a);
      const UInt<B> ub = as_unsigned(b);
      ASSERT_EQ(i128(ua.value()), ux);
      ASSERT_EQ(i128((ua + ub).value()), ux + uy);
      ASSERT_EQ(i128((ua - ub).value()), ux - uy);
      ASSERT_EQ(i128((ua * ub).value()), ux * uy);
      ASSERT_EQ(i128((a + ub).value()), x + uy);
      ASSERT_EQ((a < ub), x < uy);
      ASSERT_EQ(i128((ua & ub).value()), ux & uy);
      ASSERT_EQ(i128((ua | ub).value()), ux | uy);
    }
}

TEST(Types, IntOperationsExhaustiveForSmallWidths) {
  exhaustive_int_ops<1, 1>();
  exhaustive_int_ops<1, 5>();
  exhaustive_int_ops<3, 4>();
  exhaustive_int_ops<5, 5>();
  exhaustive_int_ops<6, 2>();
  exhaustive_int_ops<7, 7>();
}

TEST(Types, ShiftsAndSlices) {
  for (int x = -128; x < 128; ++x) {
    const Int<8> a(x);
    ASSERT_EQ(shl<3>(a).value(), x * 8);
    ASSERT_EQ(shr<3>(a).value(), static_cast<std::int64_t>(floor_div(x, 8)));
    ASSERT_EQ((a >> 2).value(), static_cast<std::int64_t>(floor_div(x, 4)));
    ASSERT_EQ((a << 1).value(), static_cast<std::int64_t>(wrap_ref(2 * x, 8)));
    const std::uint64_t bits = static_cast<std::uint8_t>(x);
    ASSERT_EQ((a.slice<5, 2>().value()), (bits >> 2) & 15u);
    for (int i = 0; i < 8; ++i) ASSERT_EQ(a.bit(i), bool((bits >> i) & 1));
    const UInt<8> u(bits);
    ASSERT_EQ((u >> 3).value(), bits >> 3);
    ASSERT_EQ(u.with_bit(0, true).value(), bits | 1u);
  }
}

TEST(Types, SixtyFourBitEdges) {
  std::mt19937_64 rng(7);
  for (int t = 0; t < 100000; ++t) {
    const std::int64_t x = static_cast<std::int64_t>(rng()) >> (rng() % 40);
    const std::int64_t y = static_cast<std::int64_t>(rng()) >> (32 + rng() % 31);
    const Int<63> a(x >> 1);
    const Int<32> b(static_cast<std::int32_t>(y));
    ASSERT_EQ(i128((a + b).value()), i128(x >> 1) + i128(static_cast<std::int32_t>(y)));
    ASSERT_EQ(i128(wrap<40>(a).value()), wrap_ref(i128(x >> 1), 40));
    ASSERT_EQ(i128(saturate<40>(a).value()), sat_ref(i128(x >> 1), 40));
    const UInt<64> u(static_cast<std::uint64_t>(x));
    ASSERT_EQ(u.value(), static_cast<std::uint64_t>(x));
    ASSERT_EQ((Int<64>(x) < u), i128(x) < i128(static_cast<std::uint64_t>(x)) ? true : false);
  }
  EXPECT_EQ(Int<64>::min_value, INT64_MIN);
  EXPECT_EQ(UInt<64>::max_value, UINT64_MAX);
}

// Every raw value of a source format converted into a target format, with every mode.
template <class Src, class Dst>
void exhaustive_conversion() {
  constexpr int Fs = Src::frac_bits, Fd = Dst::frac_bits;
  const i128 lo = Src::is_signed ? -(i128(1) << (Src::width - 1)) : 0;
  const i128 hi = Src::is_signed ? (i128(1) << (Src::width - 1)) - 1 : (i128(1) << Src::width) - 1;
  for (i128 r = lo; r <= hi; ++r) {
    const Src x = Src::from_raw_value(static_cast<std::int64_t>(r));
    const Dst y(x);
    // value = r / 2^Fs; target raw = Q(r * 2^Fd / 2^Fs), then overflow.
    i128 q = Fd >= Fs ? r * (i128(1) << (Fd - Fs)) : quantize_ref(r, i128(1) << (Fs - Fd), Dst::quant);
    if (Dst::is_signed) {
      q = Dst::overflow == Overflow::kWrap ? wrap_ref(q, Dst::width) : sat_ref(q, Dst::width);
      ASSERT_EQ(i128(static_cast<std::int64_t>(y.raw().value())), q) << "raw " << static_cast<long long>(r);
    } else {
      const i128 m = i128(1) << Dst::width;
      q = Dst::overflow == Overflow::kWrap ? ((q % m) + m) % m : (q < 0 ? 0 : q >= m ? m - 1 : q);
      ASSERT_EQ(i128(y.raw().value()), q) << "raw " << static_cast<long long>(r);
    }
  }
}

template <Quant Q, Overflow O>
void conversions_for_mode() {
  exhaustive_conversion<Fixed<8, 3>, Fixed<6, 3, Q, O>>();   // drop 2 fractional bits
  exhaustive_conversion<Fixed<8, 3>, Fixed<5, 2, Q, O>>();   // drop 2, lose an integer bit
  exhaustive_conversion<Fixed<8, 3>, Fixed<10, 3, Q, O>>();  // add fractional bits
  exhaustive_conversion<Fixed<10, 8>, Fixed<5, 5, Q, O>>();  // to integer
  exhaustive_conversion<Fixed<9, 2>, UFixed<4, 1, Q, O>>();  // signed to unsigned
  exhaustive_conversion<UFixed<9, 4>, Fixed<6, 4, Q, O>>();  // unsigned to signed
}

TEST(Types, FixedConversionsExhaustiveInEveryMode) {
  conversions_for_mode<Quant::kTrunc, Overflow::kWrap>();
  conversions_for_mode<Quant::kTrunc, Overflow::kSat>();
  conversions_for_mode<Quant::kRound, Overflow::kWrap>();
  conversions_for_mode<Quant::kRound, Overflow::kSat>();
  conversions_for_mode<Quant::kRoundEven, Overflow::kWrap>();
  conversions_for_mode<Quant::kRoundEven, Overflow::kSat>();
}

template <class A, class B>
void exhaustive_fixed_arith() {
  for (i128 ra = -(i128(1) << (A::width - 1)); ra < (i128(1) << (A::width - 1)); ++ra)
    for (i128 rb = -(i128(1) << (B::width - 1)); rb < (i128(1) << (B::width - 1)); ++rb) {
      const A a = A::from_raw_value(static_cast<std::int64_t>(ra));
      const B b = B::from_raw_value(static_cast<std::int64_t>(rb));
      constexpr int F = A::frac_bits > B::frac_bits ? A::frac_bits : B::frac_bits;
      const i128 xa = ra * (i128(1) << (F - A::frac_bits)), xb = rb * (i128(1) << (F - B::frac_bits));  // common scale
      const auto s = a + b;
      static_assert(decltype(s)::frac_bits == F);
      ASSERT_EQ(i128(s.raw().value()), xa + xb);
      ASSERT_EQ(i128((a - b).raw().value()), xa - xb);
      const auto p = a * b;
      static_assert(decltype(p)::frac_bits == A::frac_bits + B::frac_bits);
      ASSERT_EQ(i128(p.raw().value()), ra * rb);
      ASSERT_EQ((a < b), xa < xb);
      ASSERT_EQ((a == b), xa == xb);
      // Division into a rounded format: q = round(a / b * 2^F), exactly.
      if (rb != 0) {
        using Q = Fixed<16, 8, Quant::kRound, Overflow::kSat>;
        const Q q = fixed_div<Q>(a, b);
        // a / b = (ra / 2^Fa) / (rb / 2^Fb); raw = ra * 2^(8 + Fb - Fa) / rb
        i128 n = ra, d = rb;
        const int sh = 8 + B::frac_bits - A::frac_bits;
        if (sh >= 0) n *= i128(1) << sh;
        else d *= i128(1) << -sh;
        if (d < 0) {
          n = -n;
          d = -d;
        }
        ASSERT_EQ(i128(q.raw().value()), sat_ref(quantize_ref(n, d, Quant::kRound), 16));
      }
    }
}

TEST(Types, FixedArithmeticExhaustive) {
  exhaustive_fixed_arith<Fixed<6, 2>, Fixed<5, 4>>();
  exhaustive_fixed_arith<Fixed<7, 7>, Fixed<6, 1>>();
  exhaustive_fixed_arith<Fixed<5, 0>, Fixed<5, 3>>();
}

}  // namespace
}  // namespace cig::hls
