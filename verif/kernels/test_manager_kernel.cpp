// The scene manager's preliminary processing unit (hls/manager/, SPEC A.1-2, seed 000):
//  * the channel setup's sqrt(1 + t^2) rounded up, for every t of the format;
//  * the visibility flag against an EXACT reference that takes the same quantized inputs (the
//    centre transform in 128-bit integers, the plane tests by exact squared comparisons in 256 bits)
//    over random and adversarial spheres (tangent to each plane and one LSB either side, behind the
//    eye, radii larger than the world, ranges of 100 km and more, eyes at the world's edges,
//    arbitrary non-rotation matrices at the formats' extremes): no false negative, and every false
//    positive within the margin M the kernel's error bound gives (hls/manager/visibility.hpp);
//  * against its double twin (cmodel/manager/visibility_twin.hpp) and the C model's cull
//    (sphere_may_be_visible) on unquantized inputs: the kernel keeps every sphere they keep.
// The same file runs in the native and the SystemC-typed build (cig_kernel_tests,
// cig_kernel_tests_systemc).
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/manager/channel_setup.hpp"
#include "hls/manager/visibility.hpp"
#include "manager/channel_view.hpp"
#include "manager/scene_manager.hpp"
#include "manager/visibility_twin.hpp"

namespace cig::hls {
namespace {

using i128 = __int128;
using u128 = unsigned __int128;
using Rng = std::mt19937_64;

// Raw ranges of the formats (records.hpp).
constexpr int kWorldFrac = 11;                                    // u = 2^-11 m
constexpr std::int64_t kWorldMin = -(std::int64_t{1} << 31);      // -2^20 m
constexpr std::int64_t kWorldMax = (std::int64_t{1} << 31) - 1;   // 2^20 m - u
constexpr std::int64_t kRadiusMax = (std::int64_t{1} << 32) - 1;  // 2^21 m - u
constexpr std::int64_t kRotMin = -(std::int64_t{1} << 17);        // -2
constexpr std::int64_t kRotMax = (std::int64_t{1} << 17) - 1;     // 2 - 2^-16
constexpr std::int64_t kOne = std::int64_t{1} << 16;              // 1.0 in B and t
constexpr std::int64_t kTanMax = (std::int64_t{1} << 18) - 1;     // 4 - 2^-16
constexpr std::int64_t kNearMax = (std::int64_t{1} << 24) - 1;    // 8192 m - u
constexpr double kU = 1.0 / (1 << kWorldFrac);

// ---- Random numbers (the raw mt19937_64 stream) ------------------------------------------------

double unit(Rng& rng) { return double(rng() >> 11) * 0x1p-53; }  // [0, 1)
double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * unit(rng); }
double log_uniform(Rng& rng, double lo, double hi) { return lo * std::exp(std::log(hi / lo) * unit(rng)); }
std::int64_t between(Rng& rng, std::int64_t lo, std::int64_t hi) {
  return lo + std::int64_t(rng() % std::uint64_t(hi - lo + 1));
}
bool one_in(Rng& rng, int n) { return rng() % std::uint64_t(n) == 0; }

std::int64_t clamp64(std::int64_t v, std::int64_t lo, std::int64_t hi) { return v < lo ? lo : v > hi ? hi : v; }
std::int64_t world_raw(double metres) {  // the host's rounding: nearest, within the world
  const double v = std::nearbyint(metres * (1 << kWorldFrac));
  return v < double(kWorldMin) ? kWorldMin : v > double(kWorldMax) ? kWorldMax : std::int64_t(v);
}
std::int64_t radius_raw(double metres) {  // up
  const double v = std::ceil(metres * (1 << kWorldFrac));
  return v > double(kRadiusMax) ? kRadiusMax : v < 0 ? 0 : std::int64_t(v);
}
std::int64_t rotation_raw(double b) { return clamp64(std::int64_t(std::nearbyint(b * kOne)), kRotMin, kRotMax); }

// A uniformly random rotation (unit quaternion by rejection), rows = eye axes in world coordinates.
void random_rotation(Rng& rng, double (&b)[3][3]) {
  double q[4], n2 = 0;
  for (;;) {
    n2 = 0;
    for (double& v : q) {
      v = uniform(rng, -1, 1);
      n2 += v * v;
    }
    if (n2 > 1e-3 && n2 <= 1) break;
  }
  const double n = std::sqrt(n2), w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b[i][j] = m[i][j];
}

// ---- One case: the kernel's quantized inputs as raw integers ---------------------------------

struct Case {
  std::int64_t eye[3] = {0, 0, 0}, centre[3] = {0, 0, 0};             // units u
  std::int64_t b[3][3] = {{kOne, 0, 0}, {0, kOne, 0}, {0, 0, kOne}};  // units 2^-16
  std::int64_t t = kOne;                                              // units 2^-16
  std::int64_t near = 1 << kWorldFrac;                                // units u
  std::int64_t radius = 0;                                            // units u
};

struct KernelResult {
  bool visible = true;
  unsigned outside = 0;
  std::int64_t centre_eye[3] = {0, 0, 0};
  std::int64_t radius_widened = 0;
  std::int64_t side_norm = 0;
};

KernelResult run_kernel(const Case& k) {
  ManagerChannel ch;
  for (int i = 0; i < 3; ++i) {
    ch.eye[i] = WorldCoord::from_raw_value(k.eye[i]);
    for (int j = 0; j < 3; ++j) ch.b[i][j] = RotationEntry::from_raw_value(k.b[i][j]);
  }
  ch.tan_half_fov = TanHalfFov::from_raw_value(std::uint64_t(k.t));
  ch.near = NearDistance::from_raw_value(std::uint64_t(k.near));
  ManagerChannelSetup setup;
  manager_channel_setup_top(ch, setup);
  ManagerObject obj;
  for (int i = 0; i < 3; ++i) obj.centre[i] = WorldCoord::from_raw_value(k.centre[i]);
  obj.radius = WorldRadius::from_raw_value(std::uint64_t(k.radius));
  ManagerVisibility out;
  manager_visibility_top(setup, obj, out);
  KernelResult r;
  r.visible = out.visible;
  r.outside = unsigned(out.outside.value());
  for (int i = 0; i < 3; ++i) r.centre_eye[i] = out.centre_eye[i].raw().value();
  r.radius_widened = std::int64_t(out.radius_widened.raw().value());
  r.side_norm = std::int64_t(setup.side_norm.raw().value());
  return r;
}

// ---- Exact reference ---------------------------------------------------------------------------

// 256-bit unsigned products of 128-bit values, compared exactly.
struct U256 {
  u128 hi, lo;
};
U256 mul_wide(u128 a, u128 b) {
  const u128 m64 = ~std::uint64_t{0};
  const u128 a0 = a & m64, a1 = a >> 64, b0 = b & m64, b1 = b >> 64;
  const u128 p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const u128 mid = (p00 >> 64) + (p01 & m64) + (p10 & m64);  // < 3 * 2^64
  return {p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64), (p00 & m64) | (mid << 64)};
}
bool greater(const U256& x, const U256& y) { return x.hi != y.hi ? x.hi > y.hi : x.lo > y.lo; }

