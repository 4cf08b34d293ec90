// Helpers shared by the two halves of the segment-kernel tests (test_segment_kernels.cpp,
// test_segment_kernels_video.cpp): the sample lattice from its definition, the raw words of the
// kernels' records (read-back comparisons, digests, golden vectors).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "digest.hpp"
#include "hls/segment/records.hpp"
#include "hls/segment/video_channel.hpp"
#include "segment_test_support.hpp"

namespace cig::hls::segkernels {

using segtest::ceil_div;
using segtest::code_of;
using segtest::i128;
using segtest::raw_of;

// ---- The sample lattice, from its definition --------------------------------------------------------

// records.hpp: an N = 2^n raster has u = 4096 / N grid units per line; line L spans Y in
// [u L - 1, u L - 1 + u) and its sample rows r = 0..3 lie at Y = u L - 1 + (2 r + 1) u / 8, so row
// k = 4 L + r lies at 2Y = (u / 2) k + u / 4 - 2 half units. Columns lie at the same positions
// along X. Written here from that definition, independently of LatticeGeometry.
struct Lattice {
  int log2 = 0, n = 0, rows = 0;
  i128 u = 0;
  explicit Lattice(int lg) : log2(lg), n(1 << lg), rows(4 << lg), u(4096 >> lg) {}
  i128 offset() const { return u / 4 - 2; }
  i128 half(i128 k) const { return k * (u / 2) + offset(); }
  // The first row (column) whose position is at or after half-unit position h.
  i128 first_at_or_after(i128 h) const { return ceil_div(h - offset(), u / 2); }
};

// ---- Raw words of the kernels' records (fixed policies), for read-back and the digest --------------

template <class P>
void edge_words(const Edge<P>& e, std::vector<std::int64_t>& w) {
  w.insert(w.end(), {e.row_first, e.row_last, std::int64_t(e.x_begin.value()), std::int64_t(e.y_begin.value()),
                     std::int64_t(e.x_end.value()), std::int64_t(e.y_end.value()), std::int64_t(e.i_begin.value()),
                     std::int64_t(e.i_end.value()), code_of(e.z_begin), code_of(e.z_end), raw_of(e.dx_per_row),
                     raw_of(e.x_first)});
}
template <class P>
std::vector<std::int64_t> polygon_words(const PolygonEdges<P>& e) {
  const PolygonHeader<P>& h = e.h;
  std::vector<std::int64_t> w = {e.valid,
                                 std::int64_t(h.id.value()),
                                 std::int64_t(h.colour[0].value()),
                                 std::int64_t(h.colour[1].value()),
                                 std::int64_t(h.colour[2].value()),
                                 h.opaque,
                                 h.protect,
                                 std::int64_t(h.area_code.value()),
                                 std::int64_t(h.twice_area.value()),
                                 h.row_first,
                                 h.row_last,
                                 std::int64_t(h.segments_even.value()),
                                 std::int64_t(h.segments_odd.value()),
                                 std::int64_t(h.left_count.value()),
                                 std::int64_t(h.right_count.value())};
  for (int k = 0; k < int(h.left_count.value()); ++k) edge_words(e.left[k], w);
  for (int k = 0; k < int(h.right_count.value()); ++k) edge_words(e.right[k], w);
  return w;
}
// A segment's fields; X only at its covered rows (the others are not part of the segment).
template <class P>
void segment_words(const Segment<P>& s, std::vector<std::int64_t>& w) {
  const int rf = int(s.row_first.value()), rl = int(s.row_last.value());
  w.insert(w.end(), {std::int64_t(s.line.value()), std::int64_t(s.type.value()), rf, rl});
  for (int r = rf; r <= rl; ++r) w.insert(w.end(), {raw_of(s.xl[r]), raw_of(s.xr[r])});
  w.insert(w.end(), {raw_of(s.il), raw_of(s.ir), code_of(s.zl), code_of(s.zr), std::int64_t(s.source.value()),
                     s.is_light, s.opaque, std::int64_t(s.channel.value())});
}
inline void digest_words(kernel_test::Digest* dg, const std::vector<std::int64_t>& w) {
  if (!dg) return;
  for (std::int64_t v : w) dg->add_signed(v);
}

// The video channel's memories and tables, on the heap (the tables alone are megabytes).
template <class Q, int K>
struct VideoRig {
  std::unique_ptr<SegmentMemory<Q, K>> mem = std::make_unique<SegmentMemory<Q, K>>();
  std::unique_ptr<VideoTables<Q>> tables = std::make_unique<VideoTables<Q>>();
  std::unique_ptr<LineBuffer<Q>> line = std::make_unique<LineBuffer<Q>>();
  std::unique_ptr<PixelLine> pixels = std::make_unique<PixelLine>();
  // These tests hand-build segments that carry I and Z at their ends: the seed's interpolation
  // (eq. 3-4, `interp=seed`); the planes' mode is the engines' (test_attribute_accuracy.cpp).
  VideoRig() { tables->plane_mode = false; }
};

// Parts of SegmentKernels.Digest defined with their tests: the video half
// (test_segment_kernels_video.cpp) and the golden scene's outputs (test_segment_kernels_golden.cpp).
void digest_video_half(kernel_test::Digest& d);
void digest_golden(kernel_test::Digest& d);

}  // namespace cig::hls::segkernels
