// The formatter kernel (hls/formatter/formatter.hpp, SPEC C eq. 1) against the C model's snapping
// (cmodel/frame/screen_frame.cpp), independent exact references (frexp + 128-bit integers), its
// double-precision twin (cmodel/formatter/formatter_twin.hpp) and golden vectors
// (verif/golden/formatter_vectors.txt). The same file runs in the native and the SystemC-typed
// build (cig_kernel_tests, cig_kernel_tests_systemc).
#include <cfloat>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "formatter/formatter_twin.hpp"
#include "frame/screen_frame.hpp"
#include "hls/formatter/formatter.hpp"

namespace cig::hls {
namespace {

namespace fd = formatter_detail;
using i128 = __int128;

#ifdef CIG_HLS_SYSTEMC
constexpr int kRandomScale = 8;  // random-test sizes: 100000 * kRandomScale and the like
#else
constexpr int kRandomScale = 16;
#endif

// ---- binary64 helpers --------------------------------------------------------------------------

std::uint64_t raw_bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
double from_raw(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}
UInt<64> bits_of(double x) { return UInt<64>(raw_bits(x)); }

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The kernel's scalar fields.
int kx(double s) { return int(fd::grid_coordinate(bits_of(s)).value()); }
int ki(double is) { return int(fd::vertex_intensity(bits_of(is)).value()); }
int kd(double ds) { return int(fd::scaled_round<1, 11, 3>(bits_of(ds)).value()); }
int kc(double c) { return int(fd::scaled_round<255, 0, 8>(bits_of(c)).value()); }
int kz(double z) { return int(fd::to_zfloat(bits_of(z)).bits.value()); }

// ---- References ----------------------------------------------------------------------------------

// X, Y: the C model's snapped grid coordinate (std::round of the binary64 2048*s + 2047, clamped).
// NaN is not defined there (it stays NaN); the formatter's rule is 0.
int ref_grid(double s) {
  if (std::isnan(s)) return 0;
  const double g = grid_x(snap_grid_coordinate(s));
  return int(g);
}

// clamp(floor(x * mult * 2^k + 1/2), 0, max), exact: x = M * 2^(e - 53) by frexp, the product in
// 128-bit integers. NaN -> 0.
int ref_round_scaled(double x, int mult, int k, int max) {
  if (std::isnan(x) || x <= 0) return 0;
  if (std::isinf(x)) return max;
  int e = 0;
  const double m = std::frexp(x, &e);                           // x = m * 2^e, m in [0.5, 1)
  const i128 n = i128(std::int64_t(std::ldexp(m, 53))) * mult;  // x * mult = n * 2^(e - 53)
  const int s = e - 53 + k + 1;                                 // 2 * x * mult * 2^k = n * 2^s
  i128 twice;
  if (s >= 0) {
    if (s > 40) return max;
    twice = n << s;
  } else {
    twice = -s >= 120 ? 0 : n >> -s;  // floor(2y)
  }
  const i128 r = (twice + 1) >> 1;  // floor(y + 1/2)
  return r > max ? max : int(r);
}

// The value of an e8m7 code: 2^(E - 127) * (128 + m) / 128, exact in binary64.
double zvalue(int code) { return std::ldexp(double(128 + (code & 127)), (code >> 7) - 127 - 7); }

// Z: nearest e8m7 code, ties to even, by frexp and nearbyint (default rounding: to nearest even).
int ref_zfloat(double z) {
  if (std::isnan(z)) return 0x7FFF;
  if (!(z > 0)) return 0;
  if (std::isinf(z)) return 0x7FFF;
  int e = 0;
  const double m = std::frexp(z, &e);  // z = (2m) * 2^(e - 1), 2m in [1, 2)
  int E = e - 1 + 127;
  double q = std::nearbyint(m * 256);  // 8-bit significand 128..256, exact scale
  if (q == 256) {
    q = 128;
    E += 1;
  }
  if (E < 0) return 0;
  if (E > 255) return 0x7FFF;
  return E * 128 + int(q) - 128;
}

// D as the C model snaps it (snap_to_formatter_grid on a one-light frame), Ds >= 0.
int cmodel_diameter(double ds) {
  ScreenFrame f;
  ScreenLightPoint l;
  l.ds = ds;
  f.light_points.push_back(l);
  return int(snap_to_formatter_grid(f).light_points[0].ds * kGridScale);
}

double next_down(double x) { return std::nextafter(x, -kInf); }
double next_up(double x) { return std::nextafter(x, kInf); }

// ---- The shared binary64 decode ------------------------------------------------------------------

// floor(x * mult * 2^k) saturated to [-2^61, 2^61 - 1], exactly (frexp + 128-bit integers).
i128 ref_scaled_floor(double x, int mult, int k) {
  const i128 lo = -(i128(1) << 61), hi = (i128(1) << 61) - 1;
  if (std::isinf(x)) return x > 0 ? hi : lo;
  if (x == 0) return 0;
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);
  const i128 n = i128(std::int64_t(std::ldexp(m, 53))) * mult;  // |x| * mult = n * 2^(e - 53)
  const int s = e - 53 + k;
  i128 f;  // floor(|x| * mult * 2^k), or saturated
  bool inexact = false;
  if (s >= 0) {
    f = s > 20 ? hi + 1 : n << s;
  } else if (-s >= 120) {
    f = 0;
    inexact = true;
  } else {
    f = n >> -s;
    inexact = (f << -s) != n;
  }
  i128 r = x > 0 ? f : -f - (inexact ? 1 : 0);
  return r < lo ? lo : r > hi ? hi : r;
}

template <int Mult, int K>
void check_scaled_floor(std::mt19937_64& rng, int n) {
  for (int t = 0; t < n; ++t) {
    // Arbitrary patterns, and values whose scaled magnitude is near 2^0 .. 2^62.
    const double x1 = from_raw(rng());
    const double x2 =
        std::ldexp(double(std::int64_t(rng() >> 11)) * ((rng() & 1) ? 1 : -1), -53 - K + int(rng() % 70) - 4);
    for (double x : {x1, x2}) {
      const fd::ScaledFloor f = fd::scaled_floor<Mult, K>(bits_of(x));
      ASSERT_EQ(f.nan, std::isnan(x));
      if (!f.nan) { ASSERT_TRUE(i128(f.value.value()) == ref_scaled_floor(x, Mult, K)) << std::hexfloat << x; }
    }
  }
}

// The decode every field shares: floor, not truncation, for negatives (sticky), saturation, NaN.
TEST(Formatter, ScaledFloorIsExact) {
  std::mt19937_64 rng(11);
  const int n = 20000 * kRandomScale;
  check_scaled_floor<1, 61>(rng, n);   // X, Y
  check_scaled_floor<1, 9>(rng, n);    // I
  check_scaled_floor<1, 12>(rng, n);   // D
  check_scaled_floor<255, 1>(rng, n);  // colour
  check_scaled_floor<3, -20>(rng, n);
  const auto sf61 = [](double x) { return fd::scaled_floor<1, 61>(bits_of(x)); };
  EXPECT_EQ(sf61(-DBL_TRUE_MIN).value.value(), -1);
  EXPECT_EQ(sf61(DBL_TRUE_MIN).value.value(), 0);
  EXPECT_EQ(sf61(-0.0).value.value(), 0);
  EXPECT_EQ(sf61(-1.0 / 1024 * 1.5).value.value(), -(std::int64_t(3) << 50));  // -1.5 * 2^51
  EXPECT_EQ(sf61(1.0).value.value(), Int<62>::max_value);                      // 2^61 saturates
  EXPECT_EQ(sf61(-1.0).value.value(), Int<62>::min_value);                     // -2^61 exact
  EXPECT_TRUE(sf61(kNaN).nan);
}

// ---- X, Y ---------------------------------------------------------------------------------------

// Every 12-bit code k: the boundaries k - 1/2 and k + 1/2 in grid units, at Xs_b = (b - 2047)/2048
// (exact) and 1..4 binary64 steps either side. At and above b the code is ceil(b); below it is
// floor(b), unless the reference's binary64 sum 2048*Xs + 2047 rounds up onto b: that happens iff
// the distance below b, delta = 2048 * (Xs_b - Xs) (exact), is at most half the binary64 spacing
// just below b (the tie goes to b, whose last significand bit is 0). Clamped to 0..4095.
TEST(Formatter, GridEveryCodeAtItsRoundingBoundaries) {
  int summed_up = 0, points = 0;
  for (int j = -1; j <= 4095; ++j) {
    const double b = j + 0.5;
    const double sb = (b - kGridOffset) / kGridScale;
    ASSERT_EQ(kGridScale * sb + kGridOffset, b);
    const double half_gap = (b - next_down(b)) / 2;
    ASSERT_EQ(raw_bits(b) & 1, 0u);  // b is even: ties go to it
    const int lo = std::max(0, std::min(4095, j)), hi = std::max(0, std::min(4095, j + 1));
    double below = sb, above = sb;
    ASSERT_EQ(kx(sb), hi) << "at " << b;
    ASSERT_EQ(ref_grid(sb), hi) << "at " << b;
    for (int step = 1; step <= 4; ++step) {
      below = next_down(below);
      above = next_up(above);
      const double delta = kGridScale * (sb - below);
      const int expect_below = delta <= half_gap ? hi : lo;
      summed_up += (delta <= half_gap && lo != hi) ? 1 : 0;
      ASSERT_EQ(kx(below), expect_below) << "boundary " << b << ", " << step << " steps below";
      ASSERT_EQ(ref_grid(below), expect_below) << "C model, boundary " << b << ", " << step << " steps below";
      ASSERT_EQ(kx(above), hi) << "boundary " << b << ", " << step << " steps above";
      ASSERT_EQ(ref_grid(above), hi) << "C model, boundary " << b << ", " << step << " steps above";
      points += 2;
    }
  }
  // The binary64 sum of the reference does round some of these up (boundaries near X = 2047,
  // where Xs is small and has bits below 2^-42): the formatter must, and does, follow it.
  EXPECT_GT(summed_up, 1000);
  EXPECT_EQ(points, 4097 * 8);
}

// Values that lie within half a binary64 spacing below a half-integer after the sum: t = 2048*Xs
// just below m = k + 1/2 - 2047 by exactly h (a tie, rounds up) and by h plus one step of t
// (rounds down), for every k where t can hold that offset.
TEST(Formatter, GridFollowsTheReferenceSumAtTies) {
  int ties = 0;
  for (int k = 8; k <= 4094; ++k) {
    const double b = k + 0.5;
    const double h = (b - next_down(b)) / 2;
    const double m = b - kGridOffset;  // half-integer in [-2038.5, 2047.5]
    const double t_tie = m - h;
    if (m - t_tie != h) continue;  // m - h not representable: no tie for this k
    const double s_tie = t_tie / kGridScale;
    ASSERT_EQ(kx(s_tie), k + 1) << k;
    ASSERT_EQ(ref_grid(s_tie), k + 1) << k;
    const double s_past = next_down(s_tie);
    ASSERT_EQ(kx(s_past), ref_grid(s_past)) << k;
    ASSERT_EQ(kx(s_past), k) << k;
    ++ties;
  }
  EXPECT_GT(ties, 2000);
}

TEST(Formatter, GridSpecialValues) {
  const double cases[] = {0.0,
                          -0.0,
                          1.0,
                          -1.0,
                          0.5,
                          -0.5,
                          2.0,
                          -2.0,
                          1e300,
                          -1e300,
                          DBL_MAX,
                          -DBL_MAX,
                          DBL_MIN,
                          -DBL_MIN,
                          DBL_TRUE_MIN,
                          -DBL_TRUE_MIN,
                          from_raw(0x000FFFFFFFFFFFFFull),
                          kInf,
                          -kInf,
                          2047.0 / 2048,
                          2048.0 / 2048,
                          -2047.0 / 2048,
                          -2048.0 / 2048,
                          -2047.5 / 2048,
                          2048.5 / 2048};
  for (double s : cases) EXPECT_EQ(kx(s), ref_grid(s)) << s;
  EXPECT_EQ(kx(0.0), 2047);
  EXPECT_EQ(kx(-0.0), 2047);
  EXPECT_EQ(kx(-1.0), 0);  // 2048*(-1) + 2047 = -1: clamped
  EXPECT_EQ(kx(1.0), 4095);
  EXPECT_EQ(kx(kInf), 4095);
  EXPECT_EQ(kx(-kInf), 0);
  // NaN (quiet, signalling, negative): 0.
  for (std::uint64_t nan : {0x7FF8000000000000ull, 0x7FF0000000000001ull, 0xFFF8000000000000ull, 0x7FFFFFFFFFFFFFFFull})
    EXPECT_EQ(kx(from_raw(nan)), 0);
}

TEST(Formatter, GridMatchesCModelOnRandomInputs) {
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<double> screen(-1.1, 1.1);
  const int n = 100000 * kRandomScale;
  for (int t = 0; t < n; ++t) {
    // Uniform screen positions, arbitrary bit patterns, and half-integers nudged by a few units
    // of 2^-p for random p (the double-rounding region).
    const double s1 = screen(rng);
    const double s2 = from_raw(rng());
    const int k = int(rng() % 4096);
    const double sb = (k + 0.5 - kGridOffset) / kGridScale;
    const double s3 = sb + std::ldexp(double(std::int64_t(rng() % 9) - 4), -int(40 + rng() % 30));
    // Near X = 2047 (|2048*Xs| < 16, bits down to 2^-56): a few of 2^-q below a half-integer.
    const double m4 = double(std::int64_t(rng() % 32) - 16) + 0.5;
    const double s4 = (m4 - std::ldexp(double(1 + rng() % 4), -int(40 + rng() % 18))) / kGridScale;
    for (double s : {s1, s2, s3, s4}) { ASSERT_EQ(kx(s), ref_grid(s)) << std::hexfloat << s; }
  }
}

// The sub-pixel knob (--engine-opt subpixel=B): a g-bit grid, g < 12, is a subset of eq. 1's
// 12-bit grid (X = 2^(12-g) (X_g + 1) - 1), so the C model snaps to it before the formatter and the
// kernel keeps every snapped coordinate exactly; the snap moves a position by at most half a
// g-bit unit (2^(11-g) units) on screen, and a finer grid (the float reference's) by less.
TEST(Formatter, CoarserGridsAreSubsetsOfEq1TheKernelKeeps) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> screen(-0.99, 0.99);  // off the clamped edges (tested below)
  for (int g = 9; g <= 14; ++g) {
    const double unit = std::ldexp(1.0, kSeedGridBits - g);  // one g-bit unit in 12-bit units
    for (int t = 0; t < 20000; ++t) {
      const double s = t % 2 ? screen(rng) : (std::floor(screen(rng) * 1024) + 0.5) / 1024;  // ties too
      const double snapped = snap_grid_coordinate(s, g);
      const double x = grid_x(snapped);
      ASSERT_LE(std::fabs(x - grid_x(s)), 0.5 * unit) << "g " << g << std::hexfloat << " s " << s;
      if (g > kSeedGridBits) continue;
      ASSERT_EQ(double(kx(snapped)), x) << "g " << g << std::hexfloat << " s " << s;
      ASSERT_EQ(std::fmod(x + 1, unit), 0.0) << "g " << g << " X " << x;
    }
    EXPECT_EQ(grid_x(snap_grid_coordinate(-1.0, g)), 0.0);  // the screen edges stay where eq. 1 has them
    EXPECT_EQ(grid_x(snap_grid_coordinate(1.0, g)), double(kGridMax));
  }
  for (int t = 0; t < 20000; ++t) {  // 12 bits: eq. 1 itself
    const double s = screen(rng);
    ASSERT_EQ(double(kx(s)), grid_x(snap_grid_coordinate(s, kSeedGridBits)));
  }
}

