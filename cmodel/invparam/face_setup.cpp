#include "invparam/face_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/error.hpp"

namespace cig {

namespace {
using Quad = __float128;
__extension__ typedef __int128 I128;
__extension__ typedef unsigned __int128 U128;

Quad quad_abs(Quad x) { return x < 0 ? -x : x; }
Quad quad_pow2(int e) {
  Quad r = 1;
  for (int k = 0; k < e; ++k) r *= 2;
  return r;
}
}  // namespace

double invparam_sample_screen(int k, int size) { return (2.0 * k + 1.0) / size - 1.0; }

InvparamFaceValues invparam_face_values(const EyeFace& face, double tan_half_fov, int size) {
  const Quad t = tan_half_fov, l = size;
  const Quad nx = face.nx, ny = face.ny, nz = face.nz;
  // Seed's signs: Num = -d, Den = -(n.c).
  const Quad num = -Quad(face.d);
  const auto den = [&](int i, int j) {
    const Quad xs = (Quad(2 * i + 1) / l) - 1, ys = (Quad(2 * j + 1) / l) - 1;
    return -(nx * (t * xs) + ny * (t * ys) + nz);
  };
  const Quad kx = -(nx * t) * (2 / l), ky = -(ny * t) * (2 / l);
  const int last = size - 1;
  const Quad corners[4] = {den(0, -1), den(last, -1), den(0, last), den(last, last)};
  Quad den_max = 0;  // the value is linear in i, j: its largest |.| is at a corner
  for (const Quad c : corners) den_max = std::max(den_max, quad_abs(c));
  InvparamFaceValues v;
  // tau's largest |.| on the lattice is den_max / |Num|: a face whose tau would leave the word
  // (the plane nearer than den_max / kValueLimit) is decided as through the eye (face_setup.hpp).
  v.az = face.d != 0 && den_max < Quad(kValueLimit) * quad_abs(num);
  v.through_eye = face.d != 0 && !v.az;
  v.as = num < 0;
  const Quad scale = v.az ? num : Quad(1);
  v.start = den(0, -1) / scale;
  v.step_x = kx / scale;
  v.step_y = ky / scale;
  v.corner_max = den_max / quad_abs(scale);
  return v;
}

std::vector<InvparamFaceOrigin> invparam_face_list(const ScreenFrame& frame) {
  if (frame.polyhedra.size() > static_cast<std::size_t>(hls::kMaxObjects))
    throw InputError(
        "", "invparam",
        std::to_string(frame.polyhedra.size()) + " polyhedra, at most " + std::to_string(hls::kMaxObjects));
  std::vector<InvparamFaceOrigin> list;
  for (std::size_t o = 0; o < frame.polyhedra.size(); ++o) {
    const std::size_t m = frame.polyhedra[o].faces.size();
    if (m < 1 || m > static_cast<std::size_t>(hls::kMaxFacesPerObject))
      throw InputError("", "invparam",
                       "polyhedron " + std::to_string(o) + " has " + std::to_string(m) + " faces, 1.." +
                           std::to_string(hls::kMaxFacesPerObject) + " allowed");
    for (std::size_t k = 0; k < m; ++k) list.push_back({static_cast<int>(o), static_cast<int>(k)});
  }
  if (list.size() > static_cast<std::size_t>(hls::kMaxFaces))
    throw InputError("", "invparam", std::to_string(list.size()) + " faces, at most " + std::to_string(hls::kMaxFaces));
  return list;
}

void invparam_quantize(Quad value, int w, int frac_bits, std::uint64_t& hi, std::uint64_t& lo, bool* saturated) {
  // |scaled| < 2^(w-1) + 1 <= 2^112 after the clamp, so scaled + 1/2 is exact and the conversion
  // (toward zero) of it rounds to nearest, ties away from zero.
  const Quad scaled = value * quad_pow2(frac_bits);
  const Quad top = quad_pow2(w - 1);
  I128 code = 0;
  *saturated = false;
  const U128 max_bits = (w == 128) ? ~U128(0) >> 1 : (U128(1) << (w - 1)) - 1;
  if (scaled >= top - Quad(0.5)) {
    code = static_cast<I128>(max_bits);
    *saturated = true;
  } else if (scaled < -top - Quad(0.5)) {
    code = -static_cast<I128>(max_bits) - 1;
    *saturated = true;
  } else {
    code = scaled >= 0 ? static_cast<I128>(scaled + Quad(0.5)) : -static_cast<I128>(Quad(0.5) - scaled);
  }
  const U128 bits = static_cast<U128>(code);
  hi = static_cast<std::uint64_t>(bits >> 64);
  lo = static_cast<std::uint64_t>(bits);
}

double invparam_error_bound_lsb(int i, int j) { return (i + j + 2) * (0.5 + 1.0 / (1 << 14)); }

InvparamSetupDouble invparam_setup_double(const ScreenFrame& frame, const InvparamLattice& lattice, double eps) {
  InvparamSetupDouble s;
  s.size = lattice.size();
  s.eps = eps;
  s.tau_near = frame.near > 0 ? 1.0 / frame.near : std::numeric_limits<double>::infinity();
  const double t = frame.tan_half_fov, l = s.size;
  const std::vector<InvparamFaceOrigin> list = invparam_face_list(frame);
  for (const EyePolyhedron& p : frame.polyhedra) s.object_faces.push_back(static_cast<int>(p.faces.size()));
  for (std::size_t f = 0; f < list.size(); ++f) {
    const EyeFace& face = frame.polyhedra[list[f].polyhedron].faces[list[f].face];
    const double num = -face.d;
    const double den = -(face.nx * (t * (1 / l - 1)) + face.ny * (t * (-1 / l - 1)) + face.nz);
    const double kx = -(face.nx * t) * (2 / l), ky = -(face.ny * t) * (2 / l);
    InvparamFaceDouble d;
    d.az = invparam_face_values(face, t, s.size).az;  // the kernel's rule, in binary128
    d.as = num < 0;
    const double scale = d.az ? num : 1.0;
    d.start = den / scale;
    d.step_x = kx / scale;
    d.step_y = ky / scale;
    d.code = static_cast<std::uint32_t>(f);
    s.faces.push_back(d);
  }
  return s;
}

}  // namespace cig
