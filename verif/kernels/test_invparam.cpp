// Stage F (seed 002): the bit-accurate inverse-parameter kernel (hls/invparam/visibility.hpp) and
// its double twin (cmodel/invparam/invparam_double.hpp) against the exact ground truth
// (cmodel/invparam/exact_visibility.hpp) on random frames of convex polyhedra (boxes, prisms,
// hulls of random points; some overlapping in depth, some behind the eye, the eye inside one, one
// face plane through the eye) and random views on a 32 x 32 sample lattice; NearEye frames add
// face planes at 0, 1 um, 1 mm and 1 cm from the eye, eyes 0.1 to 10 mm in front of a face and a
// random near plane (issue 29); no face is avoided.
//
// The tolerance is the derived error bound, not a tuned number: the kernel's value at (i, j) is
// within invparam_error_bound_lsb(i, j) = (i + j + 2)(1/2 + 2^-14) LSB of the exact tau (or Den),
// the twin's within invparam_double_error_bound(i, j); the ground truth flags a sample uncertain
// when a decision could flip within that, and every other sample must agree exactly (the face)
// and within the bound (tau). The truth is that of the scene as the setup takes it: a face plane
// too near the eye for the word (below 0.3 um here) moved through it (face_setup.hpp); samples whose
// truth that shift changes are counted (Counts::moved) and not compared.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "digest.hpp"
#include "hls/formatter/sample_lattice.hpp"
#include "invparam/exact_visibility.hpp"
#include "invparam/face_setup.hpp"
#include "invparam/invparam_double.hpp"
#include "invparam/invparam_kernel_run.hpp"

