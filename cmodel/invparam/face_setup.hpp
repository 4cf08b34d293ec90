// Stage F's host setup (seed 002, Fig. 1: "tau_00, Den_00, Num, k_x, k_y, k_x', k_y' for each face
// of each object"): from a ScreenFrame's eye-space convex polyhedra and the sample lattice, each
// face's FaceSetup<W> (hls/invparam/records.hpp) for the bit-accurate kernel
// (hls/invparam/visibility.hpp), and the same values unquantized (double) for its twin.
//
// Geometry. Face (n, d) of an EyePolyhedron, outward n, interior n.r < d, eye s = 0. The seed's
// normals point inward: m = -n, D = -d, so Num = D - m.s = -d and Den = m.c = -(n.c). The ray of
// sample column i, row j of an L x L lattice (L = raster x S) is c = (Xs_i T, Ys_j T, 1) with
// T = tan_half_fov and Xs_k = Ys_k = (2k + 1)/L - 1: the lattice's sample centres (the formatter's
// H_k = 2^(13 - n - t) k + 2^(12 - n - t) - 2 half units, X = H_k / 2, Xs = (X - 2047) / 2048,
// hls/formatter/sample_lattice.hpp), Xs left to right, Ys top to bottom. Then
//     Den(0, -1) = -(nx T (1/L - 1) + ny T (-1/L - 1) + nz),  k_x = -nx T 2/L,  k_y = -ny T 2/L
//     az = 1:  start = Den(0, -1)/Num, step_x = k_x/Num, step_y = k_y/Num  (tau = Den/Num)
//     az = 0:  start = Den(0, -1),     step_x = k_x,     step_y = k_y
//     az = (Num != 0 and Den_max < kValueLimit |Num|), Den_max the largest |Den| at the lattice's
//          corners (Den is linear in i, j: the largest on the lattice)
//     as = (Num < 0) = (d > 0): the eye is inside the face's half-space
// So every az = 1 value stays in the word on the whole lattice (|tau| < kValueLimit = 2^23 - 1, the
// 24 integer bits' range, word.hpp) and the adds never wrap. A face whose plane passes nearer to
// the eye than Den_max / kValueLimit goes down the seed's Num = 0 path (issue 29): it is decided as
// if its plane passed through the eye, a parallel shift of the plane by |d| < Den_max 2^-23, where
// Den_max <= |n| |c| <= 1.01 sqrt(2 T^2 + 1): below 0.7 um for a field of view up to 151 degrees
// (T <= 4), below 2 um at the scenes' largest, 170. The image is the exact image of the scene so
// moved (InvparamSetup::through_eye counts these faces).
//
// Word format (word.hpp): word_bits(W) = W + 16 bits two's complement, 24 integer bits with the
// sign, F = W - 8 fractional: value = code 2^-F, |value| < 2^23. Each value is computed in
// binary128 (__float128, 113-bit significand), then rounded to the nearest code (ties away from
// zero). Binary128's error: c's components are exact (a double times a dyadic of <= 14 bits, or
// rounded once for a lattice size that is not a power of two), n.c takes <= 6 roundings, each
// <= 2^-113 S with S = |nx| |cx| + |ny| |cy| + |nz| <= 2 Den_max (the corners' signs), so
// |error(Den)| <= 12 2^-113 Den_max; tau = Den/Num then errs by <= 12 2^-113 Den_max / |Num|
// < 12 2^-113 kValueLimit < 2^-86.4, plus the division's own 2^-113 |tau| < 2^-90; the steps
// k/Num likewise less. So for W <= 80 (F <= 72) each code is within (1/2 + 2^-14) LSB of the
// exact value.
//
// Error bound of the kernel's incremental value (the adds are exact: nothing leaves the range):
//     |value_ij - exact_ij| <= (i + j + 2) (1/2 + 2^-14) LSB       (start, i step_x, (j + 1) step_y)
// invparam_error_bound_lsb() returns it.
//
// The near plane (issue 29): RGnear = 1/near rounded to the nearest code (tau_near); an object is
// drawn where its last entry lies beyond it (hls/invparam/visibility.hpp). Without a near plane
// (near <= 0) RGnear is the largest code, the seed's MAX.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "frame/screen_frame.hpp"
#include "hls/invparam/visibility.hpp"

