// The inverse-parameter pixel processor's data word (seed 002; SPEC F): two's complement fixed
// point, the format of every value a PP adds or compares (tau = 1/t, k_x', k_y', Den, k_x, k_y,
// and the registers RGres, RGh, RGtin, RGtout, RGobj, RGeps, RGnear). The seed's PP has one adder
// SM (flags z: result != 0, s: result < 0) and one comparator Cm (c: A > B); these are the only
// operations on words, so the kernels use only the functions below.
//
// Format of Word<W> (W is the seed's word length: "57 bits to 10 km, 64 to 100 km"):
//   W - kTauIntBits fractional bits        the seed's precision: LSB = 2^-(W - 8)
//   kTauIntBits = 8 integer bits           the seed's range, |tau| < 128: every depth beyond 1/128 m
//   kGuardBits = 16 more integer bits      |value| < 2^23 for the values on the way (below)
// so the register is word_bits(W) = W + 16 bits wide, kWordIntBits = 24 of them integer (sign
// included). Why the guard bits (issue 29): a face whose plane passes at a distance |d| from the
// eye has tau = Den/Num = -(n.c)/(-d) up to |c|/|d| on the lattice; with 8 integer bits a plane
// nearer than ~1 cm leaves the word, the W-bit adds wrap and the wrapped values decide the whole
// object wrongly, at any distance. With 24 integer bits every value of a face with |d| >= 2^-20 m
// (|c| <= 5.75 for tan(fov/2) <= 4: 5.75 / 2^23 < 0.7 um) is exact on the whole lattice, and a
// face nearer than that goes down the seed's Num = 0 path (face_setup.hpp: a plane shift below
// 0.7 um). Only the values below 1/near matter (RGnear, the near plane), so no depth resolution is
// lost: the fractional bits are the seed's.
//
//   word_add       SM: a + b wrapped to the register's width (the seed's adder has no carry out)
//   word_greater   Cm: a > b, signed
//   word_negative  flag s;  word_nonzero  flag z
//   word_max/min   the largest / smallest code (RGtin starts at the largest; RGtout and RGobj start at 0,
//                  Fig. 1's t = infinity: from the smallest, a missed object, tau_in = 0, would win)
//
// Stage F's kernels take W as a template parameter (the word-length study sweeps W = 40..72);
// Word<W> is the type layer's WideInt<W + kGuardBits> (hls/types/wide_int.hpp), 2 <= W + 16 <= 128.
#pragma once

// hls-subset-helper: the word type and its adder/comparator functions every stage F kernel shares.

#include "hls/types/wide_int.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kTauIntBits = 8;                          // the seed's integer bits (sign included)
constexpr int kGuardBits = 16;                          // the guard bits above them
constexpr int kWordIntBits = kTauIntBits + kGuardBits;  // the register's integer bits

// The register width and the fractional bits of the seed's W-bit word.
constexpr int word_bits(int w) { return w + kGuardBits; }
constexpr int word_frac_bits(int w) { return w - kTauIntBits; }

template <int W>
using Word = WideInt<word_bits(W)>;

// The operations take the register (WideInt<N>, N = word_bits(W)), so that W is deduced nowhere.
template <int N>
CIG_HLS_INLINE WideInt<N> word_add(const WideInt<N>& a, const WideInt<N>& b) {
  return a.add_wrap(b);
}
template <int N>
CIG_HLS_INLINE bool word_greater(const WideInt<N>& a, const WideInt<N>& b) {
  return a.greater(b);
}
template <int N>
CIG_HLS_INLINE bool word_negative(const WideInt<N>& a) {
  return a.is_negative();
}
template <int N>
CIG_HLS_INLINE bool word_nonzero(const WideInt<N>& a) {
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
