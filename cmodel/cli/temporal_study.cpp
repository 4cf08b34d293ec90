#include "cli/temporal_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

#include "common/error.hpp"
#include "common/progress.hpp"
#include "generator/image_generator.hpp"
#include "manager/channel_view.hpp"
#include "registry/engine_registry.hpp"

namespace cig {

namespace {

constexpr int kEdgeWindow = 3;        // pixels each side of the edge summed for its coverage
constexpr double kMaxEdgeSlope = 2;   // |dx/dy| of edges measured along rows
constexpr double kIsolationPx = 2;    // no other light centre this close (Chebyshev): windows apart
constexpr double kMaxLightUnits = 7;  // the formatter's largest light diameter, grid units
const Fog kNoFog{{0, 0, 0}, 1e30, 2e30};

// The frame's view with nothing in it, on black, without fog (not a copy of its lists: they hold
// up to 10^5 polygons a frame).
ScreenFrame empty_like(const ScreenFrame& f) {
  ScreenFrame e;
  e.raster = f.raster, e.frame = f.frame, e.channel = f.channel;
  e.tan_half_fov = f.tan_half_fov, e.near = f.near;
  e.background = {0, 0, 0};
  e.fog = kNoFog;
  return e;
}

// The frame's light points alone: each light's energy is its pixels' sum.
ScreenFrame lights_alone(const ScreenFrame& f) {
  ScreenFrame l = empty_like(f);
  l.light_points = f.light_points;
  for (ScreenLightPoint& p : l.light_points) p.priority = 0;
  return l;
}

// The edge object's surface polygons alone, white and unshaded: a pixel is its coverage.
ScreenFrame surface_alone(const ScreenFrame& f, int object, int subobject) {
  ScreenFrame m = empty_like(f);
  for (const ScreenPolygon& p : f.polygons) {
    if (p.object != object || p.subobject != subobject) continue;
    ScreenPolygon w = p;
    w.colour = {1, 1, 1};
    w.opaque = true;
    for (ScreenVertex& v : w.vertices) v.is = 1;
    m.polygons.push_back(w);
  }
  return m;
}

double luminance(const Image& im, int x, int y) {
  const std::uint8_t* p = im.at(x, y);
  return (double(p[0]) + p[1] + p[2]) / (3 * 255.0);
}

// The edges of the surface's outline (edges of exactly one polygon), in world coordinates, with a
// point inside the polygon that owns each.
struct OutlineEdge {
  glm::dvec3 a, b, inside;
};

std::vector<OutlineEdge> outline(const Scene& scene, int object, int subobject) {
  const Object& o = scene.objects[std::size_t(object)];
  const Subobject& s = o.subobjects[std::size_t(subobject)];
  const glm::dmat3 r = body_to_world(o.pose.heading_deg, o.pose.pitch_deg, o.pose.roll_deg);
  auto world = [&](std::uint32_t i) { return o.pose.position + r * s.vertices[i]; };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, std::size_t>> count;  // edge -> (uses, polygon)
  for (std::size_t pi = 0; pi < s.polygons.size(); ++pi) {
    const auto& idx = s.polygons[pi].indices;
    for (std::size_t k = 0; k < idx.size(); ++k) {
      const std::uint32_t a = idx[k], b = idx[(k + 1) % idx.size()];
      auto& c = count[{std::min(a, b), std::max(a, b)}];
      ++c.first;
      c.second = pi;
    }
  }
  std::vector<OutlineEdge> out;
  for (const auto& kv : count) {
    if (kv.second.first != 1) continue;
    glm::dvec3 g(0);
    for (std::uint32_t i : s.polygons[kv.second.second].indices) g += world(i);
    out.push_back(
        {world(kv.first.first), world(kv.first.second), g / double(s.polygons[kv.second.second].indices.size())});
  }
  return out;
}

}  // namespace
}  // namespace cig

