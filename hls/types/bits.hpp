// Bit-accurate integer types of the hls/ kernels: Int<W> (two's complement) and UInt<W>,
// 1 <= W <= 64.
//
// Semantics (the same as ac_int / sc_int with explicit widths):
//  * Arithmetic grows the width so that it never loses bits: a + b and a - b have
//    max(Wa, Wb) + 1 bits, a * b has Wa + Wb bits, -a has W + 1 bits. A result wider than 64
//    bits does not compile; the kernel must narrow first.
//  * Widening conversions are implicit; narrowing is explicit and names its overflow rule:
//    wrap<V>(x) keeps the low V bits (two's complement wrap), saturate<V>(x) clamps.
//  * Construction from a C++ integer is explicit and wraps to W bits.
//  * Shifts: shl<K>(x) is exact (W + K bits); x >> n is arithmetic (floor) for Int, logical
//    for UInt, and keeps W bits.
//  * Division: div_trunc(a, b) is C++'s quotient (toward zero); the kernels guard b != 0.
//
// Representation: plain 64-bit integers, kept sign- or zero-extended from bit W-1, so each
// operation is one or two machine instructions. An operation whose result provably fits its
// width (every exact operation above, widening, wrap to a width at least as wide) stores the
// machine result as it is (exact()); only a narrowing (construction from a C++ integer, wrap<V>,
// saturate<V>, a run-time left shift) re-extends, with two shifts or one mask. So a chain of
// operations compiles to the same instructions as hand-written integer code
// (verif/bench/bench_types.cpp measures it). Built with -DCIG_HLS_SYSTEMC the storage is
// SystemC's sc_dt::sc_int<W> / sc_uint<W> instead (Debian's libsystemc-dev), and every value
// passes through SystemC's own W-bit truncation; the kernel tests run in both configurations
// and must produce identical bits.
#pragma once

#include <cstdint>
#include <type_traits>

#include "hls/types/config.hpp"

#ifdef CIG_HLS_SYSTEMC
#include <systemc>
#define CIG_HLS_CONSTEXPR
#else
#define CIG_HLS_CONSTEXPR constexpr
#endif

// The type layer's one-instruction operations are always inlined (an optimiser that keeps one as a
// call costs more than the operation); the synthesis build sees plain functions.
#if defined(__GNUC__) && !defined(__SYNTHESIS__)
#define CIG_HLS_INLINE __attribute__((always_inline)) inline
#else
#define CIG_HLS_INLINE inline
#endif

CIG_HLS_BEGIN_NAMESPACE

namespace detail {

constexpr int max_width(int a, int b) { return a > b ? a : b; }

// Two's complement wrap of v to w bits, sign-extended back to 64.
constexpr std::int64_t wrap_signed(std::int64_t v, int w) {
  return w >= 64 ? v : static_cast<std::int64_t>(static_cast<std::uint64_t>(v) << (64 - w)) >> (64 - w);
}
constexpr std::uint64_t wrap_unsigned(std::uint64_t v, int w) {
  return w >= 64 ? v : (v & ((std::uint64_t{1} << w) - 1));
}
constexpr std::int64_t signed_min(int w) { return w >= 64 ? INT64_MIN : -(std::int64_t{1} << (w - 1)); }
constexpr std::int64_t signed_max(int w) { return w >= 64 ? INT64_MAX : (std::int64_t{1} << (w - 1)) - 1; }
constexpr std::uint64_t unsigned_max(int w) { return w >= 64 ? UINT64_MAX : (std::uint64_t{1} << w) - 1; }

#ifdef CIG_HLS_SYSTEMC
template <int W>
struct SignedStore {
  sc_dt::sc_int<W> s;
  std::int64_t get() const { return s.to_int64(); }
  void set(std::int64_t v) { s = v; }        // SystemC truncates to W bits
  void set_exact(std::int64_t v) { s = v; }  // ... here too: every value passes through SystemC
};
template <int W>
struct UnsignedStore {
  sc_dt::sc_uint<W> s;
  std::uint64_t get() const { return s.to_uint64(); }
  void set(std::uint64_t v) { s = v; }
  void set_exact(std::uint64_t v) { s = v; }
};
#else
template <int W>
struct SignedStore {
  std::int64_t v = 0;
  constexpr std::int64_t get() const { return v; }
  constexpr void set(std::int64_t x) { v = wrap_signed(x, W); }
  constexpr void set_exact(std::int64_t x) { v = x; }  // x already sign-extended from bit W-1
};
template <int W>
struct UnsignedStore {
  std::uint64_t v = 0;
  constexpr std::uint64_t get() const { return v; }
  constexpr void set(std::uint64_t x) { v = wrap_unsigned(x, W); }
  constexpr void set_exact(std::uint64_t x) { v = x; }  // x already below 2^W
};
#endif

// Tag of the constructors that store a value known to fit (no re-extension).
struct ExactTag {};

}  // namespace detail

