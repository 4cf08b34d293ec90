#include "reference/reference_raster.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/parallel.hpp"
#include "common/timing.hpp"
#include "reference/coverage.hpp"

namespace cig {

namespace {

// w = 1/Z as an affine function of sample coordinates, fitted through the vertex triple of
// largest area (exact for a planar polygon; well conditioned).
//
// The plane is clamped to the range of the vertices' 1/Z: inside the polygon that changes nothing
// (a plane over a convex polygon takes its extremes at vertices), but the snapped reference covers
// with the snapped vertices and takes depth from the exact ones, and a sample that snapping adds
// to a sliver lies outside the exact polygon, where the plane of a steep sliver extrapolates to any
// depth (121 km instead of 10.6 km, full fog, on airfield frame 5). Rule: the depth at a covered
// sample is the exact 1/Z plane, clamped to the polygon's vertex 1/Z range.
struct DepthPlane {
  double x0, y0, w0, a, b;
  double w_lo = 0, w_hi = 0;
  double at(double x, double y) const { return std::clamp(w0 + a * (x - x0) + b * (y - y0), w_lo, w_hi); }
  // An upper bound of at(x, y) over the samples xa <= x <= xb of row y. The plane is affine, so its
  // exact maximum is at an end (va, vb are at() there before the clamp, the same operations); each
  // evaluation as computed (a few roundings) lies within 4u of the magnitude sum `mag`, so the
  // larger end plus 2^-48 mag (32u) bounds every sample, and clamp is monotone. A NaN (degenerate
  // fit) bound compares false and rejects nothing.
  double upper_bound(double xa, double xb, double y) const {
    const double ey = b * (y - y0);
    const double va = w0 + a * (xa - x0) + ey, vb = w0 + a * (xb - x0) + ey;
    const double mag = std::abs(w0) + std::abs(a) * std::max(std::abs(xa - x0), std::abs(xb - x0)) + std::abs(ey);
    return std::clamp(std::max(va, vb) + mag * 0x1p-48, w_lo, w_hi);
  }
};

DepthPlane fit_depth_plane(const CoverageSetup& c, const ScreenPolygon& p) {
  const int n = c.n;
  int i1 = 1;
  double best = -1;
  for (int k = 1; k < n; ++k) {
    double d = (c.x[k] - c.x[0]) * (c.x[k] - c.x[0]) + (c.y[k] - c.y[0]) * (c.y[k] - c.y[0]);
    if (d > best) {
      best = d;
      i1 = k;
    }
  }
  int i2 = i1 == 1 ? 2 : 1;
  best = -1;
  for (int k = 1; k < n; ++k) {
    if (k == i1) continue;
    double a = std::abs((c.x[i1] - c.x[0]) * (c.y[k] - c.y[0]) - (c.y[i1] - c.y[0]) * (c.x[k] - c.x[0]));
    if (a > best) {
      best = a;
      i2 = k;
    }
  }
  auto w = [&](int k) { return 1.0 / p.vertices[std::size_t(c.src[k])].zs; };
  const double ux = c.x[i1] - c.x[0], uy = c.y[i1] - c.y[0];
  const double vx = c.x[i2] - c.x[0], vy = c.y[i2] - c.y[0];
  const double du = w(i1) - w(0), dv = w(i2) - w(0);
  const double det = ux * vy - uy * vx;
  DepthPlane d{c.x[0], c.y[0], w(0), 0, 0};
  d.w_lo = d.w_hi = w(0);
  for (int k = 1; k < n; ++k) {
    d.w_lo = std::min(d.w_lo, w(k));
    d.w_hi = std::max(d.w_hi, w(k));
  }
  if (det != 0) {
    d.a = (du * vy - dv * uy) / det;
    d.b = (dv * ux - du * vx) / det;
  }
  return d;
}

// Intensity at the end of a row span on edge k (eq. 3: linear in Y along the edge; a horizontal
// edge contributes its nearer endpoint).
double edge_intensity(const CoverageSetup& c, const ScreenPolygon& p, int k, double y, double x) {
  const int k1 = k + 1 == c.n ? 0 : k + 1;  // (k + 1) % n
  const double i0 = p.vertices[std::size_t(c.src[k])].is, i1 = p.vertices[std::size_t(c.src[k1])].is;
  if (c.y[k] == c.y[k1]) return std::abs(x - c.x[k]) <= std::abs(x - c.x[k1]) ? i0 : i1;
  const double t = (y - c.y[k]) / (c.y[k1] - c.y[k]);
  return i0 + t * (i1 - i0);
}

double fog_factor(const Fog& fog, double z) { return std::clamp((z - fog.start) / (fog.end - fog.start), 0.0, 1.0); }

}  // namespace

namespace {

// Depth ties go to list priority: a polygon replaces a sample's owner only when nearer by more than
// this relative margin. Coplanar decals (runway markings on the runway) precede their surface in
// the list (SPEC A.5), but the two 1/Z planes, fitted on different vertices, differ by rounding:
// evaluations of the double fit agree to about 1e-16 x the largest term, at most ~1e-11 of w when
// a grazing plane spans a 1:1e5 depth range across the screen. 2^-30 (~1e-9) is a hundred times
// that and still far below any separation a scene models (a micrometre per kilometre).
constexpr double kDepthTie = 0x1p-30;

// The raster is processed in horizontal strips of kStripPixels pixel rows: polygons and light
// points are binned by the strips they touch, and each strip's sample buffers (a few MB) are
// reused, so the work stays in cache and no full-screen sample buffer is ever allocated.
constexpr int kStripPixels = 16;

// Hidden samples are rejected by blocks of kBlockSamples samples of one sample row: each block
// keeps a lower bound of its samples' w (the smallest, refreshed after writes, which only raise
// w), so a polygon whose w over the block is at most that (with the tie margin) wins none of its
// samples and skips them; under kPriority a block whose samples are all owned is skipped.
constexpr int kBlockSamples = 16;

// Bins items by the strips their sample-row range [lo, hi] touches (counting sort: flat arrays).
struct StripBins {
  std::vector<std::uint32_t> first, items;
  template <class RangeFn>
  void build(std::size_t count, int strips, int strip_rows, RangeFn&& range) {
    first.assign(std::size_t(strips) + 1, 0);
    auto strip_range = [&](std::size_t k, int& s0, int& s1) {
      double lo, hi;
      range(k, lo, hi);
      s0 = int(std::clamp(std::floor(lo / strip_rows), 0.0, double(strips - 1)));
      s1 = int(std::clamp(std::floor(hi / strip_rows), 0.0, double(strips - 1)));
      if (hi < 0 || lo > double(strips) * strip_rows) s1 = s0 - 1;  // off screen
    };
    for (std::size_t k = 0; k < count; ++k) {
      int s0, s1;
      strip_range(k, s0, s1);
      for (int st = s0; st <= s1; ++st) ++first[std::size_t(st) + 1];
    }
    for (int st = 0; st < strips; ++st) first[std::size_t(st) + 1] += first[std::size_t(st)];
    items.resize(first.back());
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < count; ++k) {  // in list order, so each bin keeps priority order
      int s0, s1;
      strip_range(k, s0, s1);
      for (int st = s0; st <= s1; ++st) items[fill[std::size_t(st)]++] = std::uint32_t(k);
    }
  }
};

}  // namespace

