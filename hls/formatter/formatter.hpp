// The formatter (SPEC C, seed 001 eq. 1): the geometric processor's binary64 screen values to the
// fixed-point words every raster engine reads (the segment processor's frame memory, the quadtree
// raster processor's setup). Its records are in records.hpp, its grid and sample lattice in
// sample_lattice.hpp.
//
//   X = 2048*Xs + 2047  -> UInt<12>, 0..4095      Y likewise
//   I = 256*Is          -> UInt<8>,  0..255
//   D = 2048*Ds         -> UInt<3>,  0..7        (light points only; 0 for polygons)
//   C = 255*c           -> UInt<8>,  0..255      (each of R, G, B)
//   Z = Zs              -> ZFloat, e8m7, bias 127 (hls/types/zfloat.hpp)
//
// Every input is an IEEE-754 binary64 bit pattern (UInt<64>), decoded here with integer logic only
// (sign, 11-bit exponent, 52-bit fraction, hidden bit, subnormals). The decode is written once
// (scaled_floor: floor(x * Mult * 2^K) of a binary64 x, saturated) and shared by every field.
// Why it is cheap: the scale factors of eq. 1 (2048, 256) are powers of two, so each field is the
// 53-bit significand moved by a barrel shifter (no multiplier, no divider); the colour's 255 is an
// 8-bit constant multiply, and the +2047 offset of X, Y one adder. Z needs no shifter at all: a
// re-bias of the exponent and a rounding of the top 7 fraction bits.
//
// Rounding, saturation and special values (the seed gives none; chosen here, one place each):
//   X, Y    round half up of the exact 2048*Xs + 2047, EXCEPT that the reference adds 2047 in
//           binary64 before it rounds: the C model computes round(2048*xs + 2047) (round half
//           away from zero of the binary64 sum, snap_grid_coordinate in the formatter's twin,
//           cmodel/formatter), and a sum that lies within half a binary64 spacing below a
//           half-integer k + 1/2 (at most 2^-42 grid units) is rounded up to k + 1/2 there, hence
//           to k + 1. The formatter reproduces that bit for bit (grid_coordinate below), so the
//           snapped reference raster sees exactly its vertices.
//           Clamped to 0..4095. Below -0.5 round half up and round half away differ, but both
//           clamp to 0.
//   I, D, C round half up (floor(y + 1/2)) of the exact product, clamped to 0..max.
//   Z       round to nearest, ties to even, on the 7-bit mantissa; a carry out of the mantissa
//           increments the exponent. Below the smallest code (2^-127), zero, negative values and
//           binary64 subnormals -> code 0x0000; rounding beyond the largest code (255, 127)
//           -> 0x7FFF.
//   NaN     X, Y, I, D, C -> 0; Z -> 0x7FFF (the largest depth: never in front of anything).
//   +inf    clamps high (4095, 255, 7, 255, 0x7FFF); -inf clamps low (0, code 0x0000).
//   -0      is zero (X = Y = 2047, Z code 0).
#pragma once

#include "hls/formatter/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace formatter_detail {

// IEEE-754 binary64 fields of a 64-bit pattern.
struct Binary64 {
  bool sign = false;  // bit 63
  UInt<11> exp;       // bits 62..52, biased by 1023; 0: zero or subnormal, 2047: infinity or NaN
  UInt<52> frac;      // bits 51..0 (the significand without its hidden bit)
};

inline Binary64 unpack(const UInt<64>& bits) {
  Binary64 f;
  f.sign = bits.bit(63);
  f.exp = bits.slice<62, 52>();
  f.frac = bits.slice<51, 0>();
  return f;
}

inline bool is_special(const Binary64& f) { return f.exp == UInt<11>(2047); }  // inf or NaN
inline bool is_nan(const Binary64& f) { return is_special(f) && f.frac != UInt<52>(0); }

// floor(x * Mult * 2^K) of the binary64 x, saturated to Int<62> ([-2^61, 2^61 - 1]).
struct ScaledFloor {
  Int<62> value;  // 0 for NaN
  bool nan = false;
};

