// Planted violation (verif/hls_subset/README.md): a C++17 fold expression; hls/ is C++14, what
// Vitis HLS and Catapult both take.
// expect: later-standard
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <class... T>  // clean: template <class A, class B>
constexpr int planted_sum(T... t) {  // clean: constexpr int planted_sum(A a, B b) {
  return (t + ...);  // clean: return a + b;
}

inline UInt<9> planted_fold_top(const UInt<8>& a, const UInt<8>& b) {
  return UInt<9>(planted_sum(int(a.value()), int(b.value())));
}

CIG_HLS_END_NAMESPACE