namespace cig {
namespace {

__extension__ typedef __int128 i128;

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dotv(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 unit(V3 a) {
  const double l = std::sqrt(dotv(a, a));
  return {a.x / l, a.y / l, a.z / l};
}

struct Rot {
  V3 col[3];  // the images of the local axes
  V3 apply(V3 v) const {
    return {col[0].x * v.x + col[1].x * v.y + col[2].x * v.z, col[0].y * v.x + col[1].y * v.y + col[2].y * v.z,
            col[0].z * v.x + col[1].z * v.y + col[2].z * v.z};
  }
};

class SceneMaker {
 public:
  explicit SceneMaker(std::uint64_t seed) : rng_(seed) {}
  double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  int pick(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng_); }

  Rot rotation() {
    std::normal_distribution<double> g;
    double q[4];
    for (double& v : q) v = g(rng_);
    const double l = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double w = q[0] / l, x = q[1] / l, y = q[2] / l, z = q[3] / l;
    return Rot{{{1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)},
                {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)},
                {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)}}};
  }
  static EyeFace face(V3 n, V3 point) { return EyeFace{n.x, n.y, n.z, dotv(n, point), -1, {}}; }

  // A box: local [-h, h]^3 (or [0, 2 hx] along x with the x = 0 face through the eye).
  EyePolyhedron box(V3 centre, V3 h, bool face_through_eye) {
    const Rot r = rotation();
    EyePolyhedron p;
    const double hs[3] = {h.x, h.y, h.z};
    for (int k = 0; k < 3; ++k)
      for (const double sgn : {1.0, -1.0}) {
        const V3 n = r.col[k];
        const V3 ns{sgn * n.x, sgn * n.y, sgn * n.z};
        p.faces.push_back(face(ns, {centre.x + ns.x * hs[k], centre.y + ns.y * hs[k], centre.z + ns.z * hs[k]}));
      }
    if (face_through_eye) {  // move the box so that its -x face (index 1) contains the eye
      const EyeFace f = p.faces[1];
      const V3 shift{f.nx * f.d, f.ny * f.d, f.nz * f.d};  // the face plane's point nearest the eye
      for (EyeFace& g : p.faces) g.d -= g.nx * shift.x + g.ny * shift.y + g.nz * shift.z;
      p.faces[1].d = 0;
    }
    return p;
  }
  // A prism: a regular k-gon of radius rad extruded by +-h.
  EyePolyhedron prism(V3 centre, double rad, double h) {
    const Rot r = rotation();
    const int k = pick(3, 8);
    EyePolyhedron p;
    const double apothem = rad * std::cos(M_PI / k), phase = uni(0, 1);
    for (int s = 0; s < k; ++s) {
      const double a = 2 * M_PI * (s + phase) / k;
      const V3 n = r.apply({std::cos(a), std::sin(a), 0});
      p.faces.push_back(face(n, {centre.x + n.x * apothem, centre.y + n.y * apothem, centre.z + n.z * apothem}));
    }
    for (const double sgn : {1.0, -1.0}) {
      const V3 n = r.apply({0, 0, sgn});
      p.faces.push_back(face(n, {centre.x + n.x * h, centre.y + n.y * h, centre.z + n.z * h}));
    }
    return p;
  }
  // The convex hull of random points in a ball: the planes through three points with every other
  // point on one side.
  EyePolyhedron hull(V3 centre, double rad) {
    std::vector<V3> pts;
    for (int k = 0; k < 10; ++k) {
      V3 v;
      do v = {uni(-1, 1), uni(-1, 1), uni(-1, 1)};
      while (dotv(v, v) > 1);
      pts.push_back({centre.x + rad * v.x, centre.y + rad * v.y, centre.z + rad * v.z});
    }
    EyePolyhedron p;
    for (std::size_t a = 0; a < pts.size(); ++a)
      for (std::size_t b = a + 1; b < pts.size(); ++b)
        for (std::size_t c = b + 1; c < pts.size(); ++c) {
          V3 n = unit(cross(sub(pts[b], pts[a]), sub(pts[c], pts[a])));
          int above = 0, below = 0;
          for (const V3& q : pts) {
            const double s = dotv(n, sub(q, pts[a]));
            above += s > 1e-9 ? 1 : 0;
            below += s < -1e-9 ? 1 : 0;
          }
          if (above > 0 && below > 0) continue;
          if (above > 0) n = {-n.x, -n.y, -n.z};
          p.faces.push_back(face(n, pts[a]));
        }
    return p;
  }

  V3 place(double tan_half, double zmin, double zmax) {
    const double z = uni(zmin, zmax), w = std::fabs(z) * tan_half;
    return {uni(-w, w), uni(-w, w), z};
  }

  // Moves p so that its face k's plane passes at `dist` from the eye (the eye inside for dist > 0):
  // a shift v = (dist - d_k) n_k changes every d_g by n_g.v.
  static void plane_at(EyePolyhedron& p, std::size_t k, double dist) {
    const EyeFace f = p.faces[k];
    const double s = dist - f.d;
    for (EyeFace& g : p.faces) g.d += s * (g.nx * f.nx + g.ny * f.ny + g.nz * f.nz);
    p.faces[k].d = dist;
  }
  // A box just in front of the eye: its face 1 (the -x face of the local frame) `dist` ahead, the
  // eye's foot on it near the face's centre.
  EyePolyhedron box_at_eye(double dist) {
    const V3 h{uni(0.2, 2), uni(0.5, 2), uni(0.5, 2)};
    EyePolyhedron p = box({0, 0, uni(2, 4)}, h, false);
    plane_at(p, 1, -dist);
    return p;
  }

  // A frame: 6..10 polyhedra. near_eye: some face planes at 0, 0.1 um, 1 um, 1 mm or 1 cm from the eye
  // (either side), one box with the eye 0.1..10 mm in front of a face, a near plane in half the
  // frames (1 mm .. 3 m).
  ScreenFrame frame(bool near_eye = false) {
    ScreenFrame f;
    f.tan_half_fov = uni(0.4, 1.2);
    const int n = pick(6, 10);
    for (int o = 0; o < n; ++o) {
      for (int attempt = 0; attempt < 100; ++attempt) {
        EyePolyhedron p = make(o, f.tan_half_fov);
        if (p.faces.size() < 4 || p.faces.size() > 32) continue;
        if (near_eye && o >= 3 && pick(0, 1) == 1) {
          const double dists[5] = {0, 1e-7, 1e-6, 1e-3, 1e-2};  // 0.1 um: the Num = 0 path
          plane_at(p, std::size_t(pick(0, int(p.faces.size()) - 1)), dists[pick(0, 4)] * (pick(0, 1) ? 1 : -1));
        }
        p.object = o;
        f.polyhedra.push_back(p);
        break;
      }
    }
    if (near_eye) {
      f.polyhedra.push_back(box_at_eye(std::pow(10.0, uni(-4, -2))));
      f.polyhedra.back().object = n;
      if (pick(0, 1) == 1) f.near = std::pow(10.0, uni(-3, std::log10(3.0)));
    }
    return f;
  }

 private:
  EyePolyhedron make(int o, double t) {
    if (o == 0) return box({uni(-0.3, 0.3), uni(-0.3, 0.3), uni(-0.3, 0.3)}, {uni(1, 3), uni(1, 3), uni(1, 3)}, false);
    if (o == 1) return box(place(t, 2, 8), {uni(0.5, 2), uni(0.5, 2), uni(0.5, 2)}, true);  // a face through the eye
    if (o == 2) return box(place(t, -10, -2), {uni(0.5, 2), uni(0.5, 2), uni(0.5, 2)}, false);  // behind the eye
    const V3 c = place(t, 3, 20);
    switch (pick(0, 2)) {
      case 0:
        return box(c, {uni(0.3, 3), uni(0.3, 3), uni(0.3, 3)}, false);
      case 1:
        return prism(c, uni(0.3, 3), uni(0.3, 3));
      default:
        return hull(c, uni(0.5, 3));
    }
  }
  std::mt19937_64 rng_;
};