// ---- Z ----------------------------------------------------------------------------------------

// Every e8m7 code: its exact value maps to itself; the midpoint to the next code goes to the even
// one (last mantissa bit 0), one binary64 step either side to the nearer; values order as codes.
TEST(Formatter, ZFloatEveryCode) {
  for (int code = 0; code <= 0x7FFF; ++code) {
    const double v = zvalue(code);
    ZFloat z;
    z.bits = UInt<15>(code);
    ASSERT_EQ(std::ldexp(double(z.significand().value()), int(z.exponent().value()) - 127 - 7), v);
    ASSERT_EQ(kz(v), code);
    ASSERT_EQ(ref_zfloat(v), code);
    if (code < 0x7FFF) {
      const double next = zvalue(code + 1);
      ASSERT_LT(v, next) << code;         // the code order is the value order
      const double mid = (v + next) / 2;  // 9 significant bits: exact
      ASSERT_EQ(mid - v, next - mid);
      const int even = (code & 1) ? code + 1 : code;
      ASSERT_EQ(kz(mid), even) << code;
      ASSERT_EQ(kz(next_down(mid)), code) << code;
      ASSERT_EQ(kz(next_up(mid)), code + 1) << code;
      ASSERT_EQ(kz(next_down(next)), code + 1) << code;
      ASSERT_EQ(kz(next_up(v)), code) << code;
    }
  }
  // Saturation below: zero, negatives, binary64 subnormals, everything under 2^-127.
  const double smallest = zvalue(0);
  EXPECT_EQ(smallest, std::ldexp(1.0, -127));
  for (double z :
       {0.0, -0.0, -1.0, -kInf, DBL_TRUE_MIN, DBL_MIN, smallest / 2, next_down(smallest), std::ldexp(1.0, -200)})
    EXPECT_EQ(kz(z), 0) << z;
  // Saturation above: the largest code, the midpoint past it (rounds to 2^129), 2^129, 1e300, inf.
  const double largest = zvalue(0x7FFF);
  EXPECT_EQ(largest, std::ldexp(255.0, 128 - 7));
  for (double z :
       {largest, next_up(largest), (largest + std::ldexp(1.0, 129)) / 2, std::ldexp(1.0, 129), 1e300, DBL_MAX, kInf})
    EXPECT_EQ(kz(z), 0x7FFF) << z;
  EXPECT_EQ(kz(next_down(largest)), 0x7FFF);
  // NaN: the largest code (farthest depth).
  EXPECT_EQ(kz(kNaN), 0x7FFF);
  EXPECT_EQ(kz(from_raw(0xFFF8000000000000ull)), 0x7FFF);
}

