// Video channel (SPEC D, seed 001): turns one raster line's segments into pixels. Segments come
// from the line's list in the segment memory, in priority order; each covers, on each of its
// sample rows, the samples with left X <= X_i < right X (left edges inclusive, right edges
// exclusive: the float reference's tie rule). A sample takes the colour of the
// first segment that covers it (visibility by priority): colour x I, I interpolated along the
// segment, then fog by Z (interpolated along the segment, looked up in the fog table). The S x S
// samples of a pixel are averaged (the anti-aliasing filter). The per-pixel polygon id is the
// polygon owning most of the pixel's samples, light points aside (as in the float reference).
//
// The line buffer keeps, per sample row, two bit masks of 64-sample words beside the samples: the
// samples owned (a colour written) and the samples settled (owned and their first polygon known,
// which no later segment changes). A segment visits only the samples of its span that it can still
// write: a word of the span at a time, masked by the screen door and the masks, and within a word
// the set bits, lowest first (a priority encoder), so a covered run costs one step per word.
#pragma once

#include "hls/segment/y_sorter.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <class P>
struct VideoTables {
  typename P::Level polygon_colour[kMaxPolygonIds][3];
  typename P::Level light_colour[kMaxPolygonIds][3];
  typename P::FogTable fog;  // indexed by the code of Z: light points, and polygons in seed mode
  // Perspective-correct mode (plane_mode): each polygon's planes of I and W = 1/Z, written from the
  // frame memory's header as the preprocessor reads the polygon, and the fog table indexed by the
  // e8m7 code of 1/Z (hls/pixel/attribute_planes.hpp).
  bool plane_mode = true;
  typename P::Planes polygon_planes[kMaxPolygonIds];
  typename P::Plane::FogTable fog_inverse;
  typename P::Level fog_colour[3];
  typename P::Level background[3];
};

constexpr int kMaskWordLog2 = 6;  // 64 samples per mask word
constexpr int kMaskWordBits = 1 << kMaskWordLog2;
constexpr int kLineMaskWords = kMaxLatticeSize / kMaskWordBits;
using MaskWord = UInt<kMaskWordBits>;

template <class P>
struct LineBuffer {
  typename P::Sample rgb[kMaxRowsPerLine][kMaxLatticeSize][3];
  bool owned[kMaxRowsPerLine][kMaxLatticeSize];
  int polygon[kMaxRowsPerLine][kMaxLatticeSize];           // first polygon covering the sample, -1 none
  MaskWord owned_mask[kMaxRowsPerLine][kLineMaskWords];    // bit i % 64 of word i / 64: owned[r][i]
  MaskWord settled_mask[kMaxRowsPerLine][kLineMaskWords];  // owned and polygon[r][i] >= 0
};

struct PixelLine {
  UInt<8> rgb[kMaxLines][3];
  int id[kMaxLines];
};

namespace detail {

// What the samples of one sample row of a segment share (plane mode), found at the row's first
// sample to colour. W = 1/Z is linear along the row and its code (or, in the twin, its fog factor)
// monotone in W, so the fog factor of every sample between the row's ends is known from theirs
// (P::same_fog); without fog (f = 0) a sample's colour is colour x I alone; with I flat along the
// row too (D_I = 0) every sample of the row takes the same colour, found once.
template <class P>
struct RowShade {
  bool known = false;  // found for this row
  bool same_fog = false, no_fog = false, same_colour = false;
  typename P::Plane::FogFactorType f;
  typename P::Sample rgb[3];
};

// Sample i of sample row r (global row `row`) for segment s, not yet coloured by an earlier
// segment (visibility by priority): its colour.
template <class P>
struct SegmentSampler {
  const Segment<P>& s;
  const LatticeGeometry& g;
  const VideoTables<P>& t;
  int src;
  bool planes;                 // I and 1/Z from the polygon's planes
  typename P::X xlt;           // where il and zl hold (seed interpolation)
  typename P::Reciprocal inv;  // 1 / span (seed interpolation)

