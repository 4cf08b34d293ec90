// Records and formats of the scene manager's preliminary processing unit (SPEC A.1-2, seed 000):
// the channel (eye, rotation B, tan(fov/2), near), one object's bounding sphere, and the unit's
// output, the "visual" flag V[i] with the eye-space centre the preliminary sorting unit orders by.
// The derivation of every width and of the conservative widening is in README.md (this folder).
//
//   per channel and frame:  ManagerChannel --manager_channel_setup_top--> ManagerChannelSetup
//                           (adds sqrt(1 + t^2) rounded up: the side planes' normal length)
//   per object:             ManagerChannelSetup, ManagerObject --manager_visibility_top-->
//                           ManagerVisibility
//
// Formats (value = raw * 2^-F; u = 2^-11 m, the world's LSB). The host (the C model's world in
// binary64) converts INTO these formats with the rounding named in the last column, which the
// kernel's error bound assumes; the kernel itself rounds only where stated in visibility.hpp.
//
//   quantity              type                 W   I   F   range                  LSB        host rounding
//   world position c, e   Fixed<32, 21>       32  21  11   [-2^20, 2^20) m        u          nearest
//   radius r              UFixed<32, 21>      32  21  11   [0, 2^21) m            u          up
//   B entry (world->eye)  Fixed<18, 2>        18   2  16   [-2, 2)                2^-16      nearest
//   t = tan(fov/2)        UFixed<18, 2>       18   2  16   [0, 4): fov < 151.9 deg 2^-16      (*)
//   near                  UFixed<24, 13>      24  13  11   [0, 8192) m            u          (*)
//   sqrt(1 + t^2)         UFixed<19, 3>       19   3  16   [1, 4.13)              2^-16      up (setup)
//   d = c - e             Fixed<33, 22>       exact difference
//   B_ij d_j              Fixed<51, 24>       exact product (18 x 33 bits)
//   (B d)_i               Fixed<53, 26>       exact sum of three products
//   c_eye (output)        Fixed<37, 26>       (B d)_i truncated (floor) to u: the only rounding
//                                             of the transform; 26 integer bits hold every
//                                             (B d)_i, so it cannot overflow
//   widening eps          UFixed<18, 7>       4 u + ceil(2^-16 |d|_1), < 2^7 m
//   widened radius R      UFixed<33, 22>      r + eps, exact
//
// (*) t and near define the channel's pyramid: the kernel is conservative for the pyramid of the
// given t and near. A host that rounds t up and near down gets a pyramid that contains the
// designed one, so no sphere that meets the designed pyramid is culled.
//
// No intermediate can overflow (every width is the exact width of its operation, or proved in
// visibility.hpp), so the kernel has no saturation path; a B that is not a rotation (any entries in
// [-2, 2)) and radii larger than the world are handled by the same exact widths.
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kManagerPlanes = 5;  // near, left, right, top, bottom (the C model's ViewPyramid order)
constexpr int kManagerAxes = 3;    // eye axes: x right, y up, z forward

using WorldCoord = Fixed<32, 21>;     // metres, LSB u = 2^-11 m, host rounds to nearest
using WorldRadius = UFixed<32, 21>;   // metres, host rounds up
using RotationEntry = Fixed<18, 2>;   // B, world to eye, host rounds to nearest
using TanHalfFov = UFixed<18, 2>;     // t = tan(fov / 2)
using NearDistance = UFixed<24, 13>;  // metres
using SideNorm = UFixed<19, 3>;       // sqrt(1 + t^2), rounded up by manager_channel_setup_top

using ManagerDelta = Fixed<33, 22>;             // c - e, exact
using ManagerProduct = Fixed<51, 24>;           // B_ij (c - e)_j, exact
using ManagerSum = Fixed<53, 26>;               // sum over j, exact
using EyeCoord = Fixed<37, 26, Quant::kTrunc>;  // c_eye, floor to u
using ManagerWidening = UFixed<18, 7>;          // eps, units u (rounded up)
using WidenedRadius = UFixed<33, 22>;           // r + eps, exact

// One channel for one frame: the observer's eye, the rotation B (rows: the eye's x right, y up,
// z forward in world coordinates; c_eye = B (c - eye)), t = tan(fov / 2) and the near distance.
// The viewing pyramid is |x| <= t z, |y| <= t z, z >= near.
struct ManagerChannel {
  WorldCoord eye[kManagerAxes];
  RotationEntry b[kManagerAxes][kManagerAxes];  // b[i][j]: row i (eye axis), column j (world axis)
  TanHalfFov tan_half_fov;
  NearDistance near;
};

// The channel with its per-channel constant: the length of the side planes' normals (-+1, 0, t)
// and (0, -+1, t), sqrt(1 + t^2), rounded up (manager_channel_setup_top).
struct ManagerChannelSetup {
  ManagerChannel channel;
  SideNorm side_norm;
};

// One object's (or subobject's) bounding sphere in world coordinates.
struct ManagerObject {
  WorldCoord centre[kManagerAxes];
  WorldRadius radius;
};

// The unit's output for one object and channel.
struct ManagerVisibility {
  bool visible = true;                // V[i]: false only if the sphere is certainly outside
  UInt<kManagerPlanes> outside;       // bit k: certainly wholly outside plane k (near, left,
                                      // right, top, bottom); visible == (outside == 0)
  EyeCoord centre_eye[kManagerAxes];  // floor(B (c - eye)) to u, for the sorting unit
  WidenedRadius radius_widened;       // r + eps: the radius the plane tests used
};

CIG_HLS_END_NAMESPACE
