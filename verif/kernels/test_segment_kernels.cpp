// The segment processor's front half (SPEC D, seed 001): the edge generator
// (hls/segment/edge_generator.hpp), the frame memory (frame_memory.hpp) and the segment generator
// (segment_generator.hpp), against exact integer and 128-bit rational references built here from
// the polygon's vertices alone, and against each kernel's double twin run on the same integers
// (segtest::twin_input). The key property: in the default (fine) format the samples a polygon's
// segments cover are EXACTLY those of segtest::ExactCoverage, and a random tiling of the screen
// covers every sample once. Every bound is derived beside its assertion, in LSB of the formats.
// The video half (Y sorter, lights through the video channel, video channel) is in
// test_segment_kernels_video.cpp, the golden vectors in test_segment_kernels_golden.cpp;
// SegmentKernels.Digest (below) digests all three.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/segment/edge_generator.hpp"
#include "hls/segment/frame_memory.hpp"
#include "hls/segment/segment_generator.hpp"
#include "segment_test_support.hpp"
#include "test_segment_kernels.hpp"

namespace cig::hls {

namespace {

using namespace segtest;
using namespace segkernels;
using kernel_test::Digest;
using Fine = SegmentFormatFine;
using Medium = SegmentFormatMedium;
using Coarse = SegmentFormatCoarse;

#ifdef CIG_HLS_SYSTEMC
constexpr int kScale = 2;  // random-sample counts (the SystemC types are slower)
#else
constexpr int kScale = 4;
#endif
// The random counts: kScale in the tests, 1 in the digest (SegmentKernels.Digest), so that the
// native and the SystemC-typed builds digest the same values (ctest kernel_bits_identical) and the
// digest stays a fraction of the tests' time.

// ---- The reference edge generator ------------------------------------------------------------------

struct RefEdge {
  int first = 0, last = -1;            // sample rows with Y in [ya, yb), clipped to the raster
  int xa = 0, ya = 0, xb = 0, yb = 0;  // upper and lower endpoint
  int ia = 0, ib = 0, za = 0, zb = 0;  // I and Z code at them
};

struct RefPolygon {
  std::int64_t twice = 0;  // eq. 5-6 without the 1/2
  int code = 0;
  bool valid = false;
  std::vector<RefEdge> left, right;          // top to bottom
  std::vector<RefEdge> all_left, all_right;  // with the edges no sample row crosses
  int row_first = 0, row_last = -1, even = 0, odd = 0;
  int rejected = 0, horizontal = 0, vertical = 0;  // edges without a sample row, dY = 0, dX = 0
};

// Chains by the inward normal (not by walking from the top vertex, as the kernel does): with the
// edge function of ExactCoverage, e = orient (dx (sy - y0) - dy (sx - x0)), the interior lies on
// the side of +x (a left edge) when de/dsx = -orient dy > 0. An edge is kept when a sample row
// lies in [ya, yb).
RefPolygon reference_polygon(const IntPolygon& p, const Lattice& lat) {
  RefPolygon r;
  // sum_j (Y_{j+1} - Y_j)(X_{j+1} + X_j) = sum_j (X_j Y_{j+1} - X_{j+1} Y_j): the other terms
  // telescope, so eq. 6's twice-area is minus the shoelace sum.
  r.twice = -shoelace2(p);
  // The area-code function itself is checked at every octave boundary (AreaCode.EveryOctaveBoundary);
  // here: that the edge generator codes the right value and protects (code 0) protected polygons.
  r.code = p.protect ? 0 : DefaultSegmentArith::area_code(Int<32>(r.twice));
  const int orient = r.twice < 0 ? 1 : r.twice > 0 ? -1 : 0;  // sign of the shoelace sum
  for (int k = 0; k < p.n; ++k) {
    const int k1 = (k + 1) % p.n;
    const int dy = p.y[k1] - p.y[k];
    if (dy == 0) {
      ++r.horizontal;
      continue;
    }
    if (p.x[k1] == p.x[k]) ++r.vertical;
    const int a = dy > 0 ? k : k1, b = dy > 0 ? k1 : k;
    RefEdge e;
    e.xa = p.x[a], e.ya = p.y[a], e.xb = p.x[b], e.yb = p.y[b];
    e.ia = p.i[a], e.ib = p.i[b], e.za = p.z[a], e.zb = p.z[b];
    e.first = int(std::max<i128>(0, lat.first_at_or_after(2 * i128(e.ya))));
    e.last = int(std::min<i128>(lat.rows - 1, lat.first_at_or_after(2 * i128(e.yb)) - 1));
    if (orient == 0) continue;
    (-orient * dy > 0 ? r.all_left : r.all_right).push_back(e);
    if (e.first > e.last) {
      ++r.rejected;
      continue;
    }
    (-orient * dy > 0 ? r.left : r.right).push_back(e);
  }
  auto by_y = [](const RefEdge& a, const RefEdge& b) { return a.ya < b.ya; };
  std::sort(r.left.begin(), r.left.end(), by_y);
  std::sort(r.right.begin(), r.right.end(), by_y);
  r.valid = p.n >= 3 && orient != 0 && !r.left.empty() && !r.right.empty();
  if (r.valid) {
    r.row_first = r.left.front().first;
    r.row_last = r.left.back().last;
    for (int line = r.row_first / 4; line <= r.row_last / 4; ++line) (line % 2 == 0 ? r.even : r.odd) += 1;
  }
  return r;
}

// The reference edge of a chain that holds row k (nullptr: none).
const RefEdge* edge_at(const std::vector<RefEdge>& chain, int k) {
  for (const RefEdge& e : chain)
    if (e.first <= k && k <= e.last) return &e;
  return nullptr;
}

// ---- Edge generator ----------------------------------------------------------------------------------

struct EdgeStats {
  long polygons = 0, valid = 0, zero_area = 0, no_row = 0, protect = 0, rejected = 0, horizontal = 0, vertical = 0;
  long edges = 0;
};

// One polygon through the fixed kernel and its twin, against the reference.
template <class Fmt>
void check_edges(const IntPolygon& p, const Lattice& lat, EdgeStats& st, Digest* dg) {
  using P = FixedSegmentArith<Fmt>;
  using S = typename P::Slope;
  using A = decltype(Edge<P>().x_first);  // the accumulator's format (the slope's)
  const RefPolygon ref = reference_polygon(p, lat);
  PolygonEdges<P> e;
  generate_edges<P>(fixed_input(p), lat.log2, e);
  PolygonEdges<Twin> te;
  generate_edges<Twin>(twin_input(p), lat.log2, te);
  const PolygonHeader<P>& h = e.h;
  SCOPED_TRACE(::testing::Message() << Fmt::name << " N " << lat.n << " polygon " << p.id << " n " << p.n);
  // Header: the polygon's fields, eq. 5-6 exact (|twice| < 2^25 fits Int<32>; the twin's double is
  // exact on these integers), the area code, valid iff a sample row crosses a non-zero area.
  ASSERT_EQ(e.valid, ref.valid);
  ASSERT_EQ(te.valid, ref.valid);
  ASSERT_EQ(int(h.id.value()), p.id);
  for (int c = 0; c < 3; ++c) ASSERT_EQ(int(h.colour[c].value()), p.colour[c]);
  ASSERT_EQ(h.opaque, p.opaque);
  ASSERT_EQ(h.protect, p.protect);
  ASSERT_EQ(h.twice_area.value(), ref.twice);
  ASSERT_EQ(te.h.twice_area, double(ref.twice));
  ASSERT_EQ(int(h.area_code.value()), ref.code);
  ASSERT_EQ(int(te.h.area_code.value()), ref.code);
  ++st.polygons;
  st.zero_area += ref.twice == 0;
  st.no_row += ref.twice != 0 && !ref.valid;
  st.protect += p.protect;
  st.rejected += ref.rejected;
  st.horizontal += ref.horizontal;
  st.vertical += ref.vertical;
  digest_words(dg, polygon_words(e));
  if (!ref.valid) return;
  ++st.valid;
  ASSERT_EQ(int(h.left_count.value()), int(ref.left.size()));
  ASSERT_EQ(int(h.right_count.value()), int(ref.right.size()));
  ASSERT_EQ(int(te.h.left_count.value()), int(ref.left.size()));
  ASSERT_EQ(int(te.h.right_count.value()), int(ref.right.size()));
  // Both chains span the rows with Y in [Y_top, Y_bottom); raster lines crossed, by field.
  ASSERT_EQ(ref.right.front().first, ref.row_first);  // the reference's own consistency
  ASSERT_EQ(ref.right.back().last, ref.row_last);
  ASSERT_EQ(h.row_first, ref.row_first);
  ASSERT_EQ(h.row_last, ref.row_last);
  ASSERT_EQ(te.h.row_first, ref.row_first);
  ASSERT_EQ(te.h.row_last, ref.row_last);
  ASSERT_EQ(int(h.segments_even.value()), ref.even);
  ASSERT_EQ(int(h.segments_odd.value()), ref.odd);
  ASSERT_EQ(int(te.h.segments_even.value()), ref.even);
  ASSERT_EQ(int(te.h.segments_odd.value()), ref.odd);
  for (int side = 0; side < 2; ++side) {
    const std::vector<RefEdge>& chain = side ? ref.right : ref.left;
    for (std::size_t j = 0; j < chain.size(); ++j) {
      const RefEdge& r = chain[j];
      const Edge<P>& k = side ? e.right[j] : e.left[j];
      const Edge<Twin>& t = side ? te.right[j] : te.left[j];
      SCOPED_TRACE(::testing::Message() << (side ? "right" : "left") << " edge " << j);
      ASSERT_EQ(k.row_first, r.first);
      ASSERT_EQ(k.row_last, r.last);
      ASSERT_EQ(t.row_first, r.first);
      ASSERT_EQ(t.row_last, r.last);
      ASSERT_EQ(int(k.x_begin.value()), r.xa);
      ASSERT_EQ(int(k.y_begin.value()), r.ya);
      ASSERT_EQ(int(k.x_end.value()), r.xb);
      ASSERT_EQ(int(k.y_end.value()), r.yb);
      ASSERT_EQ(int(k.i_begin.value()), r.ia);
      ASSERT_EQ(int(k.i_end.value()), r.ib);
      ASSERT_EQ(code_of(k.z_begin), r.za);
      ASSERT_EQ(code_of(k.z_end), r.zb);
      ASSERT_EQ(t.x_begin, r.xa);
      ASSERT_EQ(t.y_end, r.yb);
      const i128 dx = r.xb - r.xa, dy = r.yb - r.ya;
      // Eq. 2 per sample row: dx / dy times the row spacing u / 4 grid units, rounded half up once
      // to the slope's Fs fractional bits: raw = floor(dx u 2^Fs / (4 dy) + 1/2). Error <= 1/2 LSB_S,
      // met with equality: checked bit for bit. (|slope| <= 4095 * 64 < 2^18: no saturation.)
      ASSERT_TRUE(raw_of(k.dx_per_row) == round_half_up(mul2k(dx * lat.u, S::frac_bits), 4 * dy))
          << raw_of(k.dx_per_row);
      // The first crossing xa + dx (Y_first - ya) / dy, rounded half up once to the accumulator's
      // fractional bits (the slope's): bit for bit.
      const i128 t2 = lat.half(r.first) - 2 * i128(r.ya);
      ASSERT_TRUE(raw_of(k.x_first) == mul2k(r.xa, A::frac_bits) + round_half_up(mul2k(dx * t2, A::frac_bits), 2 * dy));
      // The twin: its slope is one correctly rounded division of integers times a power of two,
      // |slope| < 2^18, error < 2^18 * 2^-53 = 2^-35; so |fixed - twin| <= LSB_S / 2 + 2^-35.
      ASSERT_LE(std::abs(value_of(k.dx_per_row) - t.dx_per_row),
                std::ldexp(1.0, -S::frac_bits - 1) + std::ldexp(1.0, -35));
      // Its crossing xa + (Y - ya) dx / dy: the product is exact (< 2^26, one fractional bit), the
      // division and the addition round once each on values below 2^13: error < 2^-39; so
      // |fixed - twin| <= LSB_A / 2 + 2^-39.
      ASSERT_LE(std::abs(value_of(k.x_first) - t.x_first), std::ldexp(1.0, -A::frac_bits - 1) + std::ldexp(1.0, -39));
      ++st.edges;
    }
  }
}

constexpr Shape kShapes[] = {Shape::kLarge,  Shape::kMedium,     Shape::kSmall,           Shape::kSliver,
                             Shape::kBorder, Shape::kDegenerate, Shape::kCollinearVertex, Shape::kAny};

template <class Fmt>
void work_edges(int scale, Digest* dg) {
  EdgeStats st;
  Rng rng(0xED6E + Fmt::X::frac_bits);
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    const Lattice lat(log2);
    for (Shape shape : kShapes)
      for (int t = 0; t < 20 * scale; ++t) {
        check_edges<Fmt>(random_polygon(rng, shape, int(st.polygons % 65536)), lat, st, dg);
        if (::testing::Test::HasFatalFailure()) return;
      }
  }
  // Every case the edge generator distinguishes occurred.
  EXPECT_GT(st.valid, st.polygons / 2);
  EXPECT_GT(st.zero_area, 50);
  EXPECT_GT(st.no_row, 20);
  EXPECT_GT(st.rejected, 100);
  EXPECT_GT(st.horizontal, 100);
  EXPECT_GT(st.vertical, 100);
  EXPECT_GT(st.protect, 100);
  if (!dg)
    std::printf("edges %s: %ld polygons (%ld valid, %ld zero area, %ld with no sample row), %ld edges, %ld rejected\n",
                Fmt::name, st.polygons, st.valid, st.zero_area, st.no_row, st.edges, st.rejected);
}

TEST(EdgeGenerator, RandomPolygonsFine) { work_edges<Fine>(kScale, nullptr); }
TEST(EdgeGenerator, RandomPolygonsMedium) { work_edges<Medium>(kScale / 2, nullptr); }
TEST(EdgeGenerator, RandomPolygonsCoarse) { work_edges<Coarse>(kScale / 2, nullptr); }

IntPolygon make_polygon(std::initializer_list<std::pair<int, int>> v, int id = 0) {
  IntPolygon p;
  p.id = id;
  for (const auto& xy : v) {
    p.x[p.n] = xy.first;
    p.y[p.n] = xy.second;
    p.i[p.n] = (37 * p.n + 11) & 255;
    p.z[p.n] = 127 * 128 + 9 * p.n;
    ++p.n;
  }
  p.colour[0] = 200, p.colour[1] = 100, p.colour[2] = 50;
  return p;
}

// Hand-built cases with known answers.
TEST(EdgeGenerator, HandBuiltCases) {
  using P = DefaultSegmentArith;
  EdgeStats st;
  auto edges = [](const IntPolygon& p, int log2) {
    PolygonEdges<P> e;
    generate_edges<P>(fixed_input(p), log2, e);
    return e;
  };
  // Two vertices: no area, dropped.
  EXPECT_FALSE(edges(make_polygon({{10, 10}, {300, 400}}), 9).valid);
  // A triangle between two sample rows (N = 512: rows at even Y; Y in [3, 4] holds none): twice
  // its area is 200 (code 21 - floor(log2 200) = 14), but no row crosses it: dropped.
  const IntPolygon thin = make_polygon({{100, 3}, {300, 3}, {200, 4}});
  PolygonEdges<P> e = edges(thin, 9);
  EXPECT_FALSE(e.valid);
  EXPECT_EQ(std::abs(e.h.twice_area.value()), 200);
  EXPECT_EQ(int(e.h.area_code.value()), 14);
  // At N = 1024 the row at Y = 3.5 crosses it: one row, one line (line 0 holds rows 0..3 at
  // Y = -0.5, 0.5, 1.5, 2.5; line 1 row 0 at Y = 3.5), one edge per chain.
  e = edges(thin, 10);
  ASSERT_TRUE(e.valid);
  EXPECT_EQ(e.h.row_first, 4);
  EXPECT_EQ(e.h.row_last, 4);
  EXPECT_EQ(int(e.h.left_count.value()), 1);
  EXPECT_EQ(int(e.h.right_count.value()), 1);
  EXPECT_EQ(int(e.h.segments_even.value()), 0);
  EXPECT_EQ(int(e.h.segments_odd.value()), 1);
  // The whole screen (clamp-limit vertices, vertical and horizontal edges) at N = 16: rows 0..63,
  // left chain x = 0, right chain x = 4095, slopes 0, twice-area 2 * 4095^2 (code 1), 8 + 8 lines.
  for (bool ccw : {false, true}) {
    const IntPolygon screen = ccw ? make_polygon({{0, 0}, {0, 4095}, {4095, 4095}, {4095, 0}})
                                  : make_polygon({{0, 0}, {4095, 0}, {4095, 4095}, {0, 4095}});
    e = edges(screen, 4);
    ASSERT_TRUE(e.valid);
    EXPECT_EQ(std::abs(e.h.twice_area.value()), 2 * 4095 * 4095);
    EXPECT_EQ(int(e.h.area_code.value()), 1);
    EXPECT_EQ(e.h.row_first, 0);
    EXPECT_EQ(e.h.row_last, 63);
    ASSERT_EQ(int(e.h.left_count.value()), 1);
    ASSERT_EQ(int(e.h.right_count.value()), 1);
    EXPECT_EQ(int(e.left[0].x_begin.value()), 0);
    EXPECT_EQ(int(e.right[0].x_begin.value()), 4095);
    EXPECT_EQ(raw_of(e.left[0].dx_per_row), 0);
    EXPECT_EQ(raw_of(e.right[0].dx_per_row), 0);
    EXPECT_EQ(int(e.h.segments_even.value()), 8);
    EXPECT_EQ(int(e.h.segments_odd.value()), 8);
    check_edges<Fine>(screen, Lattice(4), st, nullptr);
  }
  // A protected polygon has code 0 whatever its area.
  IntPolygon prot = make_polygon({{10, 10}, {20, 30}, {5, 25}});
  prot.protect = true;
  EXPECT_EQ(int(edges(prot, 9).h.area_code.value()), 0);
  // A vertex in the middle of an edge splits that chain into two edges.
  e = edges(make_polygon({{100, 100}, {500, 900}, {300, 900}, {200, 500}}), 9);
  ASSERT_TRUE(e.valid);
  EXPECT_EQ(int(e.h.left_count.value()) + int(e.h.right_count.value()), 3);
  // Collinear vertices: zero area, dropped.
  e = edges(make_polygon({{0, 0}, {100, 200}, {300, 600}}), 9);
  EXPECT_FALSE(e.valid);
  EXPECT_EQ(e.h.twice_area.value(), 0);
  // A horizontal top edge on a sample row (N = 512, Y = 10) starts the rows there; a vertex on the
  // last row (Y = 4094) is the bottom, exclusive: rows 5 .. 2046.
  e = edges(make_polygon({{40, 10}, {900, 10}, {600, 4094}}), 9);
  ASSERT_TRUE(e.valid);
  EXPECT_EQ(e.h.row_first, 5);
  EXPECT_EQ(e.h.row_last, 2046);
  EXPECT_EQ(int(e.h.left_count.value()), 1);
  EXPECT_EQ(int(e.h.right_count.value()), 1);
  // A vertical right edge and a horizontal bottom edge: the bottom row is Y = 4094 when the
  // bottom lies at Y = 4095.
  e = edges(make_polygon({{4095, 0}, {4095, 4095}, {0, 4095}}), 9);
  ASSERT_TRUE(e.valid);
  EXPECT_EQ(e.h.row_first, 0);
  EXPECT_EQ(e.h.row_last, 2047);
  EXPECT_EQ(raw_of(e.right[0].dx_per_row), 0);
}

// ---- Frame memory ------------------------------------------------------------------------------------

// A pool of valid polygons' edges of every size 3..11 words (header + edges).
std::vector<PolygonEdges<DefaultSegmentArith>> edge_pool(Rng& rng, int count) {
  std::vector<PolygonEdges<DefaultSegmentArith>> pool;
  bool size_seen[kMaxVertices + 2] = {};
  for (int t = 0; t < 100000 &&
                  (int(pool.size()) < count || !std::all_of(size_seen + 3, size_seen + 12, [](bool b) { return b; }));
       ++t) {
    PolygonEdges<DefaultSegmentArith> e;
    generate_edges<DefaultSegmentArith>(fixed_input(random_polygon(rng, Shape::kAny, int(pool.size()))), 7, e);
    if (!e.valid) continue;
    size_seen[std::min(frame_memory_words(e), kMaxVertices + 1)] = true;
    pool.push_back(e);
  }
  return pool;
}

// Capacity: a polygon takes 1 + left + right words; it is written only when it fits the rest of the
// bank (exactly filling it is fine), otherwise it is counted and nothing is written (no wrap, the
// bank's earlier contents stay). Read-back returns the written polygons in order, word for word.
// Banks: the swap makes the other bank the write bank and empties it; the bank written before
// stays readable until the next swap.
template <int K>
void work_frame_memory(int scale, Digest* dg) {
  using P = DefaultSegmentArith;
  Rng rng(0xF4A3 + K);
  const auto pool = edge_pool(rng, 300);
  auto mem = std::make_unique<FrameMemory<P, K>>();
  FrameMemory<P, K>& m = *mem;
  ASSERT_EQ(m.write_bank, 0);
  auto read_all = [&](int bank) {
    std::vector<std::vector<std::int64_t>> out;
    PolygonEdges<P> e;
    int addr = 0;
    while (true) {
      const int before = addr;
      if (!frame_memory_read(m, bank, addr, e)) break;
      EXPECT_EQ(addr - before, frame_memory_words(e));  // the read advances by the polygon's words
      out.push_back(polygon_words(e));
    }
    EXPECT_EQ(addr, m.used[bank]);  // read stops at the end of the written words
    return out;
  };
  std::vector<std::vector<std::int64_t>> frame[2];  // expected contents per bank
  bool any_filled = false;
  for (int round = 0; round < 6 * scale; ++round) {
    frame_memory_swap(m);
    const int b = m.write_bank;
    ASSERT_EQ(b, (round + 1) & 1);
    ASSERT_EQ(m.used[b], 0);
    ASSERT_EQ(m.polygons_written.value(), 0u);
    ASSERT_EQ(m.polygons_overflowed.value(), 0u);
    frame[b].clear();
    // The other bank still holds the previous frame.
    if (round > 0) { EXPECT_EQ(read_all(b ^ 1), frame[b ^ 1]); }
    int used = 0, written = 0, overflowed = 0;
    bool filled = false;
    const int polygons = round % 2 == 0 ? 400 : int(below(rng, 8));  // past the capacity, or a few
    for (int t = 0; t < polygons; ++t) {
      const auto& e = pool[std::size_t(below(rng, std::int64_t(pool.size())))];
      const int words = frame_memory_words(e);
      const bool fits = used + words <= K;
      ASSERT_EQ(frame_memory_write(e, m), fits);
      if (fits) {
        used += words;
        ++written;
        frame[b].push_back(polygon_words(e));
      } else {
        ++overflowed;
        // Fill the rest exactly when a polygon of that size exists, then overflow by one word.
        const int rest = K - used;
        for (const auto& f : pool) {
          if (filled || frame_memory_words(f) != rest) continue;
          ASSERT_TRUE(frame_memory_write(f, m));
          used += rest;
          ++written;
          frame[b].push_back(polygon_words(f));
          filled = true;
        }
      }
      ASSERT_EQ(m.used[b], used);
      ASSERT_LE(m.used[b], K);
      ASSERT_EQ(int(m.polygons_written.value()), written);
      ASSERT_EQ(int(m.polygons_overflowed.value()), overflowed);
    }
    if (round % 2 == 0) {
      EXPECT_GT(overflowed, 0);
      EXPECT_LT(K - m.used[b], 3);  // full: the smallest polygon (3 words) no longer fits
    }
    any_filled = any_filled || filled;
    EXPECT_EQ(read_all(b), frame[b]);
    for (const auto& w : frame[b]) digest_words(dg, w);
    if (dg) dg->add(std::uint64_t(m.used[b]));
  }
  EXPECT_TRUE(any_filled);  // some frame filled its bank to the last word
}

TEST(FrameMemory, CapacityOverflowReadBackAndBanks) { work_frame_memory<97>(kScale, nullptr); }

// The real bank: 16K words. 33-word polygons (16 + 16 edges) fill 496 x 33 = 16368 words; the 497th
// overflows, a 16-word polygon then fills the last 16 words exactly, and nothing more fits.
TEST(FrameMemory, SixteenKWordBanks) {
  using P = DefaultSegmentArith;
  auto mem = std::make_unique<FrameMemory<P>>();
  frame_memory_swap(*mem);
  PolygonEdges<P> big, small, tiny;
  big.valid = true;
  big.h.left_count = big.h.right_count = UInt<5>(16);
  small.h.left_count = UInt<5>(8);
  small.h.right_count = UInt<5>(7);
  tiny.h.left_count = tiny.h.right_count = UInt<5>(1);
  for (int k = 0; k < kMaxEdgesPerChain; ++k) {
    big.left[k].row_first = k;
    big.right[k].row_last = 1000 + k;
  }
  int accepted = 0;
  while (frame_memory_write_top(big, *mem)) ++accepted;
  EXPECT_EQ(accepted, 496);
  EXPECT_EQ(mem->used[mem->write_bank], 496 * 33);
  EXPECT_TRUE(frame_memory_write_top(small, *mem));
  EXPECT_EQ(mem->used[mem->write_bank], kFrameBankWords);
  EXPECT_FALSE(frame_memory_write_top(tiny, *mem));
  EXPECT_EQ(int(mem->polygons_written.value()), 497);
  EXPECT_EQ(int(mem->polygons_overflowed.value()), 2);
  // The last big polygon reads back whole.
  int addr = 495 * 33;
  PolygonEdges<P> back;
  ASSERT_TRUE(frame_memory_read(*mem, mem->write_bank, addr, back));
  EXPECT_EQ(polygon_words(back), polygon_words(big));
}

// ---- Segment generator --------------------------------------------------------------------------------

// A closed interval of sample columns (empty when lo > hi).
struct Interval {
  i128 lo = 1, hi = 0;
  bool empty() const { return lo > hi; }
};

// The exact coverage of sample row k: the columns whose sample satisfies every edge function of
// ExactCoverage with its tie rule. Each edge allows a half-line of the row, so the set is an
// interval: e(sx) = orient (dx (sy - y0) - dy (sx - x0)) = A - B sx, B = orient dy.
Interval exact_row(const ExactCoverage& ec, const Lattice& lat, i128 k) {
  Interval r{0, lat.rows - 1};
  if (ec.orient == 0) return Interval{};
  const i128 sy = lat.half(k), step = lat.u / 2, c = lat.offset();  // column i lies at sx = step i + c
  for (int j = 0; j < ec.n; ++j) {
    const int j1 = j + 1 == ec.n ? 0 : j + 1;
    const i128 x0 = ec.x[j], y0 = ec.y[j], dx = ec.x[j1] - x0, dy = ec.y[j1] - y0;
    if (dx == 0 && dy == 0) continue;
    const i128 B = ec.orient * dy, A = ec.orient * (dx * (sy - y0) + dy * x0);
    if (B == 0) {  // horizontal: e = A on the whole row; on the edge, inside iff gy = orient dx > 0
      if (!(A > 0 || (A == 0 && ec.orient * dx > 0))) return Interval{};
    } else if (B > 0) {  // gx = -B < 0, the edge excluded: A - B sx > 0 <=> i < (A - c B) / (step B)
      r.hi = std::min(r.hi, ceil_div(A - c * B, step * B) - 1);
    } else {  // gx = -B > 0, the edge included: A - B sx >= 0 <=> i >= (-A - c |B|) / (step |B|)
      r.lo = std::max(r.lo, ceil_div(-A + c * B, -step * B));
    }
  }
  return r;
}

struct SegStats {
  long polygons = 0, segments = 0, rows = 0, samples = 0, differing = 0, ends = 0, extrapolated = 0;
  long types[5] = {0, 0, 0, 0, 0};
  double worst_x = 0, worst_x_ratio = 0, worst_twin_x = 0, max_t = 0;
  double worst_i_off_boundary = 0;  // |I at an end - the boundary's own I at yt| (information)
};

// Runs a polygon through the fixed edge and segment generators and their twins and checks the
// segments against the reference; calls covered(row, lo, hi) with the columns the segments cover
// on each row (the video channel's rule).
template <class Fmt>
class SegmentChecker {
 public:
  using P = FixedSegmentArith<Fmt>;
  using X = typename P::X;
  using S = typename P::Slope;
  using I = typename P::Intensity;
  static constexpr int Fx = X::frac_bits, Fs = S::frac_bits, Fi = I::frac_bits;
  // The fine format promises exact coverage (SegmentFormatFine derives it); the others bounded.
  static constexpr bool kExact = std::is_same_v<Fmt, SegmentFormatFine>;

