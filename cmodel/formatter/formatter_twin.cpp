#include "formatter/formatter_twin.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace cig {

namespace {

hls::UInt<64> bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return hls::UInt<64>(b);
}

}  // namespace

double snap_grid_coordinate(double s, int grid_bits) {
  // q = 2^(g - 12) g-bit units per 12-bit unit; X_g = round(2^(g-1) s + 2^(g-1) - 1), and the
  // 12-bit coordinate of that grid point is (X_g + 1) / q - 1 (g = 12: X itself).
  const double q = std::ldexp(1.0, grid_bits - kSeedGridBits);
  const double xg = std::round(q * kGridScale * s + (q * (kGridOffset + 1) - 1));
  const double x = std::min(std::max((xg + 1) / q - 1, 0.0), double(kGridMax));
  return (x - kGridOffset) / kGridScale;
}

ScreenFrame snap_to_formatter_grid(const ScreenFrame& f, int grid_bits) {
  ScreenFrame s = f;
  for (auto& p : s.polygons)
    for (auto& v : p.vertices) {
      v.xs = snap_grid_coordinate(v.xs, grid_bits);
      v.ys = snap_grid_coordinate(v.ys, grid_bits);
    }
  for (auto& l : s.light_points) {
    l.xs = snap_grid_coordinate(l.xs, grid_bits);
    l.ys = snap_grid_coordinate(l.ys, grid_bits);
    double d = std::min(std::round(kGridScale * l.ds), kMaxLightDiameterUnits);
    l.ds = d / kGridScale;
  }
  return s;
}

double twin_grid(double s) { return std::clamp(kGridScale * s + kGridOffset, 0.0, double(kGridMax)); }
double twin_intensity(double is) { return std::clamp(256.0 * is, 0.0, 256.0); }
double twin_diameter(double ds) { return std::clamp(kGridScale * ds, 0.0, kMaxLightDiameterUnits); }
double twin_colour(double c) { return std::clamp(255.0 * c, 0.0, 255.0); }

TwinPrimitive formatter_twin(const ScreenPolygon& p, std::uint16_t id) {
  TwinPrimitive t;
  t.n = int(std::min<std::size_t>(p.vertices.size(), hls::kMaxVertices));
  for (int k = 0; k < t.n; ++k) {
    const ScreenVertex& v = p.vertices[std::size_t(k)];
    t.v[k] = {twin_grid(v.xs), twin_grid(v.ys), twin_intensity(v.is), v.zs};
  }
  for (int c = 0; c < 3; ++c) t.colour[c] = twin_colour(p.colour[c]);
  t.opaque = p.opaque;
  t.protect = p.protect;
  t.id = id;
  return t;
}

TwinPrimitive formatter_twin(const ScreenLightPoint& l, std::uint16_t id) {
  TwinPrimitive t;
  t.is_light = true;
  t.n = 1;
  t.v[0] = {twin_grid(l.xs), twin_grid(l.ys), twin_intensity(l.intensity), l.zs};
  t.d = twin_diameter(l.ds);
  for (int c = 0; c < 3; ++c) t.colour[c] = twin_colour(l.colour[c]);
  t.id = id;
  return t;
}

hls::RawPrimitive raw_from_polygon(const ScreenPolygon& p, std::uint16_t id) {
  if (p.vertices.empty() || p.vertices.size() > std::size_t(hls::kMaxVertices))
    throw std::invalid_argument("raw_from_polygon: " + std::to_string(p.vertices.size()) +
                                " vertices; the formatter takes 1.." + std::to_string(hls::kMaxVertices));
  hls::RawPrimitive r;
  r.is_light = false;
  r.n = hls::UInt<5>(p.vertices.size());
  for (std::size_t k = 0; k < p.vertices.size(); ++k) {
    const ScreenVertex& v = p.vertices[k];
    r.v[k] = {bits_of(v.xs), bits_of(v.ys), bits_of(v.zs), bits_of(v.is)};
  }
  for (int c = 0; c < 3; ++c) r.colour[c] = bits_of(p.colour[c]);
  r.opaque = p.opaque;
  r.protect = p.protect;
  r.id = hls::UInt<16>(id);
  return r;
}

hls::RawPrimitive raw_from_light(const ScreenLightPoint& l, std::uint16_t id) {
  hls::RawPrimitive r;
  r.is_light = true;
  r.n = hls::UInt<5>(1);
  r.v[0] = {bits_of(l.xs), bits_of(l.ys), bits_of(l.zs), bits_of(l.intensity)};
  r.ds = bits_of(l.ds);
  for (int c = 0; c < 3; ++c) r.colour[c] = bits_of(l.colour[c]);
  r.opaque = true;
  r.protect = false;
  r.id = hls::UInt<16>(id);
  return r;
}

double zfloat_to_double(hls::ZFloat z) {
  const int e = int(z.exponent().value());
  const int m = int(z.mantissa().value());
  return std::ldexp(double(128 + m), e - hls::ZFloat::kBias - hls::ZFloat::kMantissaBits);
}

}  // namespace cig