namespace cig {

// The sample lattice of stage F: raster N pixels, S = 2^side_log2 samples a side.
struct InvparamLattice {
  int raster = 512;
  int side_log2 = 2;
  int size() const { return raster << side_log2; }  // L: samples per row and per column
};

// Xs (or Ys) of sample k of an L-sample lattice: (2k + 1)/L - 1 (exact in double).
double invparam_sample_screen(int k, int size);

// Where a face of the setup list comes from: its polyhedron and its face index there.
struct InvparamFaceOrigin {
  int polyhedron = 0, face = 0;
};

// One face in binary128 (exact to 2^-100) and in double, the seed's signs.
struct InvparamFaceValues {
  bool az = true, as = false;
  bool through_eye = false;  // d != 0, but tau would leave the word: decided as d = 0 (az = 0)
  __float128 start = 0, step_x = 0, step_y = 0;
  __float128 corner_max = 0;  // max |value| over the lattice's corners (column 0 / L-1, row -1 / L-1)
};
InvparamFaceValues invparam_face_values(const EyeFace& face, double tan_half_fov, int size);

// The face list in the kernel's order: every polyhedron, every face. Throws InputError beyond the
// kernel's capacities (kMaxObjects, kMaxFacesPerObject, kMaxFaces).
std::vector<InvparamFaceOrigin> invparam_face_list(const ScreenFrame& frame);

// A value rounded to the nearest code of F fractional bits and saturated to W bits, as the two
// limbs of its 128-bit two's complement; *saturated tells whether it was clamped.
void invparam_quantize(__float128 value, int w, int frac_bits, std::uint64_t& hi, std::uint64_t& lo, bool* saturated);

// The kernel's error bound in LSB at sample (i, j) (the comment above); and RGeps, the az = 0 faces'
// tolerance: -(L + 1) LSB, beyond the largest error of an L x L lattice. kValueLimit: the largest
// |value| an az = 1 face may reach on the lattice (a margin of 1 below 2^23 for the rounding).
double invparam_error_bound_lsb(int i, int j);
inline std::int64_t invparam_eps_code(int size) { return -(static_cast<std::int64_t>(size) + 1); }
constexpr double kValueLimit = double(1 << (hls::kWordIntBits - 1)) - 1;  // 2^23 - 1

template <int W>
struct InvparamSetup {
  std::unique_ptr<hls::InvparamFaces<W>> faces = std::make_unique<hls::InvparamFaces<W>>();
  std::vector<InvparamFaceOrigin> origin;  // code c (the FaceSetup's colour) is face c of this list
  hls::Word<W> eps;                        // RGeps
  hls::Word<W> tau_near;                   // RGnear
  int size = 0;                            // L
  int saturated = 0;                       // setup values clamped to the word range (never, by the rule above)
  int out_of_range = 0;                    // faces whose value leaves the word on the lattice (never)
  int through_eye = 0;                     // faces decided as through the eye (InvparamFaceValues)
};

// A value rounded to the nearest code of word W (saturated; *saturated tells whether it was).
template <int W>
hls::Word<W> invparam_word(__float128 value, bool* saturated) {
  std::uint64_t hi = 0, lo = 0;
  invparam_quantize(value, hls::word_bits(W), hls::word_frac_bits(W), hi, lo, saturated);
  return hls::Word<W>::from_limbs(hi, lo);
}

// The FaceSetup<W> of every face of the frame; the id code of a face is its index in the list.
template <int W>
InvparamSetup<W> invparam_setup(const ScreenFrame& frame, const InvparamLattice& lattice) {
  InvparamSetup<W> s;
  s.size = lattice.size();
  s.origin = invparam_face_list(frame);
  s.eps = hls::Word<W>(invparam_eps_code(s.size));
  bool sat = false;
  s.tau_near = frame.near > 0 ? invparam_word<W>(__float128(1) / __float128(frame.near), &sat) : hls::word_max<W>();
  s.faces->objects = static_cast<int>(frame.polyhedra.size());
  for (std::size_t o = 0; o < frame.polyhedra.size(); ++o)
    s.faces->object_faces[o] = static_cast<int>(frame.polyhedra[o].faces.size());
  for (std::size_t f = 0; f < s.origin.size(); ++f) {
    const EyeFace& face = frame.polyhedra[s.origin[f].polyhedron].faces[s.origin[f].face];
    const InvparamFaceValues v = invparam_face_values(face, frame.tan_half_fov, s.size);
    hls::FaceSetup<W>& out = s.faces->face[f];
    out.az = v.az;
    out.as = v.as;
    out.colour = hls::UInt<24>(f);
    const __float128* values[3] = {&v.start, &v.step_x, &v.step_y};
    hls::Word<W>* words[3] = {&out.start, &out.step_x, &out.step_y};
    for (int k = 0; k < 3; ++k) {
      *words[k] = invparam_word<W>(*values[k], &sat);
      s.saturated += sat ? 1 : 0;
    }
    s.out_of_range += v.corner_max >= kValueLimit ? 1 : 0;
    s.through_eye += v.through_eye ? 1 : 0;
  }
  return s;
}

// The twin's setup: the same values in double.
struct InvparamFaceDouble {
  bool az = true, as = false;
  double start = 0, step_x = 0, step_y = 0;
  std::uint32_t code = 0;
};
struct InvparamSetupDouble {
  std::vector<InvparamFaceDouble> faces;  // the kernel's order
  std::vector<int> object_faces;
  double eps = 0;       // RGeps
  double tau_near = 0;  // RGnear: 1/near, or infinity without a near plane
  int size = 0;
};
InvparamSetupDouble invparam_setup_double(const ScreenFrame& frame, const InvparamLattice& lattice, double eps);

}  // namespace cig
