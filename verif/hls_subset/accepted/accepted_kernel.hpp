// Accepted forms (verif/hls_subset/README.md): valid HLS-subset code that a naive scan would take
// for violations. The check of this folder (ctest hls_subset.accepted) must pass.
//
// Comments and literals do not count: while (1) { float x = *new double; goto out; } virtual
// std::vector<int> throw.
#pragma once

#include <cstdint>
#include <type_traits>

#include "accepted_helpers.hpp"
#include "accepted_tables.hpp"
#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kAcceptedTaps = 8;
constexpr int kAcceptedBig = 1'000;  // a digit separator is not a character literal

struct AcceptedState {
  UInt<16> sum;
  static constexpr int kLanes = 2;                         // class scope: not a static local
  static AcceptedState zero() { return AcceptedState(); }  // static member function
};

struct AcceptedNoCopy {
  AcceptedNoCopy() = default;
  AcceptedNoCopy(const AcceptedNoCopy&) = delete;  // '= delete' is not dynamic memory
};

namespace accepted_detail {

// Recursion over a template parameter is unrolled at compile time: each instantiation calls a
// different function, so the call graph has no cycle.
// (C++14: the end of the recursion is an overload, not an if constexpr.)
CIG_HLS_CONSTEXPR int ones(std::integral_constant<int, 0>) { return 0; }
template <int N>
CIG_HLS_CONSTEXPR int ones(std::integral_constant<int, N>) {
  return 1 + ones(std::integral_constant<int, N - 1>{});
}
template <int N>
CIG_HLS_CONSTEXPR int ones() {
  return ones(std::integral_constant<int, N>{});
}

// A count-down loop bounded by the template parameter N.
template <int N>
UInt<16> sum_lanes(const UInt<8> (&in)[N]) {
  UInt<16> s;
  for (int i = N - 1; i >= 0; --i) s = wrap_unsigned<16>(s + in[i]);
  return s;
}

}  // namespace accepted_detail

inline UInt<16> accepted_top(const UInt<8> (&in)[kAcceptedTaps], int n, AcceptedState& state) {
  static constexpr int kRom[4] = {1, 2, 4, 8};  // const static locals are ROMs
  static const int kRom2[2] = {3, 5};
  static UInt<8> delay;  // hls-subset-ok: the kernel's one-sample delay register, kept on purpose
  struct Local {
    static int twice(int v) { return 2 * v; }  // a local class's static member function
  };
  const char* const tag = "while (1) { float x = *new double; }";  // a literal, not code
  int new_count = 0, do_steps = 0, while_seen = 0;                 // identifiers, not keywords
  UInt<16> acc = state.sum;

  for (int k = 0; k < kAcceptedTaps; ++k) {  // run-time limit: constant bound, early break
    if (k >= n) break;
    acc = wrap_unsigned<16>(acc + in[k]);
  }
  for (int k = 0; k < 2 * kAcceptedTaps + 1; k += 2) {  // an expression of constants, a constant step
    if (k >= n) break;
    ++new_count;
  }
  for (int step = 32; step > 0; step >>= 1) do_steps += step;           // a constant geometric step
  for (unsigned b = 0u; b != sizeof(std::uint32_t); b++) ++while_seen;  // sizeof
  for (int r = 0; r < AcceptedState::kLanes; ++r) acc = wrap_unsigned<16>(acc + UInt<2>(r));  // qualified
  for (int t = 0; t < kAcceptedTableSize; ++t) acc = wrap_unsigned<16>(acc + UInt<4>(kAcceptedGains[t]));
  for (int i = 0; i < 4; ++i) acc = wrap_unsigned<16>(acc + UInt<4>(kRom[i]));
  for (const UInt<8>& v : in) acc = wrap_unsigned<16>(acc + v);  // range-for over a fixed-size array
  for (int i = 0; i < 2; ++i) {
    int i2 = i;  // a local named like the counter is not the counter
    i2 += kRom2[i];
    acc = wrap_unsigned<16>(acc + UInt<4>(i2));
  }
  acc = wrap_unsigned<16>(acc + accepted_detail::sum_lanes(in) + accepted_reverse(delay));
  acc = wrap_unsigned<16>(acc + UInt<8>(Local::twice(accepted_detail::ones<3>() + new_count + do_steps + while_seen)));
  delay = in[0];
  state.sum = tag[0] == 'w' ? acc : AcceptedState::zero().sum;
  return acc;
}

CIG_HLS_END_NAMESPACE
