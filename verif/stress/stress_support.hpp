// Helpers of the segment-processor stress tests (verif/stress/):
//
//  * polygon lists built on the formatter grid (eq. 1) with sample levels that make every pixel
//    an integer in both the reference and the engine, so that images compare exactly;
//  * an independent brute-force recount of what the segment processor must store: area codes,
//    segments per field, frame-memory words (first fit), light-point segments, the overload
//    threshold by exhaustive search, and the report fields that follow from them;
//  * the samples whose coverage the engine's X arithmetic may decide differently from the exact
//    edge functions of the reference, from an error bound derived from the kernel formats.
//
// Everything is computed from the SPEC's rules and the polygon list, never from the engine's own
// code; only the kernels' format widths (hls/segment/segment_arith.hpp) are read.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/engine.hpp"
#include "formatter/formatter_twin.hpp"
#include "frame/screen_frame.hpp"
#include "hls/formatter/span_pieces.hpp"
#include "hls/segment/frame_memory.hpp"
#include "hls/segment/overload.hpp"
#include "hls/segment/records.hpp"
#include "hls/segment/segment_arith.hpp"

namespace cig::stress {

using i128 = __int128;
using Rng = std::mt19937_64;  // raw stream only (no std distributions): the same scenes everywhere

inline long below(Rng& rng, long n) { return long(rng() % std::uint64_t(n)); }
inline long between(Rng& rng, long lo, long hi) { return lo + below(rng, hi - lo + 1); }

// SPEC D memories: frame memory 2 banks x 16K words, segment memory 2 banks x 48K (even / odd lines).
constexpr long kFrameBankWords = 16 * 1024;
constexpr long kSegmentBankWords = 48 * 1024;
static_assert(kFrameBankWords == hls::kFrameBankWords && kSegmentBankWords == hls::kSegmentBankWords,
              "the kernels' memories are the SPEC's");
constexpr int kAreaCodes = 16;

// ---- Polygon lists on the formatter grid -------------------------------------------------------

// Grid unit (eq. 1: X = 2048 Xs + 2047) -> Xs, exact in binary64; values outside 0..4095 lie
// beyond the screen and are clamped by the formatter.
inline double screen_of(long grid) { return (double(grid) - 2047.0) / 2048.0; }
// The formatter's grid value of Xs or Ys: the reference's snap (bit-equal to the formatter kernel,
// verif/kernels/test_formatter.cpp).
inline long grid_of(double s) { return std::lround(kGridScale * snap_grid_coordinate(s) + kGridOffset); }

// Sample levels (output LSB) per colour channel. A polygon of colour c and intensity 1/2 shades a
// sample to c/2 in the reference (Is x colour) and in the segment processor (c x I / 256 with
// c = round(255 colour), I = round(256 Is) = 128: exact). With levels that are multiples of 16
// every pixel (the mean of its 16 samples) is an integer in both, so no rounding separates the two
// images where their samples agree. Polygon and light levels are at most 112 (c = 2 x level <= 255).
struct Level {
  int r = 0, g = 0, b = 0;
};
inline Rgb shaded_colour(Level l) { return Rgb(2.0 * l.r / 255.0, 2.0 * l.g / 255.0, 2.0 * l.b / 255.0); }
inline Rgb background_colour(Level l) { return Rgb(l.r / 255.0, l.g / 255.0, l.b / 255.0); }
// Distinct levels for polygon k (multiples of 16 in 16..112 per channel).
inline Level level_for(long k) {
  return {int(16 * (1 + k % 7)), int(16 * (1 + (k / 7) % 7)), int(16 * (1 + (k / 49) % 7))};
}

struct GridVertex {
  long x, y;
};

// A polygon on the grid; depth z (constant, so the reference's depth order is the order of z),
// intensity 1/2 at every vertex.
inline ScreenPolygon grid_polygon(const std::vector<GridVertex>& v, double z, Level level, bool opaque = true,
                                  bool protect = false) {
  ScreenPolygon p;
  for (const auto& g : v) p.vertices.push_back({screen_of(g.x), screen_of(g.y), z, 0.5});
  p.colour = shaded_colour(level);
  p.opaque = opaque;
  p.protect = protect;
  return p;
}

// A light point of diameter D grid units (eq. 1: D = 2048 Ds), intensity 1/2.
inline ScreenLightPoint grid_light(long x, long y, int diameter, double z, Level level, int priority) {
  ScreenLightPoint l;
  l.xs = screen_of(x);
  l.ys = screen_of(y);
  l.zs = z;
  l.ds = diameter / kGridScale;
  l.colour = shaded_colour(level);
  l.intensity = 0.5;
  l.priority = priority;
  return l;
}

inline ScreenFrame empty_frame(int raster, Level background) {
  ScreenFrame f;
  f.raster = raster;
  f.background = background_colour(background);
  return f;  // no fog (Fog's default range lies beyond every depth)
}

// ---- Sample lattice ------------------------------------------------------------------------------

// Sample rows and columns of an N x N raster (README, "Conventions"): pixel p spans grid units
// [u p - 1, u p - 1 + u), u = 4096 / N, and its samples lie at u p - 1 + (2s + 1) u / 8, so global
// sample k sits at u k / 4 + u / 8 - 1 grid units = u k / 2 + u / 4 - 2 half units (integers for
// N <= 1024, the segment processor's range).
struct Lattice {
  int n = 512;
  long u() const { return 4096 / n; }
  long size() const { return 4L * n; }
  long half(long k) const { return u() * k / 2 + u() / 4 - 2; }
  long spacing() const { return u() / 2; }  // half units between samples
  // First sample k (unclamped) with half(k) >= h: ceil((h - offset) / spacing).
  long first_at_or_after(long h) const {
    const long t = h - half(0), s = spacing();
    return t >= 0 ? (t + s - 1) / s : -((-t) / s);
  }
  // Samples k in 0..size-1 with half(k) in [lo, hi): [first, last] (empty when first > last).
  std::pair<long, long> in(long lo, long hi) const {
    return {std::max(0L, first_at_or_after(lo)), std::min(size() - 1, first_at_or_after(hi) - 1)};
  }
};

// ---- Brute-force recount ---------------------------------------------------------------------------

struct PolygonCount {
  std::vector<GridVertex> v;  // snapped (formatter) vertices
  long twice_area = 0;        // |eq. 5-6| x 2, grid units^2
  int code = 0;               // eq. 6 bucket; 0 protected
  bool valid = false;         // non-zero area and a sample row in [Y_top, Y_bottom)
  long first_line = 0, last_line = -1;
  long lines[2] = {0, 0};  // raster lines crossed, even / odd (one segment each)
  int edges = 0;           // edges some sample row crosses: one frame-memory word each
  int words() const { return 1 + edges; }
  // A polygon that snapping made non-convex is stored as its span pieces (hls/formatter/
  // span_pieces.hpp, whose exactness verif/kernels/test_span_pieces.cpp proves): one frame-memory
  // entry each (header and two edges), with the polygon's code. Empty for a convex polygon, which
  // is one entry described by the fields above.
  struct Entry {
    long first_line = 0, last_line = -1;
    long lines[2] = {0, 0};
    int edges = 0;
    int words() const { return 1 + edges; }
  };
  std::vector<Entry> pieces;
  std::vector<Entry> entries() const {
    if (!pieces.empty()) return pieces;
    if (!valid) return {};
    return {Entry{first_line, last_line, {lines[0], lines[1]}, edges}};
  }
};

// Area code (hls/segment/README.md): clamp(20 - floor(log2(area)), 1, 15), area = twice / 2, so
// floor(log2(area)) = floor(log2(twice)) - 1 (twice >= 1).
inline int area_code(long twice) {
  int msb = 0;
  while ((twice >> (msb + 1)) != 0) ++msb;
  return std::clamp(20 - (msb - 1), 1, 15);
}

// The span pieces of a polygon that snapping made non-convex, as entries; false for a convex one.
inline bool add_span_pieces(PolygonCount& c, const Lattice& g) {
  hls::FormattedPrimitive f;
  f.n = hls::UInt<5>(c.v.size());
  for (std::size_t k = 0; k < c.v.size(); ++k) {
    f.v[k].x = hls::UInt<12>(std::uint64_t(c.v[k].x));
    f.v[k].y = hls::UInt<12>(std::uint64_t(c.v[k].y));
  }
  auto pieces = std::make_unique<hls::SpanPieces>();
  hls::split_into_span_pieces(f, hls::raster_log2_of(g.n), *pieces);
  if (pieces->convex) return false;
  for (int k = 0; k < int(pieces->count.value()); ++k) {
    PolygonCount::Entry e;
    e.first_line = long(pieces->piece[k].row_first.value()) / 4;
    e.last_line = long(pieces->piece[k].row_last.value()) / 4;
    for (long line = e.first_line; line <= e.last_line; ++line) ++e.lines[line & 1];
    e.edges = 2;
    c.pieces.push_back(e);
  }
  c.valid = !c.pieces.empty();
  return true;
}

inline PolygonCount count_polygon(const ScreenPolygon& p, const Lattice& g) {
  PolygonCount c;
  for (const auto& v : p.vertices) c.v.push_back({grid_of(v.xs), grid_of(v.ys)});
  const std::size_t n = c.v.size();
  long twice = 0, ymin = 4096, ymax = -1;
  for (std::size_t k = 0; k < n; ++k) {
    const GridVertex &a = c.v[k], &b = c.v[(k + 1) % n];
    twice += a.x * b.y - b.x * a.y;
    ymin = std::min(ymin, a.y);
    ymax = std::max(ymax, a.y);
  }
  c.twice_area = twice < 0 ? -twice : twice;
  c.code = p.protect ? 0 : area_code(std::max(1L, c.twice_area));
  if (add_span_pieces(c, g)) return c;
  const auto rows = g.in(2 * ymin, 2 * ymax);
  c.valid = c.twice_area != 0 && rows.first <= rows.second;
  if (!c.valid) return c;
  c.first_line = rows.first / 4;
  c.last_line = rows.second / 4;
  for (long line = c.first_line; line <= c.last_line; ++line) ++c.lines[line & 1];
  for (std::size_t k = 0; k < n; ++k) {
    const long ya = c.v[k].y, yb = c.v[(k + 1) % n].y;
    if (ya == yb) continue;
    const auto r = g.in(2 * std::min(ya, yb), 2 * std::max(ya, yb));
    c.edges += r.first <= r.second ? 1 : 0;
  }
  return c;
}

// Segments of a light point: one per sample row within D/2 of its centre (the reference's disc,
// which the coding table reproduces), D = min(round(2048 Ds), 7).
inline std::vector<long> light_segment_lines(const ScreenLightPoint& l, const Lattice& g) {
  const long cy2 = 2 * grid_of(l.ys);
  const long d = std::min(std::lround(kGridScale * l.ds), 7L);
  std::vector<long> lines;
  for (long k = 0; k < g.size(); ++k)
    if (std::abs(g.half(k) - cy2) <= d) lines.push_back(k / 4);
  return lines;
}

struct FrameCount {
  int n = 512;
  std::vector<PolygonCount> polygons;
  std::vector<char> written;                       // stored in the frame memory (first fit, in list order): some entry
  std::vector<std::vector<char>> written_entries;  // per polygon, per entry (PolygonCount::entries)
  long degenerate = 0, written_count = 0, overflowed = 0, words = 0, edges = 0, protected_written = 0;
  long segments[2][kAreaCodes] = {};  // written polygons per field and code; lights in code 0
  long light_segments[2] = {0, 0};
  int threshold = 0;
  long dropped_by_code[kAreaCodes] = {};
  long dropped = 0;
  long polygon_segments = 0;  // segments of the polygons kept (code <= threshold)
  long kept[2] = {0, 0};      // segments per field reaching the Y sorter
  long stored[2] = {0, 0}, dropped_memory_full = 0;
  long per_line_max = 0;  // of the segments reaching the Y sorter
  long total_segments() const {
    long t = 0;
    for (int f = 0; f < 2; ++f)
      for (int c = 0; c < kAreaCodes; ++c) t += segments[f][c];
    return t;
  }
  // Codes 0..t fit both banks.
  bool fits(int t) const {
    for (int f = 0; f < 2; ++f) {
      long sum = 0;
      for (int c = 0; c <= t; ++c) sum += segments[f][c];
      if (sum > kSegmentBankWords) return false;
    }
    return true;
  }
};

// What the segment processor must do with a frame (SPEC D), by brute force on the snapped frame:
// polygons in list order into the frame memory while they fit; their segments counted per code
// and field, light points' segments with the protected polygons (code 0: never dropped, so they
// must fit whatever the threshold); the threshold is the largest code T (by exhaustive search)
// with the segments of codes 0..T fitting both banks, 0 when even code 0 does not fit.
inline FrameCount count_frame(const ScreenFrame& frame) {
  const Lattice g{frame.raster};
  FrameCount fc;
  fc.n = frame.raster;
  std::vector<long> per_line(std::size_t(frame.raster), 0);
  for (const auto& p : frame.polygons) {
    fc.polygons.push_back(count_polygon(p, g));
    const PolygonCount& c = fc.polygons.back();
    if (!c.valid) ++fc.degenerate;
    std::vector<char> written;  // per entry (frame-memory first fit, in list order)
    for (const PolygonCount::Entry& e : c.entries()) {
      written.push_back(fc.words + e.words() <= kFrameBankWords);
      if (!written.back()) {
        ++fc.overflowed;
        continue;
      }
      fc.words += e.words();
      ++fc.written_count;
      fc.edges += e.edges;
      fc.protected_written += p.protect ? 1 : 0;
      for (int f = 0; f < 2; ++f) fc.segments[f][c.code] += e.lines[f];
    }
    fc.written_entries.push_back(written);
    fc.written.push_back(std::count(written.begin(), written.end(), 1) > 0);
  }
  for (const auto& l : frame.light_points)
    for (long line : light_segment_lines(l, g)) {
      ++fc.light_segments[line & 1];
      ++per_line[std::size_t(line)];
    }
  for (int f = 0; f < 2; ++f) fc.segments[f][0] += fc.light_segments[f];
  fc.threshold = 0;
  for (int t = kAreaCodes - 1; t > 0; --t)
    if (fc.fits(t)) {
      fc.threshold = t;
      break;
    }
  for (std::size_t i = 0; i < fc.polygons.size(); ++i) {
    const PolygonCount& c = fc.polygons[i];
    const auto entries = c.entries();
    for (std::size_t k = 0; k < entries.size(); ++k) {
      if (!fc.written_entries[i][k]) continue;
      if (c.code > fc.threshold) {
        ++fc.dropped_by_code[c.code];
        ++fc.dropped;
        continue;
      }
      fc.polygon_segments += entries[k].lines[0] + entries[k].lines[1];
      for (int f = 0; f < 2; ++f) fc.kept[f] += entries[k].lines[f];
      for (long line = entries[k].first_line; line <= entries[k].last_line; ++line) ++per_line[std::size_t(line)];
    }
  }
  for (int f = 0; f < 2; ++f) {
    fc.kept[f] += fc.light_segments[f];
    fc.stored[f] = std::min(fc.kept[f], kSegmentBankWords);
    fc.dropped_memory_full += fc.kept[f] - fc.stored[f];
  }
  fc.per_line_max = *std::max_element(per_line.begin(), per_line.end());
  return fc;
}

// ---- Report checks ---------------------------------------------------------------------------------

inline long num(const nlohmann::ordered_json& j) { return j.get<long>(); }

// Relations every segment-engine report must satisfy, whatever the frame: what enters the Y sorter
// is stored or counted as lost; the video channel reads every stored segment; the threshold keeps
// codes 0..T (which fit both banks unless T = 0) and drops every written polygon above it; the
// protected polygons and lights (code 0) are never dropped.
inline void expect_report_self_consistent(const nlohmann::ordered_json& rep, int raster) {
  const auto& ov = rep.at("overload");
  const auto& sg = rep.at("segments");
  const auto& fm = rep.at("frame_memory");
  const int t = int(num(ov.at("threshold")));
  ASSERT_GE(t, 0);
  ASSERT_LT(t, kAreaCodes);
  EXPECT_EQ(num(ov.at("bank_capacity")), kSegmentBankWords);
  EXPECT_EQ(num(fm.at("bank_words")), kFrameBankWords);
  EXPECT_LE(num(fm.at("words_used")), kFrameBankWords);
  // The frame memory counts entries: a polygon snapping made non-convex is its span pieces.
  const long pieces_extra =
      rep.contains("span_pieces") ? num(rep.at("span_pieces")) - num(rep.at("polygons_non_convex")) : 0;
  EXPECT_EQ(num(fm.at("polygons_written")) + num(fm.at("polygons_overflowed")) + num(rep.at("polygons_degenerate")),
            num(rep.at("polygons")) + pieces_extra);
  long sum[2] = {0, 0}, kept = 0, dropped = 0, all = 0;
  for (int c = 0; c < kAreaCodes; ++c) {
    const auto& pc = ov.at("per_area_code").at(std::size_t(c));
    EXPECT_EQ(num(pc.at("code")), c);
    const long e = num(pc.at("segments_even")), o = num(pc.at("segments_odd"));
    all += e + o;
    if (c <= t) {
      sum[0] += e;
      sum[1] += o;
      kept += e + o;
      EXPECT_EQ(num(pc.at("polygons_dropped")), 0) << "code " << c << " <= threshold " << t;
    }
    dropped += num(pc.at("polygons_dropped"));
  }
  EXPECT_EQ(dropped, num(ov.at("polygons_dropped")));
  // The threshold is the largest that fits: codes 0..T fit (or T = 0), codes 0..T+1 do not.
  if (t > 0) { EXPECT_TRUE(sum[0] <= kSegmentBankWords && sum[1] <= kSegmentBankWords) << "threshold " << t; }
  if (t + 1 < kAreaCodes) {
    const auto& next = ov.at("per_area_code").at(std::size_t(t + 1));
    EXPECT_TRUE(sum[0] + num(next.at("segments_even")) > kSegmentBankWords ||
                sum[1] + num(next.at("segments_odd")) > kSegmentBankWords)
        << "threshold " << t << " is not the largest that fits";
  }
  // Code 0 holds the lights' segments too; everything kept reaches the Y sorter.
  EXPECT_EQ(num(ov.at("light_segments_even")) + num(ov.at("light_segments_odd")), num(sg.at("light")));
  EXPECT_EQ(kept, num(sg.at("polygon")) + num(sg.at("light")));
  const long stored = num(sg.at("stored_even")) + num(sg.at("stored_odd"));
  EXPECT_LE(num(sg.at("stored_even")), kSegmentBankWords);
  EXPECT_LE(num(sg.at("stored_odd")), kSegmentBankWords);
  EXPECT_EQ(stored + num(sg.at("dropped_memory_full")), num(sg.at("polygon")) + num(sg.at("light")));
  EXPECT_EQ(num(sg.at("stored_even")), std::min(sum[0], kSegmentBankWords));
  EXPECT_EQ(num(sg.at("stored_odd")), std::min(sum[1], kSegmentBankWords));
  if (t > 0) { EXPECT_EQ(num(sg.at("dropped_memory_full")), 0); }
  EXPECT_EQ(num(sg.at("read_by_video")), stored);
  EXPECT_DOUBLE_EQ(sg.at("per_line_mean").get<double>(), double(stored) / raster);
  EXPECT_LE(num(sg.at("per_line_max")), stored);
  EXPECT_GE(all, kept);
}

// The report against the brute-force recount of the same frame.
inline void expect_report_matches(const nlohmann::ordered_json& rep, const ScreenFrame& frame, const FrameCount& fc) {
  expect_report_self_consistent(rep, frame.raster);
  const auto& ov = rep.at("overload");
  const auto& sg = rep.at("segments");
  const auto& fm = rep.at("frame_memory");
  EXPECT_EQ(num(rep.at("polygons")), long(frame.polygons.size()));
  EXPECT_EQ(num(rep.at("light_points")), long(frame.light_points.size()));
  EXPECT_EQ(num(rep.at("polygons_degenerate")), fc.degenerate);
  EXPECT_EQ(num(rep.at("polygons_protected")), fc.protected_written);
  EXPECT_EQ(num(rep.at("edges")), fc.edges);
  EXPECT_EQ(num(fm.at("words_used")), fc.words);
  EXPECT_EQ(num(fm.at("polygons_written")), fc.written_count);
  EXPECT_EQ(num(fm.at("polygons_overflowed")), fc.overflowed);
  EXPECT_EQ(num(ov.at("threshold")), fc.threshold);
  EXPECT_EQ(num(ov.at("light_segments_even")), fc.light_segments[0]);
  EXPECT_EQ(num(ov.at("light_segments_odd")), fc.light_segments[1]);
  EXPECT_EQ(num(ov.at("polygons_dropped")), fc.dropped);
  for (int c = 0; c < kAreaCodes; ++c) {
    const auto& pc = ov.at("per_area_code").at(std::size_t(c));
    EXPECT_EQ(num(pc.at("segments_even")), fc.segments[0][c]) << "code " << c;
    EXPECT_EQ(num(pc.at("segments_odd")), fc.segments[1][c]) << "code " << c;
    EXPECT_EQ(num(pc.at("polygons_dropped")), fc.dropped_by_code[c]) << "code " << c;
  }
  EXPECT_EQ(num(sg.at("polygon")), fc.polygon_segments);
  EXPECT_EQ(num(sg.at("light")), fc.light_segments[0] + fc.light_segments[1]);
  EXPECT_EQ(num(sg.at("stored_even")), fc.stored[0]);
  EXPECT_EQ(num(sg.at("stored_odd")), fc.stored[1]);
  EXPECT_EQ(num(sg.at("dropped_memory_full")), fc.dropped_memory_full);
  if (fc.dropped_memory_full == 0) { EXPECT_EQ(num(sg.at("per_line_max")), fc.per_line_max); }
}

// ---- Coverage uncertainty of the engine's X --------------------------------------------------------
//
// The video channel covers sample column i of a row when left X <= X_i < right X, the reference when
// the exact edge functions say so (left edges inclusive, right exclusive); on snapped vertices the
// two agree whenever the engine's X lies on the same side of every column as the exact crossing
// x = xa + dx (Y_k - ya) / dy of the edge at that row. Derivation of the bound, fixed point (the
// kernels' structure: edge_generator.hpp, segment_generator.hpp, segment_arith.hpp):
//   * the first crossing x_first is one correctly rounded division into its format (Fc fractional
//     bits, round to nearest): error <= 2^-(Fc+1), zero when dy2 | dx 2^Fc (every crossing of the
//     edge is then a multiple of 2^-Fc; dy2 = 2 dy in half units, dx in grid units);
//   * the slope per row (eq. 2) likewise into S fractional bits: <= 2^-(S+1), zero when
//     dy2 | dx 2^(s + S) (s = log2 of the row spacing in half units);
//   * X at m rows below the edge's first row is x_first + m slope, exact in the accumulator, then
//     rounded to X (F bits): pre-rounding error delta <= 2^-(Fc+1) + m 2^-(S+1) (without the terms
//     that are exact), final error <= delta + 2^-(F+1) = eps.
// A column at distance d > 0 from x can be decided differently only if d <= eps. A column ON the
// crossing (d = 0, a multiple of 1/2 unit, hence of the X LSB) is rounded onto exactly when
// delta < 2^-(F+1) (round half up), and then decided as the reference does; otherwise it is
// uncertain. The double twin keeps x_first and the slope in binary64 (|values| < 2^14): one
// rounded division and one addition for x_first (<= 2^-39), the slope's relative 2^-53 times m
// rows plus the product's and the sum's roundings: |error| <= 2^-37 < 2^-36 = eps; zero when every
// operand is exact (dy2 | dx 2^39: at most 53 significant bits everywhere).
struct XErrorBound {
  bool twin = false;
  int frac_first = 0, frac_slope = 0, frac_x = 0;  // Fc, S, F
  template <class Fmt>
  static XErrorBound fixed() {
    using P = hls::FixedSegmentArith<Fmt>;
    using XFirst = decltype(hls::Edge<P>{}.x_first);
    return {false, XFirst::frac_bits, P::Slope::frac_bits, P::X::frac_bits};
  }
  static XErrorBound double_twin() { return {true, 39, 39, 0}; }
};

struct Uncertainty {
  int n = 512;
  std::vector<std::uint8_t> sample;  // 1: the engine may decide this sample differently
  long samples = 0;
  int at_pixel(int px, int py) const {
    int u = 0;
    const std::size_t m = std::size_t(4 * n);
    for (int sy = 0; sy < 4; ++sy)
      for (int sx = 0; sx < 4; ++sx) u += sample[std::size_t(4 * py + sy) * m + std::size_t(4 * px + sx)];
    return u;
  }
};

inline Uncertainty uncertain_samples(const ScreenFrame& frame, const XErrorBound& b) {
  const Lattice g{frame.raster};
  Uncertainty un;
  un.n = frame.raster;
  const long m = g.size();
  un.sample.assign(std::size_t(m * m), 0);
  const int s = [&] {  // log2 of the row spacing in half units
    int k = 0;
    while ((1L << k) < g.spacing()) ++k;
    return k;
  }();
  // Bounds scaled by 2^K (half units): integers.
  const int K = b.twin ? 40 : std::max({b.frac_first, b.frac_slope, b.frac_x}) + 2;
  for (const auto& p : frame.polygons) {
    const PolygonCount c = count_polygon(p, g);
    if (c.twice_area == 0) continue;
    const std::size_t n = c.v.size();
    for (std::size_t k = 0; k < n; ++k) {
      GridVertex a = c.v[k], e = c.v[(k + 1) % n];
      if (a.y == e.y) continue;
      if (e.y < a.y) std::swap(a, e);
      const long dx = e.x - a.x, dy2 = 2 * (e.y - a.y);
      const auto rows = g.in(2 * a.y, 2 * e.y);
      // dx 2^k by multiplication: a left shift of a negative value is undefined.
      const bool first_exact = i128(dx) * (i128(1) << (b.twin ? 39 : b.frac_first)) % dy2 == 0;
      const bool slope_exact = i128(dx) * (i128(1) << ((b.twin ? 39 : b.frac_slope) + s)) % dy2 == 0;
      for (long row = rows.first; row <= rows.second; ++row) {
        const long mrows = row - rows.first;
        // delta and eps in half units, times 2^K.
        i128 delta = 0, eps = 0;
        if (b.twin) {
          eps = (first_exact && slope_exact) ? 0 : i128(1) << (K - 35);  // 2^-36 units = 2^-35 half units
          delta = eps;
        } else {
          if (!first_exact) delta += i128(1) << (K - b.frac_first);      // 2 x 2^-(Fc+1)
          if (!slope_exact) delta += i128(mrows) << (K - b.frac_slope);  // 2 x m 2^-(S+1)
          eps = delta + (i128(1) << (K - b.frac_x));
        }
        if (eps == 0) continue;
        // Exact crossing in half units: x = NUM / DY.
        const i128 DY = dy2;
        const i128 NUM = i128(2 * a.x) * DY + i128(g.half(row) - 2 * a.y) * i128(2 * dx);
        const double x = double(NUM) / double(DY);
        const double e = double(eps) / double(i128(1) << K);
        const long i0 = std::max(0L, long(std::floor((x - e - double(g.half(0))) / double(g.spacing()))) - 1);
        const long i1 = std::min(m - 1, long(std::ceil((x + e - double(g.half(0))) / double(g.spacing()))) + 1);
        for (long i = i0; i <= i1; ++i) {
          const i128 dist = i128(g.half(i)) * DY - NUM;  // (column - x) x DY
          const i128 adist = dist < 0 ? -dist : dist;
          // On the column: rounded onto it unless delta reaches half an X LSB (2^-F half units).
          const bool uncertain =
              adist == 0 ? (b.twin || delta >= (i128(1) << (K - b.frac_x))) : (adist << K) <= eps * DY;
          if (uncertain && !un.sample[std::size_t(row * m + i)]) {
            un.sample[std::size_t(row * m + i)] = 1;
            ++un.samples;
          }
        }
      }
    }
  }
  return un;
}

// ---- Engine against the snapped reference ----------------------------------------------------------

struct Agreement {
  long pixels = 0, pixels_uncertain = 0, samples_uncertain = 0;
  long ids_differ = 0, values_differ = 0;  // observed
  long violations = 0;
  std::string first_violation;
  std::string summary() const {
    std::ostringstream s;
    s << pixels << " pixels, " << samples_uncertain << " uncertain samples in " << pixels_uncertain
      << " pixels; observed: " << values_differ << " pixels differ in value, " << ids_differ << " in id";
    return s.str();
  }
};

// Sample level of a colour component: polygons and lights at intensity 1/2, the background as is.
inline int level_of(double component, bool shaded) {
  return int(std::lround(component * 255.0 * (shaded ? 0.5 : 1.0)));
}

// Pixel by pixel: where no sample is uncertain, the engine's value and id equal the reference's;
// elsewhere the value differs by at most U x (largest level step) / 16 per channel, U the pixel's
// uncertain samples (each flipped sample changes the pixel's sum by at most one level step).
inline Agreement compare_with_reference(const ScreenFrame& frame, const RasterImage& got, const RasterImage& want,
                                        const Uncertainty& un) {
  int lo[3], hi[3];
  for (int c = 0; c < 3; ++c) lo[c] = hi[c] = level_of(frame.background[c], false);
  auto widen = [&](const Rgb& colour) {
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], level_of(colour[c], true));
      hi[c] = std::max(hi[c], level_of(colour[c], true));
    }
  };
  for (const auto& p : frame.polygons) widen(p.colour);
  for (const auto& l : frame.light_points) widen(l.colour);
  Agreement a;
  a.samples_uncertain = un.samples;
  const int n = frame.raster;
  for (int py = 0; py < n; ++py)
    for (int px = 0; px < n; ++px) {
      ++a.pixels;
      const int u = un.at_pixel(px, py);
      a.pixels_uncertain += u > 0;
      const std::size_t k = std::size_t(py) * std::size_t(n) + std::size_t(px);
      const bool id_differs = got.ids.id[k] != want.ids.id[k];
      a.ids_differ += id_differs;
      bool value_differs = false, ok = !(u == 0 && id_differs);
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(got.image.at(px, py)[c]) - int(want.image.at(px, py)[c]));
        value_differs = value_differs || d != 0;
        ok = ok && d <= u * (hi[c] - lo[c]) / 16;
      }
      a.values_differ += value_differs;
      if (!ok && a.violations++ == 0) {
        std::ostringstream s;
        s << "pixel (" << px << ", " << py << "): " << u << " uncertain samples; engine id " << got.ids.id[k] << " rgb "
          << int(got.image.at(px, py)[0]) << " " << int(got.image.at(px, py)[1]) << " " << int(got.image.at(px, py)[2])
          << ", reference id " << want.ids.id[k] << " rgb " << int(want.image.at(px, py)[0]) << " "
          << int(want.image.at(px, py)[1]) << " " << int(want.image.at(px, py)[2]);
        a.first_violation = s.str();
      }
    }
  return a;
}

}  // namespace cig::stress
