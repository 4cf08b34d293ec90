// Arithmetic on the e8m7 depth format (hls/types/zfloat.hpp): linear interpolation between two
// depths, as eq. 4 and the video channel need it, rounded back to e8m7.
#pragma once

// hls-subset-helper: e8m7 arithmetic shared by the segment processor (eq. 4, video channel) and the quadtree processor (1/Z).

#include "hls/types/fixed.hpp"
#include "hls/types/zfloat.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Guard bits kept below the 8-bit significand while two depths are aligned to a common exponent.
constexpr int kZGuardBits = 12;

// The e8m7 code nearest to s * 2^(e - 127 - 7 - kZGuardBits) (s < 2^41): normalise to the
// leading one, round to nearest even, saturate at both ends.
inline ZFloat zfloat_from_aligned(int e, const Int<42>& s) {
  if (s.value() <= 0) return ZFloat::from_fields(UInt<8>(0), UInt<7>(0));
  const int msb = leading_one(UInt<41>(s.value()));
  // The significand is bits [msb : msb - 7]; the exponent moves by msb - (7 + guard).
  int exp = e + msb - (7 + kZGuardBits);
  UInt<9> sig;  // 8-bit significand plus a carry bit
  if (msb <= 7) {
    sig = UInt<9>(s.value() << (7 - msb));  // exact
  } else {
    const int drop = msb - 7;
    const UInt<41> mag = UInt<41>(s.value());
    const UInt<41> floor_sig = mag >> drop;
    const UInt<41> rem = UInt<41>(mag.value() & ((UInt<41>::max_value >> (41 - drop))));
    const UInt<41> half = UInt<41>(1) << (drop - 1);
    const bool up = rem > half || (rem == half && floor_sig.bit(0));  // round to nearest even
    sig = UInt<9>(floor_sig.value() + (up ? 1u : 0u));
    if (sig.bit(8)) {  // rounding carried into the next binade
      sig = UInt<9>(128);
      exp += 1;
    }
  }
  if (exp < 0) return ZFloat::from_fields(UInt<8>(0), UInt<7>(0));
  if (exp > 255) return ZFloat::from_fields(UInt<8>(255), UInt<7>(127));
  return ZFloat::from_fields(UInt<8>(exp), UInt<7>(sig.value()));
}

// Both significands (8 bits, hidden one explicit) with kZGuardBits guard bits, aligned to the
// larger exponent e: UInt<20>, value = s * 2^(e - 127 - 7 - 12); bits shifted out are truncated
// (they lie below 2^-19 of the larger depth).
struct AlignedPair {
  int e;
  UInt<20> sa, sb;
};
inline AlignedPair zfloat_align(const ZFloat& a, const ZFloat& b) {
  const int ea = int(a.exponent().value()), eb = int(b.exponent().value());
  const int e = ea > eb ? ea : eb;
  const int da = e - ea, db = e - eb;
  AlignedPair p;
  p.e = e;
  p.sa = da >= 20 ? UInt<20>(0) : (shl<kZGuardBits>(a.significand()) >> da);
  p.sb = db >= 20 ? UInt<20>(0) : (shl<kZGuardBits>(b.significand()) >> db);
  return p;
}

// a + (b - a) * num / den, for den > 0 (num may lie outside [0, den]: extrapolation): aligned,
// interpolated exactly up to one division rounded half up (a divider's rounding), then
// normalised and rounded to nearest even (eq. 4 in the segment generator).
template <int NW, int DW>
inline ZFloat zfloat_lerp(const ZFloat& a, const ZFloat& b, const Int<NW>& num, const Int<DW>& den) {
  static_assert(NW <= 32 && DW <= 32, "zfloat_lerp: num and den up to 32 bits");
  const AlignedPair p = zfloat_align(a, b);
  const Int<53> prod = (p.sb - p.sa) * num;  // exact: Int<21> * Int<NW>
  using Quotient = Fixed<41, 41, Quant::kRound, Overflow::kSat>;
  const Quotient q = fixed_div<Quotient>(Fixed<53, 53>::from_raw(prod), Fixed<DW, DW>::from_raw(den));
  return zfloat_from_aligned(p.e, p.sa + q.raw());
}

// a + (b - a) * t for a ratio t in [0, 1] with 16 fractional bits: the video channel's
// per-sample interpolation, a multiply instead of a divide.
template <Quant Q, Overflow O>
inline ZFloat zfloat_lerp_ratio(const ZFloat& a, const ZFloat& b, const UFixed<17, 1, Q, O>& t) {
  const AlignedPair p = zfloat_align(a, b);
  using Step = Fixed<24, 24, Quant::kRound, Overflow::kSat>;  // (sb - sa) * t rounded half up
  const Step q(Fixed<21, 21>::from_raw(p.sb - p.sa) * t);
  return zfloat_from_aligned(p.e, p.sa + q.raw());
}

CIG_HLS_END_NAMESPACE
