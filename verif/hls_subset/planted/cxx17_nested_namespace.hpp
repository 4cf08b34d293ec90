// Planted violation (verif/hls_subset/README.md): a C++17 nested namespace definition; hls/ is
// C++14, what Vitis HLS and Catapult both take.
// expect: later-standard
#pragma once

#include "hls/types/bits.hpp"

namespace cig::planted_detail {  // clean: namespace cig { namespace planted_detail {
constexpr int kPlantedMask = 0xff;
}  // clean: } }

CIG_HLS_BEGIN_NAMESPACE

inline UInt<8> planted_mask_top(const UInt<16>& x) { return UInt<8>(x.value() & planted_detail::kPlantedMask); }

CIG_HLS_END_NAMESPACE