TEST(Formatter, ZFloatRandomAgainstExactReference) {
  std::mt19937_64 rng(99);
  const int n = 100000 * kRandomScale;
  for (int t = 0; t < n; ++t) {
    const double z1 = from_raw(rng());                                                          // any pattern
    const double z2 = std::ldexp(1.0 + double(rng() >> 11) * 0x1p-53, int(rng() % 270) - 135);  // the code range
    for (double z : {z1, z2}) ASSERT_EQ(kz(z), ref_zfloat(z)) << std::hexfloat << z;
  }
}

// ---- I, D, colour --------------------------------------------------------------------------------

// A boundary b/scale (exact for power-of-two scales): below it, floor; at and above, ceil.
void check_pow2_boundaries(int (*kernel)(double), int log2_scale, int max, bool cmodel_d) {
  const int scale = 1 << log2_scale;
  for (int j = -1; j <= max; ++j) {
    const double b = (j + 0.5) / scale;
    const int lo = std::max(0, std::min(max, j)), hi = std::max(0, std::min(max, j + 1));
    double below = b, above = b;
    ASSERT_EQ(kernel(b), hi) << j;
    for (int step = 1; step <= 3; ++step) {
      below = next_down(below);
      above = next_up(above);
      ASSERT_EQ(kernel(below), lo) << j;
      ASSERT_EQ(kernel(above), hi) << j;
      ASSERT_EQ(ref_round_scaled(below, 1, log2_scale, max), lo) << j;
      ASSERT_EQ(ref_round_scaled(above, 1, log2_scale, max), hi) << j;
      if (cmodel_d && below >= 0) { ASSERT_EQ(kernel(below), cmodel_diameter(below)) << j; }
      if (cmodel_d && above >= 0) { ASSERT_EQ(kernel(above), cmodel_diameter(above)) << j; }
    }
    if (cmodel_d && b >= 0) { ASSERT_EQ(kernel(b), cmodel_diameter(b)) << j; }
    // Exact codes.
    if (j >= 0) { ASSERT_EQ(kernel(double(j) / scale), j); }
  }
}

