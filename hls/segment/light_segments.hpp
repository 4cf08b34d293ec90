// Light points to segments (SPEC D, seed 001): a light point becomes one segment per sample row
// it covers, through a coding table indexed by its diameter D (eq. 1: 0..7 grid units) and the
// row's offset from its centre (the sub-pixel position).
//
// The disc is the float reference's: samples at distance <= D/2 from the centre. In half units
// (2 x grid units, in which every sample position and a formatted centre are integers) a row at
// vertical offset dy covers the samples with |2x - 2X| <= w, w = floor(sqrt(D^2 - dy^2)): the
// table holds w for every D and dy (-1: the row misses the disc). The segment spans
// [X - w/2, X + (w + 1)/2) in grid units, exclusive at the right like every segment.
#pragma once

#include "hls/segment/segment_arith.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Rows a light covers at most: D <= 7 units spans at most 7 units, rows are >= 1 unit apart.
constexpr int kMaxLightSegments = 8;

namespace detail {
constexpr int isqrt_floor(int v) {
  int r = 0;
  for (int k = 0; k < 8; ++k)
    if ((r + 1) * (r + 1) <= v) ++r;
  return r;
}
}  // namespace detail

// The coding table (a ROM): half-chord width in half units, by diameter and row offset.
struct LightCodingTable {
  int w[8][8];
  constexpr LightCodingTable() : w() {
    for (int d = 0; d < 8; ++d)
      for (int dy = 0; dy < 8; ++dy) w[d][dy] = dy > d ? -1 : detail::isqrt_floor(d * d - dy * dy);
  }
};
constexpr LightCodingTable kLightCodingTable{};

// The fixed-point light path; the double twin (cmodel) uses the exact chord instead of the table.
template <class P>
int generate_light_segments(const FormattedPrimitive& light, int raster_log2, UInt<3> channel,
                                              Segment<P> (&out)[kMaxLightSegments]) {
  const RowGeometry g = RowGeometry::for_raster(raster_log2);
  const int rows = kRowsPerLine << raster_log2;
  const int cx2 = 2 * int(light.v[0].x.value()), cy2 = 2 * int(light.v[0].y.value());
  const int d = int(light.d.value());
  int first = g.first_row_at_or_after_half(cy2 - d);
  if (first < 0) first = 0;
  int count = 0;
  for (int k = 0; k < kMaxLightSegments; ++k) {
    const int row = first + k;
    if (row >= rows) break;
    const int dy = g.row_half(row) - cy2;
    const int ady = dy < 0 ? -dy : dy;
    if (ady > d) break;
    const int w = kLightCodingTable.w[d][ady];
    Segment<P>& s = out[count++];
    s.line = UInt<10>(row >> 2);
    s.type = UInt<3>(kSegWhole);
    s.row_first = UInt<2>(row & 3);
    s.row_last = s.row_first;
    // [X - w/2, X + (w + 1)/2): exact in any X format with a fractional bit.
    const typename P::X xl(Fixed<15, 14>::from_raw(Int<15>(cx2 - w)));
    const typename P::X xr(Fixed<15, 14>::from_raw(Int<15>(cx2 + w + 1)));
    s.xl[row & 3] = xl;
    s.xr[row & 3] = xr;
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

inline int light_segments_top(const FormattedPrimitive& light, UInt<4> raster_log2, UInt<3> channel,
                              Segment<DefaultSegmentArith> (&out)[kMaxLightSegments]) {
  return generate_light_segments<DefaultSegmentArith>(light, int(raster_log2.value()), channel, out);
}

CIG_HLS_END_NAMESPACE