template <int W>
class UInt;

template <int W>
class Int {
  static_assert(W >= 1 && W <= 64, "Int<W> needs 1 <= W <= 64");

 public:
  static constexpr int width = W;
  static constexpr std::int64_t min_value = detail::signed_min(W);
  static constexpr std::int64_t max_value = detail::signed_max(W);

  CIG_HLS_CONSTEXPR Int() = default;  // zero
  // From a C++ integer: keeps the low W bits (wrap).
  template <class T, class = std::enable_if_t<std::is_integral<T>::value>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit Int(T x) {
    s_.set(static_cast<std::int64_t>(x));
  }
  // Widening from a narrower Int or UInt is exact, hence implicit.
  template <int V, class = std::enable_if_t<(V <= W)>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int(const Int<V>& x) {
    s_.set_exact(x.value());
  }
  template <int V, class = std::enable_if_t<(V < W)>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int(const UInt<V>& x) {
    s_.set_exact(static_cast<std::int64_t>(x.value()));
  }
  // A value the caller knows to lie in W bits (the result of an exact operation).
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int(detail::ExactTag, std::int64_t x) { s_.set_exact(x); }
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int exact(std::int64_t x) { return Int(detail::ExactTag{}, x); }

  CIG_HLS_CONSTEXPR CIG_HLS_INLINE std::int64_t value() const { return s_.get(); }
  CIG_HLS_CONSTEXPR bool bit(int i) const { return (static_cast<std::uint64_t>(value()) >> i) & 1u; }
  CIG_HLS_CONSTEXPR bool is_negative() const { return value() < 0; }
  // Bits [Hi:Lo] as an unsigned field.
  template <int Hi, int Lo>
  CIG_HLS_CONSTEXPR UInt<Hi - Lo + 1> slice() const;

 private:
  detail::SignedStore<W> s_;
};

template <int W>
class UInt {
  static_assert(W >= 1 && W <= 64, "UInt<W> needs 1 <= W <= 64");

 public:
  static constexpr int width = W;
  static constexpr std::uint64_t max_value = detail::unsigned_max(W);

  CIG_HLS_CONSTEXPR UInt() = default;  // zero
  template <class T, class = std::enable_if_t<std::is_integral<T>::value>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit UInt(T x) {
    s_.set(static_cast<std::uint64_t>(x));
  }
  template <int V, class = std::enable_if_t<(V <= W)>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt(const UInt<V>& x) {
    s_.set_exact(x.value());
  }
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt(detail::ExactTag, std::uint64_t x) { s_.set_exact(x); }
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt exact(std::uint64_t x) { return UInt(detail::ExactTag{}, x); }

  CIG_HLS_CONSTEXPR CIG_HLS_INLINE std::uint64_t value() const { return s_.get(); }
  CIG_HLS_CONSTEXPR bool bit(int i) const { return (value() >> i) & 1u; }
  template <int Hi, int Lo>
  CIG_HLS_CONSTEXPR UInt<Hi - Lo + 1> slice() const {
    static_assert(Lo >= 0 && Hi >= Lo && Hi < W, "slice<Hi, Lo> out of range");
    if (Hi == W - 1) return UInt<Hi - Lo + 1>::exact(value() >> Lo);  // the top bits
    return UInt<Hi - Lo + 1>(value() >> Lo);
  }
  // Sets bit i to b (returns the new value; the type is a value type).
  CIG_HLS_CONSTEXPR UInt with_bit(int i, bool b) const {
    const std::uint64_t m = std::uint64_t{1} << i;
    return UInt(b ? (value() | m) : (value() & ~m));
  }

 private:
  detail::UnsignedStore<W> s_;
};

