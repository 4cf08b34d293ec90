// Planted violation (verif/hls_subset/README.md): a function pointer (the declarator is found by
// the scan, the call through it by the call graph).
// expect: function-pointer
// expect: indirect-call
#pragma once

#include "hls/types/fixed.hpp"

CIG_HLS_BEGIN_NAMESPACE

namespace planted_detail {
inline UInt<9> add(const UInt<8>& a, const UInt<8>& b) { return a + b; }
inline UInt<9> sub_abs(const UInt<8>& a, const UInt<8>& b) { return a < b ? UInt<9>(b.value() - a.value()) : UInt<9>(a.value() - b.value()); }
}  // namespace planted_detail

inline UInt<9> planted_alu_top(const UInt<8>& a, const UInt<8>& b, bool subtract) {
  UInt<9> (*op)(const UInt<8>&, const UInt<8>&) = subtract ? planted_detail::sub_abs : planted_detail::add;  // planted-only
  return op(a, b);  // clean: return subtract ? planted_detail::sub_abs(a, b) : planted_detail::add(a, b);
}

CIG_HLS_END_NAMESPACE
