#include "studies/arch_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>

#include "common/error.hpp"
#include "common/timing.hpp"
#include "hls/quadtree/pe.hpp"
#include "hls/quadtree/setup.hpp"

namespace cig::quad {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Grid units a pixel: 4096 / N.
int grid_per_pixel(int raster_log2) { return 1 << (12 - raster_log2); }
// The level-1 period, N/2 pixels, in grid units: 2048 whatever n.
constexpr int kPeriodGrid = 2048;

// Uniform in [0, 1) from the generator's top bits (the same on every standard library).
double unit(std::mt19937& rng) { return double(rng() >> 8) * (1.0 / 16777216.0); }

class DropSink final : public PixelSink<AnalysisArith> {
 public:
  std::uint64_t pixel(int, const QuadItem<AnalysisArith>&, bool& became_full) override {
    became_full = false;
    return 0;
  }
};

}  // namespace

// ---- eq. 10 ---------------------------------------------------------------------------------

double round_significant(double x, int digits) {
  if (x == 0) return 0;
  const double e = std::floor(std::log10(std::fabs(x)));
  const double scale = std::pow(10.0, double(digits) - 1 - e);
  return std::round(x * scale) / scale;
}

std::vector<SeedPeRow> seed_pe_table() {
  constexpr int n = 10;
  // The seed's table, as printed (3.495 * 10^5, ...).
  const double printed[n] = {3.495e5, 8.738e4, 2.185e4, 5.464e3, 1.369e3, 346, 91, 28, 13, 10};
  const char* text[n] = {"3.495e5", "8.738e4", "2.185e4", "5.464e3", "1.369e3", "346", "91", "28", "13", "10"};
  std::vector<SeedPeRow> rows;
  for (int i = 1; i <= n; ++i) {
    SeedPeRow r;
    r.i = i;
    // (i-1)p(n-i+1)t; the seed writes i = 1 as "10t" and i = n (a one-level tree is one PE, a
    // pipeline stage) as "10p".
    if (i == 1) r.arch = std::to_string(n) + "t";
    else if (i == n) r.arch = std::to_string(n) + "p";
    else r.arch = std::to_string(i - 1) + "p" + std::to_string(n - i + 1) + "t";
    r.formula = seed_pe_count(n, i);
    r.parsed = Architecture::parse(r.arch, n).pe_count();
    r.seed_printed = printed[i - 1];
    r.seed_text = text[i - 1];
    rows.push_back(r);
  }
  return rows;
}

// ---- eq. 2-3 --------------------------------------------------------------------------------

double seed_relative_aperture(int n, int level, double alpha) { return 1.0 + std::ldexp(alpha - 1.0, level - n); }

double seed_window_bound(int n, int level, double area, double alpha, double beta, double shape_factor) {
  const double ai = seed_relative_aperture(n, level, alpha), bi = seed_relative_aperture(n, level, beta);
  return std::ldexp(area, 2 * (level - n)) +
         std::ldexp(shape_factor * std::sqrt((ai * ai + bi * bi) * kPi * area), level - n) + ai * bi;
}

// ---- test rectangles ------------------------------------------------------------------------

std::string TestRect::label() const {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g:1@%d", nominal_aspect, rotation_deg);
  return buf;
}

double TestRect::shape_factor(double alpha, double beta) const {
  const double g = grid_per_pixel(raster_log2);
  const double w = width / g, h = height / g;
  return (alpha * h + beta * w) / std::sqrt((alpha * alpha + beta * beta) * kPi * area);
}