// The exact eye-space centre B (c - e), units 2^-27 m (|value| < 2^51).
struct ExactCentre {
  i128 c[3];
};
ExactCentre exact_centre(const Case& k) {
  ExactCentre e;
  for (int i = 0; i < 3; ++i) {
    e.c[i] = 0;
    for (int j = 0; j < 3; ++j) e.c[i] += i128(k.b[i][j]) * (k.centre[j] - k.eye[j]);
  }
  return e;
}

// Is the sphere of radius r (units u, r >= 0) centred at the exact centre wholly outside plane k?
// near: z + r < near. Side: n . c < -r sqrt(1 + t^2), in units 2^-43 m with T = t 2^16:
// A = (+-x or +-y) 2^16 + T z < -(r 2^16) sqrt(Q), Q = 2^32 + T^2, i.e. A < 0 and A^2 > (r 2^16)^2 Q.
bool exact_outside(const Case& k, const ExactCentre& e, int plane, i128 r) {
  if (plane == 0) return e.c[2] + r * kOne < i128(k.near) * kOne;
  static const int axis[5] = {0, 0, 0, 1, 1};
  static const int sign[5] = {0, 1, -1, -1, 1};
  const i128 a = sign[plane] * e.c[axis[plane]] * kOne + i128(k.t) * e.c[2];  // |a| < 2^70
  if (a >= 0) return false;
  const u128 mag = u128(-a);
  const u128 rr = u128(r) * u128(kOne);  // < 2^50
  const u128 q = u128(std::uint64_t{1} << 32) + u128(k.t) * u128(k.t);
  return greater(mul_wide(mag, mag), mul_wide(rr * rr, q));
}

