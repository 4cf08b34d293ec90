// The inverse-parameter pixel processor's data word (seed 002; SPEC F): W bits, two's complement
// fixed point, the format of every value a PP adds or compares (tau = 1/t, k_x', k_y', Den, k_x,
// k_y, and the registers RGres, RGh, RGtin, RGtout, RGobj, RGeps). The seed's PP has one W-bit
// adder SM (flags z: result != 0, s: result < 0) and one comparator Cm (c: A > B); these are the
// only operations on words, so the kernels use only the functions below.
//
//   Word<W>        W bits, kWordIntBits integer bits (sign included), W - kWordIntBits fractional
//   word_add       SM: a + b wrapped to W bits (the seed's adder has no carry out)
//   word_greater   Cm: a > b, signed
//   word_negative  flag s;  word_nonzero  flag z
//   word_max/min   the largest / smallest code (RGtin starts at the largest; RGtout and RGobj start at 0,
//                  Fig. 1's t = infinity: from the smallest, a missed object, tau_in = 0, would win)
//
// Stage F's kernels take W as a template parameter (the seed's claims are about W: 57 bits to
// 10 km, 64 to 100 km; the word-length study sweeps W = 40..72). Word<W> is the type layer's
// WideInt<W> (hls/types/wide_int.hpp) for every W, 2 <= W <= 128.
#pragma once

// hls-subset-helper: the word type and its adder/comparator functions every stage F kernel shares.

#include "hls/types/wide_int.hpp"

CIG_HLS_BEGIN_NAMESPACE

// tau = 1/t with t the eye depth in metres (SPEC F): |tau| < 2^(kWordIntBits - 1) holds every
// depth beyond 1/128 m; larger values saturate in the host's setup.
constexpr int kWordIntBits = 8;

template <int W>
using Word = WideInt<W>;

template <int W>
CIG_HLS_INLINE Word<W> word_add(const Word<W>& a, const Word<W>& b) {
  return a.add_wrap(b);
}
template <int W>
CIG_HLS_INLINE bool word_greater(const Word<W>& a, const Word<W>& b) {
  return a.greater(b);
}
template <int W>
CIG_HLS_INLINE bool word_negative(const Word<W>& a) {
  return a.is_negative();
}
template <int W>
CIG_HLS_INLINE bool word_nonzero(const Word<W>& a) {
  return !a.is_zero();
}
template <int W>
CIG_HLS_INLINE Word<W> word_max() {
  return Word<W>::max_code();
}
template <int W>
CIG_HLS_INLINE Word<W> word_min() {
  return Word<W>::min_code();
}

CIG_HLS_END_NAMESPACE
