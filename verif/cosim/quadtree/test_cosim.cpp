// Co-simulation of the quadtree RTL against the kernels and the architecture model (cosim.hpp):
// zero data mismatches and zero cycle mismatches, for the pipeline (np) and the pipeline-tree
// (kp(n-k)t), on single polygons, random polygons, slivers, full-screen polygons, a scene of depth
// complexity 10 with masks, the airfield's polygon stream (as the quadtree engine runs it, its fan
// split on) over several frames, and with random input gaps and output back-pressure (which the
// model replays, so it predicts the stalled cycle counts too). Each failure prints the first
// mismatch in detail.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "cosim.hpp"
#include "frame/screen_frame.hpp"
#include "generator/image_generator.hpp"
#include "scene/scene_loader.hpp"

namespace cig::cosim {
namespace {

using Rng = std::mt19937_64;
double uniform(Rng& r, double a, double b) { return a + (b - a) * double(r() >> 11) * 0x1.0p-53; }

ScreenFrame empty_frame(int raster) {
  ScreenFrame f;
  f.raster = raster;
  f.fog.colour = {0.5, 0.5, 0.55};
  f.fog.start = 20;
  f.fog.end = 300;
  f.background = {0.05, 0.05, 0.1};
  return f;
}

ScreenPolygon polygon(std::vector<std::array<double, 2>> xy, double z, Rng& r, bool opaque = true) {
  ScreenPolygon p;
  for (const auto& v : xy) p.vertices.push_back({v[0], v[1], z + uniform(r, 0, 5), uniform(r, 0.2, 1.0)});
  p.colour = {uniform(r, 0.1, 1), uniform(r, 0.1, 1), uniform(r, 0.1, 1)};
  p.opaque = opaque;
  return p;
}

// A random convex polygon: points on an ellipse, in order.
ScreenPolygon random_polygon(Rng& r, double size, double z) {
  const double cx = uniform(r, -0.9, 0.9), cy = uniform(r, -0.9, 0.9);
  const double a = uniform(r, 0.3, 1.0) * size, b = uniform(r, 0.3, 1.0) * size, rot = uniform(r, 0, 3.14159);
  const int n = 3 + int(r() % 6);
  std::vector<double> angles;
  for (int k = 0; k < n; ++k) angles.push_back(uniform(r, 0, 6.28318));
  std::sort(angles.begin(), angles.end());
  std::vector<std::array<double, 2>> xy;
  for (double t : angles) {
    const double u = a * std::cos(t), v = b * std::sin(t);
    xy.push_back({std::clamp(cx + u * std::cos(rot) - v * std::sin(rot), -1.0, 1.0),
                  std::clamp(cy + u * std::sin(rot) + v * std::cos(rot), -1.0, 1.0)});
  }
  return polygon(xy, z, r, (r() % 4) != 0);
}

// FST tracing on demand: CIG_COSIM_TRACE_DIR=DIR writes every run's waveform to
// DIR/<test>_<n>.fst (a failing test's waveform, to open in gtkwave).
void trace_on_demand(RtlRunner& rtl) {
  static int run = 0;
  const char* dir = std::getenv("CIG_COSIM_TRACE_DIR");
  if (!dir || !*dir) return;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  rtl.trace_to(std::string(dir) + "/" + info->name() + "_" + std::to_string(run++) + ".fst");
}

// The mutation test's builds (verif/mutation: CIG_COSIM_SOME_CONFIGS) have only the
// configurations a mutant names, and a run skips the others; in every other build a missing
// configuration fails (make_rtl_runner gives nullptr).
bool configuration_missing(int raster_log2, int tree_levels) {
#ifdef CIG_COSIM_SOME_CONFIGS
  for (const RtlConfig& c : rtl_configs())
    if (c.raster_log2 == raster_log2 && c.tree_levels == tree_levels) return false;
  return true;
#else
  (void)raster_log2;
  (void)tree_levels;
  return false;
#endif
}

void expect_equal(const ScreenFrame& frame, int raster_log2, int tree_levels, const StallConfig& stalls = {}) {
  if (configuration_missing(raster_log2, tree_levels)) return;
  SCOPED_TRACE("raster " + std::to_string(1 << raster_log2) + ", tree levels " + std::to_string(tree_levels));
  auto rtl = make_rtl_runner(raster_log2, tree_levels);
  ASSERT_TRUE(rtl != nullptr);
  trace_on_demand(*rtl);
  const RtlConfig cfg{raster_log2, tree_levels};
  const CosimResult r = cosim_frame(frame, *rtl, cfg, stalls);
  EXPECT_TRUE(r.comparison.ok()) << r.comparison.mismatches << " mismatches of " << r.comparison.records_compared
                                 << " records; cycles model " << r.model.cycles << " RTL " << r.rtl.cycles
                                 << "\nfirst: " << r.comparison.first;
  EXPECT_GT(r.comparison.records_compared, 0);
  EXPECT_EQ(r.model.cycles, r.rtl.cycles);
}

TEST(Cosim, SinglePolygons) {
  Rng r(1);
  const std::vector<std::vector<std::array<double, 2>>> shapes = {
      {{-0.5, -0.5}, {0.6, -0.3}, {0.0, 0.7}},               // triangle
      {{-0.2, -0.2}, {0.2, -0.2}, {0.2, 0.2}, {-0.2, 0.2}},  // square
      {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}},                  // the whole screen
      {{0.01, 0.01}, {0.03, 0.012}, {0.02, 0.04}},           // sub-pixel
      {{-0.9, 0.2}, {0.9, 0.22}, {0.9, 0.24}},               // sliver
  };
  for (const auto& xy : shapes) {
    ScreenFrame f = empty_frame(64);
    f.polygons.push_back(polygon(xy, 30, r));
    for (int t = 1; t <= 2; ++t) expect_equal(f, 6, t);
  }
}

TEST(Cosim, RandomPolygons) {
  Rng r(2);
  ScreenFrame f = empty_frame(64);
  for (int k = 0; k < 150; ++k) f.polygons.push_back(random_polygon(r, uniform(r, 0.02, 0.6), 10 + k));
  for (int t = 1; t <= 2; ++t) expect_equal(f, 6, t);
}

TEST(Cosim, Slivers) {
  Rng r(3);
  ScreenFrame f = empty_frame(64);
  for (int k = 0; k < 60; ++k) {
    const double x0 = uniform(r, -1, 1), y0 = uniform(r, -1, 1), x1 = uniform(r, -1, 1), y1 = uniform(r, -1, 1);
    const double w = uniform(r, 0.001, 0.03);
    const double dx = x1 - x0, dy = y1 - y0, len = std::hypot(dx, dy) + 1e-9;
    f.polygons.push_back(polygon(
        {{x0, y0}, {x1, y1}, {std::clamp(x1 - dy / len * w, -1.0, 1.0), std::clamp(y1 + dx / len * w, -1.0, 1.0)}},
        10 + k, r));
  }
  for (int t = 1; t <= 2; ++t) expect_equal(f, 6, t);
}

TEST(Cosim, FullScreenLayersWithMasks) {
  Rng r(4);
  ScreenFrame f = empty_frame(64);
  for (int k = 0; k < 6; ++k) f.polygons.push_back(polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, 10 + 10 * k, r));
  for (int t = 1; t <= 2; ++t) expect_equal(f, 6, t);
}

