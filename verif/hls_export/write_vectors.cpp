// cig_hls_vectors OUTDIR [SCENES_DIR]: writes the golden vectors of every *_top kernel
// (OUTDIR/<top>.vec, the format of tb/tb_main.hpp) that the hand-off testbenches replay. The
// committed copies live in verif/golden/hls/; the ctest hls_export.vectors_current regenerates them
// and requires them unchanged, so a kernel whose bits change fails until its vectors are rewritten
// (and the change reviewed) with this program.
//
// Inputs: polygons of the committed polygon lists (scenes/small, scenes/stress), random convex
// polygons and light points (a fixed-seed mt19937_64, whose sequence the C++ standard fixes), and
// corner primitives; each downstream kernel takes what its upstream kernels made of them, as in
// the pipeline (formatter -> edge generator -> frame memory / segment generator -> Y sorter ->
// video channel; formatter -> quadtree setup -> PE -> mask memory / pixel processor). Stage A's
// and F's kernels take scenes through the C model: write_vectors_manager.cpp (the objects of
// scenes/airfield.json through its channels) and write_vectors_invparam.cpp (the polyhedra of
// scenes/polyhedra.json set up as the invparam engine sets them up, and the array's token stream).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "formatter/fog_table.hpp"
#include "formatter/formatter_twin.hpp"
#include "frame/screen_frame.hpp"
#include "hls/formatter/formatter.hpp"
#include "hls/quadtree/mask_memory.hpp"
#include "hls/quadtree/pe.hpp"
#include "hls/quadtree/setup.hpp"
#include "hls/quadtree/span_setup.hpp"
#include "hls/segment/edge_generator.hpp"
#include "hls/segment/light_segments.hpp"
#include "hls/segment/overload.hpp"
#include "hls/segment/segment_generator.hpp"
#include "hls/segment/span_piece_edges.hpp"
#include "hls/segment/video_channel.hpp"
#include "hls/segment/y_sorter.hpp"
#include "tb/edge_generator_top.hpp"
#include "tb/formatter_top.hpp"
#include "tb/frame_memory_write_top.hpp"
#include "tb/light_segments_top.hpp"
#include "tb/mask_memory_top.hpp"
#include "tb/overload_threshold_top.hpp"
#include "tb/quadtree_pe_top.hpp"
#include "tb/quadtree_pixel_top.hpp"
#include "tb/quadtree_setup_top.hpp"
#include "tb/quadtree_span_setup_top.hpp"
#include "tb/segment_generator_top.hpp"
#include "tb/span_piece_edges_top.hpp"
#include "tb/span_pieces_top.hpp"
#include "tb/video_channel_top.hpp"
#include "tb/y_sorter_top.hpp"
#include "vector_file.hpp"

namespace cig::hls_tb {
namespace {

using SegP = hls::DefaultSegmentArith;
using QuadP = hls::DefaultQuadArith;

class Rng {
 public:
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(gen_() >> 11) * 0x1.0p-53; }
  int below(int n) { return int(gen_() % std::uint64_t(n)); }
  bool chance(double p) { return uniform(0, 1) < p; }

