#include "studies/word_length_study.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "common/error.hpp"
#include "invparam/exact_visibility.hpp"
#include "invparam/face_setup.hpp"
#include "invparam/invparam_engine.hpp"

namespace cig {

namespace {

using Quad = __float128;
__extension__ typedef __int128 I128;
using Vec3 = std::array<double, 3>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxTurnDegrees = 3;  // yaw and pitch, uniform in +-3 degrees
constexpr double kViewWidth = 100;     // metres at R: tan_half_fov = 50 / R
constexpr double kPanelProud = 1e-3;   // the panel's front face lies 1 mm in front of the wall's

// SplitMix64: a fixed generator (the standard distributions differ between libraries).
struct SplitMix {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1p-53; }  // [0, 1)
};

// A view: the frame, and each face's four corners in eye space (the frame's face order), which the
// Z-buffer (method b) interpolates between.
struct StudyView {
  ScreenFrame frame;
  std::vector<std::array<Vec3, 4>> corners;
};

struct Pose {
  double yaw = 0, pitch = 0;  // radians
  Vec3 offset{0, 0, 0};       // the wall face's centre in eye space
  Vec3 apply(const Vec3& p) const {
    const double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
    const double y1 = cp * p[1] - sp * p[2], z1 = sp * p[1] + cp * p[2];  // pitch about x
    const double x2 = cy * p[0] + sy * z1, z2 = -sy * p[0] + cy * z1;     // yaw about y
    return {x2 + offset[0], y1 + offset[1], z2 + offset[2]};
  }
  Vec3 turn(const Vec3& n) const {
    Pose r = *this;
    r.offset = {0, 0, 0};
    return r.apply(n);
  }
};

// An axis-aligned box in the wall's frame (the wall's face at z = 0, z away from the eye), posed:
// six faces, outward normals, d = n . (the face's centre).
void add_box(StudyView& v, const Pose& pose, const Vec3& lo, const Vec3& hi) {
  EyePolyhedron poly;
  poly.object = static_cast<std::int32_t>(v.frame.polyhedra.size());
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      std::array<Vec3, 4> c;
      const double uu[4] = {lo[u], hi[u], hi[u], lo[u]}, ww[4] = {lo[w], lo[w], hi[w], hi[w]};
      Vec3 centre{0, 0, 0};
      for (int k = 0; k < 4; ++k) {
        Vec3 p;
        p[axis] = side ? hi[axis] : lo[axis];
        p[u] = uu[k];
        p[w] = ww[k];
        c[k] = pose.apply(p);
        for (int e = 0; e < 3; ++e) centre[e] += c[k][e] / 4;
      }
      Vec3 n{0, 0, 0};
      n[axis] = side ? 1 : -1;
      n = pose.turn(n);
      EyeFace f;
      f.nx = n[0];
      f.ny = n[1];
      f.nz = n[2];
      f.d = n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2];
      poly.faces.push_back(f);
      v.corners.push_back(c);
    }
  v.frame.polyhedra.push_back(poly);
}

StudyView make_view(double range, int lattice, std::uint64_t seed, int view) {
  // The same poses at every range (the seed and the view number only), so ranges compare.
  SplitMix rng{seed ^ (std::uint64_t(view) << 32)};
  StudyView v;
  v.frame.raster = lattice;
  v.frame.tan_half_fov = kViewWidth / 2 / range;
  const double sample = kViewWidth / lattice;  // metres per sample at R
  Pose pose;
  pose.yaw = (2 * rng.uniform() - 1) * kMaxTurnDegrees * kPi / 180;
  pose.pitch = (2 * rng.uniform() - 1) * kMaxTurnDegrees * kPi / 180;
  pose.offset = {rng.uniform() * sample, rng.uniform() * sample, range};
  add_box(v, pose, {-60, -20, 0}, {60, 20, 8});                           // the wall
  add_box(v, pose, {-20, -8, -kPanelProud}, {20, 8, 0.1 - kPanelProud});  // the panel
  return v;
}

