// The double twin of the inverse-parameter kernel (hls/invparam/visibility.hpp): the same
// algorithm (seed 002 Fig. 1 as the PP computes it: the same per-face rules, the same increments,
// step_x once per column and step_y once per row) on the unquantized setup
// (invparam_setup_double, face_setup.hpp) in double.
//
// Error of its incremental value at sample (i, j), |value| <= V on the lattice (V = max(128, the
// faces' largest corner_max, face_setup.hpp)): the setup's few roundings (<= 8 x 2^-53 V) plus one
// rounding per add, i + j + 1 adds of at most 2^-53 V each: invparam_double_error_bound(i, j, V) =
// (i + j + 9) 2^-53 V, stated loosely (at V = 128 about the W = 52 kernel's bound: a 64-bit kernel
// is 2^12 times more precise than this twin; a face plane 1 mm from the eye makes V ~ 1000).
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

inline double invparam_double_error_bound(int i, int j, double value_max = 128) {
  return (i + j + 9) * 0x1p-53 * (value_max > 128 ? value_max : 128);
}

}  // namespace cig
