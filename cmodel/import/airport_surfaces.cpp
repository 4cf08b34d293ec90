#include "import/airport_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

namespace cig {

GroundHeight::GroundHeight(const std::vector<TerrainTriangle>& triangles, double radius_m, double cell_m)
    : tris_(triangles),
      origin_(-radius_m - cell_m),
      cell_(cell_m),
      n_(int(std::ceil(2 * (radius_m + cell_m) / cell_m))) {
  const std::size_t cells = std::size_t(n_) * std::size_t(n_);
  std::vector<std::uint32_t> count(cells + 1, 0);
  auto cell_range = [&](const TerrainTriangle& t, int& x0, int& x1, int& y0, int& y1) {
    double lx = 1e300, hx = -1e300, ly = 1e300, hy = -1e300;
    for (const glm::dvec3& v : t.v) {
      lx = std::min(lx, v.x), hx = std::max(hx, v.x), ly = std::min(ly, v.y), hy = std::max(hy, v.y);
    }
    x0 = std::clamp(int((lx - origin_) / cell_), 0, n_ - 1), x1 = std::clamp(int((hx - origin_) / cell_), 0, n_ - 1);
    y0 = std::clamp(int((ly - origin_) / cell_), 0, n_ - 1), y1 = std::clamp(int((hy - origin_) / cell_), 0, n_ - 1);
  };
  // Two passes (count, then fill): compressed rows, no per-cell vectors.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t i = 0; i < tris_.size(); ++i) {
      int x0, x1, y0, y1;
      cell_range(tris_[i], x0, x1, y0, y1);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const std::size_t c = std::size_t(y) * std::size_t(n_) + std::size_t(x);
          if (pass == 0) ++count[c + 1];
          else items_[count[c]++] = i;
        }
    }
    if (pass == 0) {
      for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
      start_ = count;
      items_.resize(count[cells]);
    }
  }
}

double GroundHeight::at(double x, double y) const {
  const int cx = int(std::floor((x - origin_) / cell_)), cy = int(std::floor((y - origin_) / cell_));
  double best = std::numeric_limits<double>::quiet_NaN();
  if (cx < 0 || cy < 0 || cx >= n_ || cy >= n_) return best;
  const std::size_t c = std::size_t(cy) * std::size_t(n_) + std::size_t(cx);
  for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
    const TerrainTriangle& t = tris_[items_[k]];
    // Barycentric coordinates of (x, y) in the triangle's projection (faces up: positive area).
    const double d = (t.v[1].x - t.v[0].x) * (t.v[2].y - t.v[0].y) - (t.v[2].x - t.v[0].x) * (t.v[1].y - t.v[0].y);
    if (!(std::fabs(d) > 1e-12)) continue;
    const double l1 = ((x - t.v[0].x) * (t.v[2].y - t.v[0].y) - (t.v[2].x - t.v[0].x) * (y - t.v[0].y)) / d;
    const double l2 = ((t.v[1].x - t.v[0].x) * (y - t.v[0].y) - (x - t.v[0].x) * (t.v[1].y - t.v[0].y)) / d;
    const double eps = -1e-9;
    if (l1 < eps || l2 < eps || l1 + l2 > 1 - eps) continue;
    const double z = t.v[0].z + l1 * (t.v[1].z - t.v[0].z) + l2 * (t.v[2].z - t.v[0].z);
    if (!(z <= best)) best = z;
  }
  return best;
}

double GroundHeight::at_or(double x, double y, double fallback) const {
  const double z = at(x, y);
  return std::isnan(z) ? fallback : z;
}

void PolygonSoup::add(const std::vector<glm::dvec3>& corners, const Rgb& colour) {
  std::vector<std::uint32_t> p;
  for (const glm::dvec3& c : corners) {
    p.push_back(std::uint32_t(vertices.size()));
    vertices.push_back(c);
  }
  polygons.push_back(std::move(p));
  colours.push_back(colour);
}

RunwayFrame::RunwayFrame(const glm::dvec2& end0, const glm::dvec2& end1, double width_m)
    : a(end0), b(end1), width(width_m) {
  length = glm::length(end1 - end0);
  along = (end1 - end0) / length;
  right = {along.y, -along.x};
}

double RunwayFrame::heading_deg() const {
  const double h = std::atan2(along.x, along.y) * 180 / 3.14159265358979323846;
  return h < 0 ? h + 360 : h;
}