 private:
  std::mt19937_64 gen_{20261125};
};

// ---- Primitives ---------------------------------------------------------------------------------
// One draw per statement: the order of a call's arguments is unspecified (g++ and clang differ).
Rgb random_colour(Rng& rng) {
  const double r = rng.uniform(0, 1), g = rng.uniform(0, 1), b = rng.uniform(0, 1);
  return Rgb(r, g, b);
}

ScreenPolygon random_polygon(Rng& rng) {
  ScreenPolygon p;
  const int n = 3 + rng.below(14);
  const double cx = rng.uniform(-1, 1), cy = rng.uniform(-1, 1);
  const double r = rng.chance(0.3) ? rng.uniform(0.001, 0.02) : rng.uniform(0.02, 0.8);
  const double squash = rng.chance(0.3) ? rng.uniform(0.01, 0.1) : 1.0;  // slivers
  const double turn = rng.uniform(0, 6.283185307179586), z0 = std::exp(rng.uniform(0, 9));
  for (int k = 0; k < n; ++k) {
    const double a = 6.283185307179586 * k / n;
    const double x = r * std::cos(a), y = r * squash * std::sin(a);
    ScreenVertex v;
    v.xs = std::clamp(cx + x * std::cos(turn) - y * std::sin(turn), -1.0, 1.0);
    v.ys = std::clamp(cy + x * std::sin(turn) + y * std::cos(turn), -1.0, 1.0);
    v.zs = z0 * std::exp(rng.uniform(0, 3));
    v.is = rng.uniform(0, 1);
    p.vertices.push_back(v);
  }
  p.colour = random_colour(rng);
  p.opaque = !rng.chance(0.15);
  p.protect = rng.chance(0.1);
  return p;
}

ScreenLightPoint random_light(Rng& rng) {
  ScreenLightPoint l;
  l.xs = rng.uniform(-1.02, 1.02);
  l.ys = rng.uniform(-1.02, 1.02);
  l.zs = std::exp(rng.uniform(0, 9));
  l.ds = rng.chance(0.2) ? 0.0 : rng.uniform(0, 0.03);
  l.colour = random_colour(rng);
  l.intensity = rng.uniform(0, 1);
  return l;
}

// Corners of the formatter's input range: the screen's edges, -0, depths at the ends of the e8m7
// range, a polygon with repeated vertices, sixteen vertices.
std::vector<ScreenPolygon> corner_polygons() {
  auto make = [](std::vector<ScreenVertex> v) {
    ScreenPolygon p;
    p.vertices = std::move(v);
    return p;
  };
  std::vector<ScreenPolygon> out;
  out.push_back(make({{-1, -1, 1, 1}, {1, -1, 1, 0}, {1, 1, 1, 1}, {-1, 1, 1, 0}}));
  out.push_back(make({{-0.0, -0.0, 1e-30, 0}, {0.5, 0, 1e30, 1}, {0, 0.5, 1e-3, 0.5}}));
  out.push_back(make({{0.1, 0.1, 10, 1}, {0.1, 0.1, 10, 1}, {0.3, 0.1, 10, 1}, {0.3, 0.1, 10, 1}, {0.2, 0.4, 10, 1}}));
  out.push_back(make({{0.2, 0.2, 5, 0.2}, {0.2000001, 0.2, 5, 0.2}, {0.2, 0.2000001, 5, 0.2}}));
  std::vector<ScreenVertex> sixteen;
  for (int k = 0; k < hls::kMaxVertices; ++k)
    sixteen.push_back({0.9 * std::cos(0.3927 * k), 0.9 * std::sin(0.3927 * k), 2.0 + k, k / 15.0});
  out.push_back(make(sixteen));
  return out;
}

struct Sources {
  std::vector<hls::RawPrimitive> raws;            // every primitive, in the order below
  std::vector<hls::FormattedPrimitive> polygons;  // formatted, non-degenerate polygons
  std::vector<hls::FormattedPrimitive> lights;    // formatted light points
};

Sources make_sources(const std::string& scenes, Rng& rng) {
  Sources s;
  std::uint16_t id = 0;
  for (const char* name : {"small/overlap.polys.json", "stress/depth10.polys.json", "stress/overload.polys.json"}) {
    const ScreenFrame f = load_polygon_list(scenes + "/" + name);
    const std::size_t step = std::max<std::size_t>(1, f.polygons.size() / 24);
    for (std::size_t k = 0; k < f.polygons.size(); k += step) s.raws.push_back(raw_from_polygon(f.polygons[k], id++));
  }
  for (const ScreenPolygon& p : corner_polygons()) s.raws.push_back(raw_from_polygon(p, id++));
  for (int k = 0; k < 40; ++k) s.raws.push_back(raw_from_polygon(random_polygon(rng), id++));
  for (int k = 0; k < 24; ++k) s.raws.push_back(raw_from_light(random_light(rng), id++));
  for (const hls::RawPrimitive& r : s.raws) {
    hls::FormattedPrimitive f;
    hls::formatter_top(r, f);
    (f.is_light ? s.lights : s.polygons).push_back(f);
  }
  return s;
}

Fog test_fog() {
  Fog fog;
  fog.colour = Rgb(0.6, 0.65, 0.7);
  fog.start = 40;
  fog.end = 3000;
  return fog;
}

// ---- Stage C and D kernels ----------------------------------------------------------------------
void write_formatter(const std::string& dir, const Sources& s) {
  VectorFile<FormatterTopCase> file(dir,
                                    "polygons of the committed polygon lists, corners, random polygons and lights");
  FormatterTopCase::Input in;
  for (const hls::RawPrimitive& r : s.raws) {
    in.in = r;
    file.add(in);
  }
}

std::vector<hls::PolygonEdges<SegP>> edges_of(const std::vector<hls::FormattedPrimitive>& polygons, int log2) {
  std::vector<hls::PolygonEdges<SegP>> out;
  for (const hls::FormattedPrimitive& f : polygons) {
    out.emplace_back();
    hls::edge_generator_top(f, hls::UInt<4>(log2), out.back());
  }
  return out;
}

void write_edge_generator(const std::string& dir, const Sources& s) {
  VectorFile<EdgeGeneratorTopCase> file(dir, "the formatted polygons at rasters 64, 512 and 1024");
  auto in = std::make_unique<EdgeGeneratorTopCase::Input>();
  for (int log2 : {6, 9, 10})
    for (std::size_t k = 0; k < s.polygons.size(); k += log2 == 9 ? 1 : 3) {
      in->in = s.polygons[k];
      in->raster_log2 = hls::UInt<4>(log2);
      file.add(*in);
    }
}

void write_frame_memory(const std::string& dir, const Sources& s) {
  VectorFile<FrameMemoryWriteTopCase> file(dir, "an empty bank, a bank of the other field, a bank near full");
  const auto edges = edges_of(s.polygons, 9);
  for (int run = 0; run < 3; ++run) {
    auto in = std::make_unique<FrameMemoryWriteTopCase::Input>();  // large: never on the stack
    in->memory.write_bank = run == 1 ? 1 : 0;
    if (run == 2) in->memory.used[0] = hls::kFrameBankWords - 40;
    in->calls = FrameMemoryWriteTopCase::kCalls;
    for (int k = 0; k < in->calls; ++k) in->e[k] = edges[(std::size_t(run) * 17 + std::size_t(k)) % edges.size()];
    file.add(*in);
  }
}

void write_overload(const std::string& dir, const Sources& s, Rng& rng) {
  VectorFile<OverloadThresholdTopCase> file(dir, "the polygons' segment counts at three rasters, random counts");
  OverloadThresholdTopCase::Input in;
  for (int log2 : {6, 9, 10}) {
    hls::overload_reset(in.c);
    for (const auto& e : edges_of(s.polygons, log2))
      if (e.valid) hls::overload_count(e.h, in.c);
    for (int capacity : {0, 50, 400, 3000, 49152}) {
      in.bank_capacity = capacity;
      file.add(in);
    }
  }
  for (int k = 0; k < 20; ++k) {
    for (int f = 0; f < 2; ++f)
      for (int a = 0; a < hls::kAreaCodes; ++a)
        in.c.segments[f][a] = hls::UInt<24>(rng.chance(0.3) ? 0 : rng.below(k < 18 ? 5000 : 1 << 24));
    in.bank_capacity = rng.below(60000);
    file.add(in);
  }
}

void write_segment_generator(const std::string& dir, const Sources& s, Rng& rng) {
  VectorFile<SegmentGeneratorTopCase> file(dir, "the polygons' edge chains at rasters 64, 256 and 512");
  auto in = std::make_unique<SegmentGeneratorTopCase::Input>();
  for (int log2 : {6, 8, 9}) {
    const auto edges = edges_of(s.polygons, log2);
    for (std::size_t k = 0; k < edges.size(); k += log2 == 6 ? 1 : 2) {
      in->in = edges[k];
      in->raster_log2 = hls::UInt<4>(log2);
      in->channel = hls::UInt<3>(rng.below(8));
      file.add(*in);
    }
  }
}

void write_light_segments(const std::string& dir, const Sources& s) {
  VectorFile<LightSegmentsTopCase> file(dir, "random light points at rasters 64, 512 and 1024");
  LightSegmentsTopCase::Input in;
  int channel = 0;
  for (int log2 : {6, 9, 10})
    for (const hls::FormattedPrimitive& l : s.lights) {
      in.light = l;
      in.raster_log2 = hls::UInt<4>(log2);
      in.channel = hls::UInt<3>(channel++ % 8);
      file.add(in);
    }
}

// Every segment of the polygons and lights at one raster, in priority order.
std::vector<hls::Segment<SegP>> segments_of(const Sources& s, int log2) {
  std::vector<hls::Segment<SegP>> out;
  struct Lines {
    hls::Segment<SegP> s[hls::kMaxLines];
  };
  const auto buffer = std::make_unique<Lines>();
  auto& lines = buffer->s;
  for (const auto& e : edges_of(s.polygons, log2)) {
    const int n = hls::segment_generator_top(e, hls::UInt<4>(log2), hls::UInt<3>(0), lines);
    out.insert(out.end(), lines, lines + n);
  }
  for (const hls::FormattedPrimitive& l : s.lights) {
    hls::Segment<SegP> chords[hls::kMaxLightSegments];
    const int n = hls::light_segments_top(l, hls::UInt<4>(log2), hls::UInt<3>(0), chords);
    out.insert(out.end(), chords, chords + n);
  }
  return out;
}

void write_y_sorter(const std::string& dir, const Sources& s) {
  VectorFile<YSorterTopCase> file(dir, "segments of raster 64 and 512 into a reset memory, and into a near-full bank");
  for (int run = 0; run < 3; ++run) {
    const int log2 = run == 0 ? 6 : 9;
    const auto segments = segments_of(s, log2);
    auto in = std::make_unique<YSorterTopCase::Input>();
    hls::y_sorter_reset(in->memory, 1 << log2);
    if (run == 2) in->memory.used[0] = in->memory.used[1] = hls::kSegmentBankWords - 20;
    in->calls = YSorterTopCase::kCalls;
    for (int k = 0; k < in->calls; ++k)
      in->s[k] = segments[(std::size_t(run) * 101 + std::size_t(k)) % segments.size()];
    file.add(*in);
  }
}

void write_video_channel(const std::string& dir, const Sources& s) {
  VectorFile<VideoChannelTopCase> file(
      dir, "a frame of every polygon and light at rasters 64 (seed interpolation) and 128 (planes), fogged");
  const Fog fog = test_fog();
  for (int log2 : {6, 7}) {
    auto in = std::make_unique<VideoChannelTopCase::Input>();
    in->raster_log2 = hls::UInt<4>(log2);
    hls::y_sorter_reset(in->memory, 1 << log2);
    for (const auto& seg : segments_of(s, log2)) hls::y_sorter_top(seg, in->memory);
    for (const auto& p : s.polygons) {
      for (int c = 0; c < 3; ++c) in->tables.polygon_colour[p.id.value()][c] = p.colour[c];
      hls::PolygonEdges<hls::DefaultSegmentArith> edges;  // the planes travel with the header
      hls::edge_generator_top(p, hls::UInt<4>(log2), edges);
      in->tables.polygon_planes[p.id.value()] = edges.h.planes;
    }
    for (const auto& l : s.lights)
      for (int c = 0; c < 3; ++c) in->tables.light_colour[l.id.value()][c] = l.colour[c];
    fill_fog_table(in->tables.fog, fog, false);
    fill_fog_table(in->tables.fog_inverse, fog, true);
    in->tables.plane_mode = log2 == 7;  // raster 64: the seed's eq. 3-4 (interp=seed)
    for (int c = 0; c < 3; ++c) {
      in->tables.fog_colour[c] = hls::UInt<8>(int(std::lround(fog.colour[c] * 255)));
      in->tables.background[c] = hls::UInt<8>(40 + 60 * c);
    }
    in->lines = VideoChannelTopCase::kLines;
    for (int k = 0; k < in->lines; ++k) in->line[k] = hls::UInt<10>((k * 37 + 3) % (1 << log2));
    file.add(*in);
  }
}

// ---- Quadtree kernels ---------------------------------------------------------------------------
void write_quadtree_setup(const std::string& dir, const Sources& s) {
  VectorFile<QuadtreeSetupTopCase> file(dir, "the formatted polygons at rasters 64, 512 and 1024");
  auto in = std::make_unique<QuadtreeSetupTopCase::Input>();
  for (int log2 : {6, 9, 10})
    for (std::size_t k = 0; k < s.polygons.size(); k += log2 == 9 ? 1 : 3) {
      in->f = s.polygons[k];
      in->raster_log2 = hls::UInt<4>(log2);
      file.add(*in);
    }
}

// Windows on random paths from the polygons' roots down to the pixel level: every window a PE
// evaluates (paths[level]), and the pixel-level children with their samples.
struct Descent {
  std::vector<hls::QuadWindow<QuadP>> windows;
  std::vector<hls::QuadChild<QuadP>> pixels;
};

Descent descend(const Sources& s, int log2, Rng& rng) {
  Descent d;
  for (const hls::FormattedPrimitive& f : s.polygons) {
    auto setup = std::make_unique<hls::QuadSetup<QuadP>>();
    hls::quadtree_setup_top(f, hls::UInt<4>(log2), *setup);
    for (int piece = 0; piece < int(setup->pieces.value()); ++piece) {
      hls::QuadWindow<QuadP> w = setup->root[piece];
      for (int level = 0; level < log2; ++level) {
        d.windows.push_back(w);
        hls::QuadChild<QuadP> children[hls::kQuadChildren];
        hls::quadtree_pe_top(w, hls::UInt<4>(0), hls::UInt<4>(log2), children);
        int covered[hls::kQuadChildren], n = 0;
        for (int q = 0; q < hls::kQuadChildren; ++q)
          if (children[q].covered) covered[n++] = q;
        if (n == 0) break;
        const hls::QuadChild<QuadP>& c = children[covered[rng.below(n)]];
        if (level + 1 == log2) d.pixels.push_back(c);
        w = c.window;
      }
    }
  }
  return d;
}

void write_quadtree_pe(const std::string& dir, const Sources& s, Rng& rng) {
  VectorFile<QuadtreePeTopCase> file(dir, "windows on random paths from the polygons' roots at rasters 64 and 512");
  auto in = std::make_unique<QuadtreePeTopCase::Input>();
  for (int log2 : {6, 9}) {
    const Descent d = descend(s, log2, rng);
    for (std::size_t k = 0; k < d.windows.size(); k += 5) {
      in->w = d.windows[k];
      in->mask_word = hls::UInt<4>(rng.chance(0.7) ? 0 : rng.below(16));
      in->raster_log2 = hls::UInt<4>(log2);
      file.add(*in);
    }
  }
}

void write_mask_memory(const std::string& dir, Rng& rng) {
  VectorFile<MaskMemoryTopCase> file(dir, "requests that fill parents (and propagate up), and random requests");
  for (int log2 : {3, 6, 10}) {
    auto in = std::make_unique<MaskMemoryTopCase::Input>();
    in->calls = MaskMemoryTopCase::kCalls;
    for (int k = 0; k < in->calls; ++k) {
      // Requests come in groups of four: the children of one window, so that full parents occur.
      // A request names a window of level 0..n-1 (its mask word; children at level n are pixels).
      const int level = (k / 4 * 7 + log2) % log2, side = 1 << level;
      const int x = (k / 4 * 5) % side, y = (k / 4 * 3) % side;
      const bool random = rng.chance(0.25);
      in->level[k] = hls::UInt<4>(level);
      in->x[k] = hls::UInt<10>(random ? rng.below(side) : x);
      in->y[k] = hls::UInt<10>(random ? rng.below(side) : y);
      in->child[k] = hls::UInt<2>(random ? rng.below(4) : k % 4);
    }
    file.add(*in);
  }
}

void write_quadtree_pixel(const std::string& dir, const Sources& s, Rng& rng) {
  VectorFile<QuadtreePixelTopCase> file(dir, "pixel-level windows of the polygons, lights in front and behind, fogged");
  auto in = std::make_unique<QuadtreePixelTopCase::Input>();
  const Fog fog = test_fog();
  fill_fog_table(in->tables.fog, fog, true);
  for (int c = 0; c < 3; ++c) {
    in->tables.fog_colour[c] = hls::UInt<8>(int(std::lround(fog.colour[c] * 255)));
    in->tables.background[c] = hls::UInt<8>(30 + 70 * c);
  }
  const Descent d = descend(s, 9, rng);
  for (int run = 0; run < 6; ++run) {
    in->lights = {};
    if (run % 2 == 1) {
      in->lights.mask = hls::PixelSampleMask(rng.below(1 << 16));
      for (int k = 0; k < hls::kSamplesPerPixel; ++k) {
        in->lights.priority[k] = hls::UInt<17>(rng.below(200));
        for (int c = 0; c < 3; ++c)
          in->lights.colour[k][c] = QuadP::Sample::from_raw_value(std::uint64_t(rng.below(1 << 16)));
      }
    }
    in->state = {};
    in->calls = QuadtreePixelTopCase::kCalls;
    for (int k = 0; k < in->calls; ++k) {
      const hls::QuadChild<QuadP>& c = d.pixels[std::size_t(rng.below(int(d.pixels.size())))];
      in->px[k] = c.window;
      in->samples[k] = rng.chance(0.8) ? c.samples : hls::PixelSampleMask(rng.below(1 << 16));
    }
    file.add(*in);
  }
}

// ---- Span pieces (polygons that snapping made non-convex) ------------------------------------------
// Formatted polygons the snap bent: thin polygons with nearly collinear vertices rounded to the
// grid (reflex vertices, bow-ties), and random stars (many crossings); attributes from the sources.
std::vector<hls::FormattedPrimitive> bent_polygons(const Sources& s, Rng& rng) {
  std::vector<hls::FormattedPrimitive> out;
  auto pieces = std::make_unique<hls::SpanPieces>();
  for (int t = 0; out.size() < 40 && t < 20000; ++t) {
    hls::FormattedPrimitive f = s.polygons[std::size_t(t) % s.polygons.size()];
    const bool star = t % 4 == 0;
    const int n = star ? 3 + rng.below(14) : 4 + 2 * rng.below(7);
    const double cx = rng.uniform(100, 3900), cy = rng.uniform(100, 3900), angle = rng.uniform(0, 6.283185307179586);
    const double length = rng.uniform(8, 300), width = rng.uniform(0, 2.5), box = rng.uniform(20, 200);
    f.n = hls::UInt<5>(n);
    for (int k = 0; k < n; ++k) {
      double x = cx + rng.uniform(-box, box), y = cy + rng.uniform(-box, box);
      if (!star) {  // along a thin quadrilateral's two long sides, nearly collinear
        const int half = n / 2, side = k < half ? 0 : 1, j = side == 0 ? k : n - 1 - k;
        const double along = (double(j) / (half - 1) - 0.5) * length, across = (side ? -0.5 : 0.5) * width;
        x = cx + along * std::cos(angle) - across * std::sin(angle) + rng.uniform(-0.4, 0.4);
        y = cy + along * std::sin(angle) + across * std::cos(angle) + rng.uniform(-0.4, 0.4);
      }
      f.v[k].x = hls::UInt<12>(std::uint64_t(std::lround(std::clamp(x, 0.0, 4095.0))));
      f.v[k].y = hls::UInt<12>(std::uint64_t(std::lround(std::clamp(y, 0.0, 4095.0))));
    }
    hls::split_into_span_pieces(f, 9, *pieces);
    if (!pieces->convex && pieces->count.value() > 0) out.push_back(f);
  }
  return out;
}

void write_span_pieces(const std::string& dir, const std::vector<hls::FormattedPrimitive>& bent, const Sources& s) {
  VectorFile<SpanPiecesTopCase> file(
      dir, "polygons the snap bent (thin ones, stars) at rasters 64, 512, 1024, and convex ones");
  auto in = std::make_unique<SpanPiecesTopCase::Input>();
  for (int log2 : {6, 9, 10})
    for (const auto& f : bent) {
      in->in = f;
      in->raster_log2 = hls::UInt<4>(log2);
      file.add(*in);
    }
  for (std::size_t k = 0; k < s.polygons.size(); k += 8) {
    in->in = s.polygons[k];
    in->raster_log2 = hls::UInt<4>(9);
    file.add(*in);
  }
}

// Every piece of a bent polygon at one raster, with the polygon: f(polygon, piece).
template <class F>
void for_each_piece(const std::vector<hls::FormattedPrimitive>& bent, int log2, std::size_t every, F&& f) {
  auto pieces = std::make_unique<hls::SpanPieces>();
  std::size_t n = 0;
  for (const auto& poly : bent) {
    hls::split_into_span_pieces(poly, log2, *pieces);
    for (int k = 0; k < int(pieces->count.value()); ++k)
      if (n++ % every == 0) f(poly, pieces->piece[k]);
  }
}

void write_span_piece_edges(const std::string& dir, const std::vector<hls::FormattedPrimitive>& bent) {
  VectorFile<SpanPieceEdgesTopCase> file(dir, "pieces of polygons the snap bent, at rasters 64 and 512");
  auto in = std::make_unique<SpanPieceEdgesTopCase::Input>();
  for (int log2 : {6, 9})
    for_each_piece(bent, log2, 3, [&](const hls::FormattedPrimitive& f, const hls::SpanPiece& piece) {
      in->in = f;
      in->piece = piece;
      in->raster_log2 = hls::UInt<4>(log2);
      file.add(*in);
    });
}

void write_quadtree_span_setup(const std::string& dir, const std::vector<hls::FormattedPrimitive>& bent) {
  VectorFile<QuadtreeSpanSetupTopCase> file(dir, "pieces of polygons the snap bent, at rasters 64 and 512");
  auto in = std::make_unique<QuadtreeSpanSetupTopCase::Input>();
  for (int log2 : {6, 9})
    for_each_piece(bent, log2, 3, [&](const hls::FormattedPrimitive& f, const hls::SpanPiece& piece) {
      in->f = f;
      in->piece = piece;
      in->raster_log2 = hls::UInt<4>(log2);
      file.add(*in);
    });
}

void write_all(const std::string& dir, const std::string& scenes) {
  Rng rng;
  const Sources s = make_sources(scenes, rng);
  write_formatter(dir, s);
  write_edge_generator(dir, s);
  write_frame_memory(dir, s);
  write_overload(dir, s, rng);
  write_segment_generator(dir, s, rng);
  write_light_segments(dir, s);
  write_y_sorter(dir, s);
  write_video_channel(dir, s);
  write_quadtree_setup(dir, s);
  write_quadtree_pe(dir, s, rng);
  write_mask_memory(dir, rng);
  write_quadtree_pixel(dir, s, rng);
  const auto bent = bent_polygons(s, rng);
  write_span_pieces(dir, bent, s);
  write_span_piece_edges(dir, bent);
  write_quadtree_span_setup(dir, bent);
  write_manager_vectors(dir, scenes);
  write_invparam_vectors(dir, scenes);
}

}  // namespace
}  // namespace cig::hls_tb

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: cig_hls_vectors OUTDIR SCENES_DIR\n";
    return 2;
  }
  try {
    cig::hls_tb::write_all(argv[1], argv[2]);
  } catch (const std::exception& e) {
    std::cerr << "cig_hls_vectors: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
