// Bit-accurate fixed-point types of the hls/ kernels, on top of Int<W> / UInt<W>.
//
//   Fixed<W, I, Q, O>   signed two's complement, W bits, I integer bits (sign included),
//                       F = W - I fractional bits: value = raw * 2^-F
//   UFixed<W, I, Q, O>  unsigned, the same with no sign bit
//
// Q (quantization) and O (overflow) apply when a value is converted INTO the type:
//   Quant::kTrunc      drop low bits: floor (toward minus infinity)
//   Quant::kRound      round half up (toward plus infinity): floor(x + 1/2 LSB)
//   Quant::kRoundEven  round half to even (convergent)
//   Overflow::kWrap    keep the low W bits
//   Overflow::kSat     clamp to the type's range
// Arithmetic is exact and grows the format: a + b has max(Fa, Fb) fractional and
// max(Ia, Ib) + 1 integer bits; a * b has Fa + Fb fractional and Ia + Ib integer bits.
// Conversions are explicit: Fixed<...>(x) names the target format and hence its Q and O.
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

enum class Quant { kTrunc, kRound, kRoundEven };
enum class Overflow { kWrap, kSat };

namespace detail {

// Moves a raw value with `from` fractional bits to `to` fractional bits with quantization q.
// The caller guarantees the intermediate fits in 64 bits (static checks in the converters).
CIG_HLS_CONSTEXPR inline std::int64_t requantize(std::int64_t raw, int from, int to, Quant q) {
  if (to >= from) return static_cast<std::int64_t>(static_cast<std::uint64_t>(raw) << (to - from));
  const int d = from - to;
  if (d >= 63) {
    // Everything is dropped: floor is 0 or -1; rounding of |x| < 2^-to... handled as truncation.
    return raw < 0 ? -1 : 0;
  }
  const std::int64_t floor_q = raw >> d;  // arithmetic shift = floor
  if (q == Quant::kTrunc) return floor_q;
  const std::uint64_t rem = static_cast<std::uint64_t>(raw) & ((std::uint64_t{1} << d) - 1);
  const std::uint64_t half = std::uint64_t{1} << (d - 1);
  if (q == Quant::kRound) return floor_q + (rem >= half ? 1 : 0);
  return floor_q + ((rem > half || (rem == half && (floor_q & 1))) ? 1 : 0);
}

// v * 2^k for k >= 0 through the unsigned representation: a left shift of a negative value is
// undefined behaviour in C++17, the two's complement bit pattern is what hardware computes.
CIG_HLS_CONSTEXPR inline std::int64_t shift_left(std::int64_t v, int k) {
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(v) << k);
}

CIG_HLS_CONSTEXPR inline std::int64_t overflow_signed(std::int64_t v, int w, Overflow o) {
  if (o == Overflow::kWrap) return wrap_signed(v, w);
  return v < signed_min(w) ? signed_min(w) : v > signed_max(w) ? signed_max(w) : v;
}
CIG_HLS_CONSTEXPR inline std::uint64_t overflow_unsigned(std::int64_t v, int w, Overflow o) {
  if (o == Overflow::kWrap) return wrap_unsigned(static_cast<std::uint64_t>(v), w);
  if (v < 0) return 0;
  return static_cast<std::uint64_t>(v) > unsigned_max(w) ? unsigned_max(w) : static_cast<std::uint64_t>(v);
}

// The conversion of a raw value of format Src (signed or not, Src::width bits, Src::frac_bits) to
// To fractional bits with quantization Q, with everything known at compile time: requantize()
// unrolled to the one shift (and add) it is. Rounding half up adds half an LSB before the floor
// shift where that sum cannot leave 64 bits; the same value as floor_q + (rem >= half).
template <class Src, int To, Quant Q>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE std::int64_t requantize_to(std::int64_t raw) {
  constexpr int from = Src::frac_bits;
  constexpr int down = To < from && from - To < 63 ? from - To : 1;  // the right shift, valid in every branch
  if (To >= from) return shift_left(raw, To - from);
  if (from - To >= 63 || Src::width >= 63 || Q == Quant::kRoundEven) return requantize(raw, from, To, Q);
  if (Q == Quant::kTrunc) return raw >> down;
  return (raw + (std::int64_t{1} << (down - 1))) >> down;
}