unsigned exact_outcode(const Case& k, const ExactCentre& e, i128 r) {
  unsigned code = 0;
  for (int p = 0; p < 5; ++p)
    if (exact_outside(k, e, p, r)) code |= 1u << p;
  return code;
}

// The kernel's widening and the false-positive margin of visibility.hpp (units u):
// eps = 4 + ceil(|d|_1 / 2^16), R = r + eps, M = eps + ceil(R / 2^16) + 2.
std::int64_t widening_of(const Case& k) {
  std::int64_t l1 = 0;
  for (int j = 0; j < 3; ++j) l1 += std::llabs(k.centre[j] - k.eye[j]);
  return 4 + (l1 + 0xFFFF) / 0x10000;
}
std::int64_t margin_of(const Case& k) {
  const std::int64_t eps = widening_of(k), big_r = k.radius + eps;
  return eps + (big_r + 0xFFFF) / 0x10000 + 2;
}

// ---- Checking one case -------------------------------------------------------------------------

struct Tally {
  long cases = 0, exact_visible = 0, false_negatives = 0, false_positives = 0, outside_margin = 0;
  void add(const Tally& o) {
    cases += o.cases, exact_visible += o.exact_visible, false_negatives += o.false_negatives;
    false_positives += o.false_positives, outside_margin += o.outside_margin;
  }
};

// Per plane: kernel outside => exact outside (no false negative), and exact outside with radius
// r + M => kernel outside (a plane the kernel keeps is within M of the sphere).
void check_case(const Case& k, Tally& tally, const char* family) {
  const KernelResult kr = run_kernel(k);
  const ExactCentre e = exact_centre(k);
  const unsigned exact = exact_outcode(k, e, k.radius);
  const unsigned widened = exact_outcode(k, e, i128(k.radius) + margin_of(k));
  ++tally.cases;
  if (exact == 0) ++tally.exact_visible;
  const bool fn = (kr.outside & ~exact) != 0;        // a plane the kernel culls but exact keeps
  const bool beyond = (widened & ~kr.outside) != 0;  // a plane the kernel keeps though far outside
  if (fn) ++tally.false_negatives;
  if (kr.visible && exact != 0) ++tally.false_positives;
  if (beyond) ++tally.outside_margin;
  if ((fn || beyond) && tally.false_negatives + tally.outside_margin <= 5) {
    ADD_FAILURE() << family << ": kernel outcode " << kr.outside << ", exact " << exact << ", exact(r + M) " << widened
                  << "; eye " << k.eye[0] << " " << k.eye[1] << " " << k.eye[2] << ", centre " << k.centre[0] << " "
                  << k.centre[1] << " " << k.centre[2] << ", r " << k.radius << ", t " << k.t << ", near " << k.near;
  }
  ASSERT_EQ(kr.visible, kr.outside == 0);
}

