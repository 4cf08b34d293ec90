#include "cli/stress_lists.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "formatter/formatter_twin.hpp"
#include "scene/polygon_checks.hpp"

namespace cig::cli {

namespace {

// splitmix64: the same lists on every platform and standard library.
struct StressRng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double unit() { return double(next() >> 11) * 0x1p-53; }                          // [0, 1)
  double between(double a, double b) { return a + (b - a) * unit(); }               // [a, b)
  int integer(int a, int b) { return a + int(next() % std::uint64_t(b - a + 1)); }  // [a, b]
};

// Screen coordinate of grid unit g (eq. 1: X = 2048 Xs + 2047 is exact there; g = -1 is Xs = -1).
double on_grid(double g) { return (g - 2047) / 2048.0; }

// Attributes as planes over the grid (so that a polygon's I and 1/Z are planar): I = i0 + ix x +
// iy y clamped to [0, 1]; W = 1/Z = w0 + wx x + wy y, kept positive by the callers.
struct AttributePlane {
  double i0 = 1, ix = 0, iy = 0, w0 = 0.1, wx = 0, wy = 0;
  ScreenVertex at(double gx, double gy) const {
    const double w = w0 + wx * gx + wy * gy;
    return {on_grid(gx), on_grid(gy), 1.0 / w, std::clamp(i0 + ix * gx + iy * gy, 0.0, 1.0)};
  }
};

ScreenPolygon polygon_on_plane(const std::vector<std::pair<double, double>>& grid, const AttributePlane& a, Rgb c) {
  ScreenPolygon p;
  p.colour = c;
  for (const auto& [gx, gy] : grid) p.vertices.push_back(a.at(gx, gy));
  return p;
}

Rgb random_colour(StressRng& r) { return {r.between(0.1, 1), r.between(0.1, 1), r.between(0.1, 1)}; }

// W from about 1/10 m at the left to 1/900 m at the right of the screen (a fogged ramp).
AttributePlane depth_ramp(StressRng& r) {
  AttributePlane a;
  a.w0 = 0.1 * r.between(0.8, 1.2);
  a.wx = -(a.w0 - 1.0 / 900) / 4095;
  a.wy = 0;
  return a;
}

void slivers(StressRng& r, ScreenFrame& f) {
  f.fog = {{0.5, 0.6, 0.7}, 0, 1000};
  f.background = f.fog.colour;
  for (int k = 0; k < 12; ++k) {
    const double y0 = 150 + 320 * k, dy = r.integer(1, 60);
    AttributePlane a = depth_ramp(r);
    a.i0 = 0;
    a.ix = 1.0 / 4095;  // a ramp 0 -> 1 across the screen
    a.iy = r.between(-0.002, 0.002);
    if (k % 3 == 2)  // a thin quad
      f.polygons.push_back(
          polygon_on_plane({{0, y0}, {4095, y0 + dy}, {4095, y0 + dy + 2}, {0, y0 + 1}}, a, random_colour(r)));
    else
      f.polygons.push_back(polygon_on_plane(
          {{0, y0}, {4095, y0 + dy}, {r.integer(100, 3995), y0 + dy + r.integer(-8, 8) + (dy > 8 ? 0 : 9)}}, a,
          random_colour(r)));
  }
}

double edge_coordinate(StressRng& r) {
  const int pick = r.integer(0, 5);
  return pick == 0 ? -1 : pick == 1 ? 0 : pick == 2 ? 4095 : r.integer(0, 4095);
}

void screen_edges(StressRng& r, ScreenFrame& f) {
  for (int k = 0; k < 60; ++k) {
    AttributePlane a;
    a.i0 = r.between(0.2, 1);
    a.w0 = 1.0 / (10 + k);  // front to back in list order
    if (k % 4 == 0) {       // a rectangle against a screen side
      const double x0 = edge_coordinate(r), y0 = edge_coordinate(r);
      const double x1 = std::clamp(x0 + r.integer(-900, 900), -1.0, 4095.0);
      const double y1 = std::clamp(y0 + r.integer(-900, 900), -1.0, 4095.0);
      if (x0 == x1 || y0 == y1) continue;
      f.polygons.push_back(polygon_on_plane({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, a, random_colour(r)));
      continue;
    }
    std::vector<std::pair<double, double>> t;
    for (int v = 0; v < 3; ++v) t.push_back({edge_coordinate(r), edge_coordinate(r)});
    const double area = (t[1].first - t[0].first) * (t[2].second - t[0].second) -
                        (t[1].second - t[0].second) * (t[2].first - t[0].first);
    if (area != 0) f.polygons.push_back(polygon_on_plane(t, a, random_colour(r)));
  }
}

void depths(StressRng& r, ScreenFrame& f) {
  for (int k = 0; k < 48; ++k) {
    // Depth decades spread from 1e-30 to 1e38; the last four beyond e8m7 (2^-127 .. 2^128).
    const double decade = k < 44 ? -30 + 68.0 * k / 43 : (k % 2 ? 40 : -40);
    const double z0 = std::pow(10.0, decade);
    const double gx = r.integer(0, 3600), gy = r.integer(0, 3600), size = r.integer(200, 480);
    std::vector<std::pair<double, double>> t = {{gx, gy}, {gx + size, gy + r.integer(0, 100)}, {gx + 40, gy + size}};
    ScreenPolygon p;
    p.colour = random_colour(r);
    for (const auto& [x, y] : t) p.vertices.push_back({on_grid(x), on_grid(y), z0 * r.between(1, 4), r.unit()});
    f.polygons.push_back(p);
  }
}

void intensities(StressRng& r, ScreenFrame& f) {
  for (int cy = 0; cy < 6; ++cy)
    for (int cx = 0; cx < 6; ++cx) {
      const double x0 = 40 + 680 * cx, y0 = 40 + 680 * cy, s = r.integer(300, 620);
      AttributePlane a;
      a.w0 = 0.05;
      a.i0 = r.unit();
      a.ix = r.between(-1, 1) / s;
      a.iy = r.between(-1, 1) / s;
      ScreenPolygon p = polygon_on_plane({{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}}, a, random_colour(r));
      if ((cx + cy) % 2 == 1)
        for (auto& v : p.vertices) v.is = r.unit();  // four unrelated intensities: not planar
      f.polygons.push_back(p);
    }
}

void decals(StressRng& r, ScreenFrame& f) {
  for (int base = 0; base < 4; ++base) {
    AttributePlane a;  // a tilted plane: 1/Z varies across it (a runway seen from the air)
    a.w0 = 1.0 / (20 + 30 * base);
    a.wx = r.between(-1, 1) * a.w0 / 16000;
    a.wy = r.between(0.2, 1) * a.w0 / 8000;
    a.i0 = r.between(0.4, 1);
    const double x0 = 100 + 1000 * base, y0 = r.integer(100, 1500), w = 900, h = r.integer(1200, 2400);
    for (int d = 0; d < 6; ++d) {  // decals first: they precede their surface in the list
      const double dx = x0 + r.integer(20, 600), dy = y0 + r.integer(20, int(h) - 300);
      const double dw = r.integer(40, 280), dh = r.integer(8, 260);
      f.polygons.push_back(
          polygon_on_plane({{dx, dy}, {dx + dw, dy}, {dx + dw, dy + dh}, {dx, dy + dh}}, a, random_colour(r)));
    }
    f.polygons.push_back(
        polygon_on_plane({{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}}, a, random_colour(r)));
  }
}

void fans(StressRng& r, ScreenFrame& f) {
  for (int fan = 0; fan < 4; ++fan) {
    const double cx = 1024 + 2048 * (fan % 2), cy = 1024 + 2048 * (fan / 2);
    const int n = r.integer(8, 40);
    const ScreenVertex centre{on_grid(cx), on_grid(cy), 30, r.unit()};
    std::vector<ScreenVertex> rim;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * M_PI * k / n, rad = r.integer(500, 950);
      rim.push_back({on_grid(std::round(cx + rad * std::cos(t))), on_grid(std::round(cy + rad * std::sin(t))),
                     r.between(20, 60), r.unit()});
    }
    for (int k = 0; k < n; ++k) {
      ScreenPolygon p;
      p.colour = random_colour(r);
      p.vertices = {centre, rim[std::size_t(k)], rim[std::size_t((k + 1) % n)]};
      f.polygons.push_back(p);
    }
  }
}

// Whether the formatter's snap (eq. 1) turns a convex polygon non-convex or self-intersecting:
// its snapped vertices turn both ways (repeated and collinear vertices aside).
bool snaps_non_convex(const ScreenPolygon& p) {
  std::vector<glm::dvec2> s;
  for (const auto& v : p.vertices) {
    const glm::dvec2 q{twin_grid(snap_grid_coordinate(v.xs)), twin_grid(snap_grid_coordinate(v.ys))};
    if (s.empty() || q != s.back()) s.push_back(q);  // a repeat is no vertex
  }
  while (s.size() > 1 && s.back() == s.front()) s.pop_back();
  bool left = false, right = false;
  const std::size_t n = s.size();
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2 a = s[k], b = s[(k + 1) % n], c = s[(k + 2) % n];
    const double turn = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
    left = left || turn > 0;
    right = right || turn < 0;
  }
  return left && right;
}