TEST(Formatter, IntensityEveryCode) {
  // I = round(256 Is) in 0..256 (UInt<9>): full intensity is 256, so white stays 255.
  check_pow2_boundaries(ki, 8, 256, false);
  EXPECT_EQ(ki(1.0), 256);
  EXPECT_EQ(ki(next_up(1.0)), 256);  // clamps
  EXPECT_EQ(ki(2.0), 256);
  EXPECT_EQ(ki(255.5 / 256), 256);
  EXPECT_EQ(ki(next_down(255.5 / 256)), 255);
  for (double x : {0.0, -0.0, -1.0, -kInf, DBL_TRUE_MIN, -DBL_TRUE_MIN, 0.5 / 256, next_down(0.5 / 256)})
    EXPECT_EQ(ki(x), ref_round_scaled(x, 1, 8, 256)) << x;
  EXPECT_EQ(ki(kInf), 256);
  EXPECT_EQ(ki(kNaN), 0);
}

TEST(Formatter, DiameterEveryCode) {
  check_pow2_boundaries(kd, 11, 7, true);
  for (double x : {0.0, 1.0, 0.5, 7.0 / 2048, 7.5 / 2048, 100.0, DBL_MAX, DBL_TRUE_MIN})
    EXPECT_EQ(kd(x), cmodel_diameter(x)) << x;
  EXPECT_EQ(kd(-0.5), 0);  // the C model does not clamp below (Ds >= 0 is validated on input)
  EXPECT_EQ(kd(kInf), 7);
  EXPECT_EQ(kd(-kInf), 0);
  EXPECT_EQ(kd(kNaN), 0);
}