// ---- Case families -----------------------------------------------------------------------------

void random_channel(Rng& rng, Case& k, double (&b)[3][3]) {
  random_rotation(rng, b);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) k.b[i][j] = rotation_raw(b[i][j]);
  const bool local = one_in(rng, 2);
  for (int i = 0; i < 3; ++i)
    k.eye[i] = local ? world_raw(uniform(rng, -1e4, 1e4)) : between(rng, kWorldMin, kWorldMax);
  const int pick = int(rng() % 16);
  k.t = pick == 0 ? 0 : pick == 1 ? kTanMax : between(rng, kOne / 20, 3 * kOne);  // fov 5.7 .. 143 deg
  k.near = one_in(rng, 16) ? between(rng, 0, kNearMax) : std::int64_t(log_uniform(rng, 0.01, 100) / kU);
}

// World centre = eye + B^T v for an eye-space offset v (metres), rounded and kept in the world.
void place(Case& k, const double (&b)[3][3], const double (&v)[3]) {
  for (int j = 0; j < 3; ++j) {
    const double w = double(k.eye[j]) * kU + b[0][j] * v[0] + b[1][j] * v[1] + b[2][j] * v[2];
    k.centre[j] = world_raw(w);
  }
}

void random_direction(Rng& rng, double (&v)[3]) {
  for (;;) {
    double n2 = 0;
    for (double& x : v) {
      x = uniform(rng, -1, 1);
      n2 += x * x;
    }
    if (n2 > 1e-4 && n2 <= 1) {
      const double n = std::sqrt(n2);
      for (double& x : v) x /= n;
      return;
    }
  }
}

// Random spheres around a random eye: directions uniform, ranges 1 cm .. 300 km, radii 1 mm .. 10 km.
Case random_case(Rng& rng) {
  Case k;
  double b[3][3];
  random_channel(rng, k, b);
  double v[3];
  random_direction(rng, v);
  const double range = log_uniform(rng, 0.01, 3e5);
  for (double& x : v) x *= range;
  place(k, b, v);
  k.radius = radius_raw(log_uniform(rng, 1e-3, 1e4));
  return k;
}

// Behind the eye: z in [-300 km, 0), x, y up to 2 |z|, radii up to 2 |z| (some reach past near).
Case behind_case(Rng& rng) {
  Case k;
  double b[3][3];
  random_channel(rng, k, b);
  const double z = -log_uniform(rng, 1e-3, 3e5);
  const double v[3] = {uniform(rng, -2, 2) * -z, uniform(rng, -2, 2) * -z, z};
  place(k, b, v);
  k.radius = radius_raw(log_uniform(rng, 1e-3, -2 * z));
  return k;
}

// Radii larger than the world (2^19 .. 2^21 m), centres anywhere.
Case huge_case(Rng& rng) {
  Case k;
  double b[3][3];
  random_channel(rng, k, b);
  for (int j = 0; j < 3; ++j) k.centre[j] = between(rng, kWorldMin, kWorldMax);
  k.radius = between(rng, std::int64_t{1} << 30, kRadiusMax);
  return k;
}

// The world's edges: eye and centre components at the extremes or random, ranges 100 km .. 3600 km.
Case edge_case(Rng& rng) {
  Case k;
  double b[3][3];
  random_channel(rng, k, b);
  auto edge = [&](void) {
    const int p = int(rng() % 4);
    return p == 0 ? kWorldMin : p == 1 ? kWorldMax : between(rng, kWorldMin, kWorldMax);
  };
  for (int j = 0; j < 3; ++j) k.eye[j] = edge();
  for (;;) {
    for (int j = 0; j < 3; ++j) k.centre[j] = edge();
    double d2 = 0;
    for (int j = 0; j < 3; ++j) d2 += std::pow(double(k.centre[j] - k.eye[j]) * kU, 2);
    if (d2 >= 1e10) break;  // at least 100 km
  }
  k.radius = radius_raw(log_uniform(rng, 1e-3, 1e5));
  return k;
}