namespace {

RasterImage render(const ScreenFrame& frame, const ScreenFrame& depth_source, ReferenceStats& stats,
                   Visibility visibility, int side, int threads);

}  // namespace

RasterImage render_reference(const ScreenFrame& frame, ReferenceStats& stats, Visibility visibility,
                             int samples_per_side, int threads) {
  return render(frame, frame, stats, visibility, samples_per_side, threads);
}

RasterImage render_reference_snapped(const ScreenFrame& exact, ReferenceStats& stats, Visibility visibility,
                                     int samples_per_side, int threads, int grid_bits) {
  return render(snap_to_formatter_grid(exact, grid_bits), exact, stats, visibility, samples_per_side, threads);
}

namespace {

// One frame of the reference, in phases: set-up (strip bins, each polygon's coverage and depth
// plane, which lights are visible), then per strip of sample rows: polygons, light points, resolve.
class ReferenceFrame {
 public:
  ReferenceFrame(const ScreenFrame& frame, const ScreenFrame& depth_source, ReferenceStats& stats,
                 Visibility visibility, int side)
      : frame_(frame),
        stats_(stats),
        visibility_(visibility),
        lattice_{frame.raster, side},
        m_(lattice_.size()),
        n_(frame.raster),
        strip_pixels_(std::min(kStripPixels, n_)),
        strip_rows_(strip_pixels_ * side),
        strips_(n_ / strip_pixels_) {
    bin();
    set_up_polygons(depth_source);
    decide_light_visibility();
    colour_.reserve(frame_.polygons.size());
    for (const ScreenPolygon& p : frame_.polygons) colour_.push_back(p.colour);
    double sum[3] = {0, 0, 0};
    for (int s = 0; s < side * side; ++s) {
      sum[0] += frame_.background.r;
      sum[1] += frame_.background.g;
      sum[2] += frame_.background.b;
    }
    store_pixel(sum, side * side, background_pixel_);
  }