// Colour: 255*c is not a power-of-two scale, so the boundaries (k + 1/2)/255 are not binary64
// values; the binary64 values nearest them, and 3 steps either side, against the exact reference.
TEST(Formatter, ColourEveryCode) {
  for (int k = -1; k <= 255; ++k) {
    double c = (k + 0.5) / 255;
    for (int step = 0; step < 3; ++step) c = next_down(c);
    for (int step = 0; step < 7; ++step, c = next_up(c)) ASSERT_EQ(kc(c), ref_round_scaled(c, 255, 0, 255)) << k;
    if (k >= 0) { ASSERT_EQ(kc(double(k) / 255), k) << k; }
    // The exact boundary decided by the 128-bit reference: some neighbour is below, some above.
    if (k >= 0 && k < 255) {
      const double b = (k + 0.5) / 255;
      ASSERT_EQ(kc(next_down(next_down(b))), k);
      ASSERT_EQ(kc(next_up(next_up(b))), k + 1);
    }
  }
  EXPECT_EQ(kc(1.0), 255);
  EXPECT_EQ(kc(2.0), 255);
  EXPECT_EQ(kc(-0.1), 0);
  EXPECT_EQ(kc(kNaN), 0);
  EXPECT_EQ(kc(kInf), 255);
  std::mt19937_64 rng(5);
  for (int t = 0; t < 20000 * kRandomScale; ++t) {
    const double c = from_raw(rng());
    ASSERT_EQ(kc(c), ref_round_scaled(c, 255, 0, 255)) << std::hexfloat << c;
    ASSERT_EQ(ki(c), ref_round_scaled(c, 1, 8, 256)) << std::hexfloat << c;
    ASSERT_EQ(kd(c), ref_round_scaled(c, 1, 11, 7)) << std::hexfloat << c;
  }
}

// ---- Against the double twin ---------------------------------------------------------------------

// Error bounds, derived:
//  X, Y    the twin's x is the binary64 sum clamp(2048*Xs + 2047) (2048*Xs exact), the same value
//          the C model rounds; the kernel's X is that value rounded to an integer (half away from
//          zero) and clamped, so |X - x| <= 1/2 LSB exactly.
//  I, D    256*Is and 2048*Ds are exact in binary64; round half up then clamp: |I - i| <= 1/2.
//  colour  the twin's 255*c is rounded once (relative 2^-53): |C - twin| <= 1/2 + 255 * 2^-53,
//          under 1/2 + 2^-45.
//  Z       round to nearest on an 8-bit significand (hidden one + 7 bits): the error is at most half
//          a unit of 2^(E-127-7), i.e. 2^(E-127-8) <= 2^-8 * z for z in [2^-127, the largest code].
TEST(Formatter, RandomAgainstDoubleTwin) {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> screen(-1.05, 1.05), unit(-0.05, 1.05), depth_exp(-127, 128.99);
  const int n = 100000 * kRandomScale;
  const double z_max = zvalue(0x7FFF);
  for (int t = 0; t < n; ++t) {
    const double xs = screen(rng), is = unit(rng), ds = unit(rng) * (8.0 / 2048), c = unit(rng);
    const double zs = std::min(z_max, std::exp2(depth_exp(rng)));
    ASSERT_LE(std::fabs(kx(xs) - twin_grid(xs)), 0.5) << xs;
    ASSERT_LE(std::fabs(ki(is) - twin_intensity(is)), 0.5) << is;
    ASSERT_LE(std::fabs(kd(ds) - twin_diameter(ds)), 0.5) << ds;
    ASSERT_LE(std::fabs(kc(c) - twin_colour(c)), 0.5 + 0x1p-45) << c;
    if (zs >= zvalue(0)) {
      const double zq = zvalue(kz(zs));
      ASSERT_LE(std::fabs(zq - zs), std::ldexp(zs, -8)) << zs;
    }
  }
}

