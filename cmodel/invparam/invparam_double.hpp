// The double twin of the inverse-parameter kernel (hls/invparam/visibility.hpp): the same
// algorithm (seed 002 Fig. 1 as the PP computes it: the same per-face rules, the same increments,
// step_x once per column and step_y once per row) on the unquantized setup
// (invparam_setup_double, face_setup.hpp) in double.
//
// Error of its incremental value at sample (i, j), |value| < 128 on the lattice: the setup's few
// roundings (<= 8 x 2^-53 x 128 = 2^-43) plus one rounding per add, i + j + 1 adds of at most
// 2^-53 x 128 = 2^-46 each: invparam_double_error_bound(i, j) = (i + j + 9) 2^-46, stated loosely
// (about the W = 52 kernel's bound: a 64-bit kernel is 2^12 times more precise than this twin).
#pragma once

#include <cstdint>
#include <vector>

#include "invparam/face_setup.hpp"

namespace cig {

struct InvparamSampleDouble {
  bool hit = false;
  std::uint32_t code = 0;  // the visible face's index in the setup list
  double tau = 0;          // its tau = 1/t (0 when no hit)
};

// Every sample of the L x L lattice, row-major: result[j L + i] is column i, row j.
std::vector<InvparamSampleDouble> invparam_double(const InvparamSetupDouble& setup);

inline double invparam_double_error_bound(int i, int j) { return (i + j + 9) * 0x1p-46; }

}  // namespace cig