TEST(Cosim, LightPoints) {
  Rng r(5);
  ScreenFrame f = empty_frame(64);
  for (int k = 0; k < 40; ++k) f.polygons.push_back(random_polygon(r, uniform(r, 0.05, 0.5), 10 + k));
  for (int k = 0; k < 30; ++k) {
    ScreenLightPoint l;
    l.xs = uniform(r, -0.95, 0.95);
    l.ys = uniform(r, -0.95, 0.95);
    l.zs = uniform(r, 5, 60);
    l.ds = uniform(r, 0.0005, 0.0035);
    l.colour = {1.0, uniform(r, 0.5, 1), uniform(r, 0.2, 0.9)};
    l.priority = std::int32_t(r() % 41);
    f.light_points.push_back(l);
  }
  for (int t = 1; t <= 2; ++t) expect_equal(f, 6, t);
}

TEST(Cosim, StallsRandomGapsAndBackPressure) {
  Rng r(6);
  ScreenFrame f = empty_frame(64);
  for (int k = 0; k < 80; ++k) f.polygons.push_back(random_polygon(r, uniform(r, 0.02, 0.5), 10 + k));
  for (std::uint32_t seed : {11u, 12u})
    for (int t = 1; t <= 2; ++t) expect_equal(f, 6, t, StallConfig{seed, 35, 40});
}