// Bits a value of format Src needs (sign included for a signed target) after requantize_to<To, Q>:
// a left shift adds its bits, a floor right shift removes them, rounding may carry into one more.
template <class Src, int To, Quant Q, bool kSignedTarget>
constexpr int requantized_bits() {
  constexpr int w = Src::width + ((kSignedTarget && !Src::is_signed) ? 1 : 0);
  constexpr int shifted = To >= Src::frac_bits ? w + (To - Src::frac_bits) : w - (Src::frac_bits - To);
  constexpr int carried = (To < Src::frac_bits && Q != Quant::kTrunc) ? shifted + 1 : shifted;
  return carried < 1 ? 1 : carried;
}

// The overflow rule O into W bits, skipped where the source format cannot overflow W bits (the
// rule would leave every value as it is).
template <class Src, int To, Quant Q, int W, Overflow O>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE std::int64_t overflow_signed_to(std::int64_t v) {
  if (requantized_bits<Src, To, Q, true>() <= W) return v;
  return overflow_signed(v, W, O);
}
template <class Src, int To, Quant Q, int W, Overflow O>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE std::uint64_t overflow_unsigned_to(std::int64_t v) {
  constexpr bool fits = requantized_bits<Src, To, Q, false>() <= W;
  if (!Src::is_signed && fits) return static_cast<std::uint64_t>(v);
  if (O == Overflow::kSat && fits) return v < 0 ? 0 : static_cast<std::uint64_t>(v);
  return overflow_unsigned(v, W, O);
}

}  // namespace detail

template <int W, int I, Quant Q = Quant::kTrunc, Overflow O = Overflow::kWrap>
class UFixed;

template <int W, int I, Quant Q = Quant::kTrunc, Overflow O = Overflow::kWrap>
class Fixed {
  static_assert(W >= 1 && W <= 64, "Fixed<W, I>: 1 <= W <= 64");
  static_assert(W - I >= 0 && W - I <= 62, "Fixed<W, I>: 0 <= fractional bits <= 62");

 public:
  static constexpr int width = W, int_bits = I, frac_bits = W - I;
  static constexpr Quant quant = Q;
  static constexpr Overflow overflow = O;
  static constexpr bool is_signed = true;
  using Raw = Int<W>;

  CIG_HLS_CONSTEXPR Fixed() = default;
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE Fixed from_raw(const Int<W>& r) {
    Fixed f;
    f.raw_ = r;
    return f;
  }
  static CIG_HLS_CONSTEXPR Fixed from_raw_value(std::int64_t r) { return from_raw(Int<W>(r)); }
  // A raw value the caller knows to lie in W bits (an exact sum).
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE Fixed from_exact_raw(std::int64_t r) { return from_raw(Int<W>::exact(r)); }

  // From any fixed format: quantize with Q, then overflow with O.
  template <class Src, class = std::enable_if_t<Src::frac_bits >= 0>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit Fixed(const Src& x) {
    static_assert(Src::width + (frac_bits > Src::frac_bits ? frac_bits - Src::frac_bits : 0) <= 64,
                  "conversion would need more than 64 bits");
    const std::int64_t v = detail::requantize_to<Src, frac_bits, Q>(static_cast<std::int64_t>(x.raw().value()));
    raw_ = Int<W>::exact(detail::overflow_signed_to<Src, frac_bits, Q, W, O>(v));
  }
  // From an integer value.
  template <int V>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit Fixed(const Int<V>& x)
      : Fixed(Fixed<V, V, Quant::kTrunc, Overflow::kWrap>::from_raw(x)) {}
  template <int V>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit Fixed(const UInt<V>& x)
      : Fixed(UFixed<V, V, Quant::kTrunc, Overflow::kWrap>::from_raw(x)) {}

