// Synthesis top of the inverse-parameter visibility of one column (W = 64; see
// syn/formatter_top.cpp for why it is at global scope).
#include "hls/invparam/visibility.hpp"

void invparam_column_top(const cig::hls::InvparamFaces<cig::hls::kDefaultWordBits>& faces,
                         const cig::hls::InvparamColumn<cig::hls::kDefaultWordBits>& column, int rows,
                         const cig::hls::Word<cig::hls::kDefaultWordBits>& eps,
                         const cig::hls::Word<cig::hls::kDefaultWordBits>& tau_near,
                         cig::hls::InvparamSample<cig::hls::kDefaultWordBits> out[cig::hls::kMaxSamplesPerColumn]) {
  cig::hls::invparam_column_top(faces, column, rows, eps, tau_near, out);
}