// A word's value, exact (|code| < 2^113).
template <int W>
__float128 word_exact(const hls::Word<W>& w) {
  const i128 v = static_cast<i128>((static_cast<unsigned __int128>(w.high_limb()) << 64) | w.low_limb());
  __float128 scale = 1;
  for (int k = 0; k < hls::word_frac_bits(W); ++k) scale /= 2;
  return static_cast<__float128>(v) * scale;
}
template <int W>
double word_value(const hls::Word<W>& w) {
  return static_cast<double>(word_exact<W>(w));
}
double quad_abs(__float128 x) { return static_cast<double>(x < 0 ? -x : x); }

struct Counts {
  int samples = 0, hits = 0, uncertain = 0, twin_uncertain = 0;
  int moved = 0;        // samples whose truth the setup's plane shift (< 2^-20 m) changes
  int through_eye = 0;  // faces the setup decided as through the eye
};

// The frame as the setup takes it: face planes too near the eye for the word through it.
ScreenFrame as_set_up(ScreenFrame f, int size) {
  for (EyePolyhedron& p : f.polyhedra)
    for (EyeFace& e : p.faces)
      if (invparam_face_values(e, f.tan_half_fov, size).through_eye) e.d = 0;
  return f;
}

// The kernel at W and the twin against the exact ground truth on one frame.
template <int W>
void check_frame(const ScreenFrame& frame, const InvparamLattice& lattice, Counts& counts,
                 kernel_test::Digest* digest) {
  const InvparamSetup<W> setup = invparam_setup<W>(frame, lattice);
  ASSERT_EQ(setup.saturated, 0);
  ASSERT_EQ(setup.out_of_range, 0);
  counts.through_eye += setup.through_eye;
  const ScreenFrame moved = as_set_up(frame, lattice.size());
  double value_max = 0;  // the twin's bound scales with the largest value on the lattice
  for (const EyePolyhedron& p : frame.polyhedra)
    for (const EyeFace& e : p.faces)
      value_max = std::max(value_max, double(invparam_face_values(e, frame.tan_half_fov, lattice.size()).corner_max));
  const std::vector<hls::InvparamSample<W>> kernel = invparam_run_kernel<W>(setup);
  const double lsb = std::ldexp(1.0, -hls::word_frac_bits(W));
  const double eps = word_value<W>(setup.eps);
  const std::vector<InvparamSampleDouble> twin = invparam_double(invparam_setup_double(frame, lattice, eps));
  const int l = lattice.size();
  for (int j = 0; j < l; ++j)
    for (int i = 0; i < l; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * l + i;
      const double bound = invparam_error_bound_lsb(i, j) * lsb, tbound = invparam_double_error_bound(i, j, value_max);
      // The kernel and the twin each against the truth, and (on the sum of the bounds) each other.
      const ExactSample ek = exact_visibility_sample(moved, l, i, j, {bound, -eps + bound});
      const ExactSample et = exact_visibility_sample(moved, l, i, j, {tbound, -eps + tbound});
      const ExactSample both = exact_visibility_sample(moved, l, i, j, {bound + tbound, -eps + bound + tbound});
      if (setup.through_eye > 0) {  // what the shift changes: the scene's own truth
        const ExactSample e0 = exact_visibility_sample(frame, l, i, j, {bound, -eps + bound});
        counts.moved += !e0.uncertain && !ek.uncertain && (e0.hit != ek.hit || e0.code != ek.code) ? 1 : 0;
      }
      ++counts.samples;
      counts.hits += ek.hit ? 1 : 0;
      counts.uncertain += ek.uncertain ? 1 : 0;
      counts.twin_uncertain += et.uncertain ? 1 : 0;
      if (digest != nullptr) {
        digest->add_bool(kernel[k].hit);
        digest->add(kernel[k].code.value());
        digest->add(kernel[k].tau.low_limb());
        digest->add(kernel[k].tau.high_limb());
      }
      if (!ek.uncertain) {
        ASSERT_EQ(kernel[k].hit, ek.hit) << "kernel W=" << W << " i=" << i << " j=" << j;
        if (ek.hit) {
          ASSERT_EQ(kernel[k].code.value(), ek.code) << "kernel W=" << W << " i=" << i << " j=" << j;
          ASSERT_LE(quad_abs(word_exact<W>(kernel[k].tau) - ek.tau_exact), bound) << i << " " << j;
        }
      }
      if (!et.uncertain) {
        ASSERT_EQ(twin[k].hit, et.hit) << "twin i=" << i << " j=" << j;
        if (et.hit) {
          ASSERT_EQ(twin[k].code, et.code) << "twin i=" << i << " j=" << j;
          ASSERT_LE(quad_abs(twin[k].tau - et.tau_exact), tbound) << i << " " << j;
        }
      }
      if (!both.uncertain) {
        ASSERT_EQ(kernel[k].hit, twin[k].hit) << "kernel != twin W=" << W << " i=" << i << " j=" << j;
        if (twin[k].hit) {
          ASSERT_EQ(kernel[k].code.value(), twin[k].code) << i << " " << j;
          ASSERT_LE(quad_abs(word_exact<W>(kernel[k].tau) - twin[k].tau), bound + tbound) << i << " " << j;
        }
      }
    }
}