TestRect make_test_rect(int raster_log2, double area, double aspect, int rotation_deg, const std::string& option) {
  if (raster_log2 < hls::kMinRasterLog2 || raster_log2 > hls::kMaxRasterLog2)
    throw InputError("", "--n",
                     "the raster must have 16 to 1024 lines (n = 4..10), not n = " + std::to_string(raster_log2));
  if (!(area > 0) || !std::isfinite(area)) throw InputError("", option, "an area must be a positive number of pixels");
  if (!(aspect >= 1) || !std::isfinite(aspect))
    throw InputError("", "--aspects", "an aspect ratio must be a number >= 1");
  if (rotation_deg != 0 && rotation_deg != 45) throw std::invalid_argument("make_test_rect: rotation must be 0 or 45");
  TestRect r;
  r.raster_log2 = raster_log2;
  r.nominal_area = area;
  r.nominal_aspect = aspect;
  r.rotation_deg = rotation_deg;
  auto too_big = [&] {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "a %s rectangle of %g pixels does not fit the level-1 period (N/2 = %d pixels a side)",
                  r.label().c_str(), area, 1 << (raster_log2 - 1));
    return std::string(buf);
  };
  const double g = grid_per_pixel(raster_log2);
  const double target = area * g * g;  // grid units^2
  // Side parameters: axis-aligned w x h (w long); rotated (a, a) x (-b, b) (b long), area 2ab.
  const double k = rotation_deg == 45 ? 2.0 : 1.0;
  const double short_ideal = std::sqrt(target / (k * aspect));
  if (short_ideal * aspect > kPeriodGrid)  // the long side alone would not fit (and keeps the ints small)
    throw InputError("", option, too_big());
  double best = std::numeric_limits<double>::infinity();
  int bs = 1, bl = 1;
  for (int s = std::max(1, int(std::floor(short_ideal)) - 1); s <= int(std::ceil(short_ideal)) + 1; ++s) {
    const double long_ideal = target / (k * s);
    for (int l = std::max(s, int(std::floor(long_ideal)) - 1); l <= int(std::ceil(long_ideal)) + 1; ++l) {
      const double err = std::fabs(std::log(k * s * l / target)) + std::fabs(std::log(double(l) / s / aspect));
      if (err < best) {
        best = err;
        bs = s;
        bl = l;
      }
    }
  }
  if (rotation_deg == 0) {
    const int w = bl, h = bs;
    const int xs[4] = {0, w, w, 0}, ys[4] = {0, 0, h, h};
    std::copy(xs, xs + 4, r.vx);
    std::copy(ys, ys + 4, r.vy);
    r.width = w;
    r.height = h;
  } else {
    const int a = bs, b = bl;
    const int xs[4] = {b, a + b, a, 0}, ys[4] = {0, a, a + b, b};
    std::copy(xs, xs + 4, r.vx);
    std::copy(ys, ys + 4, r.vy);
    r.width = r.height = a + b;
  }
  if (r.width > kPeriodGrid - 2 || r.height > kPeriodGrid - 2) throw InputError("", option, too_big());
  r.area = k * bs * bl / (g * g);
  r.aspect = double(bl) / bs;
  return r;
}

hls::FormattedPrimitive rect_primitive(const TestRect& r, int x, int y, std::uint16_t id) {
  hls::FormattedPrimitive f;
  f.is_light = false;
  f.n = hls::UInt<5>(4);
  for (int k = 0; k < 4; ++k) {
    f.v[k].x = hls::UInt<12>(x + r.vx[k]);
    f.v[k].y = hls::UInt<12>(y + r.vy[k]);
    f.v[k].i = hls::UInt<8>(200);
    f.v[k].z = hls::ZFloat::from_fields(hls::UInt<8>(127), hls::UInt<7>(0));  // Z = 1
  }
  for (int c = 0; c < 3; ++c) f.colour[c] = hls::UInt<8>(255);
  f.opaque = true;
  f.id = hls::UInt<16>(id);
  return f;
}

std::vector<std::pair<int, int>> period_positions(const TestRect& r, int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const int x0 = (4096 - kPeriodGrid - r.width) / 2, y0 = (4096 - kPeriodGrid - r.height) / 2;
  std::vector<int> order(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) order[std::size_t(k)] = k;
  for (int k = count - 1; k > 0; --k) std::swap(order[std::size_t(k)], order[rng() % std::uint32_t(k + 1)]);
  std::vector<std::pair<int, int>> pos;
  for (int k = 0; k < count; ++k) {
    const int sx = int(std::floor((k + unit(rng)) * kPeriodGrid / count));
    const int sy = int(std::floor((order[std::size_t(k)] + unit(rng)) * kPeriodGrid / count));
    pos.push_back({x0 + std::min(sx, kPeriodGrid - 1), y0 + std::min(sy, kPeriodGrid - 1)});
  }
  return pos;
}