  // The strips are independent once set up: `threads` workers take them in turn, each with its own
  // sample buffers and counters (integer counts, so their sum is the same for any split).
  RasterImage render(int threads) {
    const auto t0 = Clock::now();
    RasterImage out{Image(n_, n_), IdBuffer(n_, n_)};
    const int workers = std::max(1, std::min(threads, strips_));
    std::vector<StripWork> work(static_cast<std::size_t>(workers));
    parallel_for(std::size_t(strips_), workers, [&](std::size_t strip, int worker) {
      StripWork& w = work[std::size_t(worker)];
      const auto t_strip = Clock::now();
      clear(w);
      draw_polygons(int(strip), w);
      draw_lights(int(strip), w);
      const auto t_resolve = Clock::now();
      resolve(int(strip), w, out);
      w.resolve_ms += ms_since(t_resolve);
      w.busy_ms += ms_since(t_strip);
    });
    double busy_ms = 0, resolve_ms = 0;
    for (const StripWork& w : work) {
      stats_.samples_covered += w.samples_covered;
      stats_.samples_written += w.samples_written;
      stats_.light_samples += w.light_samples;
      busy_ms += w.busy_ms;
      resolve_ms += w.resolve_ms;
    }
    // The resolve's share of the workers' time, applied to the wall time.
    const double wall = ms_since(t0), resolve_share = busy_ms > 0 ? resolve_ms / busy_ms : 0.0;
    stats_.resolve_ms += wall * resolve_share;
    stats_.raster_ms += wall * (1 - resolve_share);
    return out;
  }

 private:
  void light_geometry(const ScreenLightPoint& l, double& cx, double& cy, double& r) const {
    cx = lattice_.from_screen(l.xs);
    cy = lattice_.from_screen(l.ys);
    r = lattice_.length_from_grid(0.5 * std::min(kGridScale * l.ds, kMaxLightDiameterUnits));
  }

  // Polygons and light points binned by the strips of sample rows they touch.
  void bin() {
    poly_bins_.build(frame_.polygons.size(), strips_, strip_rows_, [&](std::size_t k, double& lo, double& hi) {
      lo = 1e300;
      hi = -1e300;
      for (const auto& v : frame_.polygons[k].vertices) {
        lo = std::min(lo, lattice_.from_screen(v.ys));
        hi = std::max(hi, lattice_.from_screen(v.ys));
      }
    });
    light_bins_.build(frame_.light_points.size(), strips_, strip_rows_, [&](std::size_t k, double& lo, double& hi) {
      double cx, cy, r;
      light_geometry(frame_.light_points[k], cx, cy, r);
      lo = cy - r;
      hi = cy + r;
    });
    stats_.polygons += frame_.polygons.size();
    stats_.light_points += frame_.light_points.size();
  }

