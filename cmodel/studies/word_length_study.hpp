// Stage F's word-length study (issue 15, deliverable 4): seed 002's claims that the inverse
// parameter needs "at least 57 bits for the depth within 1 mm and the right visible plane to 10 km,
// at least 64 bits to 100 km", and that "a direct Z-buffer makes visibility errors that 1/t (and an
// inverse Z-buffer) avoids", measured against the binary128 ground truth (exact_visibility.hpp).
//
// The views (word_length_view): the seed's precision case built directly as a ScreenFrame: a wall
// (a box 120 m wide, 40 m high, 8 m deep, polyhedron 0) and a panel (a box 40 m x 16 m x 0.1 m,
// polyhedron 1) whose front face lies 1 mm in front of the wall's face (its back sunk in the wall),
// the wall's face centred at eye depth R, the pair turned by a random yaw and pitch (uniform in
// +-3 degrees) about that centre and moved by a random fraction of a sample in X and Y; the field
// of view is 100 m wide at R (tan_half_fov = 50/R), so the panel covers 40 % of the lattice's
// width, the wall spans it, and the background shows above and below. Seeded (a SplitMix64 of the
// seed and the view number: the same poses at every range), so every run gives the same views.
//
// Methods, each on an L x L lattice of samples (the engine's ray c = (Xs T, Ys T, 1), t = Z):
//   a  invparam   the bit-accurate kernel (hls/invparam/visibility.hpp) at W bits, depth = 1/tau;
//                 the wall is object 0, so a tie goes to the wall (the seed's order, the worse one)
//   b  z-buffer   a direct Z-buffer: each face drawn as its polygon split into a fan of triangles,
//                 Z of a triangle interpolated LINEARLY in screen space from its vertices' Z (the
//                 plane through the three projected vertices), W-bit fixed point with kZIntBits
//                 integer bits (sign included), start and steps rounded to nearest, then one add
//                 per sample (start + i step_x + (j + 1) step_y, exact on integers: what the
//                 incremental adds give); nearest = the smallest Z among the faces covering the sample
//   c  inverse-z  an inverse Z-buffer: 1/Z is affine in screen space, so each face's tau is the
//                 kernel's (face_setup.hpp: start, steps rounded to the kernel's W - 8 fractional
//                 bits, 8 integer bits: these views' values stay below 128, so the kernel's guard
//                 bits would change nothing) added incrementally; nearest = the largest 1/Z
//   d  exact-z    Z of each covering face computed exactly per sample (a divider), then rounded to
//                 W bits with kZIntBits integer bits: the quantization alone, no interpolation
// b, c and d take each face's exact coverage (the ray enters the face inside every other plane of
// its polyhedron, in binary128), so only depth decides; a tie goes to the first face of the list.
//
// Per range, method and W: samples whose visible face differs from the truth's, samples whose
// depth differs from the truth's by more than 1 mm (both hit), and the largest depth difference.
// A sample within the word's precision of an edge of one solid (in these views, ~1e-4 of a sample
// spacing at 60 bits) may show the solid's other face at the same depth: the kernel decides between
// two entry faces by their tau (Fig. 1), so it picks either there; such a sample, another face of
// the truth's solid with the depth within 1 mm, is counted apart as an edge tie, not as a wrong face
// (the seed's "right visible plane" is the panel against the wall, 1 mm behind it).
// Samples the truth calls uncertain (within binary128's margin of an edge) are left out and counted.
//
// The bound for method a. The kernel's tau at sample (i, j) is within (i + j + 2)(1/2 + 2^-14) LSB
// of the exact tau (face_setup.hpp), LSB = 2^-(W - 8), so within L (1 + 2^-13) LSB on an L x L
// lattice (i + j + 2 <= 2L). A depth error is t^2 times the tau error (dt = -dtau / tau^2), so
// the depth is within 1 mm when L R^2 2^-(W-8) <= 1 mm. The right plane: the panel's and the wall's
// tau differ by 1 mm / R^2 (1/(R - 1 mm) - 1/R), and each of the two can be off by L LSB in
// opposite directions, so 2 L R^2 2^-(W-8) < 1 mm suffices for both:
//     W >= 8 + log2(2 L R^2 / 1 mm)                                   (word_length_bound_bits)
// L = 256: 54 bits at 10 km, 61 at 100 km; L = 2048 (512 lines at 16 samples per pixel): 57 and
// 64, the seed's figures. The errors of the steps add up linearly (not as a random walk), so the
// measured need is within a bit or two below the bound.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/progress.hpp"
#include "frame/screen_frame.hpp"

namespace cig {

enum class DepthMethod { kInverseParameter, kZBuffer, kInverseZBuffer, kExactZ };
constexpr DepthMethod kDepthMethods[] = {DepthMethod::kInverseParameter, DepthMethod::kZBuffer,
                                         DepthMethod::kInverseZBuffer, DepthMethod::kExactZ};
const char* depth_method_name(DepthMethod m);    // invparam, z-buffer, inverse-z, exact-z
const char* depth_method_letter(DepthMethod m);  // a, b, c, d

// The Z-buffer's word (methods b and d): kZIntBits integer bits with the sign, |Z| < 2^17 m =
// 131 km (ranges up to kMaxStudyRange, the views' depth margin included).
constexpr int kZIntBits = 18;
constexpr double kMinStudyRange = 100, kMaxStudyRange = 120000;
constexpr double kDepthTolerance = 1e-3;  // 1 mm

struct WordLengthOptions {
  std::vector<double> ranges{10000, 100000};  // R, metres
  int min_bits = 40, max_bits = 72;           // W, inclusive
  int views = 16;                             // per range
  int lattice = 256;                          // L: samples a side
  std::uint64_t seed = 2;
};

struct WordLengthCell {
  int bits = 0;
  long wrong_faces = 0;   // samples whose visible face is not the truth's (edge ties aside)
  long edge_ties = 0;     // another face of the truth's solid, the depth within 1 mm: the sample
                          // lies on the solid's edge within the word's precision
  long depth_errors = 0;  // samples (both hit) whose depth is off by more than 1 mm
  long in_error = 0;      // samples with either
  double max_depth_error = 0;
  bool clean() const { return wrong_faces == 0 && depth_errors == 0; }
};

struct WordLengthRow {
  double range = 0;
  DepthMethod method = DepthMethod::kInverseParameter;
  std::vector<WordLengthCell> cells;  // min_bits .. max_bits
  // The smallest W from which every measured W up to max_bits is clean; -1: none.
  int smallest_bits() const;
};

struct WordLengthStudy {
  WordLengthOptions options;
  std::vector<WordLengthRow> rows;  // range by range, method a, b, c, d
  long samples = 0;                 // per range: views x L x L
  long uncertain = 0;               // samples left out (all ranges)
};

// View `view` of range R (the comment above).
ScreenFrame word_length_view(double range, int lattice, std::uint64_t seed, int view);
// W >= 8 + log2(2 L R^2 / 1 mm), rounded up.
int word_length_bound_bits(double range, int lattice);
// Checks the options (InputError naming the option).
void check_word_length_options(const WordLengthOptions& o);
// `progress` (optional) hears of every view done: ranges x views steps.
WordLengthStudy run_word_length_study(const WordLengthOptions& o, Progress* progress = nullptr);

}  // namespace cig