// Faces covering a sample: the ray enters the face at t > 0 inside every other plane of its
// polyhedron (binary128; a sample within its margin of an edge is the truth's `uncertain`).
struct Cover {
  int face = 0;  // index in the frame's face list
  Quad t = 0;    // exact depth
  int triangle = 0;
};

Quad dot(const EyeFace& f, const Quad c[3]) { return Quad(f.nx) * c[0] + Quad(f.ny) * c[1] + Quad(f.nz) * c[2]; }

int covers(const ScreenFrame& frame, const Quad c[3], Cover out[], int capacity) {
  int n = 0, base = 0;
  for (const EyePolyhedron& p : frame.polyhedra) {
    for (std::size_t f = 0; f < p.faces.size(); ++f) {
      const EyeFace& face = p.faces[f];
      const Quad dn = dot(face, c);
      if (!(face.d < 0 && dn < 0)) continue;
      const Quad t = Quad(face.d) / dn;
      bool inside = true;
      for (std::size_t g = 0; g < p.faces.size() && inside; ++g)
        if (g != f) inside = t * dot(p.faces[g], c) - Quad(p.faces[g].d) <= 0;
      if (inside && n < capacity) out[n++] = {base + int(f), t, 0};
    }
    base += int(p.faces.size());
  }
  return n;
}

I128 quantize(Quad value, int w, int frac) {
  std::uint64_t hi = 0, lo = 0;
  bool sat = false;
  invparam_quantize(value, w, frac, hi, lo, &sat);
  return static_cast<I128>((static_cast<unsigned __int128>(hi) << 64) | lo);
}

struct Steps {
  I128 start = 0, step_x = 0, step_y = 0;
  I128 at(int i, int j) const { return start + step_x * i + step_y * (j + 1); }  // = the incremental adds
};

// Method b's planes: per face, per fan triangle (0: corners 0 1 2, 1: corners 0 2 3), Z as an affine
// function of the screen through the three projected corners; start at column 0, row -1.
struct ZTriangle {
  double x[3], y[3];
  Quad z0 = 0, dz_dx = 0, dz_dy = 0;
};

ZTriangle z_triangle(const std::array<Vec3, 4>& c, int tri, double t_half) {
  const int idx[2][3] = {{0, 1, 2}, {0, 2, 3}};
  ZTriangle r;
  Quad x[3], y[3], z[3];
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = c[std::size_t(idx[tri][k])];
    z[k] = p[2];
    x[k] = Quad(p[0]) / (z[k] * t_half);
    y[k] = Quad(p[1]) / (z[k] * t_half);
    r.x[k] = double(x[k]);
    r.y[k] = double(y[k]);
  }
  const Quad ax = x[1] - x[0], ay = y[1] - y[0], az = z[1] - z[0];
  const Quad bx = x[2] - x[0], by = y[2] - y[0], bz = z[2] - z[0];
  const Quad det = ax * by - ay * bx;
  r.dz_dx = (az * by - ay * bz) / det;
  r.dz_dy = (ax * bz - az * bx) / det;
  r.z0 = z[0] - r.dz_dx * x[0] - r.dz_dy * y[0];
  return r;
}

// Which fan triangle of the face's quad holds screen point (x, y): the side of the diagonal 0-2.
int triangle_of(const ZTriangle& t0, double x, double y) {
  const double ex = t0.x[2] - t0.x[0], ey = t0.y[2] - t0.y[0];
  const double side_p = ex * (y - t0.y[0]) - ey * (x - t0.x[0]);
  const double side_1 = ex * (t0.y[1] - t0.y[0]) - ey * (t0.x[1] - t0.x[0]);
  return (side_p > 0) == (side_1 > 0) ? 0 : 1;
}