  SegmentChecker(int log2, SegStats& st, Digest* dg)
      : lat_(log2),
        g_(LatticeGeometry::for_raster(log2)),
        st_(st),
        dg_(dg),
        segs_(std::make_unique<Segment<P>[]>(kMaxLines)),
        twin_(std::make_unique<Segment<Twin>[]>(kMaxLines)) {}

  template <class Covered>
  void run(const IntPolygon& p, Covered&& covered) {
    SCOPED_TRACE(::testing::Message() << Fmt::name << " N " << lat_.n << " polygon " << p.id);
    const RefPolygon ref = reference_polygon(p, lat_);
    PolygonEdges<P> e;
    generate_edges<P>(fixed_input(p), lat_.log2, e);
    PolygonEdges<Twin> te;
    generate_edges<Twin>(twin_input(p), lat_.log2, te);
    const UInt<3> channel(std::uint64_t(p.id % 8));
    Segment<P>(&out)[kMaxLines] = *reinterpret_cast<Segment<P>(*)[kMaxLines]>(segs_.get());
    Segment<Twin>(&tout)[kMaxLines] = *reinterpret_cast<Segment<Twin>(*)[kMaxLines]>(twin_.get());
    const int count = generate_segments<P>(e, lat_.log2, channel, false, out);
    const int tcount = generate_segments<Twin>(te, lat_.log2, channel, false, tout);
    ++st_.polygons;
    // One segment per raster line the polygon's rows touch, top line first; none when dropped.
    const int line_first = ref.row_first / 4, line_last = ref.row_last / 4;
    ASSERT_EQ(count, ref.valid ? line_last - line_first + 1 : 0);
    ASSERT_EQ(tcount, count);
    for (int j = 0; j < count; ++j) {
      check_segment(p, ref, out[j], tout[j], line_first + j, channel);
      if (::testing::Test::HasFatalFailure()) return;
      std::vector<std::int64_t> w;
      segment_words(out[j], w);
      digest_words(dg_, w);
    }
    check_coverage(p, ref, out, count, covered);
  }