double RunwayPolygons::z_at(double s) const {
  if (s <= station_s.front()) return station_z.front();
  if (s >= station_s.back()) return station_z.back();
  const std::size_t k = std::size_t(std::upper_bound(station_s.begin(), station_s.end(), s) - station_s.begin());
  const double w = (s - station_s[k - 1]) / (station_s[k] - station_s[k - 1]);
  return station_z[k - 1] + w * (station_z[k] - station_z[k - 1]);
}

}  // namespace cig

namespace cig {

namespace {

// Profile stations at most this far apart: TerraGear's pavement follows the terrain, and so does
// the runway's surface between stations (each piece level across, straight along: planar).
constexpr double kStationSpacingM = 50;
// The surface lies this far above the highest terrain under it (sampled across at the stations),
// so that a depth buffer shows it over TerraGear's own pavement rather than through it.
constexpr double kRunwayLiftM = 0.3;
const Rgb kMarkingWhite{0.85, 0.85, 0.85};

// apt.dat surface codes: 1 asphalt, 2 concrete, 3 turf, 4 dirt, 5 gravel, 12 dry lakebed, 13 water.
Rgb surface_colour(int surface) {
  switch (surface) {
    case 1:
      return {0.16, 0.16, 0.17};
    case 2:
      return {0.42, 0.42, 0.40};
    case 3:
      return {0.20, 0.30, 0.12};
    case 4:
      return {0.35, 0.27, 0.18};
    case 5:
      return {0.40, 0.38, 0.34};
    default:
      return {0.30, 0.30, 0.30};
  }
}

// Seven-segment digit strokes (a top, b top right, c bottom right, d bottom, e bottom left, f top
// left, g middle) for runway designators: ICAO's numerals (Annex 14 Fig. 5-3) reduced to strokes.
const char* const kSegments[10] = {"abcdef", "bc",     "abged", "abgcd",   "fgbc",
                                   "afgcd",  "afgedc", "abc",   "abcdefg", "abcdfg"};

struct RunwayBuilder {
  const RunwayFrame& f;
  RunwayPolygons& out;