// Thin convex polygons near random points, at fractional grid positions, kept when the snap makes
// them non-convex or self-intersecting.
void snap_nonconvex(StressRng& r, ScreenFrame& f) {
  for (int attempt = 0; attempt < 200000 && f.polygons.size() < 60; ++attempt) {
    const double cx = r.integer(310, 3780), cy = r.integer(310, 3780);  // the strip stays on the screen
    const int n = r.integer(3, 5);
    const double len = r.between(4, 300), ang = r.between(0, 2 * M_PI), thick = r.between(0.2, 1.5);
    std::vector<glm::dvec2> exact;
    ScreenPolygon p;
    p.colour = random_colour(r);
    for (int k = 0; k < n; ++k) {  // an ellipse-like convex strip, thin across
      const double t = 2 * M_PI * k / n + r.between(-0.3, 0.3);
      const double gx = cx + std::cos(ang) * len * std::cos(t) - std::sin(ang) * thick * std::sin(t);
      const double gy = cy + std::sin(ang) * len * std::cos(t) + std::cos(ang) * thick * std::sin(t);
      p.vertices.push_back({on_grid(gx), on_grid(gy), r.between(10, 50), r.unit()});
      exact.push_back({gx, gy});
    }
    if (!check_convex_2d(exact).empty() || !snaps_non_convex(p)) continue;
    // Planar attributes, so that the split into fans does not hide what the snap does.
    for (auto& v : p.vertices) {
      v.zs = 30;
      v.is = 0.6;
    }
    f.polygons.push_back(p);
  }
}

