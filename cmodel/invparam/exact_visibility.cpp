#include "invparam/exact_visibility.hpp"

namespace cig {

namespace {

using Quad = __float128;

Quad quad_abs(Quad x) { return x < 0 ? -x : x; }
const Quad kFloatMargin = Quad(1) / Quad(1ull << 50) / Quad(1ull << 50);  // 2^-100 (relative)

struct Ray {
  Quad c[3];
};
Quad dot(const EyeFace& f, const Ray& r) { return Quad(f.nx) * r.c[0] + Quad(f.ny) * r.c[1] + Quad(f.nz) * r.c[2]; }
Quad abs_dot(const EyeFace& f, const Ray& r) {
  return quad_abs(Quad(f.nx) * r.c[0]) + quad_abs(Quad(f.ny) * r.c[1]) + quad_abs(Quad(f.nz) * r.c[2]);
}

enum class Inside { kYes, kNo, kBorder };

// Is the entry point t c of face f inside plane g of its polyhedron?
Inside inside_plane(const EyeFace& g, const Ray& ray, Quad t, const ExactMargins& m) {
  const Quad r = t * dot(g, ray) - Quad(g.d);
  const Quad fp = kFloatMargin * (t * abs_dot(g, ray) + quad_abs(Quad(g.d)));
  const Quad tol = g.d != 0 ? 2 * Quad(m.tau) * quad_abs(Quad(g.d)) * t : Quad(m.den) * t;
  if (r > tol + fp) return Inside::kNo;
  if (r < -(tol + fp)) return Inside::kYes;
  return Inside::kBorder;
}

struct Candidate {
  Quad tau;
  bool border;
  int polyhedron, face;
  std::uint32_t code;
};

// The entry faces of one polyhedron whose entry point is inside (or borderline) every other plane
// and beyond the near plane (tau < tau_near; 0: none).
void polyhedron_candidates(const EyePolyhedron& p, int index, std::uint32_t code0, const Ray& ray, Quad tau_near,
                           const ExactMargins& m, std::vector<Candidate>& out) {
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const EyeFace& face = p.faces[f];
    const Quad dn = dot(face, ray);
    if (!(face.d < 0 && dn < 0)) continue;  // not a face the ray enters at some t > 0
    const Quad t = Quad(face.d) / dn, tau = dn / Quad(face.d);
    const Quad fp = kFloatMargin * abs_dot(face, ray) / quad_abs(Quad(face.d));
    bool border = tau <= Quad(m.tau) + fp;
    if (tau_near > 0) {  // what the near plane cuts away is not drawn
      if (tau > tau_near + 2 * Quad(m.tau) + fp) continue;
      border = border || tau >= tau_near - 2 * Quad(m.tau) - fp;
    }
    bool valid = true;
    for (std::size_t g = 0; g < p.faces.size() && valid; ++g) {
      if (g == f) continue;
      const Inside in = inside_plane(p.faces[g], ray, t, m);
      valid = in != Inside::kNo;
      border = border || in == Inside::kBorder;
    }
    if (valid) out.push_back({tau, border, index, static_cast<int>(f), code0 + static_cast<std::uint32_t>(f)});
  }
}

}  // namespace

ExactSample exact_visibility_sample(const ScreenFrame& frame, int size, int i, int j, const ExactMargins& margins) {
  const Quad t_half = frame.tan_half_fov;
  const Quad xs = Quad(2 * i + 1) / Quad(size) - 1, ys = Quad(2 * j + 1) / Quad(size) - 1;
  const Ray ray{{t_half * xs, t_half * ys, Quad(1)}};
  std::vector<Candidate> cands;
  std::uint32_t code0 = 0;
  const Quad tau_near = frame.near > 0 ? 1 / Quad(frame.near) : Quad(0);
  for (std::size_t p = 0; p < frame.polyhedra.size(); ++p) {
    polyhedron_candidates(frame.polyhedra[p], static_cast<int>(p), code0, ray, tau_near, margins, cands);
    code0 += static_cast<std::uint32_t>(frame.polyhedra[p].faces.size());
  }
  // The answer: the nearest (largest tau) candidate that is valid beyond doubt; the first wins a tie.
  ExactSample s;
  const Candidate* best = nullptr;
  for (const Candidate& c : cands)
    if (!c.border && (best == nullptr || c.tau > best->tau)) best = &c;
  const Quad best_tau = best != nullptr ? best->tau : Quad(0);
  const Quad near = 2 * Quad(margins.tau) + kFloatMargin * 256;
  for (const Candidate& c : cands) {
    if (&c == best) continue;
    if (c.tau >= best_tau - near) s.uncertain = true;  // a rival (or a borderline one) as near, within the margin
  }
  if (best != nullptr) {
    s.hit = true;
    s.polyhedron = best->polyhedron;
    s.face = best->face;
    s.code = best->code;
    s.tau = static_cast<double>(best->tau);
    s.tau_exact = best->tau;
    s.t = static_cast<double>(1 / best->tau);
  }
  return s;
}

}  // namespace cig