  // A rectangle in end k's frame (s from that end's point along its landing direction, t to the
  // right), cut at the profile stations so that each piece lies in the surface's plane there.
  void rect(PolygonSoup& soup, int end, double s0, double s1, double t0, double t1, const Rgb& c) {
    if (end == 1) { std::tie(s0, s1, t0, t1) = std::make_tuple(f.length - s1, f.length - s0, -t1, -t0); }
    const std::vector<double>& st = out.station_s;
    for (std::size_t k = 0; k + 1 < st.size(); ++k) {
      const double p0 = std::max(s0, st[k]), p1 = std::min(s1, st[k + 1]);
      if (!(p1 - p0 > 1e-6)) continue;
      auto corner = [&](double s, double t) {
        const glm::dvec2 h = f.at(s, t);
        return glm::dvec3(h.x, h.y, out.z_at(s));
      };
      soup.add({corner(p0, t0), corner(p0, t1), corner(p1, t1), corner(p1, t0)}, c);
    }
  }
  void marking(int end, double s0, double s1, double t0, double t1) {
    rect(out.markings, end, s0, s1, t0, t1, kMarkingWhite);
    ++out.marking_polygons;
  }
  void digit(int end, int d, double s0, double tl) {
    const double h = 9, w = 4.5, k = 1;  // ICAO: numerals 9 m high
    for (const char* p = kSegments[d]; *p; ++p) {
      switch (*p) {
        case 'a':
          marking(end, s0 + h - k, s0 + h, tl, tl + w);
          break;
        case 'b':
          marking(end, s0 + h / 2, s0 + h, tl + w - k, tl + w);
          break;
        case 'c':
          marking(end, s0, s0 + h / 2, tl + w - k, tl + w);
          break;
        case 'd':
          marking(end, s0, s0 + k, tl, tl + w);
          break;
        case 'e':
          marking(end, s0, s0 + h / 2, tl, tl + k);
          break;
        case 'f':
          marking(end, s0 + h / 2, s0 + h, tl, tl + k);
          break;
        default:
          marking(end, s0 + (h - k) / 2, s0 + (h + k) / 2, tl, tl + w);
          break;
      }
    }
  }
  void end_markings(const AptRunwayEnd& e, int end);
};

// Threshold stripes by runway width (Annex 14, 5.2.4.5): 18 m: 4, 23: 6, 30: 8, 45: 12, 60: 16.
int threshold_stripes(double width) {
  return width >= 60 ? 16 : width >= 45 ? 12 : width >= 30 ? 8 : width >= 23 ? 6 : 4;
}

void RunwayBuilder::end_markings(const AptRunwayEnd& e, int end) {
  const int code = e.markings == 4 ? 2 : e.markings == 5 ? 3 : e.markings;  // UK styles as ICAO's
  if (code <= 0) return;
  const double thr = e.displaced_threshold_m, w = f.width;
  double s = thr + 6;
  if (code >= 2) {  // threshold: stripes 30 m long, 1.8 m wide and apart, the middle gap doubled
    const int n = threshold_stripes(w);
    for (int i = 0; i < n / 2; ++i) {
      const double t = 1.8 + i * 3.6;
      marking(end, s, s + 30, t, t + 1.8);
      marking(end, s, s + 30, -t - 1.8, -t);
    }
    s += 30;
  }
  s += 12;  // designation 12 m beyond the threshold stripes (5.2.2.4)
  std::string digits;
  for (char ch : e.id)
    if (ch >= '0' && ch <= '9') digits += ch;
  const double dw = 4.5, gap = 3, total = double(digits.size()) * dw + double(digits.size() > 1 ? 1 : 0) * gap;
  for (std::size_t i = 0; i < digits.size(); ++i) digit(end, digits[i] - '0', s, -total / 2 + double(i) * (dw + gap));
  s += 9 + 12;
  // Centreline: 30 m stripes and 20 m gaps (5.2.3), 0.9 m wide on precision runways, to mid-runway
  // (the other end's markings continue it).
  const double cw = code >= 3 ? 0.9 : 0.45;
  for (double c = s; c + 30 <= f.length / 2; c += 50) marking(end, c, c + 30, -cw / 2, cw / 2);
  if (code >= 2 && f.length >= 1200) {  // aiming point: 400 m in, 60 x 10 m, inner sides 22 m apart (5.2.5)
    marking(end, thr + 400, thr + 460, 11, 21);
    marking(end, thr + 400, thr + 460, -21, -11);
  }
  if (code >= 3) {  // touchdown zone pairs of 22.5 x 3 m bars (5.2.6), 1.5 m apart
    const double at[5] = {150, 300, 600, 750, 900};
    const int bars[5] = {3, 3, 2, 2, 1};
    for (int i = 0; i < 5 && thr + at[i] + 22.5 < f.length / 2; ++i)
      for (int b = 0; b < bars[i]; ++b) {
        const double t = 11 + b * 4.5;
        marking(end, thr + at[i], thr + at[i] + 22.5, t, t + 3);
        marking(end, thr + at[i], thr + at[i] + 22.5, -t - 3, -t);
      }
    // Side stripes 0.9 m wide along both edges, this end's half (5.2.7).
    marking(end, thr, f.length / 2, w / 2 - 0.9, w / 2);
    marking(end, thr, f.length / 2, -w / 2, -w / 2 + 0.9);
  }
}

}  // namespace

RunwayPolygons build_runway(const AptRunway& rw, const RunwayFrame& f, const GroundHeight& ground, double fallback_z) {
  RunwayPolygons out;
  out.lift_m = kRunwayLiftM;
  const double s0 = -rw.ends[0].blast_pad_m, s1 = f.length + rw.ends[1].blast_pad_m;
  const int n = std::max(1, int(std::ceil((s1 - s0) / kStationSpacingM)));
  for (int k = 0; k <= n; ++k) {
    const double s = s0 + (s1 - s0) * k / n;
    double z = -1e300;
    for (double t : {-f.width / 2 - 2, -f.width / 4, 0.0, f.width / 4, f.width / 2 + 2}) {
      const glm::dvec2 h = f.at(s, t);
      z = std::max(z, ground.at_or(h.x, h.y, fallback_z));
    }
    out.station_s.push_back(s);
    out.station_z.push_back(z + kRunwayLiftM);
  }
  RunwayBuilder b{f, out};
  b.end_markings(rw.ends[0], 0);
  b.end_markings(rw.ends[1], 1);
  b.rect(out.surface, 0, s0, s1, -f.width / 2, f.width / 2, surface_colour(rw.surface));
  return out;
}

}  // namespace cig