  // Each polygon's edge setup and depth plane, once per frame: the light tests and every strip the
  // polygon touches use them. The depth plane comes from depth_source (the exact vertices when
  // `frame` is the snapped copy).
  void set_up_polygons(const ScreenFrame& depth_source) {
    coverage_.resize(frame_.polygons.size());
    depth_plane_.resize(frame_.polygons.size());
    for (std::size_t pi = 0; pi < frame_.polygons.size(); ++pi) {
      coverage_[pi] = setup_coverage(frame_.polygons[pi], lattice_);
      if (coverage_[pi].empty) {
        ++stats_.polygons_empty;
        continue;
      }
      depth_plane_[pi] = &depth_source == &frame_ ? fit_depth_plane(coverage_[pi], frame_.polygons[pi])
                                                  : fit_depth_plane(setup_coverage(depth_source.polygons[pi], lattice_),
                                                                    frame_.polygons[pi]);
    }
  }

  // Light points are points. Under kDepth a light is visible or hidden as a whole: drawn (its
  // whole disc) when it is at least as near as the polygon surface at its centre, the exact
  // position and not the nearest sample: a runway light 0.3 m above the ground seen at a grazing
  // angle lies less than half a sample above its ground point, so the sample nearest it can be
  // nearer ground and would hide it at random. The disc is a rendering of a point, so the ground
  // behind a light's lower half does not cut it. Under kPriority lights take part in the list
  // order per sample instead (draw_lights, resolve), as in the engines.
  void decide_light_visibility() {
    light_visible_.assign(frame_.light_points.size(), 1);
    if (visibility_ != Visibility::kDepth) return;
    for (std::size_t li = 0; li < frame_.light_points.size(); ++li) {
      double cx, cy, r;
      light_geometry(frame_.light_points[li], cx, cy, r);
      const int ic = int(std::clamp(std::round(cx), 0.0, double(m_ - 1)));
      const int jc = int(std::clamp(std::round(cy), 0.0, double(m_ - 1)));
      // cy lies between two sample rows, which may belong to two strips: look in both bins.
      const int strip_lo = std::min(strips_ - 1, int(std::clamp(std::floor(cy), 0.0, double(m_ - 1))) / strip_rows_);
      const int strip_hi = std::min(strips_ - 1, int(std::clamp(std::ceil(cy), 0.0, double(m_ - 1))) / strip_rows_);
      double surface = 0;  // w of the nearest polygon at (cx, cy); 0: none
      for (std::uint32_t b = poly_bins_.first[std::size_t(strip_lo)]; b < poly_bins_.first[std::size_t(strip_hi) + 1];
           ++b) {
        const std::size_t pi = poly_bins_.items[b];
        if (!screen_door_passes(frame_.polygons[pi].opaque, ic, jc)) continue;  // the pattern at that pixel
        const CoverageSetup& cov = coverage_[pi];
        if (cov.empty || !(cov.ymin <= cy && cy <= cov.ymax) || !cov.covers(cx, cy)) continue;
        surface = std::max(surface, depth_plane_[pi].at(cx, cy));
      }
      light_visible_[li] = 1.0 / frame_.light_points[li].zs >= surface;
    }
  }

  // One worker's strip: sample buffers (reused from strip to strip, sized on first use) and counters.
  struct StripWork {
    std::vector<double> depth;  // w = 1/Z; 0 = nothing drawn (infinitely far)
    std::vector<std::int32_t> owner;
    std::vector<float> intensity;
    std::vector<std::int32_t> light;
    std::vector<double> block_w;             // per block of a sample row: a lower bound of its w
    std::vector<std::uint16_t> block_owned;  // per block: samples owned (kPriority)
    std::uint64_t samples_covered = 0, samples_written = 0, light_samples = 0;
    double busy_ms = 0, resolve_ms = 0;
  };

