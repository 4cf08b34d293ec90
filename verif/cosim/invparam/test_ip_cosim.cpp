// Co-simulation of the inverse-parameter array RTL (rtl/invparam/ip_array.sv) against the
// clock-level model (ip_cosim.hpp): zero mismatches of any PP's output word, Ctrl lines and VT
// result, of the handshake (held cycles) and of the frame's cycles, in every Verilated
// configuration (W, N_PP) = (64, 8), (64, 64), (57, 16) (W the seed's word; the RTL's registers
// have W + 16 bits), on single objects (a box, a prism, faces grazed by a sample, an empty frame,
// the eye inside an object, a near plane through an object), random scenes of random words (up to
// the register's range) and boxes, random RGnear, the polyhedra scene's frames set up on an N_PP x
// N_PP lattice, frames back to back without reset (RGeps and RGnear rewritten between them), and
// random input gaps and VT back-pressure. Each failure prints the first mismatch (frame, cycle, PP,
// signal, expected, got). CIG_COSIM_TRACE_DIR=DIR writes every run's FST waveform to DIR.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "generator/image_generator.hpp"
#include "ip_cosim.hpp"
#include "scene/scene_loader.hpp"
#include "support/invparam_scenes.hpp"

namespace cig::cosim {
namespace {

using invparam::ArrayPacing;
using invparam::InvparamScene;
using invparam::StreamMode;
using invparam::scenes::uniform;

std::unique_ptr<IpRtl> rtl_for(const IpRtlConfig& cfg) {
  auto rtl = make_ip_rtl(cfg.w, cfg.n_pp);
  if (!rtl) return rtl;
  static int run = 0;
  const char* dir = std::getenv("CIG_COSIM_TRACE_DIR");
  if (dir && *dir) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    rtl->trace_to(std::string(dir) + "/" + info->name() + "_" + std::to_string(run++) + ".fst");
  }
  return rtl;
}

// The mutation test's build (verif/mutation: CIG_COSIM_SOME_CONFIGS) has only the configurations a
// mutant names, and a run skips the others; in every other build a missing one fails (nullptr).
bool configuration_missing(const IpRtlConfig& cfg) {
#ifdef CIG_COSIM_SOME_CONFIGS
  const std::vector<IpRtlConfig> built = ip_rtl_configs();
  return std::none_of(built.begin(), built.end(),
                      [&](const IpRtlConfig& c) { return c.w == cfg.w && c.n_pp == cfg.n_pp; });
#else
  (void)cfg;
  return false;
#endif
}

void expect_ok(const IpFrameResult& r, const std::string& what) {
  EXPECT_TRUE(r.ok()) << what << ": " << r.mismatches << " mismatches of " << r.checks << " checks; cycles model "
                      << r.model_cycles << " RTL " << r.rtl_cycles << "\nfirst: " << r.first;
  EXPECT_GT(r.checks, 0) << what;
  EXPECT_EQ(r.vt_results, r.samples) << what << ": one VT result per sample";
}

// Scenes through one configuration: a fresh reset per scene (its own RGeps and RGnear). The samples
// that saw an object, and the held cycles, summed over the scenes, must not be 0: the test tests
// something.
template <int W>
void expect_scenes(const IpRtlConfig& cfg, const std::vector<InvparamScene<W>>& scenes, int columns,
                   const ArrayPacing& pacing = {}, StreamMode mode = StreamMode::kFull) {
  if (configuration_missing(cfg)) return;
  auto rtl = rtl_for(cfg);
  ASSERT_TRUE(rtl != nullptr) << cfg.text();
  std::int64_t hits = 0, held = 0;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    IpCosim<W> cosim(*rtl, scenes[k].eps, scenes[k].tau_near);
    const IpFrameResult r =
        cosim.run_frame(invparam::build_frame_stream(scenes[k], columns, cfg.n_pp, mode), columns, pacing);
    expect_ok(r, cfg.text() + ", scene " + std::to_string(k));
    hits += r.vt_hits;
    held += r.held_cycles;
  }
  EXPECT_GT(hits, 0) << cfg.text();
  if (pacing.vt_stall_percent > 0) { EXPECT_GT(held, 0) << cfg.text(); }
}