namespace cig {
namespace {

// The crawl bound of a row (docs/flightgear.md): 1/S pixel, the window's rounding to 1/255, and the
// vertices' snap to the formatter grid times (1 + |dx/dy|).
double edge_bound(int s, double snap_px, double slope) {
  return 1.0 / s + snap_px * (1 + slope) + (2 * kEdgeWindow + 1) * 0.5 / 255;
}

struct Projected {
  bool valid = false, inside_right = false, steep = false;  // steep: |dx/dy| <= kMaxEdgeSlope
  double xa = 0, ya = 0, xb = 0, yb = 0;
  double x_at(double y) const { return xa + (y - ya) * (xb - xa) / (yb - ya); }
  bool covers(double y) const { return y >= std::min(ya, yb) && y < std::max(ya, yb); }
  // Another edge in the way of a row's window [x0, x1] at row centre y: a steep one crossing the
  // window there, or a flat one (a runway's end) within 1.5 rows of it and overlapping the window.
  bool blocks(double y, double x0, double x1) const {
    if (!valid) return false;
    if (steep) return covers(y) && x_at(y) > x0 && x_at(y) < x1;
    return y > std::min(ya, yb) - 1.5 && y < std::max(ya, yb) + 1.5 && std::max(xa, xb) > x0 && std::min(xa, xb) < x1;
  }
};

glm::dvec2 to_pixels(const ChannelView& v, const glm::dvec3& world, int n, bool& in_front) {
  const glm::dvec3 e = v.to_eye(world);
  in_front = e.z > v.near;
  // Stage B's projection (SPEC B): Xs = x / (z tan), Ys = -y / (z tan); pixel = (S + 1) N / 2.
  return {(e.x / (e.z * v.tan_half_fov) + 1) * n / 2, (-e.y / (e.z * v.tan_half_fov) + 1) * n / 2};
}

// Per accumulated error series: RMS and largest |value|.
struct Spread {
  double sum2 = 0, max = 0;
  long n = 0;
  void add(double v) { sum2 += v * v, max = std::max(max, std::fabs(v)), ++n; }
  double rms() const { return n ? std::sqrt(sum2 / double(n)) : 0; }
};

// Errors keyed by what they belong to (an edge's row, a light), kept one frame for the deltas.
struct Tracker {
  Spread error, delta, delta_frame;
  long violations = 0;
  std::unordered_map<std::int64_t, double> last, now;
  void add(std::int64_t key, double e, double bound) {
    error.add(e);
    if (std::fabs(e) > bound) ++violations;
    now[key] = e;
    auto it = last.find(key);
    if (it != last.end()) {
      delta.add(e - it->second);
      delta_frame.add(e - it->second);
    }
  }
  double next_frame() {  // the frame's RMS delta; the frame's errors become the last
    const double r = delta_frame.rms();
    delta_frame = {};
    last.swap(now);
    now.clear();
    return r;
  }
};

// Edge crawl in one frame: each outline edge steep enough on screen, at each pixel row inside it
// with no other edge near, its position from the row's coverage against its true position.
void measure_edges(const std::vector<OutlineEdge>& edges, const ChannelView& view, const Image& cov, int s,
                   double snap_px, Tracker& t) {
  const int n = cov.width;
  std::vector<Projected> p(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    bool fa, fb, fi;
    const glm::dvec2 a = to_pixels(view, edges[i].a, n, fa), b = to_pixels(view, edges[i].b, n, fb);
    const glm::dvec2 in = to_pixels(view, edges[i].inside, n, fi);
    if (!(fa && fb && fi)) continue;
    p[i] = {true, false, false, a.x, a.y, b.x, b.y};
    p[i].steep = std::fabs(b.x - a.x) <= kMaxEdgeSlope * std::fabs(b.y - a.y) && std::fabs(b.y - a.y) > 1e-9;
    if (p[i].steep) p[i].inside_right = in.x > p[i].x_at(in.y);
  }
  // A side of the outline is a chain of steep edges (the surface's pieces): each row is measured
  // on the one edge whose half-open row span holds its centre.
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!p[i].valid || !p[i].steep) continue;
    const double slope = std::fabs((p[i].xb - p[i].xa) / (p[i].yb - p[i].ya));
    const double bound = edge_bound(s, snap_px, slope);
    const int y0 = std::max(0, int(std::ceil(std::min(p[i].ya, p[i].yb) - 0.5)));
    const int y1 = std::min(n - 1, int(std::ceil(std::max(p[i].ya, p[i].yb) - 0.5)) - 1);
    for (int y = y0; y <= y1; ++y) {
      const double yc = y + 0.5, x = p[i].x_at(yc);
      const int i0 = int(std::floor(x)) - kEdgeWindow, i1 = int(std::floor(x)) + kEdgeWindow;
      if (i0 < 0 || i1 >= n) continue;
      bool alone = true;
      for (std::size_t j = 0; j < edges.size() && alone; ++j) alone = j == i || !p[j].blocks(yc, i0 - 1, i1 + 2);
      if (!alone) continue;
      double c = 0;
      for (int k = i0; k <= i1; ++k) c += luminance(cov, k, y);
      const double est = p[i].inside_right ? (i1 + 1) - c : i0 + c;
      t.add(std::int64_t(i) << 20 | y, est - x, bound);
    }
  }
}