template <int Mult, int K>
inline ScaledFloor scaled_floor(const UInt<64>& bits) {
  static_assert(Mult >= 1 && Mult < 256, "scaled_floor: Mult is an 8-bit constant");
  static_assert(K >= -60 && K <= 62, "scaled_floor: K keeps the shift in Int<15>");
  const Binary64 f = unpack(bits);
  ScaledFloor r;
  if (is_special(f)) {
    r.nan = is_nan(f);
    r.value = r.nan ? Int<62>(0) : f.sign ? Int<62>(Int<62>::min_value) : Int<62>(Int<62>::max_value);
    return r;
  }
  // x = sig * 2^(ee - 1075): sig = 1.frac (53 bits) for normals, 0.frac with ee = 1 for
  // subnormals and zero.
  const bool normal = f.exp != UInt<11>(0);
  const UInt<53> sig = UInt<53>(f.frac).with_bit(52, normal);
  const UInt<11> ee = normal ? f.exp : UInt<11>(1);
  const UInt<61> p = sig * UInt<8>(Mult);                // integer, exact: < 2^53 * 2^8
  const Int<15> sh = to_signed(ee) + Int<14>(K - 1075);  // integer; x * Mult * 2^K = p * 2^sh

  UInt<61> q = p;       // integer |x * Mult * 2^K|, truncated toward zero by the right shift
  bool sticky = false;  // nonzero bits shifted out on the right (makes floor of a negative exact)
  bool overflow = false;
  if (sh >= Int<2>(0)) {
    // Left barrel shifter (sh < 16): a bit pushed past bit 60 overflows. sh >= 16 always
    // overflows, because a normal p is at least 2^52.
    overflow = sh >= Int<6>(16);
    for (int b = 0; b < 4; ++b) {
      if (sh.bit(b)) {
        const int s = 1 << b;
        overflow = overflow || (q >> (61 - s)) != UInt<1>(0);
        q = q << s;  // keeps 61 bits
      }
    }
  } else {
    // Right barrel shifter (n = -sh in 1..63) with a sticky bit; n >= 64 leaves only sticky.
    const Int<16> n = -sh;
    if (n >= Int<8>(64)) {
      sticky = p != UInt<1>(0);
      q = UInt<61>(0);
    } else {
      for (int b = 0; b < 6; ++b) {
        if (n.bit(b)) {
          const int s = 1 << b;
          const UInt<61> kept = q >> s;
          sticky = sticky || (kept << s) != q;
          q = kept;
        }
      }
    }
  }
  if (overflow) {
    r.value = f.sign ? Int<62>(Int<62>::min_value) : Int<62>(Int<62>::max_value);
  } else if (f.sign) {
    // floor(-|y|) = -(floor(|y|) + sticky): Int<63> in [-2^61, 0], exact in Int<62>.
    const UInt<62> mag = q + UInt<1>(sticky ? 1 : 0);
    r.value = saturate<62>(UInt<1>(0) - mag);
  } else {
    r.value = saturate<62>(to_signed(q));  // q < 2^61: exact
  }
  return r;
}

// round_half_up(x * Mult * 2^K) = floor((floor(2 * x * Mult * 2^K) + 1) / 2), clamped to
// [0, 2^W - 1]; NaN -> 0. Exact for every binary64 x (no intermediate rounding).
template <int Mult, int K, int W>
inline UInt<W> scaled_round(const UInt<64>& bits) {
  static_assert(W >= 1 && W <= 32, "scaled_round: output width");
  const ScaledFloor twice = scaled_floor<Mult, K + 1>(bits);  // Int<62>, floor(2y)
  const Int<62> r = shr<1>(twice.value + Int<2>(1));          // Int<63> >> 1: floor(y + 1/2)
  return twice.nan ? UInt<W>(0) : saturate_unsigned<W>(r);    // clamp 0..2^W - 1
}

// I of eq. 1: round(256 Is) (half up), clamped to 0..256 (UInt<9>: 256 is full intensity).
inline UInt<9> vertex_intensity(const UInt<64>& is) {
  const UInt<9> r = scaled_round<1, 8, 9>(is);
  return r.value() > 256 ? UInt<9>(256) : r;
}