template <int W>
Counts check_frames(std::uint64_t seed, int frames, kernel_test::Digest* digest, bool near_eye = false) {
  SceneMaker maker(seed);
  Counts counts;
  const InvparamLattice lattice{16, 1};  // 32 x 32 samples
  for (int f = 0; f < frames; ++f) {
    SCOPED_TRACE(f);
    const ScreenFrame frame = maker.frame(near_eye);
    check_frame<W>(frame, lattice, counts, digest);
    if (::testing::Test::HasFatalFailure()) return counts;
  }
  return counts;
}

void expect_meaningful(const Counts& c, int max_uncertain_percent = 2) {
  // Enough hits to mean something, and uncertain samples a small minority.
  EXPECT_GT(c.hits, c.samples / 4);
  EXPECT_LE(c.uncertain * 100, c.samples * max_uncertain_percent);
  std::printf("samples %d hits %d uncertain %d (twin %d), faces through the eye %d, samples the shift moves %d\n",
              c.samples, c.hits, c.uncertain, c.twin_uncertain, c.through_eye, c.moved);
}

TEST(Invparam, Word64AgainstExact) { expect_meaningful(check_frames<64>(1, 10, nullptr)); }
TEST(Invparam, Word72AgainstExact) { expect_meaningful(check_frames<72>(2, 6, nullptr)); }
TEST(Invparam, Word48AgainstExact) { expect_meaningful(check_frames<48>(3, 6, nullptr)); }
TEST(Invparam, Word40AgainstExact) { expect_meaningful(check_frames<40>(4, 6, nullptr)); }
// Short words: the kernel errs near edges and silhouettes, and only there (the bound is tight
// enough to leave most samples certain, and wide enough to cover every error).
TEST(Invparam, Word32AgainstExact) { expect_meaningful(check_frames<32>(5, 6, nullptr)); }
TEST(Invparam, Word24AgainstExact) { expect_meaningful(check_frames<24>(6, 6, nullptr), 20); }