// The start window (ArchConfig::start_window, the RTL's start_window_i): RTL and model equal record
// for record and cycle for cycle with the option on (and off, above); on gives the image of off in
// no more cycles.
void expect_start_window(const ScreenFrame& f, int raster_log2, int tree_levels, StallConfig stalls = {}) {
  if (configuration_missing(raster_log2, tree_levels)) return;
  SCOPED_TRACE("start window, raster " + std::to_string(1 << raster_log2) + ", tree levels " +
               std::to_string(tree_levels));
  auto rtl = make_rtl_runner(raster_log2, tree_levels);
  ASSERT_TRUE(rtl != nullptr);
  const RtlConfig cfg{raster_log2, tree_levels};
  stalls.start_window = false;
  const CosimResult off = cosim_frame(f, *rtl, cfg, stalls);
  stalls.start_window = true;
  const CosimResult on = cosim_frame(f, *rtl, cfg, stalls);
  for (const CosimResult* r : {&off, &on})
    EXPECT_TRUE(r->comparison.ok()) << r->comparison.mismatches << " mismatches of " << r->comparison.records_compared
                                    << " records; cycles model " << r->model.cycles << " RTL " << r->rtl.cycles
                                    << "\nfirst: " << r->comparison.first;
  EXPECT_EQ(on.rtl.image.rgb, off.rtl.image.rgb);
  EXPECT_EQ(on.model.image.rgb, off.model.image.rgb);
  if (stalls.input_gap_percent == 0 && stalls.output_stall_percent == 0) { EXPECT_LE(on.rtl.cycles, off.rtl.cycles); }
}

TEST(Cosim, StartWindow) {
  Rng r(8);
  ScreenFrame f = empty_frame(64);
  for (int k = 0; k < 100; ++k) f.polygons.push_back(random_polygon(r, uniform(r, 0.01, 0.4), 10 + k));
  for (int t = 1; t <= 2; ++t) {
    expect_start_window(f, 6, t);
    expect_start_window(f, 6, t, StallConfig{13, 30, 30});
  }
}

TEST(Cosim, StartWindowAirfield) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  ImageGenerator pipeline(scene);
  nlohmann::ordered_json rep;
  const ScreenFrame f = pipeline.geometry(0, 1, rep);
  for (int t = 1; t <= 2; ++t) expect_start_window(f, 9, t);
}

// More lit pixels than the RTL's light-cover table holds (its LIGHT_COVERS, read from the
// Verilated model): a clear input error before any cycle.
TEST(Cosim, TooManyLitPixelsIsAnInputError) {
  auto rtl = make_rtl_runner(9, 1);
  ASSERT_TRUE(rtl != nullptr);
  const int covers = rtl->params().light_covers;
  ASSERT_EQ(covers, 4096);  // the default the README documents
  ScreenFrame f = empty_frame(512);
  for (int k = 0; k < covers + 100; ++k) {
    ScreenLightPoint l;
    l.xs = -0.99 + 1.98 * double(k % 100) / 100.0;
    l.ys = -0.99 + 1.98 * double(k / 100) / 100.0;
    l.zs = 50;
    l.ds = 0.003;  // a disc of 6 grid units: 3 sample columns (min(2048 Ds, 7), eq. 1)
    l.colour = {1, 1, 1};
    f.light_points.push_back(l);
  }
  try {
    cosim_frame(f, *rtl, RtlConfig{9, 1}, {});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("light-cover table (LIGHT_COVERS) holds " + std::to_string(covers)),
              std::string::npos)
        << e.what();
  }
}

TEST(Cosim, DepthComplexityTen) {
  const ScreenFrame f = load_polygon_list(std::string(CIG_SOURCE_DIR) + "/scenes/stress/depth10.polys.json");
  ASSERT_EQ(f.raster, 512);
  for (int t = 1; t <= 2; ++t) expect_equal(f, 9, t);
}

// The airfield's centre channel as the quadtree engine runs it (its fan split on): frame 60 at
// 7p2t, frame 120 at 9p. Frame 0 at both is cosim.engine_cycles_airfield's (`cig cosim`, whose
// cycles it compares with `cig render --engine quadtree`'s).
TEST(Cosim, AirfieldFrames) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/airfield.json");
  ImageGenerator pipeline(scene);
  for (int frame : {60, 120}) {
    nlohmann::ordered_json rep;
    const ScreenFrame f = pipeline.geometry(frame, 1, rep);
    SCOPED_TRACE("airfield frame " + std::to_string(frame));
    const RtlConfig cfg{9, frame == 60 ? 2 : 1};
    expect_equal(engine_stream(*quadtree_engine(cfg, {}, true), f).frame, 9, cfg.tree_levels);
  }
}