// ---- The top function --------------------------------------------------------------------------

RawPrimitive raw_polygon(const ScreenPolygon& p, std::uint16_t id) {
  RawPrimitive r;
  r.n = UInt<5>(p.vertices.size());
  for (std::size_t k = 0; k < p.vertices.size(); ++k) {
    const ScreenVertex& v = p.vertices[k];
    r.v[k] = {bits_of(v.xs), bits_of(v.ys), bits_of(v.zs), bits_of(v.is)};
  }
  for (int c = 0; c < 3; ++c) r.colour[c] = bits_of(p.colour[c]);
  r.opaque = p.opaque;
  r.protect = p.protect;
  r.id = UInt<16>(id);
  return r;
}

RawPrimitive raw_light(const ScreenLightPoint& l, std::uint16_t id) {
  RawPrimitive r;
  r.is_light = true;
  r.n = UInt<5>(1);
  r.v[0] = {bits_of(l.xs), bits_of(l.ys), bits_of(l.zs), bits_of(l.intensity)};
  r.ds = bits_of(l.ds);
  for (int c = 0; c < 3; ++c) r.colour[c] = bits_of(l.colour[c]);
  r.id = UInt<16>(id);
  return r;
}

ScreenPolygon random_polygon(std::mt19937_64& rng, int nv) {
  std::uniform_real_distribution<double> s(-1.02, 1.02), u(0, 1), z(0.1, 5000);
  ScreenPolygon p;
  for (int k = 0; k < nv; ++k) p.vertices.push_back({s(rng), s(rng), z(rng), u(rng)});
  p.colour = {u(rng), u(rng), u(rng)};
  p.opaque = rng() & 1;
  p.protect = rng() & 1;
  return p;
}

ScreenLightPoint random_light(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> s(-1.02, 1.02), u(0, 1), z(0.1, 5000);
  ScreenLightPoint l;
  l.xs = s(rng);
  l.ys = s(rng);
  l.zs = z(rng);
  l.ds = u(rng) * 0.004;
  l.colour = {u(rng), u(rng), u(rng)};
  l.intensity = u(rng);
  return l;
}

void expect_vertex(const FormattedVertex& v, double xs, double ys, double zs, double is) {
  EXPECT_EQ(int(v.x.value()), ref_grid(xs));
  EXPECT_EQ(int(v.y.value()), ref_grid(ys));
  EXPECT_EQ(int(v.i.value()), ref_round_scaled(is, 1, 8, 256));
  EXPECT_EQ(int(v.z.bits.value()), ref_zfloat(zs));
}

void expect_zero_vertex(const FormattedVertex& v) {
  EXPECT_EQ(v.x.value(), 0u);
  EXPECT_EQ(v.y.value(), 0u);
  EXPECT_EQ(v.i.value(), 0u);
  EXPECT_EQ(v.z.bits.value(), 0u);
}

TEST(Formatter, TopFormatsPolygonsAndLights) {
  std::mt19937_64 rng(77);
  for (int t = 0; t < 200; ++t) {
    const int nv = 3 + t % 14;
    const ScreenPolygon p = random_polygon(rng, nv);
    FormattedPrimitive out;
    formatter_top(raw_polygon(p, std::uint16_t(t)), out);
    EXPECT_FALSE(out.is_light);
    EXPECT_EQ(int(out.n.value()), nv);
    EXPECT_EQ(out.opaque, p.opaque);
    EXPECT_EQ(out.protect, p.protect);
    EXPECT_EQ(int(out.id.value()), t);
    EXPECT_EQ(out.d.value(), 0u);
    for (int k = 0; k < kMaxVertices; ++k) {
      if (k < nv) {
        const ScreenVertex& v = p.vertices[std::size_t(k)];
        expect_vertex(out.v[k], v.xs, v.ys, v.zs, v.is);
      } else {
        expect_zero_vertex(out.v[k]);
      }
    }
    const TwinPrimitive tw = formatter_twin(p, std::uint16_t(t));
    ASSERT_EQ(tw.n, nv);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(int(out.colour[c].value()), ref_round_scaled(p.colour[c], 255, 0, 255));
      EXPECT_LE(std::fabs(out.colour[c].value() - tw.colour[c]), 0.5 + 0x1p-45);
    }
    for (int k = 0; k < nv; ++k) {
      EXPECT_LE(std::fabs(out.v[k].x.value() - tw.v[k].x), 0.5);
      EXPECT_LE(std::fabs(out.v[k].y.value() - tw.v[k].y), 0.5);
      EXPECT_LE(std::fabs(out.v[k].i.value() - tw.v[k].i), 0.5);
      EXPECT_LE(std::fabs(zvalue(int(out.v[k].z.bits.value())) - tw.v[k].z), std::ldexp(tw.v[k].z, -8));
    }
  }
  for (int t = 0; t < 200; ++t) {
    const ScreenLightPoint l = random_light(rng);
    RawPrimitive raw = raw_light(l, std::uint16_t(1000 + t));
    raw.v[1] = raw.v[0];  // ignored: a light formats v[0] only
    FormattedPrimitive out;
    formatter_top(raw, out);
    EXPECT_TRUE(out.is_light);
    EXPECT_EQ(int(out.n.value()), 1);
    EXPECT_EQ(int(out.id.value()), 1000 + t);
    expect_vertex(out.v[0], l.xs, l.ys, l.zs, l.intensity);
    for (int k = 1; k < kMaxVertices; ++k) expect_zero_vertex(out.v[k]);
    EXPECT_EQ(int(out.d.value()), cmodel_diameter(l.ds));
    const TwinPrimitive tw = formatter_twin(l, std::uint16_t(1000 + t));
    EXPECT_TRUE(tw.is_light);
    EXPECT_LE(std::fabs(out.d.value() - tw.d), 0.5);
    EXPECT_LE(std::fabs(out.v[0].i.value() - tw.v[0].i), 0.5);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(int(out.colour[c].value()), ref_round_scaled(l.colour[c], 255, 0, 255));
  }
}