struct StressClass {
  const char* name;
  bool on_grid;
  void (*make)(StressRng&, ScreenFrame&);
};

const StressClass kClasses[] = {
    {"slivers", true, slivers},
    {"screen-edges", true, screen_edges},
    {"depths", true, depths},
    {"intensities", true, intensities},
    {"decals", true, decals},
    {"fans", true, fans},
    {"snap-nonconvex", false, snap_nonconvex},
};

const StressClass& find_class(const std::string& name) {
  for (const auto& c : kClasses)
    if (name == c.name) return c;
  std::string known;
  for (const auto& c : kClasses) known += (known.empty() ? "" : ", ") + std::string(c.name);
  throw InputError("", "class", "unknown stress class '" + name + "' (known: " + known + ")");
}

}  // namespace

std::vector<std::string> stress_class_names() {
  std::vector<std::string> names;
  for (const auto& c : kClasses) names.push_back(c.name);
  return names;
}

bool stress_class_on_grid(const std::string& name) { return find_class(name).on_grid; }

ScreenFrame make_stress_list(const std::string& name, std::uint64_t seed, int raster) {
  const StressClass& c = find_class(name);
  StressRng r{seed * 0x2545F4914F6CDD1Dull + 1};
  ScreenFrame f;
  f.raster = raster;
  c.make(r, f);
  // What a polygon list may hold: on the screen, convex, non-zero area (a generated triangle can be
  // collinear).
  std::vector<ScreenPolygon> kept;
  for (auto& p : f.polygons) {
    std::vector<glm::dvec2> xy;
    for (const auto& v : p.vertices) xy.push_back({v.xs, v.ys});
    const bool on_screen = std::all_of(p.vertices.begin(), p.vertices.end(), [](const ScreenVertex& v) {
      return std::abs(v.xs) <= 1 && std::abs(v.ys) <= 1;
    });
    if (on_screen && check_convex_2d(xy).empty()) kept.push_back(std::move(p));
  }
  f.polygons = std::move(kept);
  return f;
}

}  // namespace cig::cli