 private:
  // |X - exact| <= LSB_X / 2 + (m + 1) LSB_S / 2 for a row m steps below the edge's first row.
  // Derivation (segment_arith.hpp: crossing, step): the accumulator is loaded with the first
  // crossing rounded half up to Fs bits (error <= LSB_S / 2) and advanced m times by the slope
  // rounded half up to Fs bits (error <= LSB_S / 2 each, m LSB_S / 2 in all; the steps themselves
  // are exact), then rounded half up once to X's Fx bits (<= LSB_X / 2). As an integer test, with
  // the difference num / den in grid units: |num| 2^(Fs+1) <= den (2^(Fs-Fx) + m + 1).
  static bool within_x_bound(i128 num, i128 den, int m) {
    return abs128(num) * (i128(1) << (Fs + 1)) <= den * ((i128(1) << (Fs - Fx)) + m + 1);
  }
  static double x_bound(int m) { return std::ldexp(1.0, -Fx - 1) + (m + 1) * std::ldexp(1.0, -Fs - 1); }

  void check_x(const X& x, double twin, const RefEdge& r, int k) {
    // Exact crossing at row k: (2 dy xa + dx (H_k - 2 ya)) / (2 dy) grid units.
    const i128 dy2 = 2 * i128(r.yb - r.ya), num = dy2 * r.xa + i128(r.xb - r.xa) * (lat_.half(k) - 2 * i128(r.ya));
    const int m = k - r.first;
    const i128 diff = i128(raw_of(x)) * dy2 - mul2k(num, Fx);  // (X - exact) 2^Fx 2 dy
    ASSERT_TRUE(within_x_bound(diff, dy2 << Fx, m))
        << "row " << k << " X " << value_of(x) << " exact " << double(num) / double(dy2) << " m " << m;
    const double err = std::abs(double(diff) / double(dy2 << Fx));
    st_.worst_x = std::max(st_.worst_x, std::ldexp(err, Fx));
    st_.worst_x_ratio = std::max(st_.worst_x_ratio, err / x_bound(m));
    // The twin: x_first (error < 2^-39, check_edges) plus m slopes (each < 2^-35, m < 2^12) plus
    // one product and one sum rounded on values below 2^20 (< 2^-33 each): below 2^-21 in all.
    const double terr = std::abs(value_of(x) - twin);
    ASSERT_LE(terr, x_bound(m) + std::ldexp(1.0, -21)) << "row " << k;
    st_.worst_twin_x = std::max(st_.worst_twin_x, terr / (x_bound(m) + std::ldexp(1.0, -21)));
  }