template <int W>
template <int Hi, int Lo>
CIG_HLS_CONSTEXPR UInt<Hi - Lo + 1> Int<W>::slice() const {
  static_assert(Lo >= 0 && Hi >= Lo && Hi < W, "slice<Hi, Lo> out of range");
  return UInt<Hi - Lo + 1>(static_cast<std::uint64_t>(value()) >> Lo);
}

// Traits.
template <class T>
struct is_hls_int : std::false_type {};
template <int W>
struct is_hls_int<Int<W>> : std::true_type {};
template <int W>
struct is_hls_int<UInt<W>> : std::true_type {};

// ---- Narrowing ---------------------------------------------------------------------------------

// Low V bits (two's complement wrap); a width at least as wide keeps the value as it is.
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<V> wrap(const Int<W>& x) {
  if (V >= W) return Int<V>::exact(x.value());
  return Int<V>(x.value());
}
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<V> wrap(const UInt<W>& x) {
  if (V > W) return Int<V>::exact(static_cast<std::int64_t>(x.value()));
  return Int<V>(x.value());
}
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<V> wrap_unsigned(const Int<W>& x) {
  return UInt<V>(x.value());
}
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<V> wrap_unsigned(const UInt<W>& x) {
  if (V >= W) return UInt<V>::exact(x.value());
  return UInt<V>(x.value());
}

// Clamped to the range of V bits.
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<V> saturate(const Int<W>& x) {
  const std::int64_t v = x.value();
  if (V >= W) return Int<V>::exact(v);
  return Int<V>::exact(v < Int<V>::min_value ? Int<V>::min_value : v > Int<V>::max_value ? Int<V>::max_value : v);
}
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<V> saturate_unsigned(const Int<W>& x) {
  const std::int64_t v = x.value();
  if (V >= W - 1) return UInt<V>::exact(v < 0 ? 0 : static_cast<std::uint64_t>(v));
  return UInt<V>::exact(v < 0                                                ? 0
                        : static_cast<std::uint64_t>(v) > UInt<V>::max_value ? UInt<V>::max_value
                                                                             : static_cast<std::uint64_t>(v));
}
template <int V, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<V> saturate_unsigned(const UInt<W>& x) {
  const std::uint64_t v = x.value();
  if (V >= W) return UInt<V>::exact(v);
  return UInt<V>::exact(v > UInt<V>::max_value ? UInt<V>::max_value : v);
}

// Reinterpretation of the same W bits.
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<W> as_signed(const UInt<W>& x) {
  return Int<W>(x.value());
}
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<W> as_unsigned(const Int<W>& x) {
  return UInt<W>(x.value());
}

// Exact conversion of an unsigned value to signed (one more bit).
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<W + 1> to_signed(const UInt<W>& x) {
  return Int<W + 1>::exact(static_cast<std::int64_t>(x.value()));
}

// ---- Arithmetic (exact: the result is wide enough) -----------------------------------------------
// Operands are sign- (zero-) extended from their widths, so the machine result already lies in
// the result's width: stored as it is.

