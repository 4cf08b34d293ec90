// The recursive-subdivision raster processor's kernels (hls/quadtree): setup, PE, mask memory,
// pixel processor, against references written here from the definitions alone (128-bit
// integers): the recurrences equal direct evaluation bit for bit (every window of small rasters,
// random paths down the full 1024-line grid), the coverage equals an exact integer point-in-polygon
// test at every sample of random polygons, a random tiling covers every sample once, the planes
// are the exact roundings of Newell's, the masks' closure is the brute-force fixpoint, and the
// pixel processor's colours follow the formula of rtl/quadtree/README.md. The same file runs
// natively and with the SystemC-mapped types; Quadtree.Digest digests every output
// (kernel_bits_identical).
#include <algorithm>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/quadtree/mask_memory.hpp"
#include "hls/quadtree/pe.hpp"
#include "hls/quadtree/pixel_processor.hpp"
#include "hls/quadtree/setup.hpp"
#include "segment_test_support.hpp"

namespace cig::hls {
namespace {

using namespace segtest;
using kernel_test::Digest;
using P = DefaultQuadArith;  // fine: G = 16, MW = 20
using Param = P::Param;
constexpr int G = P::G;

#ifdef CIG_HLS_SYSTEMC
constexpr int kScale = 1;
#else
constexpr int kScale = 2;
#endif

// ---- Inputs -------------------------------------------------------------------------------------------

QuadPrimitiveInput<P> input_of(const IntPolygon& p) {
  QuadPrimitiveInput<P> in;
  in.n = UInt<5>(p.n);
  for (int k = 0; k < p.n; ++k) {
    in.v[k].x = UInt<12>(p.x[k]);
    in.v[k].y = UInt<12>(p.y[k]);
    in.v[k].i = UInt<8>(p.i[k]);
    in.v[k].z = zcode(p.z[k]);
  }
  for (int c = 0; c < 3; ++c) in.colour[c] = UInt<8>(p.colour[c]);
  in.opaque = p.opaque;
  in.id = UInt<16>(p.id);
  return in;
}

// ---- The lattice and the edge functions from their definitions ------------------------------------------

// Sample (i, j) of a 2^n raster lies at half-unit position (s i + o, s j + o), s = 2^(11-n),
// o = 2^(10-n) - 2 (records.hpp).
struct Lattice {
  int n;
  i128 s() const { return i128(1) << (11 - n); }
  i128 o() const { return (i128(1) << (10 - n)) - 2; }
  i128 half(i128 k) const { return s() * k + o(); }
  int samples() const { return 4 << n; }
};

// The record's edge constant: C = d_0 - (4N - 1)(max(A, 0) + max(B, 0)).
i128 edge_c(const QuadWindow<P>& root, int e, int n) {
  const i128 a = root.poly.a[e].value(), b = root.poly.b[e].value();
  return i128(root.d[e].value()) - i128((4 << n) - 1) * (std::max<i128>(a, 0) + std::max<i128>(b, 0));
}
// d of window (level, x, y) directly: the edge function at the window's maximising sample.
i128 direct_d(const QuadWindow<P>& root, int e, int n, int level, int x, int y) {
  const i128 side = i128(4) << (n - level), a = root.poly.a[e].value(), b = root.poly.b[e].value();
  return edge_c(root, e, n) + a * x * side + b * y * side + (side - 1) * (std::max<i128>(a, 0) + std::max<i128>(b, 0));
}
// f of window (level, x, y) directly: F + D i0 + E j0 at its top-left sample.
i128 direct_f(const QuadWindow<P>& root, int p, int n, int level, int x, int y) {
  const i128 side = i128(4) << (n - level);
  return i128(root.f[p].value()) + i128(root.poly.dp_di[p].value()) * x * side +
         i128(root.poly.dp_dj[p].value()) * y * side;
}

// A window's child as the walk needs it even when the PE does not emit it (not covered): its d
// (evaluate_child fills d before deciding) and f by the policy's step.
QuadWindow<P> child_of(const QuadWindow<P>& w, const QuadChild<P>& c, int q, int n) {
  QuadWindow<P> r = w;
  const int k = n - int(w.level.value()) - 1 + 2;
  r.level = UInt<4>(w.level.value() + 1);
  r.x = UInt<10>(2 * w.x.value() + (q & 1));
  r.y = UInt<10>(2 * w.y.value() + (q >> 1));
  for (int e = 0; e < kQuadMaxEdges; ++e) r.d[e] = c.window.d[e];
  for (int p = 0; p < kQuadParams; ++p) {
    Param f = w.f[p];
    if (q & 1) f = P::step(f, w.poly.dp_di[p], k);
    if (q & 2) f = P::step(f, w.poly.dp_dj[p], k);
    r.f[p] = f;
  }
  return r;
}

// ---- Recurrences ----------------------------------------------------------------------------------------

// Every window of every level (covered or not) of random polygons at N = 16 and 32: the d of every
// edge and the f of every parameter the recurrences give equal direct evaluation, exactly.
void work_recurrence_exhaustive(int scale, Digest* dg) {
  Rng rng(0x0A1);
  long windows = 0;
  for (int n = 4; n <= 5; ++n)
    for (int t = 0; t < 12 * scale; ++t) {
      const IntPolygon poly = random_polygon(rng, Shape::kAny, t);
      QuadSetup<P> s;
      quadtree_setup(input_of(poly), n, s);
      for (int piece = 0; piece < int(s.pieces.value()); ++piece) {
        const QuadWindow<P>& root = s.root[piece];
        std::vector<QuadWindow<P>> level_windows = {root};
        for (int level = 1; level <= n; ++level) {
          std::vector<QuadWindow<P>> next;
          for (const QuadWindow<P>& w : level_windows)
            for (int q = 0; q < 4; ++q) {
              QuadChild<P> c;
              evaluate_child(w, q, n, false, c);
              const QuadWindow<P> cw = child_of(w, c, q, n);
              const int x = int(cw.x.value()), y = int(cw.y.value());
              for (int e = 0; e < kQuadMaxEdges; ++e)
                ASSERT_TRUE(i128(cw.d[e].value()) == direct_d(root, e, n, level, x, y)) << level;
              for (int p = 0; p < kQuadParams; ++p)
                ASSERT_TRUE(i128(cw.f[p].value()) == direct_f(root, p, n, level, x, y)) << level;
              if (c.covered) {  // the emitted child is the same window
                for (int e = 0; e < kQuadMaxEdges; ++e) ASSERT_EQ(c.window.d[e].value(), cw.d[e].value());
                for (int p = 0; p < kQuadParams; ++p) ASSERT_EQ(c.window.f[p].value(), cw.f[p].value());
                ASSERT_EQ(c.window.x.value(), cw.x.value());
                ASSERT_EQ(c.window.y.value(), cw.y.value());
                ASSERT_EQ(c.window.level.value(), cw.level.value());
              }
              if (dg) {
                dg->add_signed(cw.d[0].value());
                dg->add_signed(cw.f[0].value());
                dg->add_bool(c.covered);
              }
              ++windows;
              if (level < n) next.push_back(cw);
            }
          level_windows.swap(next);
        }
      }
    }
  EXPECT_GT(windows, 10000);
}
TEST(QuadtreePe, RecurrencesEqualDirectEvaluationEveryWindow) { work_recurrence_exhaustive(kScale, nullptr); }

// Random paths from the root to a pixel of a 512- and a 1024-line raster.
void work_recurrence_paths(int scale, Digest* dg) {
  Rng rng(0x0A2);
  for (int n = 9; n <= 10; ++n)
    for (int t = 0; t < 60 * scale; ++t) {
      const IntPolygon poly = random_polygon(rng, Shape::kAny, t);
      QuadSetup<P> s;
      quadtree_setup(input_of(poly), n, s);
      if (s.pieces.value() == 0) continue;
      const QuadWindow<P>& root = s.root[0];
      for (int path = 0; path < 8; ++path) {
        QuadWindow<P> w = root;
        for (int level = 1; level <= n; ++level) {
          const int q = int(below(rng, 4));
          QuadChild<P> c;
          evaluate_child(w, q, n, false, c);
          w = child_of(w, c, q, n);
          const int x = int(w.x.value()), y = int(w.y.value());
          for (int e = 0; e < kQuadMaxEdges; ++e)
            ASSERT_TRUE(i128(w.d[e].value()) == direct_d(root, e, n, level, x, y));
          for (int p = 0; p < kQuadParams; ++p) ASSERT_TRUE(i128(w.f[p].value()) == direct_f(root, p, n, level, x, y));
        }
        if (dg) dg->add_signed(w.f[1].value());
      }
    }
}
TEST(QuadtreePe, RecurrencesEqualDirectEvaluationFullGrid) { work_recurrence_paths(kScale, nullptr); }

// ---- Coverage ---------------------------------------------------------------------------------------------

// All covered samples of one polygon through the setup and the PE (a depth-first walk of the
// covered windows, no masks), as a 4N x 4N bitmap; checks the full flags on the way.
std::vector<std::uint8_t> covered_samples(const IntPolygon& poly, int n, const ExactCoverage& exact, Digest* dg) {
  const Lattice lat{n};
  const int m = lat.samples();
  std::vector<std::uint8_t> got(std::size_t(m) * std::size_t(m), 0);
  QuadSetup<P> s;
  quadtree_setup(input_of(poly), n, s);
  std::vector<QuadWindow<P>> stack;
  for (int piece = 0; piece < int(s.pieces.value()); ++piece) stack.push_back(s.root[piece]);
  while (!stack.empty()) {
    const QuadWindow<P> w = stack.back();
    stack.pop_back();
    for (int q = 0; q < 4; ++q) {
      QuadChild<P> c;
      evaluate_child(w, q, n, false, c);
      const int level = int(w.level.value()) + 1;
      const int side = 4 << (n - level);
      const int x0 = (2 * int(w.x.value()) + (q & 1)) * side, y0 = (2 * int(w.y.value()) + (q >> 1)) * side;
      // full: every sample of the child covered (checked by brute force up to 32 x 32 samples; for
      // a polygon in one piece: a piece of a split polygon covers only its part of a window).
      if (c.covered && side <= 32 && s.pieces.value() == 1) {
        bool all = true;
        for (int j = y0; j < y0 + side && all; ++j)
          for (int i = x0; i < x0 + side && all; ++i)
            all = exact.covers(std::int64_t(lat.half(i)), std::int64_t(lat.half(j)));
        if (!(c.full == all))
          ADD_FAILURE() << "full flag at level " << level << " of " << n << " window (" << x0 << ", " << y0
                        << "): kernel " << c.full << ", exact " << all << ", opaque " << poly.opaque << ", samples "
                        << c.samples.value();
      }
      if (!c.covered) continue;
      if (level < n) {
        stack.push_back(c.window);
        continue;
      }
      const unsigned mask = unsigned(c.samples.value());
      if (dg) dg->add(mask);
      for (int b = 0; b < 16; ++b)
        if ((mask >> b) & 1u) {
          const std::size_t idx = std::size_t(y0 + (b >> 2)) * std::size_t(m) + std::size_t(x0 + (b & 3));
          got[idx] = std::uint8_t(got[idx] + 1);
        }
    }
  }
  return got;
}

// Every sample of the lattice: covered by the kernels exactly when the exact test (edge functions
// with the reference's tie rule, segtest::ExactCoverage) covers it, and the screen door of a
// non-opaque polygon keeps exactly the samples with i + j even. N = 16..128.
void work_coverage(int scale, Digest* dg) {
  Rng rng(0x0C0);
  long samples = 0, covered = 0;
  for (int n = 4; n <= 7; ++n)
    for (int t = 0; t < (n <= 5 ? 40 : 12) * scale; ++t) {
      const IntPolygon poly = random_polygon(rng, Shape::kAny, t);
      const ExactCoverage exact(poly);
      const std::vector<std::uint8_t> got = covered_samples(poly, n, exact, dg);
      const Lattice lat{n};
      const int m = lat.samples();
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          const bool want =
              exact.covers(std::int64_t(lat.half(i)), std::int64_t(lat.half(j))) && (poly.opaque || ((i + j) & 1) == 0);
          const int g = got[std::size_t(j) * std::size_t(m) + std::size_t(i)];
          ASSERT_EQ(g, want ? 1 : 0) << "sample (" << i << ", " << j << ") of polygon " << t << " at N = " << (1 << n);
          covered += g;
          ++samples;
        }
    }
  EXPECT_GT(covered, samples / 200);  // not vacuous
}
TEST(QuadtreePe, CoverageEqualsExactPointInPolygon) { work_coverage(kScale, nullptr); }

// A random tiling of the screen (segtest::random_tiling: jittered, with slivers): every sample of
// the lattice is covered exactly once.
void work_tiling(int scale, Digest* dg) {
  Rng rng(0x711E);
  for (int n = 4; n <= 6; ++n)
    for (int t = 0; t < scale; ++t) {
      const Lattice lat{n};
      const int m = lat.samples();
      std::vector<int> count(std::size_t(m) * std::size_t(m), 0);
      for (IntPolygon tri : random_tiling(rng)) {
        tri.opaque = true;
        const ExactCoverage exact(tri);
        const std::vector<std::uint8_t> got = covered_samples(tri, n, exact, dg);
        for (std::size_t k = 0; k < got.size(); ++k) count[k] += got[k];
      }
      for (std::size_t k = 0; k < count.size(); ++k)
        ASSERT_EQ(count[k], 1) << "sample " << k % std::size_t(m) << ", " << k / std::size_t(m);
    }
}
TEST(QuadtreePe, RandomTilingCoversEverySampleOnce) { work_tiling(kScale, nullptr); }

// ---- Setup: planes -----------------------------------------------------------------------------------------

// Triangles: Newell's sums are the exact plane, so D_raw = round(-nx s 2^G / nz), E likewise,
// and F_raw = round((sum v 2^(G+7) - D_raw si7 - E_raw sj7) / (3 * 128)) (half up, quadtree_arith.hpp).
// Bound at the vertices (derived): F_raw is within 1/2 LSB of the exact offset of the rounded
// gradients over the vertex centroid, and each rounded gradient within 1/2 LSB per sample, so
// |f(vertex k) - v_k 2^G| <= 1/2 + (|i_k - i_mean| + |j_k - j_mean|) / 2 LSB (unsaturated gradients).
void work_planes(int scale, Digest* dg) {
  Rng rng(0x91A);
  long checked = 0;
  for (int t = 0; t < 400 * scale; ++t) {
    IntPolygon poly = random_polygon(rng, Shape::kAny, t);
    if (poly.n < 3) continue;
    poly.n = 3;  // a triangle of the hull's first three vertices (still convex)
    const int n = 4 + int(below(rng, 7));
    const Lattice lat{n};
    const i128 s = lat.s(), o = lat.o();
    i128 hx[3], hy[3];
    for (int k = 0; k < 3; ++k) {
      hx[k] = 2 * i128(poly.x[k]);
      hy[k] = 2 * i128(poly.y[k]);
    }
    i128 nz = 0;
    for (int k = 0; k < 3; ++k) nz += (hx[k] - hx[(k + 1) % 3]) * (hy[k] + hy[(k + 1) % 3]);
    QuadSetup<P> st;
    quadtree_setup(input_of(poly), n, st);
    if (nz == 0) {
      ASSERT_EQ(st.pieces.value(), 0u);
      continue;
    }
    ASSERT_EQ(st.pieces.value(), 1u);
    const QuadWindow<P>& root = st.root[0];
    // Intensity values: the vertices' I.
    i128 v[3];
    for (int k = 0; k < 3; ++k) v[k] = poly.i[k];
    i128 nx = 0, ny = 0, sv = 0, si7 = 0, sj7 = 0;
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3;
      nx += (hy[k] - hy[k1]) * (v[k] + v[k1]);
      ny += (v[k] - v[k1]) * (hx[k] + hx[k1]);
      sv += v[k];
      si7 += (hx[k] - o) * (i128(128) / s);
      sj7 += (hy[k] - o) * (i128(128) / s);
    }
    const i128 lim = i128(1) << (P::V + G);  // saturation of the gradient
    auto sat = [&](i128 r) { return std::clamp<i128>(r, -lim + 1, lim - 1); };
    const i128 d = sat(round_half_up(-nx * s * (i128(1) << G) * (nz < 0 ? -1 : 1), nz < 0 ? -nz : nz));
    const i128 e = sat(round_half_up(-ny * s * (i128(1) << G) * (nz < 0 ? -1 : 1), nz < 0 ? -nz : nz));
    ASSERT_TRUE(i128(root.poly.dp_di[0].value()) == d) << t;
    ASSERT_TRUE(i128(root.poly.dp_dj[0].value()) == e) << t;
    const i128 f = round_half_up(sv * (i128(1) << (G + 7)) - d * si7 - e * sj7, 3 * 128);
    ASSERT_TRUE(i128(root.f[0].value()) == f) << t;
    if (abs128(d) < lim - 1 && abs128(e) < lim - 1) {
      for (int k = 0; k < 3; ++k) {
        // f at the vertex, in units of 2^-(G+7): F + D i_k + E j_k with i_k = (hx - o) / s.
        const i128 at = f * 128 * s + d * (hx[k] - o) * 128 + e * (hy[k] - o) * 128;  // units 2^-(G+7) / s
        const i128 want = v[k] * (i128(1) << (G + 7)) * s;
        // |i_k - i_mean| in units of 1/(3s): |3 hx_k - sum hx| / (3 s).
        const i128 di = abs128(3 * hx[k] - (hx[0] + hx[1] + hx[2])), dj = abs128(3 * hy[k] - (hy[0] + hy[1] + hy[2]));
        // bound (1/2 + (di + dj) / (3 s) / 2) LSB, in units of 2^-(G+7) / s: 64 s + 64 (di + dj) / 3; times 3 to stay integral.
        ASSERT_TRUE(3 * abs128(at - want) <= 3 * 64 * s + 64 * (di + dj)) << "polygon " << t << " vertex " << k;
        ++checked;
      }
    }
    if (dg) {
      dg->add_signed(root.poly.dp_di[1].value());
      dg->add_signed(root.poly.dp_dj[1].value());
      dg->add_signed(root.f[1].value());
      dg->add_signed(root.poly.w_exponent.value());
    }
  }
  EXPECT_GT(checked, 300);
}
TEST(QuadtreeSetup, TrianglePlanesAreTheExactRoundings) { work_planes(kScale, nullptr); }

