// Overload protection (SPEC D, eq. 5-6): as polygons enter the frame memory their segments are
// counted per area code and per field (bucket counts); before the preprocessor reads the frame,
// the threshold T is the largest code such that the segments of all polygons with codes 0..T fit
// each field's bank of the segment memory. Polygons with a larger code (the smallest ones) are
// skipped; protected polygons (code 0) never are. If protected polygons alone overflow a bank,
// T = 0 and the Y sorter reports the segments it cannot store.
#pragma once

#include "hls/segment/records.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kSegmentBankWords = 48 * 1024;  // per field (even / odd lines)

struct OverloadCounts {
  UInt<24> segments[2][kAreaCodes];  // [field][area code]
};

inline void overload_reset(OverloadCounts& c) {
  for (int f = 0; f < 2; ++f)
    for (int k = 0; k < kAreaCodes; ++k) c.segments[f][k] = UInt<24>(0);
}

template <class P>
void overload_count(const PolygonHeader<P>& h, OverloadCounts& c) {
  const int code = int(h.area_code.value());
  c.segments[0][code] = UInt<24>(c.segments[0][code].value() + h.segments_even.value());
  c.segments[1][code] = UInt<24>(c.segments[1][code].value() + h.segments_odd.value());
}

// Top function: the threshold for a bank capacity (segments per field).
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_overload_threshold_top(PORT, ARRAY, RESULT) \
  RESULT(int)                                                     \
  PORT(c, in, ap_none, const OverloadCounts&)                     \
  PORT(bank_capacity, in, ap_none, int)
inline CIG_HLS_TOP(overload_threshold_top) {
  UInt<29> sum[2] = {UInt<29>(0), UInt<29>(0)};
  int threshold = 0;
  for (int k = 0; k < kAreaCodes; ++k) {
    for (int f = 0; f < 2; ++f) sum[f] = UInt<29>(sum[f].value() + c.segments[f][k].value());
    const bool fits =
        sum[0].value() <= UInt<29>(bank_capacity).value() && sum[1].value() <= UInt<29>(bank_capacity).value();
    if (k > 0 && !fits) break;
    threshold = k;
  }
  return threshold;
}

CIG_HLS_END_NAMESPACE