  // Perspective-correct mode: sample (i, row) takes I and W = 1/Z from the polygon's planes,
  // exactly (F + D i + E j: in hardware the video channel steps the values along the row by D,
  // which gives the same bits), colour x I and fog by 1/Z, as the quadtree's pixel processor.
  void plane_sample(const RowShade<P>& rs, int i, int row, typename P::Sample (&rgb)[3]) const {
    using Plane = typename P::Plane;
    const typename P::Planes& pl = t.polygon_planes[src];
    const typename Plane::Param vi =
        Plane::at_sample(pl.f[kParamIntensity], pl.d[kParamIntensity], pl.e[kParamIntensity], i, row);
    const typename Plane::Intensity in = Plane::intensity(vi);
    if (rs.no_fog) {
      for (int c = 0; c < 3; ++c) rgb[c] = P::shade(t.polygon_colour[src][c], in);
      return;
    }
    typename Plane::FogFactorType f = rs.f;
    if (!rs.same_fog) {
      const typename Plane::Param vw =
          Plane::at_sample(pl.f[kParamInverseDepth], pl.d[kParamInverseDepth], pl.e[kParamInverseDepth], i, row);
      f = Plane::fog_factor(t.fog_inverse, vw, pl.w_exponent);
    }
    for (int c = 0; c < 3; ++c) rgb[c] = Plane::sample_colour(t.polygon_colour[src][c], in, f, t.fog_colour[c]);
  }

  // The row's shared fog factor and colour (plane mode), from its end samples i0 and i1.
  RowShade<P> row_shade(int row, int i0, int i1) const {
    using Plane = typename P::Plane;
    RowShade<P> rs;
    rs.known = true;
    if (!planes) return rs;
    const typename P::Planes& pl = t.polygon_planes[src];
    const int w = kParamInverseDepth;
    const typename Plane::Param w0 = Plane::at_sample(pl.f[w], pl.d[w], pl.e[w], i0, row);
    const typename Plane::Param w1 = Plane::at_sample(pl.f[w], pl.d[w], pl.e[w], i1, row);
    rs.same_fog = P::same_fog(t.fog_inverse, w0, w1, pl.w_exponent);
    if (!rs.same_fog) return rs;
    rs.f = Plane::fog_factor(t.fog_inverse, w0, pl.w_exponent);
    rs.no_fog = P::no_fog(rs.f);
    rs.same_colour = P::is_flat(pl.d[kParamIntensity]);
    if (rs.same_colour) plane_sample(rs, i0, row, rs.rgb);
    return rs;
  }