// The same for every configuration, the scenes made per configuration (its W and N_PP).
template <class MakeScenes>
void for_each_config(MakeScenes make, const ArrayPacing& pacing = {}) {
  for (const IpRtlConfig& cfg : ip_rtl_configs()) {
    SCOPED_TRACE(cfg.text());
    if (cfg.w == 64) {
      int columns = 0;
      const std::vector<InvparamScene<64>> s = make(std::integral_constant<int, 64>{}, cfg.n_pp, columns);
      expect_scenes<64>(cfg, s, columns, pacing);
    } else if (cfg.w == 57) {
      int columns = 0;
      const std::vector<InvparamScene<57>> s = make(std::integral_constant<int, 57>{}, cfg.n_pp, columns);
      expect_scenes<57>(cfg, s, columns, pacing);
    } else {
      ADD_FAILURE() << "no harness for " << cfg.text();
    }
  }
}

// ---- Geometric objects (eye space, outward normals; set up on an L x L lattice, L = N_PP) --------

EyeFace plane(double nx, double ny, double nz, double d) {
  EyeFace f;
  f.nx = nx;
  f.ny = ny;
  f.nz = nz;
  f.d = d;
  return f;
}

EyePolyhedron box_polyhedron(double cx, double cy, double cz, double hx, double hy, double hz) {
  EyePolyhedron p;
  p.faces = {plane(1, 0, 0, cx + hx),     plane(-1, 0, 0, -(cx - hx)), plane(0, 1, 0, cy + hy),
             plane(0, -1, 0, -(cy - hy)), plane(0, 0, 1, cz + hz),     plane(0, 0, -1, -(cz - hz))};
  return p;
}

// A triangular prism along z (z0..z1), its cross-section turned by `turn` radians.
EyePolyhedron prism_polyhedron(double cx, double cy, double r, double z0, double z1, double turn) {
  EyePolyhedron p;
  for (int k = 0; k < 3; ++k) {
    const double a = turn + k * 2.0943951023931953;
    const double nx = std::cos(a), ny = std::sin(a);
    p.faces.push_back(plane(nx, ny, 0, nx * cx + ny * cy + r));
  }
  p.faces.push_back(plane(0, 0, 1, z1));
  p.faces.push_back(plane(0, 0, -1, -z0));
  return p;
}

// near > 0: a near plane at that eye depth (RGnear = 1/near); 0: none (RGnear = MAX).
template <int W>
InvparamScene<W> geometric_scene(const std::vector<EyePolyhedron>& polyhedra, int n_pp, double near = 0) {
  ScreenFrame f;
  f.raster = n_pp;
  f.tan_half_fov = 0.8;
  f.near = near;
  f.polyhedra = polyhedra;
  return invparam::scene_of_setup(invparam_setup<W>(f, InvparamLattice{n_pp, 0}));
}

// A random RGnear: MAX (no near plane) one time in four, else a word of magnitude up to
// 2^range_log2 (the random scenes' range: it cuts some objects and not others).
template <int W>
hls::Word<W> random_tau_near(std::mt19937_64& rng, int range_log2) {
  if (uniform(rng, 0, 3) == 0) return hls::word_max<W>();
  const std::int64_t r = std::int64_t(1) << std::min(range_log2, 62);
  return hls::Word<W>(uniform(rng, -r / 4, r));
}

// The scene's words shifted left by `bits` (k doublings, wrapping to the register): magnitudes up
// to 2^(range + bits), beyond the int64 range the generators draw from, so that sums reach the
// register's top bits (the sign flag s of the 80- and 73-bit adder).
template <int W>
InvparamScene<W> shifted(InvparamScene<W> s, int bits) {
  auto shift = [bits](hls::Word<W>& x) {
    for (int k = 0; k < bits; ++k) x = hls::word_add(x, x);
  };
  for (hls::FaceSetup<W>& f : s.faces) {
    shift(f.start);
    shift(f.step_x);
    shift(f.step_y);
  }
  shift(s.eps);
  if (s.tau_near != hls::word_max<W>()) shift(s.tau_near);
  return s;
}