  // I and Z at one end: eq. 3-4 on the chain edge that holds the middle row rm, at the centre yt of
  // the covered rows (yt_q = H_rf + H_rl quarter units: t4 = yt_q - 4 ya of dy4 = 4 dy), with t4
  // clamped to the edge [0, dy4] (the edge can end inside the line).
  void check_end(const I& in, const ZFloat& z, double tin, double tz, const RefEdge& r, i128 ytq,
                 const std::vector<RefEdge>& side) {
    const i128 dy4 = 4 * i128(r.yb - r.ya), t4_unclamped = ytq - 4 * i128(r.ya);
    const i128 t4 = std::clamp<i128>(t4_unclamped, 0, dy4);
    // Fixed I: ia + (ib - ia) t4 / dy4 rounded half up once to Fi bits, saturated to the format
    // (0 .. 256 - LSB_I; the intermediate's saturation at +-512 cannot change the result, since
    // |ia| <= 255): bit for bit, i.e. error <= 1/2 LSB_I before saturation.
    const i128 imax = (i128(1) << I::width) - 1;
    i128 expect = mul2k(r.ia, Fi) + round_half_up(i128(r.ib - r.ia) * t4 * (i128(1) << Fi), dy4);
    expect = expect < 0 ? 0 : expect > imax ? imax : expect;
    ASSERT_TRUE(i128(raw_of(in)) == expect) << raw_of(in) << " vs " << std::int64_t(expect);
    // The twin clamps the exact value v to [0, 255] (one division, error < 2^-44 on values < 2^9):
    // |fixed - twin| <= LSB_I / 2 + 2^-40 while v < 255; beyond, the fixed saturates at the format's
    // top, 256 - LSB_I, and the twin at 255: <= 1 - LSB_I.
    const double lsb = std::ldexp(1.0, -Fi);
    ASSERT_LE(std::abs(value_of(in) - tin), (tin >= 255 ? 1 - lsb : lsb / 2) + std::ldexp(1.0, -40));
    // Z by eq. 4 on e8m7: judge_lerp holds the exact rational reference and the derivation.
    const int zc = code_of(z);
    const LerpVerdict v = judge_lerp(r.za, r.zb, std::int64_t(t4), std::int64_t(dy4), zc);
    ASSERT_TRUE(v.ok) << "Z codes " << r.za << " " << r.zb << " t " << std::int64_t(t4) << "/" << std::int64_t(dy4)
                      << " got " << zc << " admissible " << v.lo << ".." << v.hi;
    // Against the twin's double: the kernel rounds x = v + err with |err| <= E (judge_lerp:
    // U (|1 - t| + |t|) when the exponents differ by more than 12, plus U / 2, U = 2^(emax - 146)),
    // to nearest even e8m7 (relative error <= 2^-8); the twin's v has a relative error < 2^-50.
    // So |Z - twin| <= 2^-8 (|twin| + E) + E + 2^-50 (|za| + |zb|)(|t| + 1), while v > 0 (the twin
    // clamps v <= 0 to 1e-30, the kernel to code 0: judge_lerp covers that case).
    const double t = double(t4) / double(dy4);
    const int ea = r.za >> 7, eb = r.zb >> 7, emax = std::max(ea, eb);
    const double U = std::ldexp(1.0, emax - 146);
    const double E = (std::abs(ea - eb) > 12 ? U * (std::abs(1 - t) + std::abs(t)) : 0) + U / 2;
    if (tz > 1e-30) {
      const double bound = std::ldexp(std::abs(tz) + E, -8) + E +
                           std::ldexp((zvalue(r.za) + zvalue(r.zb)) * (std::abs(t) + 1), -50) + std::ldexp(1.0, -126);
      ASSERT_LE(std::abs(zvalue(zc) - tz), bound) << "Z " << zc;
    }
    ++st_.ends;
    st_.extrapolated += t4_unclamped != t4;
    st_.max_t = std::max(st_.max_t, double(t4_unclamped) / double(dy4));
    // Information, not a bound: where a chain vertex lies between the middle row and yt, eq. 3 is
    // evaluated at its edge's end (t clamped to 1): how far that lands from the I of the polygon's
    // own boundary at yt (on the edge that contains yt).
    for (const RefEdge& b : side)
      if (4 * i128(b.ya) <= ytq && ytq <= 4 * i128(b.yb)) {
        const double own = b.ia + (b.ib - b.ia) * (double(ytq) / 4 - b.ya) / (b.yb - b.ya);
        st_.worst_i_off_boundary = std::max(st_.worst_i_off_boundary, std::abs(std::min(tin, 255.0) - own));
        break;
      }
  }