// Scintillation in one frame: each isolated light's energy against its disc's.
void measure_lights(const ScreenFrame& f, const Image& im, int s, bool snapped, Tracker& t) {
  const int n = im.width;
  std::unordered_map<std::int64_t, std::vector<glm::dvec2>> cells;
  auto cell = [](double x, double y) {
    return std::int64_t(std::floor(x / kIsolationPx)) << 32 ^ std::int64_t(std::floor(y / kIsolationPx));
  };
  std::vector<glm::dvec2> c(f.light_points.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i] = {(f.light_points[i].xs + 1) * n / 2, (f.light_points[i].ys + 1) * n / 2};
    cells[cell(c[i].x, c[i].y)].push_back(c[i]);
  }
  for (std::size_t i = 0; i < c.size(); ++i) {
    const ScreenLightPoint& l = f.light_points[i];
    const double units = std::min(kMaxLightUnits, l.ds * 2048), d = units * n / 4096;
    // The pixels the disc (diameter d < 1 pixel, plus the grid snap) can touch: at most 2 x 2.
    const double r = d / 2 + 1.0 / 16;
    const int x0 = int(std::floor(c[i].x - r)), x1 = int(std::floor(c[i].x + r));
    const int y0 = int(std::floor(c[i].y - r)), y1 = int(std::floor(c[i].y + r));
    if (x0 < 0 || y0 < 0 || x1 >= n || y1 >= n) continue;
    int near = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        auto it = cells.find(cell(c[i].x + dx * kIsolationPx, c[i].y + dy * kIsolationPx));
        if (it == cells.end()) continue;
        for (const glm::dvec2& q : it->second)
          if (std::max(std::fabs(q.x - c[i].x), std::fabs(q.y - c[i].y)) < kIsolationPx) ++near;
      }
    if (near > 1) continue;  // itself only
    const double area = 3.14159265358979323846 * d * d / 4,
                 shade = l.intensity * (l.colour.r + l.colour.g + l.colour.b) / 3;
    if (!(area * shade > 0)) continue;
    double e = 0;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) e += luminance(im, x, y);
    // Lattice bound: the disc's outline meets at most 4 d s + 4 sample cells, each off by at most
    // one sample; 4 pixels rounded to 1/255; the fixed-point engines' diameter rounded to a unit.
    double bound = (4 * d * s + 4) / (area * s * s) + 4 * 0.5 / 255 / (area * shade);
    if (snapped) bound += ((units + 0.5) * (units + 0.5) - units * units) / (units * units);
    t.add(std::int64_t(l.object) << 24 | l.light, e / (area * shade) - 1, bound);
  }
}

}  // namespace
}  // namespace cig