// A frame with no polygon (everything culled): both sides take the frame-start cycle and nothing
// else, with or without stalls, and the image is the background.
TEST(Cosim, EmptyFrameTakesTheFrameStartCycleOnBothSides) {
  for (int t = 1; t <= 2; ++t)
    for (const StallConfig stalls : {StallConfig{}, StallConfig{7, 50, 50}}) {
      if (configuration_missing(6, t)) continue;
      SCOPED_TRACE("tree levels " + std::to_string(t) + ", stalls " + std::to_string(stalls.input_gap_percent));
      auto rtl = make_rtl_runner(6, t);
      const CosimResult r = cosim_frame(empty_frame(64), *rtl, RtlConfig{6, t}, stalls);
      EXPECT_TRUE(r.comparison.ok()) << r.comparison.first;
      EXPECT_EQ(r.comparison.records_compared, 64 * 64);  // the image, all background; no window record
      EXPECT_EQ(r.model.cycles, 1);
      EXPECT_EQ(r.rtl.cycles, 1);
    }
}

// Frames through ONE Verilated instance, reset once when it is made and never again: each frame
// is the configuration writes, the frame start (frame_start_i) and the stream (RtlRunner::run).
// The model's side of every frame is an independent frame (cosim_stream: a new ArchModel, a cleared
// mask memory, the pixel states begun), because the frame start must clear every state
// (rtl/quadtree/README.md "Frame"): frame k of the RTL must equal it whatever frames 0..k-1 left
// behind. The order makes every frame-start clear matter (rtl/quadtree/README.md "Frame-start
// clears"):
//   1. a full-screen opaque polygon owns every pixel and fills every mask word (and leaves the
//      input FIFO's pointers at 1: one root);
//   2. random polygons: masks that survived would drop them, pixel states that survived would
//      own every sample already, stale FIFO pointers would replay the full-screen root;
//   3. an empty frame: its image is the background, so pixel states that survived show;
//   4, 5. the same random frame twice: every pixel of the second was touched by the first, so
//      sums or owned masks that survived change its records and its image.
// Frame 0 (random polygons and light points) also checks that the runner clears the light index
// of the pixels it lit (the tables are not frame state: the host rewrites them).
struct FrameStep {
  std::string name;
  ScreenFrame frame;
  StallConfig stalls;
};

ScreenFrame random_frame(int raster, int polygons, double max_size, Rng& r) {
  ScreenFrame f = empty_frame(raster);
  for (int k = 0; k < polygons; ++k) f.polygons.push_back(random_polygon(r, uniform(r, 0.02, max_size), 10 + k));
  return f;
}