#ifndef CIG_HLS_SYSTEMC
// The C model's bridge (native configuration only): bit copies, and the exact value of each code.
TEST(Formatter, BridgeCopiesBitsAndDecodesDepth) {
  std::mt19937_64 rng(3);
  const ScreenPolygon p = random_polygon(rng, 16);
  const RawPrimitive a = raw_from_polygon(p, 42), b = raw_polygon(p, 42);
  EXPECT_EQ(a.n.value(), 16u);
  EXPECT_EQ(a.id.value(), 42u);
  EXPECT_EQ(a.opaque, p.opaque);
  EXPECT_EQ(a.protect, p.protect);
  for (int k = 0; k < 16; ++k) {
    EXPECT_EQ(a.v[k].xs.value(), b.v[k].xs.value());
    EXPECT_EQ(a.v[k].ys.value(), b.v[k].ys.value());
    EXPECT_EQ(a.v[k].zs.value(), b.v[k].zs.value());
    EXPECT_EQ(a.v[k].is.value(), b.v[k].is.value());
  }
  for (int c = 0; c < 3; ++c) EXPECT_EQ(a.colour[c].value(), raw_bits(p.colour[c]));
  ScreenPolygon big = p;
  big.vertices.push_back(big.vertices[0]);
  EXPECT_THROW(raw_from_polygon(big, 0), std::invalid_argument);

  const ScreenLightPoint l = random_light(rng);
  const RawPrimitive rl = raw_from_light(l, 7);
  EXPECT_TRUE(rl.is_light);
  EXPECT_EQ(rl.n.value(), 1u);
  EXPECT_EQ(rl.v[0].xs.value(), raw_bits(l.xs));
  EXPECT_EQ(rl.v[0].is.value(), raw_bits(l.intensity));
  EXPECT_EQ(rl.ds.value(), raw_bits(l.ds));

  for (int code = 0; code <= 0x7FFF; ++code) {
    ZFloat z;
    z.bits = UInt<15>(code);
    ASSERT_EQ(zfloat_to_double(z), zvalue(code));
  }
}
#endif

// ---- Golden vectors ------------------------------------------------------------------------------

std::string golden_path() { return std::string(CIG_SOURCE_DIR) + "/verif/golden/formatter_vectors.txt"; }

// The expected output of one field by the references above (X: the C model).
int reference_output(char field, double x) {
  switch (field) {
    case 'X':
      return ref_grid(x);
    case 'I':
      return ref_round_scaled(x, 1, 8, 256);
    case 'D':
      return ref_round_scaled(x, 1, 11, 7);
    case 'C':
      return ref_round_scaled(x, 255, 0, 255);
    case 'Z':
      return ref_zfloat(x);
  }
  return -1;
}

int kernel_output(char field, double x) {
  switch (field) {
    case 'X':
      return kx(x);
    case 'I':
      return ki(x);
    case 'D':
      return kd(x);
    case 'C':
      return kc(x);
    case 'Z':
      return kz(x);
  }
  return -1;
}

