// Golden vectors of the segment processor's kernels (SPEC D, seed 001), default format: a fixed
// scene (hand-built polygons for every case the kernels distinguish, seeded random polygons of every
// shape, light points in the priority order) through the edge generator, the segment generator, the
// light coding table, the Y sorter and the video channel; verif/golden/segment_vectors.txt holds the
// inputs and every output (edges, segments with all fields, the rendered raster), written by
// SegmentKernels.DISABLED_WriteSegmentGoldenVectors and checked bit for bit by
// SegmentKernels.GoldenVectors (the pattern of test_formatter.cpp's golden vectors).
#include <algorithm>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/segment/edge_generator.hpp"
#include "hls/segment/light_segments.hpp"
#include "hls/segment/segment_generator.hpp"
#include "hls/segment/video_channel.hpp"
#include "hls/segment/y_sorter.hpp"
#include "segment_test_support.hpp"
#include "test_segment_kernels.hpp"

namespace cig::hls {
namespace {

using namespace segtest;
using namespace segkernels;
using P = DefaultSegmentArith;

// ---- Golden vectors ----------------------------------------------------------------------------------

std::string golden_path() { return std::string(CIG_SOURCE_DIR) + "/verif/golden/segment_vectors.txt"; }

// The golden scene: polygons and lights in priority order, the fog and the background.
struct GoldenItem {
  bool light = false;
  IntPolygon p;  // a light: v[0], d
  int d = 0;
};
struct GoldenScene {
  int log2 = 5;
  int fog_start = 0, fog_end = 0;  // e8m7 codes
  int fog[3] = {0, 0, 0}, background[3] = {0, 0, 0};
  std::vector<GoldenItem> items;
};

std::string hex(std::int64_t v) {
  char b[24];
  std::snprintf(b, sizeof b, "%s%" PRIx64, v < 0 ? "-" : "", std::uint64_t(v < 0 ? -v : v));
  return b;
}
std::string rgb(const int* c) {
  char b[8];
  std::snprintf(b, sizeof b, "%02x%02x%02x", c[0], c[1], c[2]);
  return b;
}

// The scene's lines, inputs and outputs in order: the file's content without its comments.
std::vector<std::string> golden_lines(const GoldenScene& sc) {
  std::vector<std::string> out;
  const int log2 = sc.log2, n = 1 << log2;
  auto line = [&](const std::ostringstream& s) { out.push_back(s.str()); };
  {
    std::ostringstream s;
    s << "N " << log2;
    line(s);
    std::ostringstream t;
    t << "T " << hex(sc.fog_start) << " " << hex(sc.fog_end) << " " << rgb(sc.fog) << " " << rgb(sc.background);
    line(t);
  }
  VideoRig<P, 4096> rig;
  VideoTables<P>& t = *rig.tables;
  const double zs = zvalue(sc.fog_start), ze = zvalue(sc.fog_end);
  for (int code = 0; code < (1 << 15); ++code) {
    const double f = std::clamp((zvalue(code) - zs) / (ze - zs), 0.0, 1.0);
    t.fog.f[code] = P::FogFactor::from_raw_value(std::uint64_t(std::lround(f * 256)));
  }
  for (int c = 0; c < 3; ++c) {
    t.fog_colour[c] = UInt<8>(std::uint64_t(sc.fog[c]));
    t.background[c] = UInt<8>(std::uint64_t(sc.background[c]));
  }
  y_sorter_reset(*rig.mem, n);
  auto segs = std::make_unique<Segment<P>[]>(kMaxLines);
  Segment<P>(&seg)[kMaxLines] = *reinterpret_cast<Segment<P>(*)[kMaxLines]>(segs.get());
  auto segment_line = [&](const Segment<P>& g) {
    std::ostringstream s;
    const int rf = int(g.row_first.value()), rl = int(g.row_last.value());
    s << "S " << hex(std::int64_t(g.line.value())) << " " << hex(std::int64_t(g.type.value())) << " " << rf << " "
      << rl;
    for (int r = rf; r <= rl; ++r) s << " " << hex(raw_of(g.xl[r])) << ":" << hex(raw_of(g.xr[r]));
    s << " " << hex(raw_of(g.il)) << " " << hex(raw_of(g.ir)) << " " << hex(code_of(g.zl)) << " " << hex(code_of(g.zr))
      << " " << hex(std::int64_t(g.source.value())) << " " << g.is_light << " " << g.opaque << " "
      << hex(std::int64_t(g.channel.value()));
    line(s);
    EXPECT_TRUE(y_sort(g, *rig.mem));
  };
  for (const GoldenItem& it : sc.items) {
    const IntPolygon& p = it.p;
    std::ostringstream in;
    if (it.light) {
      in << "L " << p.id << " " << p.x[0] << " " << p.y[0] << " " << p.i[0] << " " << hex(p.z[0]) << " " << it.d << " "
         << rgb(p.colour);
      line(in);
      FormattedPrimitive f = fixed_input(p);
      f.is_light = true;
      f.n = UInt<5>(1);
      f.d = UInt<3>(std::uint64_t(it.d));
      for (int c = 0; c < 3; ++c) t.light_colour[p.id][c] = UInt<8>(std::uint64_t(p.colour[c]));
      Segment<P> ls[kMaxLightSegments];
      const int k = generate_light_segments<P>(f, log2, UInt<3>(3), ls);
      for (int j = 0; j < k; ++j) segment_line(ls[j]);
      continue;
    }
    in << "P " << p.id << " " << p.opaque << " " << p.protect << " " << rgb(p.colour) << " " << p.n;
    for (int k = 0; k < p.n; ++k) in << " " << p.x[k] << "," << p.y[k] << "," << p.i[k] << "," << hex(p.z[k]);
    line(in);
    for (int c = 0; c < 3; ++c) t.polygon_colour[p.id][c] = UInt<8>(std::uint64_t(p.colour[c]));
    PolygonEdges<P> e;
    generate_edges<P>(fixed_input(p), log2, e);
    const PolygonHeader<P>& h = e.h;
    std::ostringstream hs;
    hs << "H " << e.valid << " " << hex(std::int64_t(h.area_code.value())) << " " << hex(h.twice_area.value()) << " "
       << hex(h.row_first) << " " << hex(h.row_last) << " " << hex(std::int64_t(h.segments_even.value())) << " "
       << hex(std::int64_t(h.segments_odd.value())) << " " << hex(std::int64_t(h.left_count.value())) << " "
       << hex(std::int64_t(h.right_count.value()));
    line(hs);
    if (!e.valid) continue;
    for (int side = 0; side < 2; ++side) {
      const int count = int((side ? h.right_count : h.left_count).value());
      for (int k = 0; k < count; ++k) {
        const Edge<P>& g = side ? e.right[k] : e.left[k];
        std::ostringstream es;
        es << "E " << (side ? 'R' : 'L') << " " << hex(g.row_first) << " " << hex(g.row_last) << " "
           << hex(std::int64_t(g.x_begin.value())) << "," << hex(std::int64_t(g.y_begin.value())) << ","
           << hex(std::int64_t(g.i_begin.value())) << "," << hex(code_of(g.z_begin)) << " "
           << hex(std::int64_t(g.x_end.value())) << "," << hex(std::int64_t(g.y_end.value())) << ","
           << hex(std::int64_t(g.i_end.value())) << "," << hex(code_of(g.z_end)) << " " << hex(raw_of(g.dx_per_row))
           << " " << hex(raw_of(g.x_first));
        line(es);
      }
    }
    const int k = generate_segments<P>(e, log2, UInt<3>(3), false, seg);
    for (int j = 0; j < k; ++j) segment_line(seg[j]);
  }
  for (int l = 0; l < n; ++l) {
    render_line(l, log2, *rig.mem, t, *rig.line, *rig.pixels);
    std::ostringstream s;
    s << "R " << l;
    for (int p = 0; p < n; ++p) {
      const int c[3] = {int(rig.pixels->rgb[p][0].value()), int(rig.pixels->rgb[p][1].value()),
                        int(rig.pixels->rgb[p][2].value())};
      s << " " << rgb(c) << ":" << rig.pixels->id[p];
    }
    line(s);
  }
  return out;
}

// The inputs: hand-built polygons for the cases the kernels distinguish, seeded random polygons of
// every shape, four lights interleaved in the priority order, a ground polygon last.
GoldenScene golden_scene() {
  GoldenScene sc;
  sc.fog_start = 129 * 128;  // 4 .. 64 (depth units)
  sc.fog_end = 133 * 128;
  const int fog[3] = {180, 190, 200}, bg[3] = {20, 40, 90};
  std::copy(fog, fog + 3, sc.fog);
  std::copy(bg, bg + 3, sc.background);
  int id = 0;
  auto poly = [&](std::initializer_list<std::pair<int, int>> v, bool opaque = true, bool protect = false) {
    GoldenItem it;
    IntPolygon& p = it.p;
    p.id = id;
    for (const auto& xy : v) {
      p.x[p.n] = xy.first;
      p.y[p.n] = xy.second;
      p.i[p.n] = (97 * (id + p.n)) & 255;
      p.z[p.n] = 128 * 128 + 37 * ((id + 3 * p.n) % 9);
      ++p.n;
    }
    p.colour[0] = (53 * id + 10) & 255, p.colour[1] = (101 * id + 60) & 255, p.colour[2] = (31 * id + 200) & 255;
    p.opaque = opaque;
    p.protect = protect;
    ++id;
    sc.items.push_back(it);
  };
  int light_id = 0;
  auto light = [&](int x, int y, int d, int i) {
    GoldenItem it;
    it.light = true;
    it.d = d;
    it.p.n = 1;
    it.p.id = light_id;
    it.p.x[0] = x, it.p.y[0] = y, it.p.i[0] = i, it.p.z[0] = 126 * 128 + 7 * light_id;
    it.p.colour[0] = 255, it.p.colour[1] = (60 * light_id + 120) & 255, it.p.colour[2] = (90 * light_id) & 255;
    ++light_id;
    sc.items.push_back(it);
  };
  // Lights on sample positions (at N = 32 samples lie 32 units apart, X, Y = 32 i + 15; a light
  // covers those within D / 2 <= 3.5 units of its centre).
  light(2063, 2063, 7, 255);                                                   // in front of everything
  poly({{500, 1290}, {1500, 1300}, {1000, 1400}});                             // one line tall (line 10 at N = 32)
  poly({{0, 0}, {900, 0}, {0, 700}});                                          // clamp-limit corner
  poly({{4095, 4095}, {3000, 4095}, {4095, 3500}});                            // the opposite corner
  poly({{1000, 1000}, {1600, 1000}, {1600, 1800}, {1000, 1800}});              // vertical and horizontal edges
  poly({{2000, 500}, {2600, 900}, {2000, 1500}});                              // a vertical left edge
  poly({{200, 3000}, {3900, 3100}, {3900, 3104}});                             // a sliver across the screen
  poly({{2500, 100}, {2503, 3900}, {2501, 3900}});                             // a near-vertical sliver
  poly({{100, 100}, {200, 200}, {300, 300}});                                  // collinear: zero area
  poly({{1000, 10}, {1010, 10}, {1005, 12}});                                  // between two sample rows: dropped
  poly({{600, 2200}, {1000, 2200}, {1000, 2600}, {1000, 3000}, {600, 3000}});  // a vertex mid-edge
  poly({{2200, 2200}, {3800, 2400}, {3000, 3600}}, false);                     // screen door
  poly({{3000, 200}, {4095, 200}, {4095, 1200}}, true, true);                  // protected, right border
  poly({{1200, 64}, {1400, 64}, {1300, 191}});                                 // inside one line, on its rows
  light(16, 4079, 5, 200);                                                     // the corner
  Rng rng(0x601D);
  const Shape shapes[] = {Shape::kMedium,          Shape::kSmall,  Shape::kSliver, Shape::kBorder,
                          Shape::kCollinearVertex, Shape::kMedium, Shape::kLarge,  Shape::kDegenerate};
  for (int k = 0; k < 22; ++k) {
    GoldenItem it;
    it.p = random_polygon(rng, shapes[k % 8], id++);
    sc.items.push_back(it);
    if (k == 10) light(1231, 559, 3, 128);
  }
  poly({{0, 0}, {4095, 0}, {4095, 4095}, {0, 4095}});  // the ground
  light(2991, 2991, 6, 255);                           // behind the ground: hidden
  return sc;
}

// Parses the input lines (N, T, P, L) of the file back into a scene.
bool parse_scene(const std::vector<std::string>& lines, GoldenScene& sc, std::string& error) {
  for (const std::string& l : lines) {
    std::istringstream s(l);
    std::string tag;
    s >> tag;
    auto hexval = [&](std::string v) { return int(std::stol(v, nullptr, 16)); };
    auto colour = [&](const std::string& v, int* c) {
      for (int k = 0; k < 3; ++k) c[k] = hexval(v.substr(std::size_t(2 * k), 2));
    };
    if (tag == "N") {
      s >> sc.log2;
    } else if (tag == "T") {
      std::string a, b, f, g;
      s >> a >> b >> f >> g;
      sc.fog_start = hexval(a);
      sc.fog_end = hexval(b);
      colour(f, sc.fog);
      colour(g, sc.background);
    } else if (tag == "P") {
      GoldenItem it;
      std::string c;
      s >> it.p.id >> it.p.opaque >> it.p.protect >> c >> it.p.n;
      colour(c, it.p.colour);
      if (it.p.n < 1 || it.p.n > kMaxVertices) {
        error = l;
        return false;
      }
      for (int k = 0; k < it.p.n; ++k) {
        std::string v;
        s >> v;
        char z[16] = {};
        if (std::sscanf(v.c_str(), "%d,%d,%d,%15s", &it.p.x[k], &it.p.y[k], &it.p.i[k], z) != 4) {
          error = l;
          return false;
        }
        it.p.z[k] = hexval(z);
      }
      sc.items.push_back(it);
    } else if (tag == "L") {
      GoldenItem it;
      it.light = true;
      it.p.n = 1;
      std::string z, c;
      s >> it.p.id >> it.p.x[0] >> it.p.y[0] >> it.p.i[0] >> z >> it.d >> c;
      it.p.z[0] = hexval(z);
      colour(c, it.p.colour);
      sc.items.push_back(it);
    } else {
      continue;
    }
    if (s.fail()) {
      error = l;
      return false;
    }
  }
  return true;
}

// The generator: run once (--gtest_also_run_disabled_tests --gtest_filter=*WriteSegmentGoldenVectors)
// and commit the file; the kernels are then frozen against it, bit for bit.
TEST(SegmentKernels, DISABLED_WriteSegmentGoldenVectors) {
  std::ofstream out(golden_path());
  ASSERT_TRUE(out) << golden_path();
  out << "# Segment processor golden vectors (SPEC D, seed 001), default format " << SegmentFormatDefault::name
      << ":\n"
         "# written by SegmentKernels.DISABLED_WriteSegmentGoldenVectors, checked bit for bit by\n"
         "# SegmentKernels.GoldenVectors (verif/kernels/test_segment_kernels_golden.cpp). Inputs in decimal\n"
         "# (colours rrggbb, e8m7 depth codes in hex); outputs in hex (signed: a leading '-').\n"
         "# N log2 of the raster     T fog start and end (e8m7 codes), fog colour, background\n"
         "# P id opaque protect colour n x,y,I,Z...  (a polygon, in priority order)\n"
         "#   H valid area_code twice_area row_first row_last lines_even lines_odd left_edges right_edges\n"
         "#   E L|R row_first row_last x,y,I,Z(begin) x,y,I,Z(end) slope_per_row x_first  (raw fixed point)\n"
         "#   S line type row_first row_last xl:xr (raw, per covered row) il ir zl zr source light opaque channel\n"
         "# L id x y I Z D colour  (a light point, in priority order; its S lines follow)\n"
         "# R line rrggbb:id per pixel  (the video channel's output, after every polygon and light)\n";
  for (const std::string& l : golden_lines(golden_scene())) out << l << "\n";
}

TEST(SegmentKernels, GoldenVectors) {
  std::ifstream in(golden_path());
  ASSERT_TRUE(in) << golden_path();
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l))
    if (!l.empty() && l[0] != '#') lines.push_back(l);
  GoldenScene sc;
  std::string error;
  ASSERT_TRUE(parse_scene(lines, sc, error)) << error;
  const std::vector<std::string> got = golden_lines(sc);
  ASSERT_EQ(got.size(), lines.size());
  int tags[256] = {}, light_segments = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    ASSERT_EQ(got[k], lines[k]) << "line " << k + 1 << " of the vectors (comments not counted)";
    tags[static_cast<unsigned char>(lines[k][0])] += 1;
    std::istringstream fields(lines[k]);
    std::vector<std::string> f;
    for (std::string w; fields >> w;) f.push_back(w);
    light_segments += f[0] == "S" && f.size() > 3 && f[f.size() - 3] == "1";  // ... source light opaque channel
  }
  // The file holds what it should: a few dozen polygons and their edges and segments, lights, and
  // every raster line.
  EXPECT_GE(tags[unsigned('P')], 30);
  EXPECT_GE(tags[unsigned('L')], 4);
  EXPECT_GE(light_segments, 4);
  EXPECT_GE(tags[unsigned('E')], 60);
  EXPECT_GE(tags[unsigned('S')], 150);
  EXPECT_EQ(tags[unsigned('R')], 1 << sc.log2);
}

}  // namespace

namespace segkernels {
void digest_golden(kernel_test::Digest& d) {
  for (const std::string& l : golden_lines(golden_scene()))
    for (char c : l) d.add(std::uint64_t(static_cast<unsigned char>(c)));
}
}  // namespace segkernels

}  // namespace cig::hls