  void check_segment(const IntPolygon& p, const RefPolygon& ref, const Segment<P>& s, const Segment<Twin>& ts, int L,
                     const UInt<3>& channel) {
    SCOPED_TRACE(::testing::Message() << "line " << L);
    // Covered rows of the line, and the type: 1 holds the polygon's top row, 2 its bottom, 4 both.
    const int rf = std::max(ref.row_first, 4 * L), rl = std::min(ref.row_last, 4 * L + 3);
    const bool top = rf == ref.row_first, bottom = rl == ref.row_last;
    const unsigned type = top && bottom ? kSegWhole : top ? kSegTop : bottom ? kSegBottom : kSegMiddle;
    ASSERT_EQ(int(s.line.value()), L);
    ASSERT_EQ(s.type.value(), type);
    ASSERT_EQ(int(s.row_first.value()), rf - 4 * L);
    ASSERT_EQ(int(s.row_last.value()), rl - 4 * L);
    ASSERT_EQ(int(s.source.value()), p.id);
    ASSERT_FALSE(s.is_light);
    ASSERT_EQ(s.opaque, p.opaque);
    ASSERT_EQ(s.channel.value(), channel.value());
    ASSERT_EQ(int(ts.line.value()), L);
    ASSERT_EQ(ts.type.value(), type);
    ASSERT_EQ(ts.row_first.value(), s.row_first.value());
    ASSERT_EQ(ts.row_last.value(), s.row_last.value());
    ++st_.segments;
    ++st_.types[type];
    for (int k = rf; k <= rl; ++k) {
      const RefEdge* le = edge_at(ref.left, k);
      const RefEdge* re = edge_at(ref.right, k);
      ASSERT_TRUE(le && re);
      check_x(s.xl[k - 4 * L], ts.xl[k - 4 * L], *le, k);
      check_x(s.xr[k - 4 * L], ts.xr[k - 4 * L], *re, k);
      if (::testing::Test::HasFatalFailure()) return;
      ++st_.rows;
    }
    const int rm = (rf + rl) / 2;
    const i128 ytq = lat_.half(rf) + lat_.half(rl);
    check_end(s.il, s.zl, ts.il, ts.zl, *edge_at(ref.left, rm), ytq, ref.all_left);
    check_end(s.ir, s.zr, ts.ir, ts.zr, *edge_at(ref.right, rm), ytq, ref.all_right);
  }