// Every raw input anywhere in its format (B not a rotation), extremes often.
Case extreme_case(Rng& rng) {
  Case k;
  auto pick = [&](std::int64_t lo, std::int64_t hi) {
    const int p = int(rng() % 5);
    return p == 0 ? lo : p == 1 ? hi : p == 2 ? std::int64_t(0) : between(rng, lo, hi);
  };
  for (int i = 0; i < 3; ++i) {
    k.eye[i] = pick(kWorldMin, kWorldMax);
    k.centre[i] = pick(kWorldMin, kWorldMax);
    for (int j = 0; j < 3; ++j) k.b[i][j] = pick(kRotMin, kRotMax);
  }
  k.t = pick(0, kTanMax);
  k.near = pick(0, kNearMax);
  k.radius = pick(0, kRadiusMax);
  return k;
}

// Tangent to plane `plane` (near, left, right, top, bottom) from outside: a point p on the face,
// inside the other planes, moved out along the plane's normal by r. The smallest raw radius r0 the
// exact test keeps is then found by bisection, and the sphere is checked at r0 - 1, r0, r0 + 1 and
// with the centre one LSB off along each world axis: "just outside, tangent, just inside".
void tangent_cases(Rng& rng, int plane, Tally& tally) {
  Case k;
  double b[3][3];
  random_channel(rng, k, b);
  if (one_in(rng, 4)) {  // axis-aligned eyes too (B exact: +-1 entries)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b[i][j] = i == j ? 1 : 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) k.b[i][j] = i == j ? kOne : 0;
  }
  if (k.t == 0) k.t = kOne / 2;
  const double t = double(k.t) / kOne, near = double(k.near) * kU;
  const double z = plane == 0 ? near : near + log_uniform(rng, 1e-2, 2e5);
  const double a = uniform(rng, -0.95, 0.95) * t * z, c = uniform(rng, -0.95, 0.95) * t * z;
  double p[3], n[3];  // the point on the face and the plane's outward unit normal
  const double s = std::sqrt(1 + t * t);
  switch (plane) {
    case 0:
      p[0] = a, p[1] = c, p[2] = z, n[0] = 0, n[1] = 0, n[2] = -1;
      break;
    case 1:
      p[0] = -t * z, p[1] = a, p[2] = z, n[0] = -1 / s, n[1] = 0, n[2] = -t / s;
      break;
    case 2:
      p[0] = t * z, p[1] = a, p[2] = z, n[0] = 1 / s, n[1] = 0, n[2] = -t / s;
      break;
    case 3:
      p[0] = a, p[1] = t * z, p[2] = z, n[0] = 0, n[1] = 1 / s, n[2] = -t / s;
      break;
    default:
      p[0] = a, p[1] = -t * z, p[2] = z, n[0] = 0, n[1] = -1 / s, n[2] = -t / s;
      break;
  }
  const double r = log_uniform(rng, 1e-3, 1e4);
  const double v[3] = {p[0] + r * n[0], p[1] + r * n[1], p[2] + r * n[2]};
  place(k, b, v);
  const ExactCentre e = exact_centre(k);
  std::int64_t lo = 0, hi = kRadiusMax;  // find the smallest r with exact outcode 0
  if (exact_outcode(k, e, hi) != 0) return;
  if (exact_outcode(k, e, lo) != 0) {
    for (int step = 0; step < 40 && hi - lo > 1; ++step) {
      const std::int64_t mid = lo + (hi - lo) / 2;
      (exact_outcode(k, e, mid) == 0 ? hi : lo) = mid;
    }
  } else {
    hi = 0;
  }
  const std::int64_t r0 = hi;
  for (std::int64_t dr = -1; dr <= 1; ++dr) {
    if (r0 + dr < 0 || r0 + dr > kRadiusMax) continue;
    Case v2 = k;
    v2.radius = r0 + dr;
    check_case(v2, tally, "tangent");
  }
  for (int j = 0; j < 3; ++j) {
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      Case v2 = k;
      v2.radius = r0;
      v2.centre[j] = clamp64(k.centre[j] + sgn, kWorldMin, kWorldMax);
      check_case(v2, tally, "tangent");
    }
  }
}