std::vector<std::pair<int, int>> screen_positions(const TestRect& r, int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::pair<int, int>> pos;
  for (int k = 0; k < count; ++k) {
    const int x = int(rng() % std::uint32_t(4096 - r.width));
    const int y = int(rng() % std::uint32_t(4096 - r.height));
    pos.push_back({x, y});
  }
  return pos;
}

AnalysisWindow setup_root(const hls::FormattedPrimitive& f, int raster_log2) {
  hls::QuadSetup<AnalysisArith> s;
  hls::quadtree_setup_top(f, hls::UInt<4>(raster_log2), s);
  if (s.pieces.value() != 1) throw std::logic_error("setup_root: the polygon is not one convex piece");
  return s.root[0];
}

double rect_overlap_area(const TestRect& r, int level) {
  const int n = r.raster_log2;
  if (level == 0) return 1;
  const double p = std::ldexp(1.0, n - level);  // window side, pixels
  const double a = seed_relative_aperture(n, level, kSampleAperture);
  const double g = grid_per_pixel(n);
  return r.area / (p * p) + a * (r.width + r.height) / g / p + a * a;  // the Minkowski sum (header)
}

double rect_grid_excess(const TestRect& r, int level) {
  const int n = r.raster_log2;
  const bool samples_on_grid = n <= 9;  // o = 2^(10-n) - 2 half units is even
  if (level == 0 || r.rotation_deg != 45 || !samples_on_grid) return 0;
  const long long g = grid_per_pixel(n), p = 1LL << (n - level);
  const long long sigma = (4 * p - 1) * g / 4;  // the box side, grid units (g/4 a sample step)
  return double(2 * sigma - 1) / double(g * p * g * p);
}

double rect_conservative_expectation(const TestRect& r, int level) {
  return level == 0 ? 1 : rect_overlap_area(r, level) + rect_grid_excess(r, level);
}

// ---- window counts --------------------------------------------------------------------------

void count_windows(const AnalysisWindow& root, int raster_log2, PolygonWindows& out) {
  const int n = raster_log2;
  out.conservative.assign(std::size_t(n) + 1, 0);
  out.exact.assign(std::size_t(n) + 1, 0);
  out.conservative[0] = 1;
  std::vector<AnalysisWindow> stack{root};
  std::vector<std::uint32_t> pixels;  // y << 10 | x of every pixel holding a covered sample
  hls::QuadChild<AnalysisArith> child;
  while (!stack.empty()) {
    const AnalysisWindow w = stack.back();
    stack.pop_back();
    const int level = int(w.level.value()) + 1;
    for (int q = 0; q < hls::kQuadChildren; ++q) {
      hls::evaluate_child(w, q, n, false, child);
      if (!child.covered) continue;
      ++out.conservative[std::size_t(level)];
      if (level == n)
        pixels.push_back(std::uint32_t(child.window.y.value()) << 10 | std::uint32_t(child.window.x.value()));
      else stack.push_back(child.window);
    }
  }
  // The ideal test: a window of level l is covered when one of its pixels is.
  std::vector<std::uint32_t> keys;
  for (int l = 0; l <= n; ++l) {
    const int sh = n - l;
    keys.clear();
    for (std::uint32_t p : pixels) keys.push_back(((p >> 10) >> sh) << 10 | ((p & 1023u) >> sh));
    std::sort(keys.begin(), keys.end());
    out.exact[std::size_t(l)] = int(std::unique(keys.begin(), keys.end()) - keys.begin());
  }
}