// Issue 29: face planes at 0, 0.1 um, 1 um, 1 mm and 1 cm from the eye, the eye 0.1..10 mm in front of a
// face, near planes; nothing avoided. CIG_NEAR_EYE_FRAMES sets the frames per word (the campaign).
int near_eye_frames(int fallback) {
  const char* v = std::getenv("CIG_NEAR_EYE_FRAMES");
  return v != nullptr ? std::max(1, std::atoi(v)) : fallback;
}
TEST(Invparam, NearEyeWord64AgainstExact) {
  expect_meaningful(check_frames<64>(21, near_eye_frames(24), nullptr, true));
}
TEST(Invparam, NearEyeWord57AgainstExact) {
  expect_meaningful(check_frames<57>(22, near_eye_frames(24), nullptr, true));
}
TEST(Invparam, NearEyeWord40AgainstExact) {
  expect_meaningful(check_frames<40>(23, near_eye_frames(8), nullptr, true));
}

TEST(Invparam, InvparamDigest) {
  kernel_test::Digest digest;
  check_frames<64>(11, 2, &digest);
  check_frames<40>(12, 2, &digest);
  kernel_test::print_digest("invparam_visibility", digest);
}

// Hand-checked cases: a cube 1 m a side centred 5 m ahead (the centre ray meets its front face at
// t = 4.5), the same cube around the eye (not drawn: no entry face), and behind the eye.
TEST(Invparam, HandScenes) {
  auto cube = [](double cz, double h) {
    EyePolyhedron p;
    p.faces = {{1, 0, 0, h, -1, {}},  {-1, 0, 0, h, -1, {}},     {0, 1, 0, h, -1, {}},
               {0, -1, 0, h, -1, {}}, {0, 0, 1, cz + h, -1, {}}, {0, 0, -1, -cz + h, -1, {}}};
    return p;
  };
  const InvparamLattice lattice{16, 1};
  ScreenFrame f;
  f.tan_half_fov = 0.5;
  f.polyhedra = {cube(5, 0.5)};
  const InvparamSetup<64> s = invparam_setup<64>(f, lattice);
  const auto k = invparam_run_kernel<64>(s);
  const auto& centre = k[16 * 32 + 16];
  EXPECT_TRUE(centre.hit);
  EXPECT_EQ(centre.code.value(), 5u);  // the -z face, the one facing the eye
  EXPECT_NEAR(word_value<64>(centre.tau), 1 / 4.5, 1e-15);
  EXPECT_FALSE(k[0].hit);  // the corner ray passes by
  f.polyhedra = {cube(0, 2)};
  for (const auto& x : invparam_run_kernel<64>(invparam_setup<64>(f, lattice))) EXPECT_FALSE(x.hit);
  f.polyhedra = {cube(-5, 0.5)};
  for (const auto& x : invparam_run_kernel<64>(invparam_setup<64>(f, lattice))) EXPECT_FALSE(x.hit);
}

// Exact corner cases, set up so that every setup value is dyadic (exact codes): on the 32 x 32
// lattice with tan_half_fov = 1, sample (16, 16) looks along c = (1/32, 1/32, 1).
struct Corner {
  bool hit;
  std::uint32_t code;
};
std::vector<Corner> corner_results(const std::vector<EyeFace>& faces, int i, int j) {
  ScreenFrame f;
  f.tan_half_fov = 1;
  f.polyhedra = {EyePolyhedron{faces, 0}};
  const InvparamLattice lattice{16, 1};
  const InvparamSetup<64> s = invparam_setup<64>(f, lattice);
  const auto k = invparam_run_kernel<64>(s)[static_cast<std::size_t>(j) * 32 + i];
  const auto t =
      invparam_double(invparam_setup_double(f, lattice, word_value<64>(s.eps)))[static_cast<std::size_t>(j) * 32 + i];
  return {{k.hit, static_cast<std::uint32_t>(k.code.value())}, {t.hit, t.code}};
}
void expect_corner(const std::vector<EyeFace>& faces, int i, bool hit, std::uint32_t code) {
  for (const Corner& c : corner_results(faces, i, 16)) {
    EXPECT_EQ(c.hit, hit) << i;
    if (hit) { EXPECT_EQ(c.code, code) << i; }
  }
}