  int blocks_per_row() const { return (m_ + kBlockSamples - 1) / kBlockSamples; }

  void clear(StripWork& w) const {
    const std::size_t samples = std::size_t(m_) * std::size_t(strip_rows_);
    const std::size_t blocks = std::size_t(blocks_per_row()) * std::size_t(strip_rows_);
    w.depth.assign(samples, 0.0);
    w.owner.assign(samples, -1);
    w.intensity.resize(samples);
    w.light.assign(samples, -1);
    w.block_w.assign(blocks, 0.0);
    w.block_owned.assign(blocks, 0);
  }

  // Screen-door samples of run lo..hi of row j: all when opaque, else those with (i + j) even.
  static std::uint64_t run_samples(bool opaque, int lo, int hi, int j) {
    if (opaque) return std::uint64_t(hi - lo + 1);
    const int first = lo + ((lo + j) & 1);  // the first i >= lo with (i + j) even
    return first > hi ? 0 : std::uint64_t((hi - first) / 2 + 1);
  }

  // Intensity along a row: il + slope*(x - xl).
  struct RowShade {
    double il, slope, xl;
    float at(int i) const { return float(std::clamp(il + slope * (double(i) - xl), 0.0, 1.0)); }
  };

  std::size_t block_index(int a, int j, int row0) const {
    return std::size_t(j - row0) * std::size_t(blocks_per_row()) + std::size_t(a / kBlockSamples);
  }

  // True when polygon pi wins none of samples a..b of row j (one block), which is then skipped
  // (kBlockSamples above). Under kDepth, first against the plane's largest value w_hi (at() never
  // exceeds it; a NaN plane wins nothing either), then against the row's bound.
  bool block_hidden(const DepthPlane& dp, int a, int b, int j, int row0, const StripWork& w) const {
    const std::size_t blk = block_index(a, j, row0);
    if (visibility_ == Visibility::kPriority) return w.block_owned[blk] == block_width(a);
    const double held = w.block_w[blk] * (1 + kDepthTie);
    return dp.w_hi <= held || dp.upper_bound(a, b, j) <= held;
  }

  // Samples a..b of row j (one block, not hidden) of polygon pi, each a z-buffer test and write.
  // Screen-door polygons visit every other sample, those with (i + j) even.
  void draw_block_depth(std::size_t pi, const DepthPlane& dp, int a, int b, int j, int row0, const RowShade& shade,
                        StripWork& w) const {
    const std::size_t blk = block_index(a, j, row0);
    const bool opaque = frame_.polygons[pi].opaque;
    const std::int32_t id = std::int32_t(pi);
    const std::size_t row = std::size_t(j - row0) * std::size_t(m_);
    // Locals, so that the stores below cannot alias them: at() term by term, in its order.
    const DepthPlane plane = dp;
    const double ey = plane.b * (double(j) - plane.y0);
    double* depth = w.depth.data() + row;
    std::int32_t* owner = w.owner.data() + row;
    float* intensity = w.intensity.data() + row;
    std::uint64_t written = 0;
    for (int i = opaque ? a : a + ((a + j) & 1); i <= b; i += opaque ? 1 : 2) {
      const double z = std::clamp(plane.w0 + plane.a * (double(i) - plane.x0) + ey, plane.w_lo, plane.w_hi);
      if (z > depth[i] * (1 + kDepthTie)) {
        depth[i] = z;
        owner[i] = id;
        intensity[i] = shade.at(i);
        ++written;
      }
    }
    w.samples_written += written;
    if (written) refresh_block(blk, row, w);
  }