// One sample of one method: `got` and `want` are face indices (-1: none), `solid` maps a face to
// its polyhedron. A different face of the same solid with the depth within 1 mm is an edge tie
// (the sample lies on the solid's edge within the word's precision), not a wrong face.
void tally(WordLengthCell& c, int got, int want, Quad depth, Quad truth_t, const std::vector<int>& solid) {
  bool over = false;
  if (got >= 0 && want >= 0) {
    const double err = double(depth > truth_t ? depth - truth_t : truth_t - depth);
    over = err > kDepthTolerance;
    c.max_depth_error = std::max(c.max_depth_error, err);
  }
  const bool differs = got != want;
  const bool tie = differs && !over && got >= 0 && want >= 0 && solid[std::size_t(got)] == solid[std::size_t(want)];
  c.wrong_faces += differs && !tie ? 1 : 0;
  c.edge_ties += tie ? 1 : 0;
  c.depth_errors += over ? 1 : 0;
  c.in_error += ((differs && !tie) || over) ? 1 : 0;
}

std::vector<int> face_solids(const ScreenFrame& frame) {
  std::vector<int> solid;
  for (std::size_t p = 0; p < frame.polyhedra.size(); ++p)
    for (std::size_t f = 0; f < frame.polyhedra[p].faces.size(); ++f) solid.push_back(int(p));
  return solid;
}

// The tables one view needs for methods b, c, d at every W.
struct ViewTables {
  int faces = 0, widths = 0;
  std::vector<ZTriangle> tri;    // [face][2]
  std::vector<Steps> z_steps;    // [face][2][W]   method b
  std::vector<Steps> tau_steps;  // [face][W]      method c
};

ViewTables view_tables(const StudyView& v, const WordLengthOptions& o) {
  ViewTables t;
  t.faces = int(v.corners.size());
  t.widths = o.max_bits - o.min_bits + 1;
  const int L = o.lattice;
  const double th = v.frame.tan_half_fov;
  std::vector<InvparamFaceValues> values;
  for (const EyePolyhedron& p : v.frame.polyhedra)
    for (const EyeFace& f : p.faces) values.push_back(invparam_face_values(f, th, L));
  const Quad x0 = invparam_sample_screen(0, L), y0 = invparam_sample_screen(-1, L), step = Quad(2) / L;
  for (int f = 0; f < t.faces; ++f) {
    for (int k = 0; k < 2; ++k) t.tri.push_back(z_triangle(v.corners[std::size_t(f)], k, th));
    for (int k = 0; k < 2; ++k) {
      const ZTriangle& z = t.tri[std::size_t(2 * f + k)];
      const Quad start = z.z0 + z.dz_dx * x0 + z.dz_dy * y0;
      for (int w = o.min_bits; w <= o.max_bits; ++w) {
        const int frac = w - kZIntBits;
        t.z_steps.push_back(
            {quantize(start, w, frac), quantize(z.dz_dx * step, w, frac), quantize(z.dz_dy * step, w, frac)});
      }
    }
    const InvparamFaceValues& val = values[std::size_t(f)];
    for (int w = o.min_bits; w <= o.max_bits; ++w) {
      const int frac = w - 8;
      t.tau_steps.push_back(
          {quantize(val.start, w, frac), quantize(val.step_x, w, frac), quantize(val.step_y, w, frac)});
    }
  }
  return t;
}

// The truth of every sample of the view.
struct ViewTruth {
  std::vector<std::int32_t> face;
  std::vector<Quad> t;  // binary128: the depth errors of 72-bit words are ~1e-17 m
  std::vector<std::uint8_t> uncertain;
};

ViewTruth view_truth(const ScreenFrame& frame, int L) {
  ViewTruth t;
  const std::size_t n = std::size_t(L) * std::size_t(L);
  t.face.assign(n, -1);
  t.t.assign(n, 0);
  t.uncertain.assign(n, 0);
  for (int j = 0; j < L; ++j)
    for (int i = 0; i < L; ++i) {
      const ExactSample s = exact_visibility_sample(frame, L, i, j, ExactMargins{});
      const std::size_t k = std::size_t(j) * std::size_t(L) + std::size_t(i);
      t.uncertain[k] = s.uncertain ? 1 : 0;
      if (s.hit) {
        t.face[k] = std::int32_t(s.code);
        t.t[k] = 1 / s.tau_exact;
      }
    }
  return t;
}

