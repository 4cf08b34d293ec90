// The one fog-table fill of the fixed engines (host side, per frame). A fog table maps an e8m7 code
// to the fog factor f = clamp((Z - start) / (end - start), 0, 1) (SPEC D eq. 5), stored as
// UFixed<9, 1> rounded to nearest (raw = round(256 f), 0..256). The segment processor indexes it by
// the code of Z, the quadtree pixel processor by the code of w = 1/Z: `code_is_inverse_depth`.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "formatter/formatter_twin.hpp"
#include "hls/types/fixed.hpp"
#include "hls/types/zfloat.hpp"
#include "scene/scene.hpp"

namespace cig {

template <class Table>
void fill_fog_table(Table& table, const Fog& fog, bool code_is_inverse_depth) {
  for (int code = 0; code < (1 << 15); ++code) {  // every e8m7 code (UInt<15>)
    hls::ZFloat c;
    c.bits = hls::UInt<15>(code);
    const double z = code_is_inverse_depth ? 1.0 / zfloat_to_double(c) : zfloat_to_double(c);
    const double f = std::clamp((z - fog.start) / (fog.end - fog.start), 0.0, 1.0);
    table.f[code] = typename std::remove_reference_t<decltype(table.f[0])>(
        hls::UFixed<9, 1>::from_raw_value(std::uint64_t(std::lround(f * 256))));
  }
}

}  // namespace cig