  CIG_HLS_CONSTEXPR CIG_HLS_INLINE const Int<W>& raw() const { return raw_; }
  // Integer part, floor.
  CIG_HLS_CONSTEXPR Int<(I > 0 ? I : 1)> floor_int() const {
    return Int<(I > 0 ? I : 1)>::exact(raw_.value() >> frac_bits);
  }

 private:
  Int<W> raw_;
};

template <int W, int I, Quant Q, Overflow O>
class UFixed {
  static_assert(W >= 1 && W <= 64, "UFixed<W, I>: 1 <= W <= 64");
  static_assert(W - I >= 0 && W - I <= 62, "UFixed<W, I>: 0 <= fractional bits <= 62");

 public:
  static constexpr int width = W, int_bits = I, frac_bits = W - I;
  static constexpr Quant quant = Q;
  static constexpr Overflow overflow = O;
  static constexpr bool is_signed = false;
  using Raw = UInt<W>;

  CIG_HLS_CONSTEXPR UFixed() = default;
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE UFixed from_raw(const UInt<W>& r) {
    UFixed f;
    f.raw_ = r;
    return f;
  }
  static CIG_HLS_CONSTEXPR UFixed from_raw_value(std::uint64_t r) { return from_raw(UInt<W>(r)); }
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE UFixed from_exact_raw(std::uint64_t r) { return from_raw(UInt<W>::exact(r)); }

  template <class Src, class = std::enable_if_t<Src::frac_bits >= 0>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit UFixed(const Src& x) {
    static_assert(Src::width + (frac_bits > Src::frac_bits ? frac_bits - Src::frac_bits : 0) <= 64,
                  "conversion would need more than 64 bits");
    static_assert(Src::is_signed || Src::width < 64, "64-bit unsigned sources are not supported");
    const std::int64_t v = detail::requantize_to<Src, frac_bits, Q>(static_cast<std::int64_t>(x.raw().value()));
    raw_ = UInt<W>::exact(detail::overflow_unsigned_to<Src, frac_bits, Q, W, O>(v));
  }
  template <int V>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit UFixed(const UInt<V>& x)
      : UFixed(UFixed<V, V, Quant::kTrunc, Overflow::kWrap>::from_raw(x)) {}
  template <int V>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit UFixed(const Int<V>& x)
      : UFixed(Fixed<V, V, Quant::kTrunc, Overflow::kWrap>::from_raw(x)) {}

  CIG_HLS_CONSTEXPR CIG_HLS_INLINE const UInt<W>& raw() const { return raw_; }
  CIG_HLS_CONSTEXPR UInt<(I > 0 ? I : 1)> floor_int() const {
    return UInt<(I > 0 ? I : 1)>::exact(raw_.value() >> frac_bits);
  }

 private:
  UInt<W> raw_;
};

template <class T>
struct is_hls_fixed : std::false_type {};
template <int W, int I, Quant Q, Overflow O>
struct is_hls_fixed<Fixed<W, I, Q, O>> : std::true_type {};
template <int W, int I, Quant Q, Overflow O>
struct is_hls_fixed<UFixed<W, I, Q, O>> : std::true_type {};

// Exact signed view of an unsigned fixed value (one more integer bit).
template <int W, int I, Quant Q, Overflow O>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Fixed<W + 1, I + 1> to_signed(const UFixed<W, I, Q, O>& x) {
  return Fixed<W + 1, I + 1>::from_raw(to_signed(x.raw()));
}
template <int W, int I, Quant Q, Overflow O>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Fixed<W, I> to_signed(const Fixed<W, I, Q, O>& x) {
  return Fixed<W, I>::from_raw(x.raw());
}

// ---- Exact arithmetic ----------------------------------------------------------------------------

