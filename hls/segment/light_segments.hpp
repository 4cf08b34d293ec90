// Light points to segments (SPEC D, seed 001): a light point becomes one segment per sample row
// it covers, from the chords of the coding table (hls/pixel/light_coding.hpp, shared with the
// quadtree engine). A chord at half-unit centre 2X and half-width w becomes the segment
// [X - w/2, X + (w + 1)/2) in grid units, exclusive at the right like every segment.
#pragma once

#include "hls/pixel/light_coding.hpp"
#include "hls/segment/segment_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Segments a light yields at most: one per chord.
constexpr int kMaxLightSegments = kMaxLightRows;

// The fixed-point light path; the double twin (cmodel) uses the exact chord instead of the table.
template <class P>
int generate_light_segments(const FormattedPrimitive& light, int raster_log2, UInt<3> channel,
                            Segment<P> (&out)[kMaxLightSegments], int side_log2 = kDefaultSideLog2) {
  LightChord chords[kMaxLightRows];
  const int count = light_chords(light, raster_log2, chords, side_log2);
  const int within = (1 << side_log2) - 1;  // row within its line
  for (int k = 0; k < kMaxLightRows; ++k) {
    if (k >= count) break;
    const int row = chords[k].row, cx2 = chords[k].centre_half, w = chords[k].w;
    Segment<P>& s = out[k];
    s.line = UInt<10>(row >> side_log2);
    s.type = UInt<3>(kSegWhole);
    s.row_first = UInt<3>(row & within);
    s.row_last = s.row_first;
    // [X - w/2, X + (w + 1)/2): exact in any X format with a fractional bit.
    const typename P::X xl(Fixed<15, 14>::from_raw(Int<15>(cx2 - w)));
    const typename P::X xr(Fixed<15, 14>::from_raw(Int<15>(cx2 + w + 1)));
    s.xl[row & within] = xl;
    s.xr[row & within] = xr;
    s.il = typename P::Intensity(light.v[0].i);
    s.ir = s.il;
    s.zl = light.v[0].z;
    s.zr = light.v[0].z;
    s.source = light.id;
    s.is_light = true;
    s.opaque = true;
    s.channel = channel;
  }
  return count;
}

// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_light_segments_top(PORT, ARRAY, RESULT) \
  RESULT(int)                                                 \
  PORT(light, in, ap_none, const FormattedPrimitive&)         \
  PORT(raster_log2, in, ap_none, UInt<4>)                     \
  PORT(channel, in, ap_none, UInt<3>)                         \
  ARRAY(out, out, ap_vld, Segment<DefaultSegmentArith>, kMaxLightSegments)
inline CIG_HLS_TOP(light_segments_top) {
  return generate_light_segments<DefaultSegmentArith>(light, int(raster_log2.value()), channel, out);
}

CIG_HLS_END_NAMESPACE