  // The KEY property. Kernel: on each covered row, the columns i with left X <= X_i < right X
  // (first_column_at_or_after, as the video channel), clipped to the raster. Exact: exact_row. In
  // the fine format they are EQUAL (segment_arith.hpp, SegmentFormatFine, derives why). In the
  // others a sample can differ only where an exact edge passes within the X error bound of it: its
  // column lies between the kernel's X and the exact crossing, so |X_i - exact| <= |X - exact|.
  template <class Covered>
  void check_coverage(const IntPolygon& p, const RefPolygon& ref, const Segment<P>* out, int count, Covered&& covered) {
    const ExactCoverage ec(p);
    const int cols = lat_.rows;
    int ymin = 4095, ymax = 0;
    for (int k = 0; k < p.n; ++k) ymin = std::min(ymin, p.y[k]), ymax = std::max(ymax, p.y[k]);
    const int k0 = int(std::max<i128>(0, lat_.first_at_or_after(2 * ymin) - 1));
    const int k1 = int(std::min<i128>(lat_.rows - 1, lat_.first_at_or_after(2 * ymax)));
    const bool brute = lat_.n == 16;  // the smallest raster: every sample of the row by ExactCoverage
    for (int k = k0; k <= k1; ++k) {
      const Interval ex = exact_row(ec, lat_, k);
      // The interval derivation against ExactCoverage itself.
      auto covers = [&](i128 i) { return ec.covers(std::int64_t(lat_.half(i)), std::int64_t(lat_.half(k))); };
      if (brute) {
        for (int i = 0; i < cols; ++i) ASSERT_EQ(covers(i), i >= ex.lo && i <= ex.hi) << "row " << k << " col " << i;
      } else if (!ex.empty()) {
        ASSERT_TRUE(covers(ex.lo) && covers(ex.hi) && (ex.lo == 0 || !covers(ex.lo - 1)) &&
                    (ex.hi == cols - 1 || !covers(ex.hi + 1)))
            << "row " << k;
      }
      Interval kr;  // the kernel's columns on row k
      const int L = k / 4, j = L - ref.row_first / 4;
      if (j >= 0 && j < count) {
        const Segment<P>& s = out[j];
        const int r = k - 4 * L;
        if (r >= int(s.row_first.value()) && r <= int(s.row_last.value())) {
          kr.lo = std::max(0, P::first_column_at_or_after(g_, s.xl[r]));
          kr.hi = std::min(cols - 1, P::first_column_at_or_after(g_, s.xr[r]) - 1);
        }
      }
      if (!kr.empty()) covered(k, int(kr.lo), int(kr.hi));
      if (!ex.empty()) st_.samples += long(ex.hi - ex.lo + 1);
      if (kExact) {
        ASSERT_TRUE(ex.empty() == kr.empty() && (ex.empty() || (ex.lo == kr.lo && ex.hi == kr.hi)))
            << "row " << k << ": kernel " << std::int64_t(kr.lo) << ".." << std::int64_t(kr.hi) << ", exact "
            << std::int64_t(ex.lo) << ".." << std::int64_t(ex.hi);
        continue;
      }
      // Coarse and medium: every sample in the symmetric difference is within the X bound of the
      // exact left or right crossing of its row (rows themselves are exact decisions: outside the
      // polygon's rows both are empty).
      const RefEdge* le = ref.valid ? edge_at(ref.left, k) : nullptr;
      const RefEdge* re = ref.valid ? edge_at(ref.right, k) : nullptr;
      auto near = [&](const RefEdge* r, i128 i) {
        if (!r) return false;
        const i128 dy2 = 2 * i128(r->yb - r->ya);
        const i128 num = dy2 * r->xa + i128(r->xb - r->xa) * (lat_.half(k) - 2 * i128(r->ya));  // exact X * dy2
        return within_x_bound(lat_.half(i) * dy2 - 2 * num, 2 * dy2, k - r->first);             // X_i - exact
      };
      // The symmetric difference lies between the two left ends and between the two right ends
      // (or is one whole interval when the other is empty).
      auto visit = [&](i128 a, i128 b) {
        for (i128 i = a; i <= b; ++i) {
          const bool in_k = i >= kr.lo && i <= kr.hi, in_e = i >= ex.lo && i <= ex.hi;
          if (in_k == in_e) continue;
          ++st_.differing;
          ASSERT_TRUE(near(le, i) || near(re, i)) << "row " << k << " col " << std::int64_t(i) << " kernel " << in_k;
        }
      };
      if (kr.empty() || ex.empty()) {
        visit(kr.lo, kr.hi);
        visit(ex.lo, ex.hi);
      } else {
        visit(std::min(kr.lo, ex.lo), std::max(kr.lo, ex.lo) - 1);
        visit(std::min(kr.hi, ex.hi) + 1, std::max(kr.hi, ex.hi));
      }
      if (::testing::Test::HasFatalFailure()) return;
    }
  }