namespace detail {
template <class A, class B>
struct SumFormat {
  static constexpr int F = max_width(A::frac_bits, B::frac_bits);
  static constexpr int I = max_width(A::int_bits, B::int_bits) + 1;
  using type = Fixed<I + F, I>;
};
template <class A, class B>
struct UnsignedSumFormat {
  static constexpr int F = max_width(A::frac_bits, B::frac_bits);
  static constexpr int I = max_width(A::int_bits, B::int_bits) + 1;
  using type = UFixed<I + F, I>;
};
}  // namespace detail

template <int Wa, int Ia, Quant Qa, Overflow Oa, int Wb, int Ib, Quant Qb, Overflow Ob>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator+(const Fixed<Wa, Ia, Qa, Oa>& a, const Fixed<Wb, Ib, Qb, Ob>& b) {
  using R = typename detail::SumFormat<Fixed<Wa, Ia>, Fixed<Wb, Ib>>::type;
  return R::from_exact_raw(detail::shift_left(a.raw().value(), R::frac_bits - (Wa - Ia)) +
                           detail::shift_left(b.raw().value(), R::frac_bits - (Wb - Ib)));
}
template <int Wa, int Ia, Quant Qa, Overflow Oa, int Wb, int Ib, Quant Qb, Overflow Ob>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator-(const Fixed<Wa, Ia, Qa, Oa>& a, const Fixed<Wb, Ib, Qb, Ob>& b) {
  using R = typename detail::SumFormat<Fixed<Wa, Ia>, Fixed<Wb, Ib>>::type;
  return R::from_exact_raw(detail::shift_left(a.raw().value(), R::frac_bits - (Wa - Ia)) -
                           detail::shift_left(b.raw().value(), R::frac_bits - (Wb - Ib)));
}
template <int Wa, int Ia, Quant Qa, Overflow Oa, int Wb, int Ib, Quant Qb, Overflow Ob>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Fixed<Wa + Wb, Ia + Ib> operator*(const Fixed<Wa, Ia, Qa, Oa>& a,
                                                                   const Fixed<Wb, Ib, Qb, Ob>& b) {
  return Fixed<Wa + Wb, Ia + Ib>::from_raw(a.raw() * b.raw());
}
template <int W, int I, Quant Q, Overflow O>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Fixed<W + 1, I + 1> operator-(const Fixed<W, I, Q, O>& a) {
  return Fixed<W + 1, I + 1>::from_raw(-a.raw());
}
template <int Wa, int Ia, Quant Qa, Overflow Oa, int Wb, int Ib, Quant Qb, Overflow Ob>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator+(const UFixed<Wa, Ia, Qa, Oa>& a, const UFixed<Wb, Ib, Qb, Ob>& b) {
  using R = typename detail::UnsignedSumFormat<UFixed<Wa, Ia>, UFixed<Wb, Ib>>::type;
  return R::from_exact_raw(detail::shift_left(a.raw().value(), R::frac_bits - (Wa - Ia)) +
                           detail::shift_left(b.raw().value(), R::frac_bits - (Wb - Ib)));
}
template <int Wa, int Ia, Quant Qa, Overflow Oa, int Wb, int Ib, Quant Qb, Overflow Ob>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UFixed<Wa + Wb, Ia + Ib> operator*(const UFixed<Wa, Ia, Qa, Oa>& a,
                                                                    const UFixed<Wb, Ib, Qb, Ob>& b) {
  return UFixed<Wa + Wb, Ia + Ib>::from_raw(a.raw() * b.raw());
}
// Mixed or unsigned difference: through the signed view.
template <
    class A, class B,
    class = std::enable_if_t<is_hls_fixed<A>::value && is_hls_fixed<B>::value && (!A::is_signed || !B::is_signed)>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator-(const A& a, const B& b) {
  return to_signed(a) - to_signed(b);
}
template <class A, class B,
          class = std::enable_if_t<is_hls_fixed<A>::value && is_hls_fixed<B>::value && (A::is_signed != B::is_signed)>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator+(const A& a, const B& b) {
  return to_signed(a) + to_signed(b);
}
template <class A, class B,
          class = std::enable_if_t<is_hls_fixed<A>::value && is_hls_fixed<B>::value && (A::is_signed != B::is_signed)>,
          class = void>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator*(const A& a, const B& b) {
  return to_signed(a) * to_signed(b);
}