template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<detail::max_width(A, B) + 1> operator+(const Int<A>& a, const Int<B>& b) {
  return Int<detail::max_width(A, B) + 1>::exact(a.value() + b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<detail::max_width(A, B) + 1> operator-(const Int<A>& a, const Int<B>& b) {
  return Int<detail::max_width(A, B) + 1>::exact(a.value() - b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<A + B> operator*(const Int<A>& a, const Int<B>& b) {
  return Int<A + B>::exact(a.value() * b.value());
}
template <int A>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<A + 1> operator-(const Int<A>& a) {
  return Int<A + 1>::exact(-a.value());
}

template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<detail::max_width(A, B) + 1> operator+(const UInt<A>& a, const UInt<B>& b) {
  return UInt<detail::max_width(A, B) + 1>::exact(a.value() + b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<detail::max_width(A, B) + 1> operator-(const UInt<A>& a, const UInt<B>& b) {
  return Int<detail::max_width(A, B) + 1>::exact(static_cast<std::int64_t>(a.value()) -
                                                 static_cast<std::int64_t>(b.value()));
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<A + B> operator*(const UInt<A>& a, const UInt<B>& b) {
  return UInt<A + B>::exact(a.value() * b.value());
}

// Mixed signed/unsigned: the unsigned operand is first made signed (exactly, one more bit).
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator+(const Int<A>& a, const UInt<B>& b) {
  return a + to_signed(b);
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator+(const UInt<A>& a, const Int<B>& b) {
  return to_signed(a) + b;
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator-(const Int<A>& a, const UInt<B>& b) {
  return a - to_signed(b);
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator-(const UInt<A>& a, const Int<B>& b) {
  return to_signed(a) - b;
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator*(const Int<A>& a, const UInt<B>& b) {
  return a * to_signed(b);
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE auto operator*(const UInt<A>& a, const Int<B>& b) {
  return to_signed(a) * b;
}

// Quotient toward zero (C++ semantics); width of the dividend plus one (for min / -1).
template <int A, int B>
CIG_HLS_CONSTEXPR Int<(A < 64 ? A + 1 : 64)> div_trunc(const Int<A>& a, const Int<B>& b) {
  return Int<(A < 64 ? A + 1 : 64)>(b.value() == 0 ? 0 : a.value() / b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR UInt<A> div_trunc(const UInt<A>& a, const UInt<B>& b) {
  return UInt<A>::exact(b.value() == 0 ? 0 : a.value() / b.value());
}

// ---- Shifts ---------------------------------------------------------------------------------------

template <int K, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<W + K> shl(const Int<W>& x) {
  static_assert(K >= 0, "shl<K>: K >= 0");
  return Int<W + K>::exact(static_cast<std::int64_t>(static_cast<std::uint64_t>(x.value()) << K));
}
template <int K, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<W + K> shl(const UInt<W>& x) {
  static_assert(K >= 0, "shl<K>: K >= 0");
  return UInt<W + K>::exact(x.value() << K);
}
// Exact right shift by a constant: drops K low bits (floor), narrows the type.
template <int K, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<(W - K > 0 ? W - K : 1)> shr(const Int<W>& x) {
  static_assert(K >= 0 && K < 64, "shr<K>: 0 <= K < 64");
  return Int<(W - K > 0 ? W - K : 1)>::exact(x.value() >> K);
}
template <int K, int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<(W - K > 0 ? W - K : 1)> shr(const UInt<W>& x) {
  static_assert(K >= 0 && K < 64, "shr<K>: 0 <= K < 64");
  return UInt<(W - K > 0 ? W - K : 1)>::exact(x.value() >> K);
}
// Run-time shifts keep the width (a barrel shifter): left wraps, right is arithmetic/logical.
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<W> operator<<(const Int<W>& x, int n) {
  return Int<W>(static_cast<std::int64_t>(static_cast<std::uint64_t>(x.value()) << n));
}
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<W> operator>>(const Int<W>& x, int n) {
  return Int<W>::exact(x.value() >> n);
}
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<W> operator<<(const UInt<W>& x, int n) {
  return UInt<W>(x.value() << n);
}
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<W> operator>>(const UInt<W>& x, int n) {
  return UInt<W>::exact(x.value() >> n);
}

// ---- Bitwise (same signedness; the wider width) ------------------------------------------------------
// Of two values extended from their widths, the result is extended from the wider: stored as it is.

template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<detail::max_width(A, B)> operator&(const UInt<A>& a, const UInt<B>& b) {
  return UInt<detail::max_width(A, B)>::exact(a.value() & b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<detail::max_width(A, B)> operator|(const UInt<A>& a, const UInt<B>& b) {
  return UInt<detail::max_width(A, B)>::exact(a.value() | b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<detail::max_width(A, B)> operator^(const UInt<A>& a, const UInt<B>& b) {
  return UInt<detail::max_width(A, B)>::exact(a.value() ^ b.value());
}
template <int A>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE UInt<A> operator~(const UInt<A>& a) {
  return UInt<A>(~a.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<detail::max_width(A, B)> operator&(const Int<A>& a, const Int<B>& b) {
  return Int<detail::max_width(A, B)>::exact(a.value() & b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<detail::max_width(A, B)> operator|(const Int<A>& a, const Int<B>& b) {
  return Int<detail::max_width(A, B)>::exact(a.value() | b.value());
}
template <int A, int B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<detail::max_width(A, B)> operator^(const Int<A>& a, const Int<B>& b) {
  return Int<detail::max_width(A, B)>::exact(a.value() ^ b.value());
}

// ---- Comparisons (any widths, any signedness: compared as mathematical integers) ---------------------

namespace detail {
// a < b and a == b as mathematical integers, chosen by the operands' value types (int64 for Int,
// uint64 for UInt). Unsigned values of 64 bits may exceed int64, so a signed and an unsigned
// operand compare through the sign first; any narrower unsigned value fits int64 and compares
// directly.
template <int WA, int WB, class V>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool less_values(V a, V b) {
  return a < b;
}
template <int WA, int WB>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool less_values(std::int64_t a, std::uint64_t b) {
  if (WB < 64) return a < static_cast<std::int64_t>(b);
  return a < 0 || static_cast<std::uint64_t>(a) < b;
}
template <int WA, int WB>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool less_values(std::uint64_t a, std::int64_t b) {
  if (WA < 64) return static_cast<std::int64_t>(a) < b;
  return !(b < 0 || static_cast<std::uint64_t>(b) <= a);
}
template <class V>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool equal_values(V a, V b) {
  return a == b;
}
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool equal_values(std::int64_t a, std::uint64_t b) {
  return a >= 0 && static_cast<std::uint64_t>(a) == b;
}
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool equal_values(std::uint64_t a, std::int64_t b) {
  return b >= 0 && static_cast<std::uint64_t>(b) == a;
}
template <class A, class B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool less(const A& a, const B& b) {
  return less_values<A::width, B::width>(a.value(), b.value());
}
template <class A, class B>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool equal(const A& a, const B& b) {
  return equal_values(a.value(), b.value());
}
}  // namespace detail

template <class A, class B, class = std::enable_if_t<is_hls_int<A>::value && is_hls_int<B>::value>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator==(const A& a, const B& b) {
  return detail::equal(a, b);
}
template <class A, class B, class = std::enable_if_t<is_hls_int<A>::value && is_hls_int<B>::value>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator!=(const A& a, const B& b) {
  return !detail::equal(a, b);
}
template <class A, class B, class = std::enable_if_t<is_hls_int<A>::value && is_hls_int<B>::value>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator<(const A& a, const B& b) {
  return detail::less(a, b);
}
template <class A, class B, class = std::enable_if_t<is_hls_int<A>::value && is_hls_int<B>::value>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator<=(const A& a, const B& b) {
  return !detail::less(b, a);
}
template <class A, class B, class = std::enable_if_t<is_hls_int<A>::value && is_hls_int<B>::value>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator>(const A& a, const B& b) {
  return detail::less(b, a);
}
template <class A, class B, class = std::enable_if_t<is_hls_int<A>::value && is_hls_int<B>::value>>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator>=(const A& a, const B& b) {
  return !detail::less(a, b);
}

// ---- Small helpers kernels use often ---------------------------------------------------------------

template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE Int<W + 1> abs_value(const Int<W>& x) {
  return Int<W + 1>::exact(x.value() < 0 ? -x.value() : x.value());
}

// Position of the most significant set bit (floor(log2(x))), -1 for zero: a priority encoder,
// written as a binary search (log2(W) steps) rather than a scan over every bit. The C model's
// native build takes the processor's count of leading zeros instead (the same result).
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE int leading_one(const UInt<W>& x) {
  std::uint64_t v = x.value();
  if (v == 0) return -1;
#if defined(__GNUC__) && !defined(__SYNTHESIS__)
  return 63 - __builtin_clzll(v);
#else
  int pos = 0;
  for (int step = 32; step > 0; step >>= 1) {
    if (v >> step) {
      v >>= step;
      pos += step;
    }
  }
  return pos;
#endif
}

// Position of the least significant set bit, -1 for zero (the priority encoder from the other end).
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE int lowest_one(const UInt<W>& x) {
  std::uint64_t v = x.value();
  if (v == 0) return -1;
#if defined(__GNUC__) && !defined(__SYNTHESIS__)
  return __builtin_ctzll(v);
#else
  int pos = 0;
  for (int step = 32; step > 0; step >>= 1) {
    if ((v & ((std::uint64_t{1} << step) - 1)) == 0) {
      v >>= step;
      pos += step;
    }
  }
  return pos;
#endif
}

template <class T>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE T min_of(const T& a, const T& b) {
  return b < a ? b : a;
}
template <class T>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE T max_of(const T& a, const T& b) {
  return a < b ? b : a;
}

CIG_HLS_END_NAMESPACE
