// WideInt<W>: a W-bit two's complement integer, 2 <= W <= 128, with only the operations a wide
// register of an adder/comparator datapath needs (stage F's word, hls/invparam/word.hpp):
//
//   WideInt<W>(int64)          the low W bits of the value (wrap)
//   from_limbs(hi, lo)         the low W bits of the 128-bit two's complement value hi:lo (wrap)
//   add_wrap(b)                a + b wrapped to W bits (an adder without carry out)
//   greater(b), equal(b)       signed compare
//   is_negative(), is_zero()   the sign and zero flags
//   max_code(), min_code()     2^(W-1) - 1 and -2^(W-1)
//   high_limb(), low_limb()    the value sign-extended to 128 bits, as two 64-bit limbs (tests
//                              read it as a long double or an __int128 from these)
//
// Int<W> (bits.hpp) stops at 64 bits; this type has no widening arithmetic, which is all the
// inverse-parameter processor uses (one W-bit adder, one W-bit comparator).
//
// Representation: natively a signed __int128 kept sign-extended from bit W-1 (so compares are
// the machine's); with -DCIG_HLS_SYSTEMC SystemC's sc_dt::sc_bigint<W>, so every value passes
// through SystemC's own W-bit truncation (the kernel tests compare the two builds' digests).
#pragma once

#include <cstdint>
#include <type_traits>

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace detail {

__extension__ typedef __int128 WideStore;            // GCC/Clang extension, both configurations
__extension__ typedef unsigned __int128 WideUStore;  // the same bits, unsigned (wrapping) arithmetic

// The two's complement value hi:lo sign-extended from bit w-1 (1 < w <= 128).
CIG_HLS_INLINE constexpr WideStore wide_extend(WideUStore bits, int w) {
  return w >= 128 ? static_cast<WideStore>(bits) : static_cast<WideStore>(bits << (128 - w)) >> (128 - w);
}
CIG_HLS_INLINE constexpr WideUStore wide_bits(std::uint64_t hi, std::uint64_t lo) {
  return (static_cast<WideUStore>(hi) << 64) | lo;
}

}  // namespace detail

template <int W>
class WideInt {
  static_assert(W >= 2 && W <= 128, "WideInt<W> needs 2 <= W <= 128");

 public:
  static constexpr int width = W;

  CIG_HLS_CONSTEXPR WideInt() = default;  // zero
  // From a C++ integer: its low W bits.
  template <class T, class = std::enable_if_t<std::is_integral<T>::value>>
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE explicit WideInt(T x) {
    std::uint64_t hi = 0;
    if (std::is_signed<T>::value) hi = x < 0 ? ~std::uint64_t{0} : 0;
    set_bits(detail::wide_bits(hi, static_cast<std::uint64_t>(x)));
  }
  // The low W bits of the 128-bit two's complement value hi:lo.
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE WideInt from_limbs(std::uint64_t hi, std::uint64_t lo) {
    WideInt r;
    r.set_bits(detail::wide_bits(hi, lo));
    return r;
  }
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE WideInt max_code() {  // 0 then W - 1 ones
    constexpr std::uint64_t kOnes = ~std::uint64_t{0};
    // The shifts of the branches not taken are clamped to 0, so every branch is valid for every W.
    if (W > 65) return from_limbs(kOnes >> (W > 65 ? 129 - W : 0), kOnes);
    if (W == 65) return from_limbs(0, kOnes);
    return from_limbs(0, kOnes >> (W < 65 ? 65 - W : 0));
  }
  static CIG_HLS_CONSTEXPR CIG_HLS_INLINE WideInt min_code() {  // 1 then W - 1 zeros
    constexpr std::uint64_t kOnes = ~std::uint64_t{0};
    if (W > 64) return from_limbs(kOnes << (W > 64 ? W - 65 : 0), 0);
    return from_limbs(kOnes, kOnes << (W <= 64 ? W - 1 : 0));
  }

  // a + b wrapped to W bits.
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE WideInt add_wrap(const WideInt& b) const {
#ifdef CIG_HLS_SYSTEMC
    WideInt r;
    r.s_ = s_ + b.s_;  // the W + 1-bit sum, truncated to W bits by the assignment
    return r;
#else
    WideInt r;
    r.v_ = detail::wide_extend(static_cast<detail::WideUStore>(v_) + static_cast<detail::WideUStore>(b.v_), W);
    return r;
#endif
  }
#ifdef CIG_HLS_SYSTEMC
  bool greater(const WideInt& b) const { return s_ > b.s_; }
  bool equal(const WideInt& b) const { return s_ == b.s_; }
  bool is_negative() const { return s_ < 0; }
  bool is_zero() const { return s_ == 0; }
  std::uint64_t low_limb() const { return limb(0); }
  std::uint64_t high_limb() const { return limb(64); }
#else
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool greater(const WideInt& b) const { return v_ > b.v_; }
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool equal(const WideInt& b) const { return v_ == b.v_; }
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool is_negative() const { return v_ < 0; }
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool is_zero() const { return v_ == 0; }
  CIG_HLS_CONSTEXPR std::uint64_t low_limb() const { return static_cast<std::uint64_t>(v_); }
  CIG_HLS_CONSTEXPR std::uint64_t high_limb() const {
    return static_cast<std::uint64_t>(static_cast<detail::WideUStore>(v_) >> 64);
  }
#endif
  // The value as an int64 (W <= 64 only: Int<W>'s accessor, for code written against it).
  template <int V = W, class = std::enable_if_t<(V <= 64)>>
  CIG_HLS_CONSTEXPR std::int64_t value() const {
    return static_cast<std::int64_t>(low_limb());
  }

 private:
#ifdef CIG_HLS_SYSTEMC
  void set_bits(detail::WideUStore bits) {
    sc_dt::sc_biguint<128> u = static_cast<std::uint64_t>(bits >> 64);
    u <<= 64;
    u |= sc_dt::sc_biguint<128>(static_cast<std::uint64_t>(bits));
    s_ = u;  // SystemC keeps the low W bits as a W-bit two's complement value
  }
  std::uint64_t limb(int lo) const {
    const sc_dt::sc_bigint<128> e = s_;  // sign-extended
    return sc_dt::sc_biguint<64>(e.range(lo + 63, lo)).to_uint64();
  }
  sc_dt::sc_bigint<W> s_ = 0;
#else
  CIG_HLS_CONSTEXPR CIG_HLS_INLINE void set_bits(detail::WideUStore bits) { v_ = detail::wide_extend(bits, W); }
  detail::WideStore v_ = 0;  // sign-extended from bit W - 1
#endif
};

template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator==(const WideInt<W>& a, const WideInt<W>& b) {
  return a.equal(b);
}
template <int W>
CIG_HLS_CONSTEXPR CIG_HLS_INLINE bool operator!=(const WideInt<W>& a, const WideInt<W>& b) {
  return !a.equal(b);
}

CIG_HLS_END_NAMESPACE