void report(const char* family, const Tally& t) {
  std::printf(
      "manager visibility %-9s %7ld cases, %7ld visible (exact), %ld false negatives, %5ld false positives (%.4f%%)\n",
      family, t.cases, t.exact_visible, t.false_negatives, t.false_positives,
      t.cases ? 100.0 * double(t.false_positives) / double(t.cases) : 0.0);
  std::fflush(stdout);
}

// ---- Tests -------------------------------------------------------------------------------------

// s_q = S 2^-16 with S = ceil(sqrt(2^32 + T^2)) for every T of TanHalfFov (2^18 values).
TEST(ManagerChannelSetup, SideNormIsTheSquareRootRoundedUpForEveryT) {
  for (std::int64_t t = 0; t <= kTanMax; ++t) {
    ManagerChannel ch;
    ch.tan_half_fov = TanHalfFov::from_raw_value(std::uint64_t(t));
    ManagerChannelSetup setup;
    manager_channel_setup_top(ch, setup);
    const i128 s = i128(setup.side_norm.raw().value());
    const i128 q = (i128(1) << 32) + i128(t) * t;
    ASSERT_TRUE(s * s >= q && (s - 1) * (s - 1) < q) << "T " << t << ": S " << std::int64_t(s);
  }
}

// The exact reference on spheres whose tangency is exact: B the identity, t = 3/4 (sqrt(1 + t^2) =
// 5/4) or 0, centres and radii chosen so that the sphere touches the plane in exact arithmetic.
// The reference must keep the tangent sphere and cull it one LSB smaller; the kernel keeps both
// ends of the tie.
TEST(ManagerVisibility, ExactTangentsKeptAndReferenceExact) {
  Rng rng(20240613);
  long checked = 0;
  for (int n = 0; n < 2000; ++n) {
    Case k;
    for (int j = 0; j < 3; ++j) k.eye[j] = between(rng, -(1 << 30), 1 << 30);
    k.t = one_in(rng, 2) ? 3 * kOne / 4 : 0;
    k.near = between(rng, 1, 1 << 16);
    const int plane = int(rng() % 5);
    std::int64_t c[3] = {0, 0, 0}, r = 0;
    if (plane == 0) {
      c[2] = k.near - between(rng, 1, 1 << 24);  // z < near, r = near - z
      c[0] = between(rng, -(1 << 20), 1 << 20), c[1] = between(rng, -(1 << 20), 1 << 20);
      r = k.near - c[2];
    } else {
      // side plane: sgn * w + t z = -r s. t = 3/4: w = -(5 r + 3 z) / 4 with z = 4 a, r = 4 b;
      // t = 0: w = -r.
      const std::int64_t a = between(rng, -(1 << 22), 1 << 22), bb = between(rng, 1, 1 << 22);
      const std::int64_t z = 4 * a;
      r = 4 * bb;
      const std::int64_t w = k.t ? -(5 * r + 3 * z) / 4 : -r;
      const int sgn = (plane == 1 || plane == 4) ? 1 : -1, axis = plane <= 2 ? 0 : 1;
      c[axis] = sgn * w, c[2] = z;
      c[1 - axis] = 0;
    }
    for (int j = 0; j < 3; ++j) k.centre[j] = k.eye[j] + c[j];
    k.radius = r;
    const ExactCentre e = exact_centre(k);
    const unsigned bit = 1u << plane;  // the other planes may cull these spheres: only this one counts
    ASSERT_EQ(exact_outcode(k, e, r) & bit, 0u) << "plane " << plane << ": the tangent sphere is kept";
    ASSERT_NE(exact_outcode(k, e, r - 1) & bit, 0u) << "plane " << plane << ": one LSB smaller is culled";
    EXPECT_EQ(run_kernel(k).outside & bit, 0u) << "plane " << plane << ": the kernel keeps the tangent sphere";
    Tally tally;
    check_case(k, tally, "exact-tangent");
    k.radius = r - 1;
    check_case(k, tally, "exact-tangent");
    ASSERT_EQ(tally.false_negatives + tally.outside_margin, 0);
    ++checked;
  }
  EXPECT_EQ(checked, 2000);
}

