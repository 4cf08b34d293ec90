// Planted violation (verif/hls_subset/README.md): a C++17 inline variable; hls/ is C++14, what
// Vitis HLS and Catapult both take.
// expect: later-standard
#pragma once

#include "hls/types/bits.hpp"

CIG_HLS_BEGIN_NAMESPACE

inline constexpr int kPlantedShift = 3;  // clean: constexpr int kPlantedShift = 3;

inline UInt<16> planted_shift_top(const UInt<16>& x) { return UInt<16>(x.value() >> kPlantedShift); }

CIG_HLS_END_NAMESPACE