  void sample(const RowShade<P>& rs, int r, int row, int i, LineBuffer<P>& w) const {
    w.owned[r][i] = true;
    if (rs.same_colour) {
      for (int c = 0; c < 3; ++c) w.rgb[r][i][c] = rs.rgb[c];
      return;
    }
    if (planes) {
      plane_sample(rs, i, row, w.rgb[r][i]);
      return;
    }
    const typename P::Ratio along = P::ratio(typename P::X(P::column_x(g, i) - xlt), inv);
    const typename P::Intensity in = P::lerp_intensity(s.il, s.ir, along);
    const typename P::Depth z = P::lerp_depth(s.zl, s.zr, along);
    const typename P::FogFactor f = P::fog_factor(t.fog, z);
    for (int c = 0; c < 3; ++c) {
      const typename P::Level colour = s.is_light ? t.light_colour[src][c] : t.polygon_colour[src][c];
      w.rgb[r][i][c] = P::mix(P::shade(colour, in), t.fog_colour[c], f);
    }
  }
};

// Bits lo..hi (0 <= lo <= hi < 64) of a mask word.
inline MaskWord mask_bits(int lo, int hi) {
  const MaskWord all(~std::uint64_t{0});
  return (all << lo) & (all >> (kMaskWordBits - 1 - hi));
}

// Samples i0..i1 of sample row r that segment s may still write: word by word, the span's bits
// that the screen door leaves open and that no earlier segment settled (a polygon) or owned (a
// light); within a word only the set bits, lowest first. A polygon's samples there have no first
// polygon yet (a sample gets one as it settles): each takes this one; the samples that no segment
// owned yet (the owned mask) take its colour.
template <class P>
void draw_row(const SegmentSampler<P>& sm, int r, int row, int i0, int i1, LineBuffer<P>& w) {
  // Screen door: samples with (i + row) even (a word starts at an even i).
  const MaskWord door(sm.s.opaque ? ~std::uint64_t{0} : (row & 1) ? 0xAAAAAAAAAAAAAAAAull : 0x5555555555555555ull);
  RowShade<P> rs;
  const int first = i0 >> kMaskWordLog2, last = i1 >> kMaskWordLog2;
  for (int k = 0; k < kLineMaskWords; ++k) {
    const int word = first + k;
    if (word > last) break;
    const int base = word << kMaskWordLog2;
    const MaskWord span = mask_bits(word == first ? i0 - base : 0, word == last ? i1 - base : kMaskWordBits - 1);
    const MaskWord closed = sm.s.is_light ? w.owned_mask[r][word] : w.settled_mask[r][word];
    MaskWord todo = span & door & ~closed;
    MaskWord fresh = todo & ~w.owned_mask[r][word];
    w.owned_mask[r][word] = w.owned_mask[r][word] | todo;
    // A polygon's samples here take it as their first polygon; those no light owned (the common
    // case: every one) in the colouring pass below.
    const bool mark_while_colouring = !sm.s.is_light && todo.value() == fresh.value();
    if (!sm.s.is_light) {
      w.settled_mask[r][word] = w.settled_mask[r][word] | todo;
      for (int b = 0; b < kMaskWordBits; ++b) {
        if (mark_while_colouring || todo.value() == 0) break;
        w.polygon[r][base + lowest_one(todo)] = sm.src;
        todo = todo & MaskWord(todo.value() - 1);  // clears the lowest set bit
      }
    }
    if (fresh.value() == 0) continue;
    if (!rs.known) rs = sm.row_shade(row, i0, i1);
    // A row whose fog varies: the word's samples may still share theirs (the same rule, on the
    // word's first and last sample to colour, when they lie P::kWordFogSpan or more apart).
    const int lo = lowest_one(fresh), hi = leading_one(fresh);
    const RowShade<P> ws = rs.same_fog || hi - lo < P::kWordFogSpan ? rs : sm.row_shade(row, base + lo, base + hi);
    for (int b = 0; b < kMaskWordBits; ++b) {
      if (fresh.value() == 0) break;
      const int bit = lowest_one(fresh);
      fresh = fresh & MaskWord(fresh.value() - 1);
      if (mark_while_colouring) w.polygon[r][base + bit] = sm.src;
      sm.sample(ws, r, row, base + bit, w);
    }
  }
}

template <class P>
void draw_segment(const Segment<P>& s, int line, const LatticeGeometry& g, int cols, const VideoTables<P>& t,
                  LineBuffer<P>& w) {
  const int rf = int(s.row_first.value()), rl = int(s.row_last.value());
  // Where il and zl (ir and zr) hold: the left (right) X at the centre of the covered rows.
  const typename P::X xlt = P::midpoint(s.xl[rf], s.xl[rl]);
  const typename P::X xrt = P::midpoint(s.xr[rf], s.xr[rl]);
  const bool planes = t.plane_mode && !s.is_light;  // I and 1/Z from the polygon's planes
  // The seed's interpolation along the segment: one reciprocal per segment (planes need none).
  const typename P::Reciprocal inv = planes ? typename P::Reciprocal() : P::reciprocal(typename P::X(xrt - xlt));
  const SegmentSampler<P> sm{s, g, t, int(s.source.value()), planes, xlt, inv};
  for (int r = 0; r < kMaxRowsPerLine; ++r) {
    if (r >= g.side()) break;
    if (r < rf || r > rl) continue;
    int i0 = P::first_column_at_or_after(g, s.xl[r]);
    int i1 = P::first_column_at_or_after(g, s.xr[r]) - 1;  // right end exclusive
    if (i0 < 0) i0 = 0;
    if (i1 > cols - 1) i1 = cols - 1;
    if (i0 > i1) continue;
    draw_row(sm, r, g.side() * line + r, i0, i1, w);
  }
}

}  // namespace detail