// The exact reference against plain doubles where the plane values are far from zero.
TEST(ManagerVisibility, ExactReferenceAgreesWithDoublesAwayFromTies) {
  Rng rng(7);
  for (int n = 0; n < 20000; ++n) {
    const Case k = random_case(rng);
    double eye[3], centre[3], b[3][3];
    for (int i = 0; i < 3; ++i) {
      eye[i] = double(k.eye[i]) * kU, centre[i] = double(k.centre[i]) * kU;
      for (int j = 0; j < 3; ++j) b[i][j] = double(k.b[i][j]) / kOne;
    }
    const VisibilityTwinResult tw =
        manager_visibility_twin(eye, b, double(k.t) / kOne, double(k.near) * kU, centre, double(k.radius) * kU);
    const unsigned exact = exact_outcode(k, exact_centre(k), k.radius);
    for (int p = 0; p < 5; ++p) {
      if (std::fabs(tw.plane_value[p]) < 1e-3) continue;
      ASSERT_EQ((exact >> p) & 1u, (tw.outside >> p) & 1u) << "case " << n << " plane " << p;
    }
  }
}

// The main property over >= 100,000 cases: no false negative against the exact test, every false
// positive within the margin M (visibility.hpp, claim 3). Prints each family's false-positive rate.
TEST(ManagerVisibility, NoFalseNegativeAndFalsePositivesWithinMargin) {
  Rng rng(0x5eed000);
  Tally all;
  struct Family {
    const char* name;
    Case (*make)(Rng&);
    int count;
  };
  const Family families[] = {{"random", random_case, 60000},
                             {"behind", behind_case, 15000},
                             {"huge", huge_case, 10000},
                             {"edges", edge_case, 15000},
                             {"extremes", extreme_case, 15000}};
  for (const Family& f : families) {
    Tally t;
    for (int n = 0; n < f.count; ++n) check_case(f.make(rng), t, f.name);
    report(f.name, t);
    all.add(t);
    EXPECT_EQ(t.false_negatives, 0) << f.name;
    EXPECT_EQ(t.outside_margin, 0) << f.name;
    if (std::string(f.name) == "random") { EXPECT_LT(double(t.false_positives), 1e-3 * double(t.cases)); }
  }
  Tally tangent;
  for (int n = 0; n < 3000; ++n) tangent_cases(rng, n % 5, tangent);
  report("tangent", tangent);
  all.add(tangent);
  EXPECT_EQ(tangent.false_negatives, 0);
  EXPECT_EQ(tangent.outside_margin, 0);
  EXPECT_GT(tangent.cases, 20000);
  report("all", all);
  EXPECT_GE(all.cases, 100000);
  EXPECT_EQ(all.false_negatives, 0);
  EXPECT_EQ(all.outside_margin, 0);
}

