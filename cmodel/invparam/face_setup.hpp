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
//     az = (Num != 0):  start = Den(0, -1)/Num, step_x = k_x/Num, step_y = k_y/Num  (tau = Den/Num)
//     az = 0:           start = Den(0, -1),     step_x = k_x,     step_y = k_y
//     as = (Num < 0) = (d > 0): the eye is inside the face's half-space
//
// Word format (word.hpp): W bits two's complement, kWordIntBits = 8 integer bits with the sign,
// F = W - 8 fractional: value = code 2^-F, |value| < 128. Each value is computed in binary128
// (__float128, 113-bit significand: products of two doubles are exact, every further operation
// rounds with relative error <= 2^-113, at most 8 of them), then rounded to the nearest code
// (ties away from zero) and saturated. For |n| <= 1.01, T <= 4, |d| >= 1/64 the binary128 error is
// below 2^-100, so for W <= 80 each code is within (1/2 + 2^-28) LSB of the exact value.
//
// Error bound of the kernel's incremental value (the W-bit adds are exact while nothing leaves the
// range, which in_range below checks at the lattice's corners, the value being linear in i, j):
//     |value_ij - exact_ij| <= (i + j + 2) (1/2 + 2^-28) LSB       (start, i step_x, (j + 1) step_y)
// invparam_error_bound() returns it.
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
// tolerance: -(L + 1) LSB, beyond the largest error of an L x L lattice.
double invparam_error_bound_lsb(int i, int j);
inline std::int64_t invparam_eps_code(int size) { return -(static_cast<std::int64_t>(size) + 1); }

template <int W>
struct InvparamSetup {
  std::unique_ptr<hls::InvparamFaces<W>> faces = std::make_unique<hls::InvparamFaces<W>>();
  std::vector<InvparamFaceOrigin> origin;  // code c (the FaceSetup's colour) is face c of this list
  hls::Word<W> eps;                        // RGeps
  int size = 0;                            // L
  int saturated = 0;                       // setup values clamped to the word range
  int out_of_range = 0;                    // faces whose value leaves |value| < 128 on the lattice
};

// The FaceSetup<W> of every face of the frame; the id code of a face is its index in the list.
template <int W>
InvparamSetup<W> invparam_setup(const ScreenFrame& frame, const InvparamLattice& lattice) {
  constexpr int kFrac = W - hls::kWordIntBits;
  InvparamSetup<W> s;
  s.size = lattice.size();
  s.origin = invparam_face_list(frame);
  s.eps = hls::Word<W>(invparam_eps_code(s.size));
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
    bool sat = false;
    std::uint64_t hi = 0, lo = 0;
    const __float128* values[3] = {&v.start, &v.step_x, &v.step_y};
    hls::Word<W>* words[3] = {&out.start, &out.step_x, &out.step_y};
    for (int k = 0; k < 3; ++k) {
      invparam_quantize(*values[k], W, kFrac, hi, lo, &sat);
      *words[k] = hls::Word<W>::from_limbs(hi, lo);
      s.saturated += sat ? 1 : 0;
    }
    if (v.corner_max >= 127) ++s.out_of_range;  // a margin of 1 below 128 for the rounding
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
  double eps = 0;  // RGeps
  int size = 0;
};
InvparamSetupDouble invparam_setup_double(const ScreenFrame& frame, const InvparamLattice& lattice, double eps);

}  // namespace cig