  // The same under kPriority: polygons come in list order, so the first to cover a sample keeps it.
  void draw_block_priority(std::size_t pi, const DepthPlane& dp, int a, int b, int j, int row0, const RowShade& shade,
                           StripWork& w) const {
    const std::size_t blk = block_index(a, j, row0);
    const bool opaque = frame_.polygons[pi].opaque;
    const std::int32_t id = std::int32_t(pi);
    const std::size_t row = std::size_t(j - row0) * std::size_t(m_);
    for (int i = opaque ? a : a + ((a + j) & 1); i <= b; i += opaque ? 1 : 2) {
      const std::size_t idx = row + std::size_t(i);
      if (w.owner[idx] >= 0) continue;
      ++w.block_owned[blk];
      w.depth[idx] = dp.at(double(i), double(j));
      w.owner[idx] = id;
      w.intensity[idx] = shade.at(i);
      ++w.samples_written;
    }
  }

  int block_width(int a) const { return std::min(kBlockSamples, m_ - a / kBlockSamples * kBlockSamples); }

  void refresh_block(std::size_t blk, std::size_t row, StripWork& w) const {
    const int first = int(blk % std::size_t(blocks_per_row())) * kBlockSamples;
    double lo = w.depth[row + std::size_t(first)];
    for (int i = first + 1; i < first + block_width(first); ++i) lo = std::min(lo, w.depth[row + std::size_t(i)]);
    w.block_w[blk] = lo;
  }

  void draw_polygons(int strip, StripWork& w) const {
    const int row0 = strip * strip_rows_, row1 = row0 + strip_rows_ - 1;
    for (std::uint32_t b = poly_bins_.first[std::size_t(strip)]; b < poly_bins_.first[std::size_t(strip) + 1]; ++b) {
      const std::size_t pi = poly_bins_.items[b];
      const ScreenPolygon& p = frame_.polygons[pi];
      const CoverageSetup& cov = coverage_[pi];
      if (cov.empty) continue;
      const DepthPlane& dp = depth_plane_[pi];
      for_each_covered_run(cov, m_, row0, row1, [&](int j, const RowSpan& s, int lo, int hi) {
        w.samples_covered += run_samples(p.opaque, lo, hi, j);
        // The row's Gouraud ends (eq. 3) only once a block of the run is not hidden: a run hidden
        // whole (most of a small triangle behind nearer ones) needs none of the three divisions.
        RowShade shade{0, 0, 0};
        bool shaded = false;
        for (int a = lo; a <= hi; a = (a / kBlockSamples + 1) * kBlockSamples) {
          const int b = std::min(hi, (a / kBlockSamples + 1) * kBlockSamples - 1);
          if (block_hidden(dp, a, b, j, row0, w)) continue;
          if (!shaded) {
            const double il = edge_intensity(cov, p, s.el, double(j), s.xl);
            const double ir = edge_intensity(cov, p, s.er, double(j), s.xr);
            shade = RowShade{il, s.xr > s.xl ? (ir - il) / (s.xr - s.xl) : 0.0, s.xl};
            shaded = true;
          }
          if (visibility_ == Visibility::kPriority) draw_block_priority(pi, dp, a, b, j, row0, shade, w);
          else draw_block_depth(pi, dp, a, b, j, row0, shade, w);
        }
      });
    }
  }

  // Visible light points over the polygons; a sample keeps the nearest light (ties: the later one).
  void draw_lights(int strip, StripWork& w) const {
    const int row0 = strip * strip_rows_, row1 = row0 + strip_rows_ - 1;
    for (std::uint32_t b = light_bins_.first[std::size_t(strip)]; b < light_bins_.first[std::size_t(strip) + 1]; ++b) {
      const std::size_t li = light_bins_.items[b];
      if (!light_visible_[li]) continue;
      const ScreenLightPoint& l = frame_.light_points[li];
      double cx, cy, r;
      light_geometry(l, cx, cy, r);
      const double wl = 1.0 / l.zs;
      const int j0 = int(std::max(double(row0), std::ceil(cy - r)));
      const int j1 = int(std::min(double(row1), std::floor(cy + r)));
      const int i0 = int(std::max(0.0, std::ceil(cx - r)));
      const int i1 = int(std::min(double(m_ - 1), std::floor(cx + r)));
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const double dx = double(i) - cx, dy = double(j) - cy;
          if (dx * dx + dy * dy > r * r) continue;
          const std::size_t idx = std::size_t(j - row0) * std::size_t(m_) + std::size_t(i);
          std::int32_t& held = w.light[idx];
          // kDepth: the nearest light keeps the sample (ties: the later one); kPriority: the light
          // earliest in the list (ties: the earlier light), as the engines' light point units.
          if (held >= 0 &&
              (visibility_ == Visibility::kPriority ? frame_.light_points[std::size_t(held)].priority <= l.priority
                                                    : wl < 1.0 / frame_.light_points[std::size_t(held)].zs))
            continue;
          if (held < 0) ++w.light_samples;
          held = std::int32_t(li);
        }
    }
  }