// X or Y of eq. 1: the C model's round(2048*s + 2047) (round half away from zero of the
// binary64 sum), clamped to 0..4095, for every binary64 s.
//
//   t = 2048*s is exact in binary64 (a power-of-two scale); T = floor(t * 2^50) = floor(s * 2^61),
//   saturated to Int<62> (|t| < 2048; outside, X clamps anyway: t >= 2048 gives v >= 4095 and
//   t < -2048 gives v < -1). v = t + 2047 in 2^-50 units plus one half:
//     w = T + (2047 + 1/2) * 2^50         Int<64>, 50 fractional bits
//     k0 = floor(w / 2^50)                = floor(v + 1/2), round half up of the exact sum
//   The binary64 sum fl(v) reaches k0 + 1/2 (so that round gives k0 + 1) iff
//   v >= k0 + 1/2 - h: h is half the binary64 spacing just below b = k0 + 1/2, and the tie goes
//   to b because b (at most 13 significant bits) is even. For b in [2^j, 2^(j+1)), h = 2^(j-53),
//   i.e. 2^(j-3) units of 2^-50, an integer for j >= 3 (k0 >= 8); below 8 no v lies that close
//   (there v = t + 2047 with |t| >= 1024 is a multiple of 2^-42 > h). The test on the floored w is
//   exact because the threshold is a multiple of 2^-50:
//     X = clamp(k0 + carry(frac50(w) + 2^(j-3)), 0, 4095)
inline UInt<12> grid_coordinate(const UInt<64>& s_bits) {
  const ScaledFloor t = scaled_floor<1, 61>(s_bits);  // Int<62>: t, 50 fractional bits, floor, sat.
  const Int<63> kOffsetHalf(4095LL << 49);            // (2047 + 1/2), 50 fractional bits, exact
  const Int<64> w = t.value + kOffsetHalf;            // v + 1/2: 14 integer (sign incl.) + 50 frac, exact
  const Int<14> k0 = shr<50>(w);                      // integer -1..4095: floor(v + 1/2)
  const UInt<50> frac = w.slice<49, 0>();             // fraction of v + 1/2, 2^-50 units
  UInt<9> h(0);                                       // 2^(j-3) in 2^-50 units, j = floor(log2 k0); 0 below 8
  for (int j = 3; j < 12; ++j) {
    if (k0 >= Int<14>(1 << j)) h = UInt<9>(1 << (j - 3));
  }
  const UInt<51> frac_plus = frac + h;                        // exact; bit 50 set iff v >= k0 + 1/2 - h
  const Int<15> k = k0 + UInt<1>(frac_plus.bit(50) ? 1 : 0);  // integer, exact
  return t.nan ? UInt<12>(0) : saturate_unsigned<12>(k);      // clamp 0..4095
}

// Z of eq. 1: binary64 -> e8m7 (bias 127), mantissa rounded to nearest, ties to even.
// The code is formed as E * 128 + m + round_up, so a mantissa carry increments E by itself; the
// code is monotonic in the value, which makes both saturations a clamp of that sum to 0..0x7FFF.
inline ZFloat to_zfloat(const UInt<64>& bits) {
  const Binary64 f = unpack(bits);
  ZFloat z;
  if (is_special(f)) {
    z.bits = (f.sign && !is_nan(f)) ? UInt<15>(0) : UInt<15>(0x7FFF);  // -inf low; +inf, NaN high
    return z;
  }
  if (f.sign || f.exp == UInt<11>(0)) {
    z.bits = UInt<15>(0);  // negative, zero, subnormal (< 2^-1022): below the smallest code
    return z;
  }
  const Int<13> e = to_signed(f.exp) - Int<11>(1023 - ZFloat::kBias);  // integer re-bias: E = exp - 896
  const UInt<7> m = f.frac.slice<51, 45>();                            // top 7 fraction bits (truncated)
  const bool guard = f.frac.bit(44);
  const bool sticky = f.frac.slice<43, 0>() != UInt<1>(0);
  const bool round_up = guard && (sticky || m.bit(0));             // nearest, ties to even
  const Int<22> code = shl<7>(e) + m + UInt<1>(round_up ? 1 : 0);  // integer E*128 + m + up, exact
  z.bits = saturate_unsigned<15>(code);  // < 0: below 2^-127 -> 0; > 0x7FFF: beyond the largest
  return z;
}

}  // namespace formatter_detail

// The formatter kernel: one primitive (polygon or light point) per call.
//   Polygon: vertices 0..n-1 formatted (at most kMaxVertices), the rest zero; d = 0.
//   Light:   v[0] is the centre (x, y, z; i from Is = the light's intensity), d its diameter; the
//            other vertices zero.
//   Colour, n, opaque, protect and id are copied or formatted for both.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_formatter_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                           \
  PORT(in, in, ap_none, const RawPrimitive&)             \
  PORT(out, out, ap_vld, FormattedPrimitive&)
inline CIG_HLS_TOP(formatter_top) {
  const UInt<5> count = in.is_light ? UInt<5>(1) : in.n;
  for (int k = 0; k < kMaxVertices; ++k) {
    FormattedVertex fv;  // zero when unused
    if (UInt<5>(k) < count) {
      fv.x = formatter_detail::grid_coordinate(in.v[k].xs);
      fv.y = formatter_detail::grid_coordinate(in.v[k].ys);
      fv.i = formatter_detail::vertex_intensity(in.v[k].is);
      fv.z = formatter_detail::to_zfloat(in.v[k].zs);
    }
    out.v[k] = fv;
  }
  out.d = in.is_light ? formatter_detail::scaled_round<1, 11, 3>(in.ds) : UInt<3>(0);  // 2048*Ds, 0..7
  for (int c = 0; c < 3; ++c) {
    out.colour[c] = formatter_detail::scaled_round<255, 0, 8>(in.colour[c]);  // 255*c, 0..255
  }
  out.is_light = in.is_light;
  out.n = in.n;
  out.opaque = in.opaque;
  out.protect = in.protect;
  out.id = in.id;
}

CIG_HLS_END_NAMESPACE