WindowTable measure_windows(const TestRect& r, int positions, std::uint32_t seed) {
  const int n = r.raster_log2;
  WindowTable t;
  t.rect = r;
  t.positions = positions;
  t.level.assign(std::size_t(n) + 1, LevelWindows());
  std::vector<double> sum(std::size_t(n) + 1, 0), sum_sq(std::size_t(n) + 1, 0), exact_sum(std::size_t(n) + 1, 0);
  PolygonWindows pw;
  for (const auto& [x, y] : period_positions(r, positions, seed)) {
    count_windows(setup_root(rect_primitive(r, x, y, 0), n), n, pw);
    for (int l = 0; l <= n; ++l) {
      LevelWindows& lw = t.level[std::size_t(l)];
      sum[std::size_t(l)] += pw.conservative[std::size_t(l)];
      sum_sq[std::size_t(l)] += double(pw.conservative[std::size_t(l)]) * pw.conservative[std::size_t(l)];
      exact_sum[std::size_t(l)] += pw.exact[std::size_t(l)];
      lw.max = std::max(lw.max, pw.conservative[std::size_t(l)]);
      lw.exact_max = std::max(lw.exact_max, pw.exact[std::size_t(l)]);
    }
  }
  for (int l = 0; l <= n; ++l) {
    LevelWindows& lw = t.level[std::size_t(l)];
    lw.mean = positions > 0 ? sum[std::size_t(l)] / positions : 0;
    lw.exact_mean = positions > 0 ? exact_sum[std::size_t(l)] / positions : 0;
    const double var =
        positions > 1 ? std::max(0.0, (sum_sq[std::size_t(l)] - positions * lw.mean * lw.mean) / (positions - 1)) : 0;
    lw.mean_se = positions > 0 ? std::sqrt(var / positions) : 0;
    lw.bound = seed_window_bound(n, l, r.area, kSampleAperture, kSampleAperture, kSeedShapeFactor);
    lw.area_expectation = rect_overlap_area(r, l);
    lw.expectation = rect_conservative_expectation(r, l);
  }
  return t;
}

// ---- architectures --------------------------------------------------------------------------

std::vector<AnalysisWindow> rect_stream(const TestRect& r, int count, std::uint32_t seed) {
  std::vector<AnalysisWindow> roots;
  roots.reserve(std::size_t(count));
  int id = 0;
  for (const auto& [x, y] : screen_positions(r, count, seed))
    roots.push_back(setup_root(rect_primitive(r, x, y, std::uint16_t(id++)), r.raster_log2));
  return roots;
}

ArchMeasurement run_architecture(const Architecture& arch, const std::vector<AnalysisWindow>& roots, int fifo_depth) {
  const auto t0 = Clock::now();
  ArchConfig cfg;
  cfg.fifo_depth = fifo_depth;
  cfg.masks = false;
  auto masks = std::make_unique<hls::MaskMemory>();
  DropSink sink;
  ArchStats st;
  long long pes = 0;
  {
    ArchModel<AnalysisArith> model(arch, cfg);
    st = model.run(roots, *masks, sink);
    pes = model.pe_count();
  }
  ArchMeasurement m;
  m.arch = arch.text;
  m.pes = pes;
  m.polygons = int(roots.size());
  m.cycles = st.cycles;
  m.cycles_per_polygon = roots.empty() ? 0 : double(st.cycles) / double(roots.size());
  for (long long b : st.pe_busy_cycles) m.busy_cycles += b;
  for (long long s : st.pe_stall_cycles) m.stall_cycles += s;
  m.utilisation = st.cycles > 0 ? double(m.busy_cycles) / (double(st.cycles) * double(pes)) : 0;
  for (const LevelStats& l : st.level) m.covered.push_back(l.covered);
  if (!m.covered.empty()) m.covered[0] = (long long)roots.size();
  m.seconds = seconds_since(t0);
  return m;
}

double analytic_cycles_per_polygon(const Architecture& arch, const std::vector<double>& w, double tp_over_te) {
  auto t = [&](int level) {
    return 4.0 * w.at(std::size_t(level - 1)) + tp_over_te * w.at(std::size_t(level));
  };  // eq. 5-6
  double slowest = 0;
  for (const ArchStage& s : arch.stages) {
    double stage = 0;
    if (s.kind == 's')
      for (int l = s.first_level; l <= s.last_level; ++l) stage += t(l);
    else stage = t(s.first_level);
    slowest = std::max(slowest, stage);
  }
  return slowest;
}

std::vector<double> seed_model_windows(int n, double area, double alpha, double shape_factor) {
  std::vector<double> w{1.0};
  for (int l = 1; l <= n; ++l) w.push_back(seed_window_bound(n, l, area, alpha, alpha, shape_factor));
  return w;
}

}  // namespace cig::quad
