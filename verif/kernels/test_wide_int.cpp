// WideInt<W> (hls/types/wide_int.hpp) and the stage F word (hls/invparam/word.hpp) against
// __int128 arithmetic: edge values (0, +-1, the extreme codes and their neighbours, powers of two)
// and random values, for widths 2..128. The same file runs natively and with the SystemC
// sc_bigint storage; WideIntDigest prints the results so that kernel_bits_identical compares the
// two builds bit for bit.
#include <cstdint>
#include <random>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/invparam/word.hpp"

namespace cig::hls {
namespace {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

i128 as_i128(std::uint64_t hi, std::uint64_t lo) { return static_cast<i128>((static_cast<u128>(hi) << 64) | lo); }
template <int W>
i128 val(const WideInt<W>& x) {
  return as_i128(x.high_limb(), x.low_limb());
}
i128 lo_of(int w) { return w == 128 ? static_cast<i128>(u128(1) << 127) : -(i128(1) << (w - 1)); }
i128 hi_of(int w) { return w == 128 ? static_cast<i128>((u128(1) << 127) - 1) : (i128(1) << (w - 1)) - 1; }
// r is the W-bit wrap of the exact value x (a u128 bit pattern of the true sum, with the true
// sum's sign in `negative_carry` not needed): r in range and r == x mod 2^W.
bool is_wrap_of(i128 r, u128 x_bits, int w) {
  if (r < lo_of(w) || r > hi_of(w)) return false;
  const u128 diff = static_cast<u128>(r) - x_bits;
  return w == 128 ? diff == 0 : (diff & ((u128(1) << w) - 1)) == 0;
}

template <int W>
std::vector<i128> edge_values() {
  std::vector<i128> c = {0, 1, -1, 2, -2, lo_of(W), lo_of(W) + 1, hi_of(W), hi_of(W) - 1};
  for (int k = 0; k < W - 1; k += 7) {
    c.push_back(i128(1) << k);
    c.push_back(-(i128(1) << k));
  }
  std::vector<i128> v;  // those that W bits hold
  for (const i128 x : c)
    if (x >= lo_of(W) && x <= hi_of(W)) v.push_back(x);
  return v;
}

template <int W>
std::vector<i128> test_values(std::mt19937_64& rng) {
  std::vector<i128> v = edge_values<W>();
  for (int k = 0; k < 200; ++k) {
    const u128 bits = (static_cast<u128>(rng()) << 64) | rng();
    const int shift = 128 - W + static_cast<int>(rng() % W);  // random magnitudes too
    v.push_back(static_cast<i128>(bits) >> (shift > 127 ? 127 : shift));
  }
  return v;
}

template <int W>
void check_width(std::mt19937_64& rng, kernel_test::Digest& digest) {
  SCOPED_TRACE(W);
  EXPECT_EQ(val(WideInt<W>::max_code()), hi_of(W));
  EXPECT_EQ(val(WideInt<W>::min_code()), lo_of(W));
  const std::vector<i128> values = test_values<W>(rng);
  for (const i128 x : values) {
    const WideInt<W> a =
        WideInt<W>::from_limbs(static_cast<std::uint64_t>(static_cast<u128>(x) >> 64), static_cast<std::uint64_t>(x));
    ASSERT_EQ(val(a), x);
    if (x >= INT64_MIN && x <= INT64_MAX) { ASSERT_EQ(val(WideInt<W>(static_cast<std::int64_t>(x))), x); }
    ASSERT_EQ(word_negative(a), x < 0);
    ASSERT_EQ(word_nonzero(a), x != 0);
    for (int k = 0; k < 8; ++k) {
      const i128 y = values[rng() % values.size()];
      const WideInt<W> b =
          WideInt<W>::from_limbs(static_cast<std::uint64_t>(static_cast<u128>(y) >> 64), static_cast<std::uint64_t>(y));
      const WideInt<W> s = word_add(a, b);
      ASSERT_TRUE(is_wrap_of(val(s), static_cast<u128>(x) + static_cast<u128>(y), W));
      ASSERT_EQ(word_greater(a, b), x > y);
      ASSERT_EQ(a == b, x == y);
      digest.add(s.low_limb());
      digest.add(s.high_limb());
      digest.add_bool(word_greater(a, b));
    }
  }
  // Construction from an int64 wraps to W bits.
  for (const std::int64_t x : {INT64_MIN, INT64_MAX, std::int64_t{-5}, std::int64_t{1} << 40}) {
    ASSERT_TRUE(is_wrap_of(val(WideInt<W>(x)), static_cast<u128>(static_cast<i128>(x)), W));
  }
  // An unsigned 64-bit value is not negative.
  ASSERT_TRUE(is_wrap_of(val(WideInt<W>(~std::uint64_t{0})), static_cast<u128>(~std::uint64_t{0}), W));
}

TEST(WideInt, AgainstInt128) {
  std::mt19937_64 rng(2024);
  kernel_test::Digest digest;
  check_width<2>(rng, digest);
  check_width<8>(rng, digest);
  check_width<32>(rng, digest);
  check_width<40>(rng, digest);
  check_width<57>(rng, digest);
  check_width<63>(rng, digest);
  check_width<64>(rng, digest);
  check_width<65>(rng, digest);
  check_width<72>(rng, digest);
  check_width<100>(rng, digest);
  check_width<127>(rng, digest);
  check_width<128>(rng, digest);
}

TEST(WideInt, WrapAtTheEnds) {
  // The seed's adder has no carry out: MAX + 1 is MIN, MIN - 1 is MAX.
  EXPECT_EQ(word_add(word_max<72>(), Word<72>(1)), word_min<72>());
  EXPECT_EQ(word_add(word_min<40>(), Word<40>(-1)), word_max<40>());
  EXPECT_TRUE(word_greater(word_max<64>(), word_min<64>()));
  EXPECT_TRUE(word_negative(Word<64>(-7)) && word_nonzero(Word<64>(-7)));
  // The PP's register: the seed's W plus the guard bits (word.hpp).
  static_assert(std::is_same<Word<64>, WideInt<80>>::value && std::is_same<Word<57>, WideInt<73>>::value, "");
  EXPECT_EQ(word_add(word_max<57>(), Word<57>(1)), word_min<57>());
}

TEST(WideInt, WideIntDigest) {
  std::mt19937_64 rng(77);
  kernel_test::Digest digest;
  check_width<40>(rng, digest);
  check_width<64>(rng, digest);
  check_width<72>(rng, digest);
  check_width<128>(rng, digest);
  kernel_test::print_digest("wide_int", digest);
}

}  // namespace
}  // namespace cig::hls