// The generator: specials, boundaries and seeded random values per field, expected outputs from
// the references. Run once (--gtest_also_run_disabled_tests --gtest_filter=*WriteGoldenVectors)
// and commit the file; the reference and kernel are then frozen against it.
TEST(Formatter, DISABLED_WriteGoldenVectors) {
  std::vector<std::uint64_t> common = {
      0x0000000000000000ull, 0x8000000000000000ull, 0x7FF0000000000000ull, 0xFFF0000000000000ull, 0x7FF8000000000000ull,
      0x7FF0000000000001ull, 0xFFF8000000000000ull, 0x0000000000000001ull, 0x000FFFFFFFFFFFFFull, 0x0010000000000000ull,
      0x7FEFFFFFFFFFFFFFull, 0xFFEFFFFFFFFFFFFFull, raw_bits(1.0),         raw_bits(-1.0),        raw_bits(0.5),
      raw_bits(-0.5),        raw_bits(2.0),         raw_bits(1e-300)};
  std::mt19937_64 rng(0xF0A7);
  std::ofstream out(golden_path());
  ASSERT_TRUE(out) << golden_path();
  out << "# Formatter golden vectors (SPEC C eq. 1): written by DISABLED_WriteGoldenVectors in\n"
         "# verif/kernels/test_formatter.cpp, checked bit for bit by Formatter.GoldenVectors.\n"
         "# field  input (IEEE-754 binary64, hex)  expected output (hex)\n"
         "#   X  grid coordinate 2048*s + 2047, 0..4095 (Y is the same function)\n"
         "#   I  256*Is, 0..255     D  2048*Ds, 0..7     C  255*c, 0..255\n"
         "#   Z  e8m7 depth code, bias 127, 0..7fff\n";
  auto emit = [&](char field, std::uint64_t b) {
    char line[64];
    std::snprintf(line, sizeof line, "%c %016" PRIx64 " %04x\n", field, b,
                  unsigned(reference_output(field, from_raw(b))));
    out << line;
  };
  std::uniform_real_distribution<double> u(0, 1);
  for (char field : {'X', 'I', 'D', 'C', 'Z'}) {
    for (std::uint64_t b : common) emit(field, b);
    for (int t = 0; t < 40; ++t) {
      double x = 0;
      switch (field) {
        case 'X': {
          const double sb = (double(rng() % 4097) - 0.5 - kGridOffset) / kGridScale;
          x = t < 10 ? sb : t < 20 ? next_down(sb) : t < 30 ? next_up(sb) : 2.2 * u(rng) - 1.1;
          break;
        }
        case 'I': {
          const double b = (double(rng() % 257) - 0.5) / 256;
          x = t < 10 ? b : t < 20 ? next_down(b) : t < 30 ? next_up(b) : 1.1 * u(rng) - 0.05;
          break;
        }
        case 'D': {
          const double b = (double(rng() % 9) - 0.5) / 2048;
          x = t < 10 ? b : t < 20 ? next_down(b) : t < 30 ? next_up(b) : 9.0 / 2048 * u(rng);
          break;
        }
        case 'C': {
          const double b = (double(rng() % 257) - 0.5) / 255;
          x = t < 10 ? b : t < 20 ? next_down(b) : t < 30 ? next_up(b) : 1.1 * u(rng) - 0.05;
          break;
        }
        case 'Z': {
          const int code = int(rng() % 0x8000);
          const double v = zvalue(code), mid = code < 0x7FFF ? (v + zvalue(code + 1)) / 2 : v;
          x = t < 10 ? v : t < 20 ? mid : t < 30 ? next_up(mid) : std::exp2(260 * u(rng) - 130);
          break;
        }
      }
      emit(field, raw_bits(x));
    }
  }
  // Double rounding of the reference's sum: X just below a half-integer boundary.
  for (int k : {8, 100, 1024, 1500, 2046, 2047, 2048, 3000, 4094}) {
    const double b = k + 0.5, h = (b - next_down(b)) / 2, m = b - kGridOffset;
    emit('X', raw_bits((m - h) / kGridScale));
    emit('X', raw_bits(next_down((m - h) / kGridScale)));
  }
}

TEST(Formatter, GoldenVectors) {
  std::ifstream in(golden_path());
  ASSERT_TRUE(in) << golden_path();
  std::string line;
  int count = 0, fields[5] = {0, 0, 0, 0, 0};
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    char field = 0;
    unsigned long long input = 0;
    unsigned expected = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%c %llx %x", &field, &input, &expected), 3) << line;
    const double x = from_raw(input);
    ASSERT_EQ(kernel_output(field, x), int(expected)) << line;
    ASSERT_EQ(reference_output(field, x), int(expected)) << line;
    ++count;
    for (int f = 0; f < 5; ++f) fields[f] += field == "XIDCZ"[f];
  }
  EXPECT_GE(count, 250);
  for (int f = 0; f < 5; ++f) EXPECT_GE(fields[f], 50) << "XIDCZ"[f];
}

// A digest of the kernel's output on a fixed input stream (digest.hpp), printed as a DIGEST line:
// the native and the SystemC-typed runs must print the same one (ctest kernel_bits_identical).
TEST(Formatter, OutputDigest) {
  std::mt19937_64 rng(2024);
  kernel_test::Digest d;
  for (int t = 0; t < 2000; ++t) {
    RawPrimitive r;
    r.is_light = (t % 5) == 0;
    r.n = UInt<5>(3 + t % 14);
    for (int k = 0; k < kMaxVertices; ++k)
      r.v[k] = {UInt<64>(rng()), UInt<64>(rng()), UInt<64>(rng()), UInt<64>(rng())};
    if (t % 2) r.v[0].xs = bits_of(double(rng() % 4096) / 2048 - 1);
    r.ds = UInt<64>(rng());
    for (int c = 0; c < 3; ++c) r.colour[c] = UInt<64>(rng());
    r.id = UInt<16>(t);
    FormattedPrimitive out;
    formatter_top(r, out);
    for (int k = 0; k < kMaxVertices; ++k) {
      d.add(out.v[k].x.value());
      d.add(out.v[k].y.value());
      d.add(out.v[k].i.value());
      d.add(out.v[k].z.bits.value());
    }
    d.add(out.d.value());
    for (int c = 0; c < 3; ++c) d.add(out.colour[c].value());
    d.add(out.n.value() | (out.id.value() << 8) | (std::uint64_t(out.is_light) << 24));
  }
  kernel_test::print_digest("formatter", d);
}

}  // namespace
}  // namespace cig::hls