// Word-level faces grazed by samples: tau exactly 0 on a column (an entry face) and on a row (an
// exit face), an az = 0 face whose Den is exactly RGeps on one row and RGeps + 1 on the next, two
// entry faces at the same tau (the later one's colour), and a second object with the same tau_in
// (the first object keeps the sample: RGtin > RGobj is strict).
template <int W>
InvparamScene<W> grazing_scene() {
  InvparamScene<W> s;
  s.background = hls::ParCode(0x55aa55);
  s.eps = hls::Word<W>(-40);
  auto face = [&](bool az, bool as, std::int64_t start, std::int64_t sx, std::int64_t sy, unsigned c) {
    hls::FaceSetup<W> f;
    f.az = az;
    f.as = as;
    f.start = hls::Word<W>(start);
    f.step_x = hls::Word<W>(sx);
    f.step_y = hls::Word<W>(sy);
    f.colour = hls::ParCode(c);
    s.faces.push_back(f);
  };
  invparam::ObjectSpan a;
  a.first_face = 0;
  face(true, false, -3000, 1000, 0, 0x101);  // tau = 1000 (i - 3): 0 at column 3
  face(true, false, -3000, 1000, 0, 0x102);  // the same plane again: the later entry face's colour
  face(true, true, -4000, 0, 500, 0x103);    // exit, tau = 500 (j + 1) - 4000: 0 at row 7
  face(false, false, -40 - 6, 0, 1, 0x104);  // Den = eps + j - 5: = eps at row 5, eps + 1 at row 6
  a.face_count = 4;
  s.objects.push_back(a);
  invparam::ObjectSpan b;
  b.first_face = 4;
  face(true, false, -3000, 1000, 0, 0x201);  // the same tau_in as object a: a keeps it
  b.face_count = 1;
  s.objects.push_back(b);
  return s;
}

// The models' W is the register width of the seed's word the configuration names (hls word_bits).
TEST(IpCosim, ConfigurationsHaveTheirParameters) {
  for (const IpRtlConfig& cfg : ip_rtl_configs()) {
    auto rtl = make_ip_rtl(cfg.w, cfg.n_pp);
    ASSERT_TRUE(rtl != nullptr) << cfg.text();
    EXPECT_EQ(rtl->register_bits(), hls::word_bits(cfg.w)) << cfg.text();
    EXPECT_EQ(rtl->register_bits(), cfg.register_bits()) << cfg.text();
    EXPECT_EQ(rtl->n_pp(), cfg.n_pp);
  }
  EXPECT_EQ((IpRtlConfig{64, 8}.register_bits()), 80);
  EXPECT_EQ((IpRtlConfig{57, 16}.register_bits()), 73);
  EXPECT_EQ(make_ip_rtl(64, 9), nullptr);
  // A harness of another word than the model's registers refuses to run.
  if (auto rtl = make_ip_rtl(64, 8)) {
    EXPECT_THROW(IpCosim<57>(*rtl, hls::Word<57>(-1), hls::word_max<57>()), std::logic_error);
  }
}

