// Testbench case of overload_threshold_top (hls/segment/overload.hpp): the per-field segment counts
// by area code and a bank's capacity in, the largest area code whose polygons fit out (SPEC D).
#pragma once

#include "hls/segment/overload.hpp"
#include "top_case.hpp"

namespace cig {
namespace hls_tb {

template <>
struct Fields<hls::OverloadCounts> {
  template <class V, class R>
  static void visit(V& v, R& r) {
    v(r.segments, "segments");
  }
};

}  // namespace hls_tb
}  // namespace cig

CIG_TB_CALL_CASE(OverloadThresholdTopCase, overload_threshold_top)