// The majority owner of a pixel's samples: most samples wins; ties go to the earlier polygon; the
// background (-1) loses ties (as the float reference). The rule orders the owners by (count, id), so
// the owners can be counted in any order: each distinct owner once, with its count (a pixel's
// samples have few owners: a row's run of one owner costs one comparison a sample).
inline int majority_polygon(const int (&ids)[kMaxSamplesPerPixel], int count) {
  int owner[kMaxSamplesPerPixel], votes[kMaxSamplesPerPixel];
  owner[0] = ids[0];
  votes[0] = 0;
  int owners = 1, last = 0;  // last: the owner of the sample before
  for (int a = 0; a < kMaxSamplesPerPixel; ++a) {
    if (a >= count) break;
    if (ids[a] != owner[last]) {
      last = owners;
      for (int k = 0; k < kMaxSamplesPerPixel; ++k) {
        if (k >= owners) break;
        if (owner[k] == ids[a]) {
          last = k;
          break;
        }
      }
      if (last == owners) {
        owner[owners] = ids[a];
        votes[owners++] = 0;
      }
    }
    ++votes[last];
  }
  int best = owner[0], best_count = votes[0];
  for (int k = 1; k < kMaxSamplesPerPixel; ++k) {
    if (k >= owners) break;
    const int id = owner[k], n = votes[k];
    if (n > best_count || (n == best_count && (best == -1 ? id >= 0 : (id >= 0 && id < best)))) {
      best = id;
      best_count = n;
    }
  }
  return best;
}

namespace detail {

// Box filter and majority id of pixel px from the line buffer, for S samples a side (a
// loop nest of static bounds for each lattice): the samples summed in row order as they are read
// (an accumulator per colour component).
template <class P, int S>
void resolve_samples(int px, int side_log2, const VideoTables<P>& t, const LineBuffer<P>& w, PixelLine& out) {
  typename P::BoxAccum sum[3] = {};
  typename P::Sample background[3];
  for (int c = 0; c < 3; ++c) background[c] = P::level_sample(t.background[c]);
  int ids[kMaxSamplesPerPixel];
  bool one_owner = true;  // the common case: every sample has the first one's polygon
  for (int r = 0; r < S; ++r)
    for (int q = 0; q < S; ++q) {
      const int i = S * px + q;
      const bool owned = w.owned[r][i];
      for (int c = 0; c < 3; ++c) sum[c] = P::box_add(sum[c], owned ? w.rgb[r][i][c] : background[c]);
      ids[S * r + q] = w.polygon[r][i];
      one_owner = one_owner && w.polygon[r][i] == w.polygon[0][S * px];
    }
  for (int c = 0; c < 3; ++c) out.rgb[px][c] = P::resolve_sum(sum[c], side_log2);
  out.id[px] = one_owner ? ids[0] : majority_polygon(ids, S * S);
}

}  // namespace detail

