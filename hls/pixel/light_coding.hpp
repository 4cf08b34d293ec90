// The light point coding table (SPEC D, seed 001): which samples a formatted light point covers,
// one chord per sample row, through a ROM indexed by its diameter D (eq. 1: 0..7 grid units) and
// the row's offset from its centre (the sub-pixel position).
//
// Why it lives here and not in hls/segment: the disc is the float reference's (samples at distance
// <= D/2 from the centre), defined on the sample lattice of hls/formatter, and every raster engine
// must cover the same samples with it: the segment processor turns each chord into a segment
// (hls/segment/light_segments.hpp), the quadtree engine's light point unit into per-pixel sample
// covers (cmodel/quadtree/quadtree_frame.hpp). It depends on nothing but the formatter's records.
//
// In half units (2 x grid units, in which every sample position and a formatted centre are
// integers) a row at vertical offset dy covers the samples with |2x - 2X| <= w,
// w = floor(sqrt(D^2 - dy^2)): the table holds w for every D and dy (-1: the row misses the disc).
#pragma once

// hls-subset-helper: the light point coding table shared by the segment and quadtree engines.

#include "hls/formatter/records.hpp"

CIG_HLS_BEGIN_NAMESPACE

// Rows a light covers at most: D <= 7 units spans at most 7 units, rows are >= 1 unit apart.
constexpr int kMaxLightRows = 8;

namespace light_detail {
constexpr int isqrt_floor(int v) {
  int r = 0;
  for (int k = 0; k < 8; ++k)
    if ((r + 1) * (r + 1) <= v) ++r;
  return r;
}
}  // namespace light_detail

// The coding table (a ROM): half-chord width in half units, by diameter and row offset.
struct LightCodingTable {
  int w[kMaxLightDiameter + 1][kMaxLightRows];
  constexpr LightCodingTable() : w() {
    for (int d = 0; d <= kMaxLightDiameter; ++d)
      for (int dy = 0; dy < kMaxLightRows; ++dy) w[d][dy] = dy > d ? -1 : light_detail::isqrt_floor(d * d - dy * dy);
  }
};
constexpr LightCodingTable kLightCodingTable{};

// One covered sample row: the samples at half-unit X in [centre_half - w, centre_half + w].
struct LightChord {
  int row;          // global sample row 0..SN-1
  int centre_half;  // 2X of the light's centre
  int w;            // half-chord, half units (>= 0)
};

// The chords of a formatted light point, top to bottom; returns how many (0..kMaxLightRows).
inline int light_chords(const FormattedPrimitive& light, int raster_log2, LightChord (&out)[kMaxLightRows],
                        int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int rows = g.rows();
  const int cx2 = 2 * int(light.v[0].x.value()), cy2 = 2 * int(light.v[0].y.value());
  const int d = int(light.d.value());
  int first = g.first_sample_at_or_after_half(cy2 - d);
  if (first < 0) first = 0;
  int count = 0;
  for (int k = 0; k < kMaxLightRows; ++k) {
    const int row = first + k;
    if (row >= rows) break;
    const int dy = g.sample_half(row) - cy2;
    const int ady = dy < 0 ? -dy : dy;
    if (ady > d) break;
    out[count].row = row;
    out[count].centre_half = cx2;
    out[count].w = kLightCodingTable.w[d][ady];
    ++count;
  }
  return count;
}

// The sample columns [first, last] of a chord (the lattice's columns with 2X_i in
// [centre - w, centre + w]); last < first when the chord falls between two columns.
inline void light_chord_columns(const LightChord& c, const LatticeGeometry& g, int& first, int& last) {
  first = g.first_sample_at_or_after_half(c.centre_half - c.w);
  last = g.first_sample_at_or_after_half(c.centre_half + c.w + 1) - 1;
}

CIG_HLS_END_NAMESPACE