TEST(IpCosim, SingleObjects) {
  for_each_config([](auto w, int n_pp, int& columns) {
    constexpr int W = decltype(w)::value;
    columns = n_pp;
    std::vector<InvparamScene<W>> s;
    s.push_back(geometric_scene<W>({box_polyhedron(0.3, -0.2, 10, 3, 2, 1.5)}, n_pp));      // a box
    s.push_back(geometric_scene<W>({prism_polyhedron(-0.5, 0.7, 2.5, 6, 14, 0.3)}, n_pp));  // a prism
    s.push_back(geometric_scene<W>({}, n_pp));                                              // empty
    s.push_back(geometric_scene<W>({box_polyhedron(0, 0, 0, 5, 5, 5), box_polyhedron(1, 1, 20, 4, 4, 2)},
                                   n_pp));  // the eye inside an object, another behind it
    EyePolyhedron cut = box_polyhedron(0, 0, 8, 4, 3, 1);
    cut.faces.push_back(plane(1, 0, 0, 0));  // x <= 0: a plane through the eye (Num = 0, az = 0)
    s.push_back(geometric_scene<W>({cut}, n_pp));
    // A near plane at depth 9 through the first box (z 8.5..11.5) and in front of the prism (z 6..14):
    // where the box's front face is nearer, it is cut away and its back faces do not show either.
    s.push_back(
        geometric_scene<W>({box_polyhedron(0.3, -0.2, 10, 3, 2, 1.5), box_polyhedron(-2, 1, 12, 1, 1, 1)}, n_pp, 9.0));
    s.push_back(geometric_scene<W>({box_polyhedron(0.3, -0.2, 10, 3, 2, 1.5)}, n_pp, 1.0));  // near, cuts nothing
    InvparamScene<W> box;  // the unit tests' word-level box
    box.background = hls::ParCode(0xabcdef);
    box.eps = hls::Word<W>(-16);
    invparam::scenes::add_box(box, 1, columns - 2, 1, n_pp - 2, 1 << 20, 100);
    s.push_back(box);
    s.push_back(grazing_scene<W>());
    return s;
  });
}

TEST(IpCosim, RandomScenes) {
  for_each_config([](auto w, int n_pp, int& columns) {
    constexpr int W = decltype(w)::value;
    constexpr int kBits = hls::word_bits(W);  // the register
    std::mt19937_64 rng(std::uint64_t(100 + W + n_pp)), near_rng(std::uint64_t(300 + W + n_pp));
    columns = 6;
    std::vector<InvparamScene<W>> s;
    for (int k = 0; k < 12; ++k) {
      const int range = std::vector<int>{6, 20, W - 4}[std::size_t(k % 3)];
      s.push_back(invparam::scenes::random_scene<W>(rng, int(uniform(rng, 0, 6)), 7, range));
      // RGnear at random in the scene's range (or MAX) in every other scene: Obj clock 3's compare.
      if (k % 2 == 1) s.back().tau_near = random_tau_near<W>(near_rng, range);
    }
    for (int k = 0; k < 4; ++k) s.push_back(invparam::scenes::box_scene<W>(rng, int(uniform(rng, 1, 5)), 6, n_pp));
    // Words up to the register's range (2^62 from the generator, shifted to 2^(kBits - 1)): the
    // sign flag of sums >= 2^(kBits - 2), and wraps.
    for (int k = 0; k < 6; ++k) {
      InvparamScene<W> r = invparam::scenes::random_scene<W>(rng, int(uniform(rng, 1, 6)), 7, 62);
      if (k % 2 == 1) r.tau_near = random_tau_near<W>(near_rng, 62);
      s.push_back(shifted(r, k < 2 ? 0 : kBits - 1 - 62));
    }
    return s;
  });
}

// Covered-columns streaming: column chains of different lengths (and their padding).
TEST(IpCosim, CoveredColumnsStream) {
  std::mt19937_64 rng(7);
  std::vector<InvparamScene<64>> s;
  for (int k = 0; k < 6; ++k) s.push_back(invparam::scenes::box_scene<64>(rng, int(uniform(rng, 1, 6)), 10, 8));
  expect_scenes<64>(IpRtlConfig{64, 8}, s, 10, {}, StreamMode::kCoveredColumns);
  expect_scenes<64>(IpRtlConfig{64, 8}, s, 10, ArrayPacing{5, 30, 30}, StreamMode::kCoveredColumns);
}

