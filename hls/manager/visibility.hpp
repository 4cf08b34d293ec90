// The scene manager's preliminary processing unit (SPEC A.1-2, seed 000): "transforming Po_i into
// the pilot coordinate system; forming a visual flag V[i]". One object's bounding-sphere centre is
// moved into eye coordinates, c_eye = B (c - eye), and the sphere is tested against the five
// planes of the channel's viewing pyramid (|x| <= t z, |y| <= t z, z >= near). V[i] = 0 only if the
// sphere lies wholly outside one plane, and only when that is certain: every rounding goes towards
// "visible". Formats: records.hpp; derivation and measured false positives: README.md.
//
// Datapath (u = 2^-11 m; every step exact except the one truncation):
//   d_j    = c_j - eye_j                       Fixed<33, 22>  exact
//   p_ij   = B_ij d_j                          Fixed<51, 24>  exact, 9 multipliers 18 x 33
//   c^_i   = floor_u(p_i0 + p_i1 + p_i2)       Fixed<37, 26>  the sum Fixed<53, 26> is exact; the
//                                                             floor drops 16 bits (wires only)
//   eps    = 4 u + ceil_u(2^-16 |d|_1)         UFixed<18, 7>  three magnitudes, two adds, a shift
//   R      = r + eps                           UFixed<33, 22> exact
//   near:  outside iff c^_z + R < near                           exact compare
//   side:  outside iff n . c^ + R s_q < 0, n . c^ one of
//          c^_x + t c^_z (left), t c^_z - c^_x (right), t c^_z - c^_y (top), t c^_z + c^_y (bottom)
//          Fixed<58, 31>, exact; t c^_z (18 x 37) and R s_q (33 x 19) are shared by the four
//          planes; the test is the sign bit.
// No divider, no square root per object (s_q = sqrt(1 + t^2) rounded up comes from
// channel_setup.hpp once per channel), no saturation: no step can overflow (exact widths).
//
// Error bound and why the flag is conservative (s = sqrt(1 + t^2) = |n| for a side plane,
// s <= s_q = S 2^-16 < s + 2^-16):
//
// 1. Against the exact test on the SAME quantized inputs (c_x = B (c - e) exact): the floor gives
//    c_x - c^ in [0, u)^3, |c_x - c^| < sqrt(3) u < 2 u. If the kernel says "outside a side plane",
//      n . c_x <= n . c^ + s |c_x - c^| < -R s_q + 2 u s <= -(r + eps - 2 u) s <= -r s,
//    (R s_q >= R s), so the sphere is outside in exact arithmetic. Near: c_x,z < c^_z + u and
//    c^_z + R < near give c_x,z + r < near (eps >= u). No false negative; tangent spheres stay
//    visible (the exact test, like the C model's, culls only on a strict inequality).
// 2. Against the unquantized world (the C model's binary64 c*, e*, rotation B*), with the host's
//    rounding (records.hpp): |c - c*|, |e - e*| <= u/2 per component, |B - B*| <= 2^-17 per entry,
//    r >= r*. Then with d = c - e, d* = c* - e*,
//      B* d* - c^ = B* (d* - d) + (B* - B) d + (B d - c^)
//      |B* d* - c^| <= sqrt(3) u + sqrt(3) 2^-17 |d|_1 + sqrt(3) u < 3.47 u + 2^-16 |d|_1 <= eps
//    (B* is orthogonal: |B* v| = |v|; each row of B* - B has entries <= 2^-17, so each component
//    of (B* - B) d is at most 2^-17 |d|_1). As in 1, n . B* d* < -R s_q + eps s_q <= -r* s, so the
//    true sphere is wholly outside the plane: a sphere the C model keeps is never culled.
// 3. False positives are bounded: if the kernel keeps plane k, the exact sphere of radius r + M,
//      M = eps + ceil_u(2^-16 R) + 2 u,
//    is not outside plane k (n . c_x >= n . c^ - 2 u s >= -R s_q - 2 u s > -(R + 2^-16 R + 2 u) s).
//    So a sphere the kernel keeps but the exact test culls lies within M beyond the plane:
//    about 8 u + 2^-16 (|d|_1 + r) (|d|_1 <= sqrt(3) |d|): 7 mm for a 10 m object 100 m away,
//    2.7 m for a 1 km object 100 km away. The kernel test asserts 1 and 3 for every case (and 2
//    against the double twin) and counts the false positives.
#pragma once

#include "hls/manager/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace manager_detail {

// eps = 4 u + ceil(|d|_1 / 2^16) u (raw units u). |d_j| <= 2^32 - 1 raw, so |d|_1 < 3 2^32 and
// eps <= 4 + 3 2^16 < 2^18.
inline ManagerWidening widening(const ManagerDelta (&d)[kManagerAxes]) {
  const Int<36> l1 = abs_value(d[0].raw()) + abs_value(d[1].raw()) + abs_value(d[2].raw());  // exact
  const Int<21> up = shr<16>(l1 + Int<17>(0xFFFF));                                          // ceil(l1 / 2^16) >= 0
  return ManagerWidening::from_raw(wrap_unsigned<18>(up + Int<4>(4)));                       // < 2^18: exact
}

}  // namespace manager_detail

// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_manager_visibility_top(PORT, ARRAY, RESULT) \
  RESULT(void)                                                    \
  PORT(setup, in, ap_none, const ManagerChannelSetup&)            \
  PORT(obj, in, ap_none, const ManagerObject&)                    \
  PORT(out, out, ap_vld, ManagerVisibility&)
inline CIG_HLS_TOP(manager_visibility_top) {
  const ManagerChannel& ch = setup.channel;

  // Centre transform: exact difference and products, one floor.
  ManagerDelta d[kManagerAxes];
  for (int j = 0; j < kManagerAxes; ++j) d[j] = obj.centre[j] - ch.eye[j];
  EyeCoord c[kManagerAxes];
  for (int i = 0; i < kManagerAxes; ++i) {
    const ManagerSum sum = ch.b[i][0] * d[0] + ch.b[i][1] * d[1] + ch.b[i][2] * d[2];
    c[i] = EyeCoord(sum);  // floor to u; 26 integer bits hold the exact sum: no overflow
  }

  // The widened radius.
  const WidenedRadius radius = obj.radius + manager_detail::widening(d);

  // Plane values, exact; outside iff negative.
  const auto tz = ch.tan_half_fov * c[2];           // Fixed<56, 29>
  const auto rs = radius * setup.side_norm;         // UFixed<52, 25>
  const auto near_value = c[2] + radius - ch.near;  // Fixed<39, 28>
  const auto left_value = c[0] + tz + rs;           // Fixed<58, 31>
  const auto right_value = tz - c[0] + rs;          // Fixed<58, 31>
  const auto top_value = tz - c[1] + rs;            // Fixed<58, 31>
  const auto bottom_value = tz + c[1] + rs;         // Fixed<58, 31>
  static_assert(decltype(left_value)::width == 58 && decltype(near_value)::width == 39, "plane widths");

  UInt<kManagerPlanes> outside(0);
  outside = outside.with_bit(0, near_value.raw().is_negative());
  outside = outside.with_bit(1, left_value.raw().is_negative());
  outside = outside.with_bit(2, right_value.raw().is_negative());
  outside = outside.with_bit(3, top_value.raw().is_negative());
  outside = outside.with_bit(4, bottom_value.raw().is_negative());

  out.visible = outside == UInt<1>(0);
  out.outside = outside;
  for (int i = 0; i < kManagerAxes; ++i) out.centre_eye[i] = c[i];
  out.radius_widened = radius;
}

CIG_HLS_END_NAMESPACE