  Lattice lat_;
  LatticeGeometry g_;
  SegStats& st_;
  Digest* dg_;
  std::unique_ptr<Segment<P>[]> segs_;
  std::unique_ptr<Segment<Twin>[]> twin_;
};

template <class Fmt>
void report_segments(const char* what, const SegStats& st) {
  std::printf(
      "%s %s: %ld polygons, %ld segments, %ld rows, %ld samples; X error <= %.3f LSB_X (%.3f of the bound), "
      "twin %.3f of its bound; %ld differing samples; I/Z ends %ld, %ld clamped to their edge (t up to %.1f unclamped; I up to %.1f "
      "off the boundary's at yt)\n",
      what, Fmt::name, st.polygons, st.segments, st.rows, st.samples, st.worst_x, st.worst_x_ratio, st.worst_twin_x,
      st.differing, st.ends, st.extrapolated, st.max_t, st.worst_i_off_boundary);
  const std::string p = std::string(Fmt::name) + "_" + what;
  ::testing::Test::RecordProperty(p + "_worst_x_lsb", std::to_string(st.worst_x));
  ::testing::Test::RecordProperty(p + "_worst_x_of_bound", std::to_string(st.worst_x_ratio));
  ::testing::Test::RecordProperty(p + "_differing_samples", std::to_string(st.differing));
  ::testing::Test::RecordProperty(p + "_ends_clamped", std::to_string(st.extrapolated));
  ::testing::Test::RecordProperty(p + "_worst_i_off_boundary", std::to_string(st.worst_i_off_boundary));
}

// Random polygons of every shape at every raster 16..1024.
template <class Fmt>
void work_segments(int scale, Digest* dg) {
  SegStats st;
  Rng rng(0x5E65 + Fmt::X::frac_bits);
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    SegmentChecker<Fmt> check(log2, st, dg);
    const int count = scale * (log2 <= 6 ? 30 : log2 <= 8 ? 15 : 6);
    for (Shape shape : kShapes)
      for (int t = 0; t < count; ++t) {
        check.run(random_polygon(rng, shape, t), [](int, int, int) {});
        if (::testing::Test::HasFatalFailure()) return;
      }
  }
  EXPECT_GT(st.segments, 2500 * scale);
  for (unsigned type : {kSegTop, kSegBottom, kSegMiddle, kSegWhole}) EXPECT_GT(st.types[type], 100) << "type " << type;
  if (SegmentChecker<Fmt>::kExact) { EXPECT_EQ(st.differing, 0); }
  if (!dg) report_segments<Fmt>("random", st);
}