std::vector<FrameStep> frame_sequence(int raster, int polygons, double max_size, std::uint32_t seed) {
  Rng r(seed);
  const StallConfig none{}, stalls{seed, 30, 35};
  ScreenFrame lit = random_frame(raster, polygons, max_size, r);
  for (int k = 0; k < 12; ++k) {
    ScreenLightPoint l;
    l.xs = uniform(r, -0.9, 0.9);
    l.ys = uniform(r, -0.9, 0.9);
    l.zs = uniform(r, 5, 60);
    l.ds = uniform(r, 0.0005, 0.0035);
    l.colour = {1.0, uniform(r, 0.5, 1), uniform(r, 0.2, 0.9)};
    l.priority = std::int32_t(r() % std::uint64_t(polygons + 1));
    lit.light_points.push_back(l);
  }
  ScreenFrame full = empty_frame(raster);
  full.polygons.push_back(polygon({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, 20, r, true));
  const ScreenFrame after_full = random_frame(raster, polygons, max_size, r);
  const ScreenFrame again = random_frame(raster, polygons, max_size, r);
  return {{"random polygons and light points", lit, none},
          {"full-screen opaque polygon", full, none},
          {"random polygons after the full screen", after_full, stalls},
          {"empty", empty_frame(raster), stalls},
          {"random polygons after the empty frame", again, none},
          {"the same frame again, with stalls", again, stalls}};
}

void expect_frames_equal(const std::vector<FrameStep>& seq, int raster_log2, int tree_levels) {
  if (configuration_missing(raster_log2, tree_levels)) return;
  SCOPED_TRACE("frames without reset, raster " + std::to_string(1 << raster_log2) + ", tree levels " +
               std::to_string(tree_levels));
  auto rtl = make_rtl_runner(raster_log2, tree_levels);  // the one instance: reset here only
  ASSERT_TRUE(rtl != nullptr);
  trace_on_demand(*rtl);
  const RtlConfig cfg{raster_log2, tree_levels};
  const long long pixels = 1LL << (2 * raster_log2);
  std::vector<Image> images;
  for (std::size_t k = 0; k < seq.size(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k) + " (" + seq[k].name + ")");
    const CosimResult r = cosim_frame(seq[k].frame, *rtl, cfg, seq[k].stalls);
    EXPECT_TRUE(r.comparison.ok()) << r.comparison.mismatches << " mismatches of " << r.comparison.records_compared
                                   << " records; cycles model " << r.model.cycles << " RTL " << r.rtl.cycles
                                   << "\nfirst: " << r.comparison.first;
    EXPECT_EQ(r.model.cycles, r.rtl.cycles);
    images.push_back(r.rtl.image);
    // The sequence's premises (else a clear would stop mattering without a failure here).
    if (seq[k].frame.polygons.empty()) {
      EXPECT_EQ(r.model.cycles, 1);
    } else if (seq[k].frame.polygons.size() == 1) {
      EXPECT_EQ(r.stats.pixels_full, pixels) << "the full-screen frame owns every pixel";
    } else {
      EXPECT_GT(r.stats.pixels_full, 0) << "a random frame draws and fills pixels";
    }
  }
  ASSERT_EQ(images.size(), std::size_t(6));
  EXPECT_EQ(images[4].rgb, images[5].rgb) << "the same frame twice";
}

TEST(Cosim, FramesWithoutReset) {
  for (int t = 1; t <= 2; ++t) expect_frames_equal(frame_sequence(64, 40, 0.5, 21), 6, t);
}

TEST(Cosim, FramesWithoutResetN512Pipeline) { expect_frames_equal(frame_sequence(512, 24, 0.12, 22), 9, 1); }

TEST(Cosim, FramesWithoutResetN512Tree) { expect_frames_equal(frame_sequence(512, 24, 0.12, 23), 9, 2); }

// The model's trace of the cycles before `cut` (what RtlRunner::run_cut shows), no image.
Trace before_cycle(const Trace& t, long long cut) {
  const auto keep = [cut](const std::vector<Event>& in) {
    std::vector<Event> out;
    for (const Event& e : in)
      if (e.cycle < cut) out.push_back(e);
    return out;
  };
  Trace out;
  out.cycles = cut;
  for (const auto& s : t.pe) out.pe.push_back(keep(s));
  for (const auto& s : t.pixel) out.pixel.push_back(keep(s));
  for (const MaskSetEvent& m : t.mask_sets)
    if (m.cycle < cut) out.mask_sets.push_back(m);
  return out;
}

// Runs `f` on the RTL for `fraction` of the model's cycles, then `hold` cycles backed up
// (RtlRunner::run_cut), and compares those cycles with the model's.
void expect_cut_frame(const ScreenFrame& f, RtlRunner& rtl, const RtlConfig& cfg, const StallConfig& stalls,
                      double fraction, int hold) {
  SCOPED_TRACE("frame cut at " + std::to_string(fraction) + " of its cycles, held " + std::to_string(hold));
  quad::FrontEndStats fe;
  const auto roots = quad::front_end<RtlArith>(f, cfg.raster_log2, fe);
  quad::PixelFrame<RtlArith> pixels;
  pixels.begin(f, cfg.raster_log2);
  const quad::Architecture arch = quad::Architecture::parse(cfg.arch_text(), cfg.raster_log2);
  const Trace model = model_trace(arch, roots, pixels, stalls, 2);
  const long long cut = (long long)(double(model.cycles) * fraction);
  pixels.begin(f, cfg.raster_log2);
  const Trace rtl_cut = rtl.run_cut(roots, pixels, stalls, cut, hold);
  const Comparison c = compare_traces(rtl_layout(), before_cycle(model, cut), rtl_cut, false);
  EXPECT_TRUE(c.ok()) << c.mismatches << " mismatches of " << c.records_compared << "\nfirst: " << c.first;
  EXPECT_TRUE(rtl_cut.busy_at_cut) << "the frame was cut before it was done";
}