namespace cig {
namespace {

// The object whose surface gives the edges: named, or the "runway_*" nearest the observer at the
// run's last frame (the runway being approached); its subobject "surface", or its only one.
void find_edge_object(const Scene& scene, int last_frame, std::string& name, int& object, int& subobject) {
  const glm::dvec3 eye = observer_pose(scene, last_frame).position;
  double best = 1e300;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& o = scene.objects[i];
    const bool runway = o.name.rfind("runway_", 0) == 0;
    if (!name.empty() ? o.name != name : !runway) continue;
    const double d = glm::length(o.pose.position + o.sphere_centre - eye);
    if (d < best) best = d, object = int(i);
  }
  if (object < 0)
    throw InputError(scene.file, "--edge-object",
                     name.empty() ? "no object named runway_*: name one" : "no object '" + name + "'");
  const Object& o = scene.objects[std::size_t(object)];
  name = o.name;
  for (std::size_t k = 0; k < o.subobjects.size(); ++k)
    if (o.subobjects[k].name == "surface" || o.subobjects.size() == 1) subobject = int(k);
  if (subobject < 0) throw InputError(scene.file, "--edge-object", "object '" + name + "' has no subobject 'surface'");
}

long drops_of(const nlohmann::ordered_json& report) {
  long n = 0;
  if (report.contains("dropped"))
    for (const auto& kv : report["dropped"].items())
      if (kv.value().is_number_integer()) n += kv.value().get<long>();
  return n;
}

// Objects that cover at least `least` pixels in one frame and none in the other.
long pops_between(const std::unordered_map<int, long>& a, const std::unordered_map<int, long>& b, double least) {
  long pops = 0;
  for (const auto& kv : a)
    if (kv.second >= least && !b.count(kv.first)) ++pops;
  for (const auto& kv : b)
    if (kv.second >= least && !a.count(kv.first)) ++pops;
  return pops;
}

TemporalSeries run_series(const Scene& scene, const ImageGenerator& gen, const TemporalOptions& o,
                          const std::string& engine, int spp, const std::vector<OutlineEdge>& edges, int edge_object,
                          int edge_sub, Progress& progress) {
  TemporalSeries ts;
  ts.engine = engine;
  ts.spp = spp;
  EngineOptions eo;
  eo.params["spp"] = std::to_string(spp);
  // "float-snap": the reference with positions snapped to the formatter grid, the fixed-point
  // engines' like-for-like peer.
  eo.snap = engine == "float-snap";
  const auto eng = make_engine(eo.snap ? "float" : engine, eo);
  const int s = int(std::lround(std::sqrt(double(spp))));
  const bool snapped = engine != "float";
  const double snap_px = snapped ? 0.5 * scene.raster / 4096.0 : 0;
  Tracker lights, crawl;
  std::unordered_map<int, long> last_cover;
  const auto t0 = std::chrono::steady_clock::now();
  for (int frame = o.first; frame <= o.last; ++frame) {
    nlohmann::ordered_json unused;
    const std::vector<ScreenFrame> parts = gen.geometry_parts(frame, o.channel, o.pipelines, unused);
    const ScreenFrame f = parts.size() > 1 ? concatenate_parts(parts) : parts[0];
    // Engines that do not merge pipelines (the float reference) render their concatenation.
    const EngineRun full = parts.size() > 1 && eng->renders_parts() ? eng->render_parts(parts) : eng->render(f);
    std::unordered_map<int, long> cover;
    for (std::int32_t id : full.out.ids.id)
      if (id >= 0 && std::size_t(id) < f.polygons.size()) ++cover[f.polygons[std::size_t(id)].object];
    const long pops = frame > o.first ? pops_between(last_cover, cover, o.pop_pixels) : 0;
    ts.pops += pops;
    ts.pops_frame.push_back(pops);
    ts.dropped += drops_of(full.report);
    last_cover.swap(cover);
    const ScreenFrame alone = lights_alone(f);
    measure_lights(alone, eng->render(alone).out.image, s, snapped, lights);
    const ScreenFrame mask = surface_alone(f, edge_object, edge_sub);
    measure_edges(edges, make_channel_view(scene, frame, o.channel), eng->render(mask).out.image, s, snap_px, crawl);
    ts.light_delta_frame.push_back(lights.next_frame());
    ts.edge_delta_frame.push_back(crawl.next_frame());
    progress.step(engine + " spp " + std::to_string(spp) + " frame " + std::to_string(frame));
  }
  ts.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ts.light_frames = lights.error.n, ts.light_deltas = lights.delta.n, ts.light_bound_violations = lights.violations;
  ts.light_rms_error = lights.error.rms(), ts.light_max_error = lights.error.max;
  ts.light_rms_delta = lights.delta.rms(), ts.light_max_delta = lights.delta.max;
  ts.edge_rows = crawl.error.n, ts.edge_deltas = crawl.delta.n, ts.edge_bound_violations = crawl.violations;
  ts.edge_rms_error = crawl.error.rms(), ts.edge_max_error = crawl.error.max;
  ts.edge_rms_delta = crawl.delta.rms(), ts.edge_max_delta = crawl.delta.max;
  ts.edge_bound = edge_bound(s, snap_px, kMaxEdgeSlope);
  return ts;
}

}  // namespace

TemporalStudy run_temporal_study(const Scene& scene, const TemporalOptions& o) {
  TemporalStudy study;
  study.raster = scene.raster;
  study.edge_object = o.edge_object;
  int object = -1, sub = -1;
  find_edge_object(scene, o.last, study.edge_object, object, sub);
  const std::vector<OutlineEdge> edges = outline(scene, object, sub);
  const ImageGenerator gen(scene);
  Progress progress("cig temporal", (long long)(o.engines.size() * o.spp.size()) * (o.last - o.first + 1));
  for (const std::string& e : o.engines)
    for (int spp : o.spp) study.series.push_back(run_series(scene, gen, o, e, spp, edges, object, sub, progress));
  return study;
}

}  // namespace cig