// Against the unquantized world (claim 2): the double twin and the C model's cull on the true
// centre, eye, rotation and radius; the kernel on their host-rounded values (t and near are the
// channel's, the same in all three). The kernel keeps every plane the twin keeps, and culls every
// plane the twin culls with the radius r + M' (M' = 2 eps + ceil(R / 2^16) + 2 u). The twin and
// the C model agree away from double-rounding ties.
TEST(ManagerVisibility, KeepsWhatTheDoubleTwinAndTheCModelKeep) {
  Rng rng(1234567);
  long cases = 0, twin_visible = 0, kernel_visible = 0, cmodel_differs = 0;
  for (int n = 0; n < 40000; ++n) {
    Case k;
    double b[3][3];
    random_channel(rng, k, b);
    double eye[3], centre[3], v[3];
    for (int j = 0; j < 3; ++j) eye[j] = double(k.eye[j]) * kU + uniform(rng, -kU, kU);
    random_direction(rng, v);
    const double range = n % 4 == 0 ? log_uniform(rng, 1e4, 2e5) : log_uniform(rng, 0.01, 1e4);
    for (int j = 0; j < 3; ++j) centre[j] = eye[j] + (b[0][j] * v[0] + b[1][j] * v[1] + b[2][j] * v[2]) * range;
    const double radius = log_uniform(rng, 1e-3, 1e4);
    const double t = double(k.t) / kOne, near = double(k.near) * kU;
    bool in_world = true;
    for (int j = 0; j < 3; ++j) {
      in_world = in_world && std::fabs(eye[j]) < 1048000 && std::fabs(centre[j]) < 1048000;
      k.eye[j] = world_raw(eye[j]), k.centre[j] = world_raw(centre[j]);
    }
    if (!in_world) continue;
    k.radius = radius_raw(radius);
    const KernelResult kr = run_kernel(k);
    const VisibilityTwinResult tw = manager_visibility_twin(eye, b, t, near, centre, radius);
    const std::int64_t eps = widening_of(k);
    const double m2 = double(2 * eps + (kr.radius_widened + 0xFFFF) / 0x10000 + 2) * kU;
    const VisibilityTwinResult tw_wide = manager_visibility_twin(eye, b, t, near, centre, radius + m2);
    ASSERT_EQ(kr.radius_widened, k.radius + eps);
    ASSERT_EQ(kr.outside & ~tw.outside, 0u) << "case " << n << ": the kernel culls a plane the twin keeps";
    ASSERT_EQ(tw_wide.outside & ~kr.outside, 0u) << "case " << n << ": the kernel keeps a plane beyond M'";
    // The C model's own cull (manager/scene_manager.cpp) on the same doubles.
    const ViewPyramid pyramid(t, near);
    const glm::dvec3 ce(tw.centre_eye[0], tw.centre_eye[1], tw.centre_eye[2]);
    const bool cm = sphere_may_be_visible(pyramid, ce, radius);
    if (cm != tw.visible) {
      ++cmodel_differs;
      double closest = 1e300;
      for (double pv : tw.plane_value) closest = std::fmin(closest, std::fabs(pv));
      EXPECT_LT(closest, 1e-6) << "case " << n << ": the twin and the C model differ away from a tie";
    }
    EXPECT_TRUE(!cm || kr.visible) << "case " << n << ": the kernel culls a sphere the C model keeps";
    ++cases;
    twin_visible += tw.visible, kernel_visible += kr.visible;
  }
  std::printf(
      "manager visibility vs double twin: %ld cases, twin keeps %ld, kernel keeps %ld (+%ld), C model differs %ld\n",
      cases, twin_visible, kernel_visible, kernel_visible - twin_visible, cmodel_differs);
  EXPECT_GT(cases, 30000);
}

// Digest of the kernel's outputs on fixed inputs (kernel_bits_identical: native == SystemC types).
TEST(ManagerKernelDigest, Digest) {
  kernel_test::Digest d;
  Rng rng(42);
  for (int n = 0; n < 4000; ++n) {
    const Case k = n % 4 == 3 ? extreme_case(rng) : random_case(rng);
    const KernelResult r = run_kernel(k);
    d.add_bool(r.visible);
    d.add(r.outside);
    for (std::int64_t c : r.centre_eye) d.add_signed(c);
    d.add_signed(r.radius_widened);
    d.add_signed(r.side_norm);
  }
  kernel_test::print_digest("manager_visibility", d);
}

}  // namespace
}  // namespace cig::hls