// A frame start that cuts a frame short (a frame overrun, rtl/quadtree/README.md "Frame"): FIFOs
// still hold records and PEs windows, which only the frame start's clears of the FIFO counts and
// the PEs' busy and todo remove (a frame that ran to its end leaves them empty, so
// FramesWithoutReset cannot see those clears). The cut frame's cycles match the model's; the frame
// after it must equal an independent frame. Cut once mid-frame (FIFOs partly full) and once backed
// up (every FIFO full, every PE stalled), one Verilated instance per configuration.
TEST(Cosim, FrameStartCutsAnUnfinishedFrame) {
  for (int t = 1; t <= 2; ++t) {
    if (configuration_missing(6, t)) continue;
    SCOPED_TRACE("tree levels " + std::to_string(t));
    auto rtl = make_rtl_runner(6, t);
    ASSERT_TRUE(rtl != nullptr);
    trace_on_demand(*rtl);
    const RtlConfig cfg{6, t};
    Rng r(24);
    const ScreenFrame a = random_frame(64, 60, 0.5, r), b = random_frame(64, 40, 0.5, r);
    const StallConfig stalls{25, 30, 35};
    for (const int hold : {0, 40}) {
      SCOPED_TRACE("cut and held " + std::to_string(hold) + " cycles");
      expect_cut_frame(a, *rtl, cfg, stalls, 0.5, hold);
      const CosimResult next = cosim_frame(b, *rtl, cfg, hold == 0 ? StallConfig{} : stalls);
      EXPECT_TRUE(next.comparison.ok()) << "the frame after the cut: " << next.comparison.mismatches
                                        << " mismatches of " << next.comparison.records_compared << "; cycles model "
                                        << next.model.cycles << " RTL " << next.rtl.cycles
                                        << "\nfirst: " << next.comparison.first;
    }
  }
}

// The C++ field table (record_bits.hpp: widths from the hls/ types) against what every Verilated
// configuration elaborated from rtl/quadtree/qt_pkg.sv (its wrapper's public parameters), and the
// unit counts against the architecture model's: an edit of one side alone fails here, by name.
// (rtl.RtlWindowFields.* checks every field's offset.)
TEST(RtlLayout, FieldTableMatchesTheVerilatedModels) {
  const RtlLayout L = rtl_layout();
  ASSERT_FALSE(rtl_configs().empty());
  for (const RtlConfig& cfg : rtl_configs()) {
    SCOPED_TRACE(cfg.arch_text());
    auto rtl = make_rtl_runner(cfg.raster_log2, cfg.tree_levels);
    ASSERT_TRUE(rtl != nullptr);
    const RtlModelParams& m = rtl->params();
    EXPECT_EQ(m.ne, L.field_count(RecordField::kD)) << "NE: edges (hls kQuadMaxEdges)";
    EXPECT_EQ(m.ne, L.field_count(RecordField::kA)) << "NE: edge gradients";
    EXPECT_EQ(m.np, L.field_count(RecordField::kF)) << "NP: parameters (hls kQuadParams)";
    EXPECT_EQ(m.np, L.field_count(RecordField::kDpDi)) << "NP: parameter gradients";
    EXPECT_EQ(m.ew, L.slot(RecordField::kD).width) << "EW: hls EdgeValue";
    EXPECT_EQ(m.aw, L.slot(RecordField::kA).width) << "AW: hls EdgeGradient";
    EXPECT_EQ(m.pw, L.slot(RecordField::kF).width) << "PW: RtlArith::Param";
    EXPECT_EQ(m.gw, L.slot(RecordField::kDpDi).width) << "GW: RtlArith::Gradient";
    EXPECT_EQ(m.g, RtlArith::G) << "G";
    EXPECT_EQ(m.win_w, L.win_w) << "WIN_W";
    EXPECT_EQ(m.pix_w, L.pix_w) << "PIX_W";
    EXPECT_EQ(m.mask_set_w, MaskSetLayout::width) << "MASK_SET_W: hls mask_memory_top's request";
    const quad::Architecture arch = quad::Architecture::parse(cfg.arch_text(), cfg.raster_log2);
    const quad::ArchModel<RtlArith> model(arch, quad::ArchConfig{});
    EXPECT_EQ(m.npe, model.pe_count()) << "NPE";
    EXPECT_EQ(m.npix, model.pixel_units()) << "NPIX";
  }
}

}  // namespace
}  // namespace cig::cosim
