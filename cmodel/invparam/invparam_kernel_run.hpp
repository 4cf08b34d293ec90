// Runs the bit-accurate kernel (hls/invparam/visibility.hpp) over a whole lattice as the host
// would: column 0 from the faces' start values, then one W-bit add of step_x per face per column,
// each column through invparam_column (the chain of PPs).
#pragma once

#include <memory>
#include <vector>

#include "hls/invparam/visibility.hpp"
#include "invparam/face_setup.hpp"

namespace cig {

// Every sample of the L x L lattice, row-major: result[j L + i] is column i, row j.
template <int W>
std::vector<hls::InvparamSample<W>> invparam_run_kernel(const InvparamSetup<W>& setup) {
  const int l = setup.size;
  std::vector<hls::InvparamSample<W>> result(static_cast<std::size_t>(l) * l);
  auto column = std::make_unique<hls::InvparamColumn<W>>();
  auto out = std::make_unique<hls::InvparamSample<W>[]>(hls::kMaxSamplesPerColumn);
  hls::invparam_first_column(*setup.faces, *column);
  for (int i = 0; i < l; ++i) {
    if (i > 0) hls::invparam_next_column(*setup.faces, *column);
    hls::invparam_column(*setup.faces, *column, l, setup.eps, setup.tau_near, out.get());
    for (int j = 0; j < l; ++j) result[static_cast<std::size_t>(j) * l + i] = out[j];
  }
  return result;
}

}  // namespace cig