// W of a vertex: round(2^(MW + 7 + e_min - e) / significand), half up; 0 below half a unit;
// every e8m7 code against the nearest binade 0..255.
TEST(QuadtreeSetup, InverseDepthValuesEveryCode) {
  for (int e_min = 0; e_min < 256; e_min += 17)
    for (int code = e_min * 128; code < 32768; code += 5) {
      const ZFloat z = zcode(code);
      const int sh = P::MW + 7 + e_min - (code >> 7);
      const i128 want = sh < 0 ? 0 : round_half_up(i128(1) << sh, 128 + (code & 127));
      ASSERT_TRUE(i128(P::inverse_depth_value(z, e_min).value()) == want) << code;
    }
}

// ---- Mask memory -----------------------------------------------------------------------------------------

// Random set requests at every level of a 32-line raster: after each, the memory equals the least
// fixpoint computed by brute force from the direct sets (a bit is set iff it was set directly or
// its child's word is full), bottom-up.
TEST(QuadtreeMasks, ClosureIsTheBruteForceFixpoint) {
  Rng rng(0x3A5);
  const int n = 5;
  auto m = std::make_unique<MaskMemory>();
  mask_clear(*m, n);
  std::vector<std::vector<unsigned>> direct{std::size_t(n)};
  for (int l = 0; l < n; ++l) direct[std::size_t(l)].assign(std::size_t(1) << (2 * l), 0u);
  for (int k = 0; k < 3000; ++k) {
    const int l = int(below(rng, n)), x = int(below(rng, 1 << l)), y = int(below(rng, 1 << l)), q = int(below(rng, 4));
    direct[std::size_t(l)][std::size_t((y << l) + x)] |= 1u << q;
    mask_set(*m, l, x, y, q);
    if (k % 97 != 0) continue;
    std::vector<std::vector<unsigned>> want = direct;
    for (int lv = n - 1; lv >= 1; --lv)
      for (int yy = 0; yy < (1 << lv); ++yy)
        for (int xx = 0; xx < (1 << lv); ++xx)
          if (want[std::size_t(lv)][std::size_t((yy << lv) + xx)] == 0xFu)
            want[std::size_t(lv - 1)][std::size_t(((yy >> 1) << (lv - 1)) + (xx >> 1))] |=
                1u << (((yy & 1) << 1) | (xx & 1));
    for (int lv = 0; lv < n; ++lv)
      for (int yy = 0; yy < (1 << lv); ++yy)
        for (int xx = 0; xx < (1 << lv); ++xx)
          ASSERT_EQ(unsigned(mask_read(*m, lv, xx, yy).value()), want[std::size_t(lv)][std::size_t((yy << lv) + xx)])
              << lv;
  }
}