  // The colour of one sample after fog: a light, a polygon, or the background.
  Rgb sample_colour(const StripWork& w, std::size_t idx) const {
    const Fog& fog = frame_.fog;
    const std::int32_t o = w.owner[idx];
    // kPriority: a polygon earlier in the list than the light hides it at this sample.
    const bool light_shows = w.light[idx] >= 0 && (visibility_ == Visibility::kDepth || o < 0 ||
                                                   o >= frame_.light_points[std::size_t(w.light[idx])].priority);
    if (light_shows) {
      const ScreenLightPoint& l = frame_.light_points[std::size_t(w.light[idx])];
      const double f = fog_factor(fog, l.zs);
      return (1 - f) * l.intensity * l.colour + f * fog.colour;
    }
    if (o >= 0) {
      const double f = fog_factor(fog, 1.0 / w.depth[idx]);
      return (1 - f) * double(w.intensity[idx]) * frame_.polygons[std::size_t(o)].colour + f * fog.colour;
    }
    return frame_.background;
  }

  // Resolve the strip: box filter of the side x side samples of each pixel, summed in sample
  // order. A pixel of background samples only (no polygon, no light) is background_pixel_.
  void resolve(int strip, const StripWork& w, RasterImage& out) const {
    if (lattice_.side == kSamplesPerSide) resolve_strip<kSamplesPerSide>(strip, w, out);
    else resolve_strip<0>(strip, w, out);
  }

  // kSide: the lattice's samples per side when known at compile time (the engines' 4 x 4, whose
  // sample loops then unroll), 0 for any other.
  template <int kSide>
  void resolve_strip(int strip, const StripWork& w, RasterImage& out) const {
    const int row0 = strip * strip_rows_, side = kSide ? kSide : lattice_.side;
    std::int32_t ids[kMaxReferenceSamplesPerSide * kMaxReferenceSamplesPerSide];
    // sample_colour's polygon case (no light) on operands held in locals: the same operations.
    const std::int32_t* owner = w.owner.data();
    const std::int32_t* light = w.light.data();
    const double* depth = w.depth.data();
    const float* intensity = w.intensity.data();
    const Fog& fog = frame_.fog;
    const double fog_start = fog.start, fog_span = fog.end - fog.start;
    const Rgb fog_colour = fog.colour;
    auto polygon_colour = [&](std::size_t idx, std::int32_t o) {
      const double f = std::clamp((1.0 / depth[idx] - fog_start) / fog_span, 0.0, 1.0);  // fog_factor
      return Rgb((1 - f) * double(intensity[idx]) * colour_[std::size_t(o)] + f * fog_colour);
    };
    for (int py = strip * strip_pixels_; py < (strip + 1) * strip_pixels_; ++py)
      for (int px = 0; px < n_; ++px) {
        const std::size_t first = std::size_t(py * side - row0) * std::size_t(m_) + std::size_t(px * side);
        std::uint8_t* dst = out.image.at(px, py);
        std::int32_t& id = out.ids.id[std::size_t(py) * std::size_t(n_) + std::size_t(px)];
        if (w.owner[first] < 0 && background_only(w, first, side)) {
          std::copy(background_pixel_, background_pixel_ + 3, dst);
          id = -1;
          continue;
        }
        double sum[3] = {0, 0, 0};
        int nid = 0;
        bool one_owner = true;
        for (int sy = 0; sy < side; ++sy)
          for (int sx = 0; sx < side; ++sx, ++nid) {
            const std::size_t idx = first + std::size_t(sy) * std::size_t(m_) + std::size_t(sx);
            const std::int32_t o = owner[idx];
            ids[nid] = o;
            one_owner &= o == ids[0];
            const Rgb c = light[idx] >= 0 ? sample_colour(w, idx) : o >= 0 ? polygon_colour(idx, o) : frame_.background;
            sum[0] += c.r;
            sum[1] += c.g;
            sum[2] += c.b;
          }
        store_pixel(sum, nid, dst);
        id = one_owner ? ids[0] : nid <= kSamplesPerPixel ? few_owners_majority(ids, nid) : majority_owner(ids, nid);
      }
  }