TEST(Invparam, ExactCornerCases) {
  const EyeFace front{0, 0, -1, -4, -1, {}}, back{0, 0, 1, 6, -1, {}}, up{0, -1, 0, 1, -1, {}},
      down{0, 1, 0, 1, -1, {}};
  // Grazing an edge: the entry (front, tau 1/4) and the exit (x = 1/8, tau 1/4) coincide; the seed's
  // strict tau_in > tau_out makes it no hit. One sample to the left the ray passes inside.
  const std::vector<EyeFace> graze = {front, back, {1, 0, 0, 0.125, -1, {}}, {-1, 0, 0, 1, -1, {}}, up, down};
  expect_corner(graze, 16, false, 0);
  expect_corner(graze, 15, true, 0);
  // Entering through an edge: two entry faces of equal tau; the PP keeps the later one (tau <= tau_in).
  const EyeFace left{-1, 0, 0, -0.125, -1, {}};
  expect_corner({front, left, {1, 0, 0, 1, -1, {}}, back, up, down}, 16, true, 1);
  expect_corner({left, front, {1, 0, 0, 1, -1, {}}, back, up, down}, 16, true, 1);
  // A face parallel to the ray (tau = 0) with the eye outside it: a miss (Fig. 1 literally would
  // skip it and see the front face).
  const std::vector<EyeFace> parallel = {front, back, {1, 0, -1.0 / 32, -0.125, -1, {}}, {-1, 0, 0, 1, -1, {}},
                                         up,    down};
  expect_corner(parallel, 16, false, 0);
  expect_corner(parallel, 15, true, 0);
}

// The setup's sample positions are the formatter's lattice (Xs = (H_k / 2 - 2047) / 2048).
TEST(Invparam, SamplePositionsAreTheFormattersLattice) {
  for (int n = hls::kMinRasterLog2; n <= hls::kMaxRasterLog2; ++n)
    for (int t = 0; t <= hls::kMaxSideLog2; ++t) {
      if (!hls::lattice_supported(n, t)) continue;
      const hls::LatticeGeometry g = hls::LatticeGeometry::for_raster(n, t);
      for (int k = 0; k < g.rows(); k += 7)
        ASSERT_EQ(invparam_sample_screen(k, g.rows()), (g.sample_half(k) / 2.0 - 2047) / 2048)
            << n << " " << t << " " << k;
    }
}

// Round to nearest and saturation of the setup's quantizer.
TEST(Invparam, SetupQuantization) {
  std::uint64_t hi = 0, lo = 0;
  bool sat = false;
  invparam_quantize(__float128(0.75), 10, 1, hi, lo, &sat);  // 1.5 -> 2 (ties away)
  EXPECT_EQ(lo, 2u);
  EXPECT_FALSE(sat);
  invparam_quantize(__float128(-0.75), 10, 1, hi, lo, &sat);
  EXPECT_EQ(static_cast<std::int64_t>(lo), -2);
  EXPECT_EQ(hi, ~std::uint64_t{0});
  invparam_quantize(__float128(200), 16, 8, hi, lo, &sat);  // beyond 127.996...: the largest code
  EXPECT_TRUE(sat);
  EXPECT_EQ(lo, 0x7FFFu);
  invparam_quantize(__float128(-200), 72, 64, hi, lo, &sat);
  EXPECT_TRUE(sat);
  EXPECT_EQ(hi, ~std::uint64_t{0} << 7);
  EXPECT_EQ(lo, 0u);
  invparam_quantize(__float128(1) / 3, 72, 64, hi, lo, &sat);  // 2^64 / 3 = 6148914691236517205.33
  EXPECT_EQ(hi, 0u);
  EXPECT_EQ(lo, 6148914691236517205ull);
}

}  // namespace
}  // namespace cig