TEST(IpCosim, RandomGapsAndBackPressure) {
  for (std::uint32_t seed : {11u, 12u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    for_each_config(
        [](auto w, int n_pp, int& columns) {
          constexpr int W = decltype(w)::value;
          std::mt19937_64 rng(std::uint64_t(200 + W + n_pp));
          columns = 5;
          std::vector<InvparamScene<W>> s;
          for (int k = 0; k < 6; ++k)
            s.push_back(invparam::scenes::random_scene<W>(rng, int(uniform(rng, 0, 5)), 7, 20));
          s.push_back(invparam::scenes::box_scene<W>(rng, 3, 5, n_pp));
          return s;
        },
        ArrayPacing{seed, 35, 40});
  }
}

// Frames back to back through one chain and one RTL, no reset between them: random scenes, empty
// ones, paced and not; RGeps and RGnear rewritten (IpCosim::configure) before every third frame.
template <int W>
void expect_consecutive(const IpRtlConfig& cfg, std::uint64_t seed) {
  if (configuration_missing(cfg)) return;
  auto rtl = rtl_for(cfg);
  ASSERT_TRUE(rtl != nullptr);
  std::mt19937_64 rng(seed), near_rng(seed + 1000);
  hls::Word<W> eps(-100), tau_near = hls::word_max<W>();
  IpCosim<W> cosim(*rtl, eps, tau_near);
  const int columns = 4;
  for (int frame = 0; frame < 10; ++frame) {
    InvparamScene<W> s = invparam::scenes::random_scene<W>(rng, frame % 4 == 1 ? 0 : int(uniform(rng, 1, 5)), 7, 20);
    if (frame % 3 == 2) {
      eps = hls::Word<W>(-uniform(near_rng, 1, 1 << 16));
      tau_near = random_tau_near<W>(near_rng, 20);
      cosim.configure(eps, tau_near);
    }
    s.eps = eps;
    s.tau_near = tau_near;
    const ArrayPacing pacing{std::uint32_t(frame + 3), frame % 2 ? 30 : 0, frame % 3 ? 35 : 0};
    const IpFrameResult r =
        cosim.run_frame(invparam::build_frame_stream(s, columns, cfg.n_pp, StreamMode::kFull), columns, pacing);
    expect_ok(r, cfg.text() + ", frame " + std::to_string(frame));
  }
}

TEST(IpCosim, ConsecutiveFramesWithoutReset) {
  expect_consecutive<64>(IpRtlConfig{64, 8}, 31);
  expect_consecutive<57>(IpRtlConfig{57, 16}, 32);
  expect_consecutive<64>(IpRtlConfig{64, 64}, 33);
}

// scenes/polyhedra.json through stage B, each frame set up on a 64 x 64 lattice (W = 64,
// N_PP = 64): frames 0 and 3, every channel, back to back through one RTL; frame 0's centre
// channel once more with input gaps and VT back-pressure.
TEST(IpCosim, PolyhedraFrames) {
  if (configuration_missing(IpRtlConfig{64, 64})) GTEST_SKIP() << "(64, 64) not built";
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/polyhedra.json");
  ImageGenerator pipeline(scene);
  auto rtl = rtl_for(IpRtlConfig{64, 64});
  ASSERT_TRUE(rtl != nullptr);
  const std::unique_ptr<IpFrameCosim> cosim = make_ip_frame_cosim(*rtl);
  std::int64_t faces = 0;
  for (int frame : {0, 3})
    for (int channel = 0; channel < int(scene.channels.size()); ++channel) {
      nlohmann::ordered_json rep;
      const ScreenFrame f = pipeline.geometry(frame, channel, rep);
      const IpFrameResult r = cosim->run(f, {});
      expect_ok(r, "polyhedra frame " + std::to_string(frame) + " channel " + std::to_string(channel));
      EXPECT_EQ(r.samples, 64 * 64);
      EXPECT_GT(r.vt_hits, 64) << "frame " << frame << " channel " << channel;
      faces += r.faces;
    }
  EXPECT_GT(faces, 20);  // the frames do have polyhedra
  nlohmann::ordered_json rep;
  const IpFrameResult r = cosim->run(pipeline.geometry(0, 1, rep), ArrayPacing{17, 30, 30});
  expect_ok(r, "polyhedra frame 0 channel 1, paced");
  EXPECT_GT(r.held_cycles, 0);
}

}  // namespace
}  // namespace cig::cosim