// ---- Comparisons -----------------------------------------------------------------------------------

namespace detail {
// Both raw values aligned to the larger fractional part (exact), compared as integers.
template <class A, class B>
struct AlignedFixed {
  static constexpr int F = max_width(A::frac_bits, B::frac_bits);
  static_assert(A::width + F - A::frac_bits <= 64 && B::width + F - B::frac_bits <= 64,
                "comparison needs more than 64 bits");
  std::int64_t x, y;
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE AlignedFixed(const A& a, const B& b)
      : x(shift_left(static_cast<std::int64_t>(a.raw().value()), F - A::frac_bits)),
        y(shift_left(static_cast<std::int64_t>(b.raw().value()), F - B::frac_bits)) {}
};
}  // namespace detail

#define CIG_HLS_FIXED_COMPARE(op)                                                                         \
  template <class A, class B, class = std::enable_if_t<is_hls_fixed<A>::value && is_hls_fixed<B>::value>, \
            class = void, class = void>                                                                   \
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator op(const A& a, const B& b) {                             \
    const detail::AlignedFixed<A, B> p(a, b);                                                             \
    return p.x op p.y;                                                                                    \
  }
CIG_HLS_FIXED_COMPARE(==)
CIG_HLS_FIXED_COMPARE(!=)
CIG_HLS_FIXED_COMPARE(<)
CIG_HLS_FIXED_COMPARE(<=)
CIG_HLS_FIXED_COMPARE(>)
CIG_HLS_FIXED_COMPARE(>=)
#undef CIG_HLS_FIXED_COMPARE

// ---- Division ---------------------------------------------------------------------------------------

// num / den in the format R, quantized with R's Q (kTrunc = floor) and overflowing with R's O.
// A zero divisor gives R's extreme of the numerator's sign (a saturating divider).
template <class R, class N, class D>
CIG_HLS_CONSTEXPR R fixed_div(const N& num, const D& den) {
  // q = num * 2^(R.F + D.F - N.F) / den, in raw units.
  constexpr int s = R::frac_bits + D::frac_bits - N::frac_bits;
  static_assert(s >= 0 ? N::width + s <= 63 : D::width - s <= 63, "fixed_div needs more than 63 bits");
  std::int64_t n = static_cast<std::int64_t>(num.raw().value());
  std::int64_t d = static_cast<std::int64_t>(den.raw().value());
  if (s >= 0) n = static_cast<std::int64_t>(static_cast<std::uint64_t>(n) << s);
  else d = static_cast<std::int64_t>(static_cast<std::uint64_t>(d) << (-s));
  if (d == 0) {
    if (R::is_signed) return R::from_raw_value(n < 0 ? detail::signed_min(R::width) : detail::signed_max(R::width));
    return R::from_raw_value(n < 0 ? 0 : detail::unsigned_max(R::width));
  }
  if (d < 0) {
    n = -n;
    d = -d;
  }
  std::int64_t q = n / d;
  std::int64_t r = n % d;
  if (r < 0) {  // floor division
    q -= 1;
    r += d;
  }
  const std::uint64_t twice_r = static_cast<std::uint64_t>(r) * 2;
  if (R::quant == Quant::kRound && twice_r >= static_cast<std::uint64_t>(d)) q += 1;
  if (R::quant == Quant::kRoundEven &&
      (twice_r > static_cast<std::uint64_t>(d) || (twice_r == static_cast<std::uint64_t>(d) && (q & 1))))
    q += 1;
  if (R::is_signed) return R::from_raw_value(detail::overflow_signed(q, R::width, R::overflow));
  return R::from_raw_value(detail::overflow_unsigned(q, R::width, R::overflow));
}

CIG_HLS_END_NAMESPACE