// Method a: the kernel at every W.
void run_kernel(const StudyView& v, const ViewTruth& truth, const WordLengthOptions& o, WordLengthRow& row) {
  const InvparamLattice lattice{o.lattice, 0};
  const std::vector<int> solid = face_solids(v.frame);
  for (int w = o.min_bits; w <= o.max_bits; ++w) {
    const InvparamHits h = invparam_kernel_hits(v.frame, lattice, w);
    WordLengthCell& cell = row.cells[std::size_t(w - o.min_bits)];
    for (std::size_t k = 0; k < h.face.size(); ++k) {
      if (truth.uncertain[k]) continue;
      tally(cell, h.face[k], truth.face[k], h.face[k] >= 0 ? 1 / Quad(h.tau[k]) : Quad(0), truth.t[k], solid);
    }
  }
}

// Methods b, c, d at one sample, every W.
void depth_buffers(const ViewTables& tab, const Cover* cov, int n, int i, int j, int want, Quad truth_t,
                   const WordLengthOptions& o, const std::vector<int>& solid, WordLengthRow* rows[3]) {
  for (int wi = 0; wi < tab.widths; ++wi) {
    const int w = o.min_bits + wi;
    int got_b = -1, got_c = -1, got_d = -1;
    I128 best_b = 0, best_c = 0, best_d = 0;
    for (int k = 0; k < n; ++k) {
      const int f = cov[k].face;
      const I128 zb = tab.z_steps[std::size_t((2 * f + cov[k].triangle) * tab.widths + wi)].at(i, j);
      const I128 tc = tab.tau_steps[std::size_t(f * tab.widths + wi)].at(i, j);
      const I128 zd = static_cast<I128>(cov[k].t * std::ldexp(1.0, w - kZIntBits) + Quad(0.5));
      if (got_b < 0 || zb < best_b) got_b = f, best_b = zb;
      if (got_c < 0 || tc > best_c) got_c = f, best_c = tc;
      if (got_d < 0 || zd < best_d) got_d = f, best_d = zd;
    }
    const Quad zscale = std::ldexp(1.0, -(w - kZIntBits));  // a power of two, exact
    const Quad depth_c = best_c > 0 ? Quad(std::ldexp(1.0, w - 8)) / Quad(best_c) : Quad(0);
    tally(rows[0]->cells[std::size_t(wi)], got_b, want, Quad(best_b) * zscale, truth_t, solid);
    tally(rows[1]->cells[std::size_t(wi)], best_c > 0 ? got_c : -1, want, depth_c, truth_t, solid);
    tally(rows[2]->cells[std::size_t(wi)], got_d, want, Quad(best_d) * zscale, truth_t, solid);
  }
}

void run_depth_buffers(const StudyView& v, const ViewTruth& truth, const WordLengthOptions& o, WordLengthRow* rows[3]) {
  const ViewTables tab = view_tables(v, o);
  const std::vector<int> solid = face_solids(v.frame);
  const int L = o.lattice;
  const Quad th = v.frame.tan_half_fov;
  for (int j = 0; j < L; ++j)
    for (int i = 0; i < L; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(L) + std::size_t(i);
      if (truth.uncertain[k]) continue;
      const double x = invparam_sample_screen(i, L), y = invparam_sample_screen(j, L);
      const Quad c[3] = {th * Quad(x), th * Quad(y), Quad(1)};
      Cover cov[8];
      const int n = covers(v.frame, c, cov, 8);
      for (int m = 0; m < n; ++m) cov[m].triangle = triangle_of(tab.tri[std::size_t(2 * cov[m].face)], x, y);
      depth_buffers(tab, cov, n, i, j, truth.face[k], truth.t[k], o, solid, rows);
    }
}

}  // namespace