  // No polygon and no light on the pixel whose first sample is `first`: every owner and light is
  // negative (-1), so the AND of them all keeps the sign bit (no branch per sample).
  bool background_only(const StripWork& w, std::size_t first, int side) const {
    std::int32_t all = -1;
    for (int sy = 0; sy < side; ++sy) {
      const std::int32_t* owner = w.owner.data() + first + std::size_t(sy) * std::size_t(m_);
      const std::int32_t* light = w.light.data() + first + std::size_t(sy) * std::size_t(m_);
      for (int sx = 0; sx < side; ++sx) all &= owner[sx] & light[sx];
    }
    return all < 0;
  }

  static void store_pixel(const double* sum, int count, std::uint8_t* dst) {
    for (int k = 0; k < 3; ++k) dst[k] = round_to_byte(std::clamp(sum[k] / count, 0.0, 1.0) * 255.0);
  }

  // std::lround of x in [0, 255] (half away from zero) without the library call: x - trunc(x) is
  // exact there.
  static std::uint8_t round_to_byte(double x) {
    const int r = int(x);
    return std::uint8_t(x - double(r) >= 0.5 ? r + 1 : r);
  }

  // majority_owner's rule (image/raster_image.hpp: the owner of most samples, ties to the earlier
  // polygon, the background losing ties) by counting the few distinct owners, without the sort.
  static std::int32_t few_owners_majority(const std::int32_t* ids, int count) {
    std::int32_t owner[kSamplesPerPixel];
    int n[kSamplesPerPixel], distinct = 0;
    for (int s = 0; s < count; ++s) {
      int d = 0;
      while (d < distinct && owner[d] != ids[s]) ++d;
      if (d == distinct) {
        owner[distinct] = ids[s];
        n[distinct++] = 0;
      }
      ++n[d];
    }
    std::int32_t best = -1;
    int best_count = 0;
    for (int d = 0; d < distinct; ++d) {
      const bool earlier = owner[d] >= 0 && (best < 0 || owner[d] < best);
      if (n[d] > best_count || (n[d] == best_count && earlier)) {
        best = owner[d];
        best_count = n[d];
      }
    }
    return best;
  }

  const ScreenFrame& frame_;
  ReferenceStats& stats_;
  const Visibility visibility_;
  const SampleLattice lattice_;
  const int m_, n_, strip_pixels_, strip_rows_, strips_;
  StripBins poly_bins_, light_bins_;
  std::vector<CoverageSetup> coverage_;
  std::vector<DepthPlane> depth_plane_;
  std::vector<char> light_visible_;
  std::vector<Rgb> colour_;           // the polygons' colours, side by side
  std::uint8_t background_pixel_[3];  // the resolve of side x side background samples
};

RasterImage render(const ScreenFrame& frame, const ScreenFrame& depth_source, ReferenceStats& stats,
                   Visibility visibility, int side, int threads) {
  return ReferenceFrame(frame, depth_source, stats, visibility, side).render(threads);
}

}  // namespace

}  // namespace cig