// ---- Pixel processor --------------------------------------------------------------------------------------

// The colour of a fresh sample by the formula of rtl/quadtree/README.md, written with plain integers.
std::int64_t readme_code(std::int64_t vw, int w_exponent) {
  std::int64_t s = std::min<std::int64_t>(vw, (std::int64_t{1} << 41) - 1);
  if (s <= 0) return 0;
  int msb = 0;
  while ((s >> (msb + 1)) != 0) ++msb;
  int e = w_exponent - G + 146 + msb - 19;
  std::int64_t sig;
  if (msb <= 7) {
    sig = s << (7 - msb);
  } else {
    const int drop = msb - 7;
    const std::int64_t fl = s >> drop, rem = s & ((std::int64_t{1} << drop) - 1), half = std::int64_t{1} << (drop - 1);
    sig = fl + ((rem > half || (rem == half && (fl & 1))) ? 1 : 0);
    if (sig == 256) {
      sig = 128;
      ++e;
    }
  }
  if (e < 0) return 0;
  if (e > 255) return 0x7FFF;
  return (std::int64_t(e) << 7) | (sig & 127);
}

TEST(QuadtreePixel, SampleColoursFollowTheFormula) {
  Rng rng(0x91C);
  auto t = std::make_unique<QuadPixelTables<P>>();
  for (int c = 0; c < kFogTableSize; ++c) t->fog.f[c] = FogFactor::from_raw_value(std::uint64_t(below(rng, 257)));
  for (int c = 0; c < 3; ++c) {
    t->fog_colour[c] = UInt<8>(below(rng, 256));
    t->background[c] = UInt<8>(below(rng, 256));
  }
  const QuadLightCover<P> none{};
  for (int k = 0; k < 2000; ++k) {
    QuadWindow<P> px;
    px.level = UInt<4>(9);
    px.poly.id = UInt<16>(below(rng, 1000));
    for (int c = 0; c < 3; ++c) px.poly.colour[c] = UInt<8>(below(rng, 256));
    px.poly.w_exponent = Int<10>(between(rng, -150, 115));
    px.f[0] = Param(between(rng, -(std::int64_t{20} << G), std::int64_t{270} << G));
    px.f[1] = Param(between(rng, -(std::int64_t{1} << 30), std::int64_t{1} << 38));
    for (int p = 0; p < 2; ++p) {
      px.poly.dp_di[p] = P::Gradient(between(rng, -(std::int64_t{1} << 28), std::int64_t{1} << 28));
      px.poly.dp_dj[p] = P::Gradient(between(rng, -(std::int64_t{1} << 28), std::int64_t{1} << 28));
    }
    QuadPixelState<P> st;
    quad_pixel_clear(st);
    const unsigned owned0 = unsigned(below(rng, 65536)) & unsigned(below(rng, 65536));
    st.owned = UInt<16>(owned0);
    const unsigned samples = unsigned(below(rng, 65536));
    const unsigned fresh = unsigned(quad_pixel_process(px, UInt<16>(samples), *t, none, st).value());
    ASSERT_EQ(fresh, samples & ~owned0 & 0xFFFFu);
    ASSERT_EQ(unsigned(st.owned.value()), owned0 | fresh);
    std::int64_t sum[3] = {0, 0, 0};
    for (int s = 0; s < 16; ++s) {
      if (!((fresh >> s) & 1u)) continue;
      const int di = s & 3, dj = s >> 2;
      const std::int64_t vi = px.f[0].value() + px.poly.dp_di[0].value() * di + px.poly.dp_dj[0].value() * dj;
      const std::int64_t vw = px.f[1].value() + px.poly.dp_di[1].value() * di + px.poly.dp_dj[1].value() * dj;
      const std::int64_t i_raw = std::clamp<std::int64_t>(vi, 0, (std::int64_t{1} << (8 + G)) - 1);
      const std::int64_t f9 = std::int64_t(t->fog.f[readme_code(vw, int(px.poly.w_exponent.value()))].raw().value());
      for (int c = 0; c < 3; ++c) {
        const std::int64_t shade = std::min<std::int64_t>(
            (std::int64_t(px.poly.colour[c].value()) * i_raw + (std::int64_t{1} << (G - 1))) >> G, 65535);
        const std::int64_t mix = std::clamp<std::int64_t>(
            (shade * (256 - f9) + ((std::int64_t(t->fog_colour[c].value()) * f9) << 8) + 128) >> 8, 0, 65535);
        sum[c] += mix;
      }
    }
    for (int c = 0; c < 3; ++c) ASSERT_EQ(std::int64_t(st.sum[c].raw().value()), sum[c]) << k;
    UInt<8> rgb[3];
    quad_pixel_resolve(st, *t, none, rgb);
    for (int c = 0; c < 3; ++c) {
      std::int64_t total = sum[c];
      for (int s = 0; s < 16; ++s)
        if (!(((owned0 | fresh) >> s) & 1u)) total += std::int64_t(t->background[c].value()) << 8;
      ASSERT_EQ(std::int64_t(rgb[c].value()), std::min<std::int64_t>((total + 2048) >> 12, 255));
    }
  }
}

// ---- Digest ---------------------------------------------------------------------------------------------

TEST(Quadtree, Digest) {
  Digest d;
  work_recurrence_exhaustive(1, &d);
  work_recurrence_paths(1, &d);
  work_coverage(1, &d);
  work_planes(1, &d);
  kernel_test::print_digest("quadtree", d);
}

}  // namespace
}  // namespace cig::hls