// Box filter and majority id of pixel px from the line buffer (S x S samples, S = g.side()): one
// case per lattice up to the build's largest (kMaxSideLog2, 3 unless an HLS build sets less).
template <class P>
void resolve_pixel(int px, const LatticeGeometry& g, const VideoTables<P>& t, const LineBuffer<P>& w, PixelLine& out) {
  static_assert(kMaxSideLog2 <= 3, "resolve_pixel: a case for each lattice");
  constexpr int k2 = kMaxSamplesPerSide < 2 ? kMaxSamplesPerSide : 2;
  constexpr int k4 = kMaxSamplesPerSide < 4 ? kMaxSamplesPerSide : 4;
  switch (g.side_log2) {
    case 0:
      detail::resolve_samples<P, 1>(px, 0, t, w, out);
      break;
    case 1:
      detail::resolve_samples<P, k2>(px, 1, t, w, out);
      break;
    case 2:
      detail::resolve_samples<P, k4>(px, 2, t, w, out);
      break;
    default:
      detail::resolve_samples<P, kMaxSamplesPerSide>(px, 3, t, w, out);
      break;
  }
}

// The line buffer's S sample rows of `cols` samples, cleared (nothing owned, no polygon): a mask
// word's 64 samples at a time.
template <class P>
void clear_line_buffer(const LatticeGeometry& g, int cols, LineBuffer<P>& w) {
  for (int r = 0; r < kMaxRowsPerLine; ++r) {
    if (r >= g.side()) break;
    for (int k = 0; k < kLineMaskWords; ++k) {
      if (k << kMaskWordLog2 >= cols) break;
      w.owned_mask[r][k] = MaskWord(0);
      w.settled_mask[r][k] = MaskWord(0);
      for (int b = 0; b < kMaskWordBits; ++b) w.owned[r][(k << kMaskWordLog2) + b] = false;
      for (int b = 0; b < kMaskWordBits; ++b) w.polygon[r][(k << kMaskWordLog2) + b] = -1;
    }
  }
}

// Draws line `line`'s segments from the segment memory into the line buffer, in priority order
// (samples already owned keep their colour); returns the segments it read.
template <class P, int K>
int draw_line(int line, const LatticeGeometry& g, int cols, const SegmentMemory<P, K>& m, const VideoTables<P>& t,
              LineBuffer<P>& w) {
  const int b = line & 1;
  int p = m.head[line];
  int read = 0;
  for (int k = 0; k < K; ++k) {
    if (p == kNullPointer) break;
    detail::draw_segment(m.seg[b][p], line, g, cols, t, w);
    ++read;
    p = m.next[b][p];
  }
  return read;
}

// Renders raster line `line` of an N = 2^raster_log2 raster with S = 2^side_log2 sample rows per
// line; returns the segments it read.
template <class P, int K>
int render_line(int line, int raster_log2, const SegmentMemory<P, K>& m, const VideoTables<P>& t, LineBuffer<P>& w,
                PixelLine& out, int side_log2 = kDefaultSideLog2) {
  const LatticeGeometry g = LatticeGeometry::for_raster(raster_log2, side_log2);
  const int n = 1 << raster_log2, cols = g.rows();
  clear_line_buffer(g, cols, w);
  const int read = draw_line(line, g, cols, m, t, w);
  for (int px = 0; px < kMaxLines; ++px) {
    if (px >= n) break;
    resolve_pixel(px, g, t, w, out);
  }
  return read;
}
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_video_channel_top(PORT, ARRAY, RESULT)        \
  RESULT(int)                                                       \
  PORT(line, in, ap_none, UInt<10>)                                 \
  PORT(raster_log2, in, ap_none, UInt<4>)                           \
  PORT(m, in, ap_memory, const SegmentMemory<DefaultSegmentArith>&) \
  PORT(t, in, ap_memory, const VideoTables<DefaultSegmentArith>&)   \
  PORT(w, inout, ap_memory, LineBuffer<DefaultSegmentArith>&)       \
  PORT(out, out, ap_vld, PixelLine&)
inline CIG_HLS_TOP(video_channel_top) { return render_line(int(line.value()), int(raster_log2.value()), m, t, w, out); }

CIG_HLS_END_NAMESPACE