// The methods' names and letters in kDepthMethods' order (the enum's).
const char* depth_method_name(DepthMethod m) {
  static const char* const kNames[] = {"invparam", "z-buffer", "inverse-z", "exact-z"};
  return kNames[int(m)];
}
const char* depth_method_letter(DepthMethod m) {
  static const char* const kLetters[] = {"a", "b", "c", "d"};
  return kLetters[int(m)];
}

int WordLengthRow::smallest_bits() const {
  int smallest = -1;
  for (auto c = cells.rbegin(); c != cells.rend() && c->clean(); ++c) smallest = c->bits;
  return smallest;
}

ScreenFrame word_length_view(double range, int lattice, std::uint64_t seed, int view) {
  return make_view(range, lattice, seed, view).frame;
}

int word_length_bound_bits(double range, int lattice) {
  return 8 + int(std::ceil(std::log2(2.0 * lattice * range * range / kDepthTolerance)));
}

void check_word_length_options(const WordLengthOptions& o) {
  if (o.ranges.empty()) throw InputError("", "--ranges", "no range given");
  for (double r : o.ranges)
    if (!(r >= kMinStudyRange && r <= kMaxStudyRange))
      throw InputError("", "--ranges",
                       "range " + std::to_string(r) + " m is not 100..120000 m (the Z-buffer's word has " +
                           std::to_string(kZIntBits) + " integer bits)");
  if (o.min_bits < kMinWordBits || o.max_bits > kMaxWordBits || o.min_bits > o.max_bits)
    throw InputError("", "--bits",
                     "word lengths " + std::to_string(o.min_bits) + ":" + std::to_string(o.max_bits) +
                         " are not A:B with " + std::to_string(kMinWordBits) +
                         " <= A <= B <= " + std::to_string(kMaxWordBits));
  if (o.views < 1 || o.views > 1000)
    throw InputError("", "--views", "views must be 1..1000, not " + std::to_string(o.views));
  const bool pow2 = o.lattice > 0 && (o.lattice & (o.lattice - 1)) == 0;
  if (!pow2 || o.lattice < 16 || o.lattice > hls::kMaxSamplesPerColumn)
    throw InputError("", "--lattice",
                     "the lattice must be a power of two, 16.." + std::to_string(hls::kMaxSamplesPerColumn) +
                         " samples a side, not " + std::to_string(o.lattice));
}

WordLengthStudy run_word_length_study(const WordLengthOptions& o, Progress* progress) {
  check_word_length_options(o);
  WordLengthStudy s;
  s.options = o;
  s.samples = long(o.views) * o.lattice * o.lattice;
  for (double range : o.ranges) {
    const std::size_t first = s.rows.size();
    for (DepthMethod m : kDepthMethods) {
      WordLengthRow row;
      row.range = range;
      row.method = m;
      for (int w = o.min_bits; w <= o.max_bits; ++w) row.cells.push_back(WordLengthCell{w});
      s.rows.push_back(row);
    }
    WordLengthRow* buffers[3] = {&s.rows[first + 1], &s.rows[first + 2], &s.rows[first + 3]};
    for (int view = 0; view < o.views; ++view) {
      const StudyView v = make_view(range, o.lattice, o.seed, view);
      const ViewTruth truth = view_truth(v.frame, o.lattice);
      for (std::uint8_t u : truth.uncertain) s.uncertain += u;
      run_kernel(v, truth, o, s.rows[first]);
      run_depth_buffers(v, truth, o, buffers);
      if (progress)
        progress->step("range " + std::to_string(long(range)) + " m, view " + std::to_string(view + 1) + "/" +
                       std::to_string(o.views));
    }
  }
  return s;
}

}  // namespace cig