TEST(SegmentGenerator, RandomPolygonsFineCoverageExact) { work_segments<Fine>(kScale, nullptr); }
TEST(SegmentGenerator, RandomPolygonsMedium) { work_segments<Medium>(kScale / 2, nullptr); }
TEST(SegmentGenerator, RandomPolygonsCoarse) { work_segments<Coarse>(kScale / 2, nullptr); }

// ---- A random tiling of the screen through the segment path -------------------------------------------

// segtest::random_tiling (segment_test_support.hpp): a jittered triangulation of the screen square
// with slivers.

// Every sample of the screen square (0 <= X_i, Y_k < 4095: at N = 1024 column and row 0 lie at
// -0.5, outside every polygon) is covered by exactly one triangle through the segment path, in
// the fine format (whose coverage is exact, and exact coverage with the tie rule partitions the
// square). Each tile also passes every check of the random-polygon test (SegmentChecker). Medium
// and coarse: each tile's differences are bounded as there; the samples covered 0 or 2+ times are
// counted.
template <class Fmt>
void work_tiling(int scale, Digest* dg) {
  SegStats st;
  Rng rng(0x711E + Fmt::X::frac_bits);
  long wrong = 0, slivers = 0;
  for (int log2 = kMinRasterLog2; log2 <= kMaxRasterLog2; ++log2) {
    const Lattice lat(log2);
    SegmentChecker<Fmt> check(log2, st, dg);
    const int tilings = log2 >= 9 ? 1 : (scale + 1) / 2;
    for (int t = 0; t < tilings; ++t) {
      std::vector<std::uint8_t> count(std::size_t(lat.rows) * std::size_t(lat.rows), 0);
      for (const IntPolygon& tri : random_tiling(rng)) {
        slivers += std::abs(shoelace2(tri)) < 2 * 4095;  // thinner than one unit on average
        check.run(tri, [&](int k, int lo, int hi) {
          for (int i = lo; i <= hi; ++i) count[std::size_t(k) * std::size_t(lat.rows) + std::size_t(i)] += 1;
        });
        if (::testing::Test::HasFatalFailure()) return;
      }
      long miss = 0, twice = 0;
      for (int k = 0; k < lat.rows; ++k)
        for (int i = 0; i < lat.rows; ++i) {
          const bool inside = lat.half(k) >= 0 && lat.half(i) >= 0;  // half(.) < 8190 at every raster
          const int c = count[std::size_t(k) * std::size_t(lat.rows) + std::size_t(i)];
          miss += inside && c == 0;
          twice += c > 1 || (!inside && c > 0);
        }
      if (SegmentChecker<Fmt>::kExact) {
        ASSERT_EQ(miss, 0) << "N " << lat.n;
        ASSERT_EQ(twice, 0) << "N " << lat.n;
      }
      wrong += miss + twice;
      if (dg) dg->add(std::uint64_t(miss + twice));
    }
  }
  EXPECT_GT(slivers, 10);
  if (!dg) {
    report_segments<Fmt>("tiling", st);
    std::printf("tiling %s: %ld samples covered 0 or 2+ times, %ld slivers\n", Fmt::name, wrong, slivers);
    ::testing::Test::RecordProperty(std::string(Fmt::name) + "_tiling_wrong_samples", std::to_string(wrong));
  }
}

TEST(SegmentGenerator, RandomTilingCoversEverySampleOnceFine) { work_tiling<Fine>(kScale, nullptr); }
TEST(SegmentGenerator, RandomTilingMedium) { work_tiling<Medium>(kScale / 2, nullptr); }
TEST(SegmentGenerator, RandomTilingCoarse) { work_tiling<Coarse>(kScale / 2, nullptr); }

// ---- Digest (both halves) ------------------------------------------------------------------------------

TEST(SegmentKernels, Digest) {
  Digest d;
  work_edges<Fine>(1, &d);
  work_edges<Medium>(1, &d);
  work_edges<Coarse>(1, &d);
  work_frame_memory<97>(1, &d);
  work_segments<Fine>(1, &d);
  work_segments<Coarse>(1, &d);
  work_tiling<Fine>(1, &d);
  work_tiling<Coarse>(1, &d);
  digest_video_half(d);
  digest_golden(d);
  kernel_test::print_digest("segment_kernels", d);
}

}  // namespace
}  // namespace cig::hls
