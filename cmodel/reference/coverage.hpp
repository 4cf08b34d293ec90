// Exact, watertight sample coverage of a convex polygon (the float reference's rule, which the
// fixed-point engines reproduce on snapped vertices).
//
// Edge function. For an edge with endpoints ordered canonically (a before b by (y, x)), the
// function C(q) = (b.x - a.x)*(q.y - a.y) - (b.y - a.y)*(q.x - a.x) is evaluated with the same
// operands in both polygons that share the edge, so the two get bit-identical values of opposite
// meaning: no sample falls between them or into both, whatever the rounding.
//
// Tie rule (sample exactly on an edge, E = 0): the sample belongs to the polygon into which the
// edge's inward gradient points along +x, or, for horizontal edges, along +y (downward). This is
// symbolic perturbation of the sample to (x + e, y + e^2) with e -> 0+, so at shared vertices too
// exactly one polygon of a tiling owns the sample. In raster terms: left and top edges are
// inclusive, right and bottom edges exclusive (the top-left rule, y pointing down).
//
// Crossing rule. Snapping a convex polygon's vertices to the formatter grid can make it
// non-convex, self-intersecting (a sliver whose vertices cross becomes a bow-tie) or reversed. Such
// a polygon covers the samples whose perturbed point (x + e, y + e^2) has an odd crossing number:
// the edges whose Y range holds y (half-open, [y_min, y_max)) and whose crossing with the row lies
// right of x, a crossing exactly at x counting as left of x + e. For a convex polygon this is the
// same set as the edge functions' (the edge-function test is just faster), so the rule is one.
#pragma once

#include <algorithm>
#include <cmath>

#include "reference/sample_lattice.hpp"

namespace cig {

struct EdgeEquation {
  double ax, ay;   // canonical start point a
  double dx, dy;   // b - a
  double sign;     // +1 or -1: interior is sign*C > 0
  bool owns_ties;  // the polygon owns samples with C == 0 on this edge
};

struct CoverageSetup {
  int n = 0;
  double x[kMaxScreenVertices], y[kMaxScreenVertices];  // sample coordinates
  int src[kMaxScreenVertices];                          // index of each vertex in the input
  EdgeEquation edge[kMaxScreenVertices];
  double ymin = 0, ymax = 0;
  bool empty = true;   // zero area: covers nothing
  bool convex = true;  // false: the crossing rule decides (snapped non-convex or self-intersecting)

  // True when sample (i, j) is covered (E > 0 on every edge, or E == 0 on an owned edge).
  bool covers(double qx, double qy) const {
    if (!convex) return odd_crossings(qx, qy);
    for (int k = 0; k < n; ++k) {
      const EdgeEquation& e = edge[k];
      const double c = e.sign * (e.dx * (qy - e.ay) - e.dy * (qx - e.ax));
      if (c < 0 || (c == 0 && !e.owns_ties)) return false;
    }
    return true;
  }

  // The crossing rule (above): E of the canonical edge (dy > 0) is positive where the edge's
  // crossing with the row lies right of the sample.
  bool odd_crossings(double qx, double qy) const {
    bool inside = false;
    for (int k = 0; k < n; ++k) {
      const EdgeEquation& e = edge[k];
      if (e.dy == 0 || qy < e.ay || qy >= e.ay + e.dy) continue;
      if (e.dx * (qy - e.ay) - e.dy * (qx - e.ax) > 0) inside = !inside;
    }
    return inside;
  }

  // Left and right ends of the polygon's intersection with row y (ymin <= y <= ymax), with the
  // index of the edge that produced each end (for attribute interpolation). Rounded; used only to
  // bound the exact per-sample tests.
  void row_span(double yr, double& xl, double& xr, int& el, int& er) const {
    xl = 1e300;
    xr = -1e300;
    el = er = 0;
    for (int k = 0; k < n; ++k) {
      const int k1 = k + 1 == n ? 0 : k + 1;  // (k + 1) % n without a division on every row
      const double y0 = y[k], y1 = y[k1];
      if (yr < std::min(y0, y1) || yr > std::max(y0, y1)) continue;
      double xa, xb;
      if (y0 == y1) {
        xa = std::min(x[k], x[k1]);
        xb = std::max(x[k], x[k1]);
      } else {
        xa = xb = x[k] + (yr - y0) * (x[k1] - x[k]) / (y1 - y0);
      }
      if (xa < xl) {
        xl = xa;
        el = k;
      }
      if (xb > xr) {
        xr = xb;
        er = k;
      }
    }
  }
};

// Exact on the snapped grid (dyadic coordinates): every turn has the orientation's sign (or is
// straight) and the boundary runs once around (its Y changes direction at most twice), so the
// polygon is convex and the edge functions decide its coverage.
inline bool is_convex(const double* x, const double* y, int n, double area2) {
  if (!(area2 != 0)) return false;
  int y_turns = 0;
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n, k2 = (k + 2) % n;
    const double turn = (x[k1] - x[k]) * (y[k2] - y[k1]) - (y[k1] - y[k]) * (x[k2] - x[k1]);
    if (turn * area2 < 0) return false;
    // Direction changes of Y along the boundary (horizontal edges skipped).
    const double d0 = y[k1] - y[k];
    int j = k2;
    double d1 = y[k2] - y[k1];
    for (int s = 0; s < n && d1 == 0; ++s, j = (j + 1) % n) d1 = y[(j + 1) % n] - y[j];
    if (d0 != 0 && d0 * d1 < 0) ++y_turns;
  }
  return y_turns <= 2;
}

inline bool all_collinear(const double* x, const double* y, int n) {
  for (int k = 2; k < n; ++k)
    if ((x[1] - x[0]) * (y[k] - y[0]) - (y[1] - y[0]) * (x[k] - x[0]) != 0) return false;
  return true;
}

// Builds the edge equations from vertices in sample coordinates. Zero-area polygons are empty.
// Repeated consecutive vertices (snapping can merge two) are dropped: a zero-length edge has
// C = 0 everywhere and would otherwise reject every sample.
inline CoverageSetup setup_coverage(const double* in_x, const double* in_y, int in_n) {
  CoverageSetup s;
  double xs[kMaxScreenVertices], ys[kMaxScreenVertices];
  int n = 0;
  for (int k = 0; k < in_n && k < kMaxScreenVertices; ++k) {
    if (n > 0 && in_x[k] == xs[n - 1] && in_y[k] == ys[n - 1]) continue;
    xs[n] = in_x[k];
    ys[n] = in_y[k];
    s.src[n] = k;
    ++n;
  }
  while (n > 1 && xs[n - 1] == xs[0] && ys[n - 1] == ys[0]) --n;
  s.n = n;
  double area2 = 0;
  for (int k = 0; k < n; ++k) {
    s.x[k] = xs[k];
    s.y[k] = ys[k];
    const int k1 = (k + 1) % n;
    area2 += xs[k] * ys[k1] - xs[k1] * ys[k];
  }
  s.convex = is_convex(xs, ys, n, area2);
  // A bow-tie can have zero signed area and still cover samples: empty only when every vertex
  // lies on one line.
  s.empty = n < 3 || (s.convex && !(area2 != 0)) || all_collinear(xs, ys, n);
  if (s.empty) return s;
  const double orientation = area2 > 0 ? 1.0 : -1.0;
  s.ymin = s.ymax = ys[0];
  for (int k = 0; k < n; ++k) {
    s.ymin = std::min(s.ymin, ys[k]);
    s.ymax = std::max(s.ymax, ys[k]);
    const int k1 = (k + 1) % n;
    // Canonical order: a before b when (a.y, a.x) < (b.y, b.x).
    const bool forward = ys[k] < ys[k1] || (ys[k] == ys[k1] && xs[k] < xs[k1]);
    const int a = forward ? k : k1, b = forward ? k1 : k;
    EdgeEquation& e = s.edge[k];
    e.ax = xs[a];
    e.ay = ys[a];
    e.dx = xs[b] - xs[a];
    e.dy = ys[b] - ys[a];
    // cross(p_{k+1} - p_k, q - p_k) is positive inside a polygon of positive signed area (in
    // these coordinates); with the canonical operands it equals +-C(q).
    e.sign = orientation * (forward ? 1.0 : -1.0);
    // Gradient of sign*C with respect to q is sign*(-dy, dx).
    const double gx = -e.sign * e.dy, gy = e.sign * e.dx;
    e.owns_ties = gx > 0 || (gx == 0 && gy > 0);
  }
  return s;
}

// Row boundary of a polygon at one sample row, rounded: for attribute interpolation only.
struct RowSpan {
  double xl, xr;
  int el, er;  // edges that produced the left and right ends
};

// The candidate samples of row j: [i0, i1] from the rounded span, which lies within far less than
// a sample of the exact one, so every sample the exact test can accept is inside. False when the
// row has no candidates.
inline bool row_candidates(const CoverageSetup& s, int m, int j, RowSpan& span, int& i0, int& i1) {
  s.row_span(double(j), span.xl, span.xr, span.el, span.er);
  if (!(span.xl <= span.xr)) return false;
  i0 = int(std::max(0.0, std::floor(span.xl)));
  i1 = int(std::min(double(m - 1), std::ceil(span.xr)));
  return true;
}

// The covered samples of candidates [i0, i1] of row j as runs of consecutive samples: run(lo, hi)
// in increasing order. Exactly the samples covers() accepts, with far fewer tests: along a row,
// each edge function as computed (qx - ax, times dy, subtracted from a constant, each rounded) is
// monotone in qx, since rounding is monotone; so each edge accepts a half-line (or all or nothing
// when horizontal) and a convex polygon's covered samples are one run, found by testing inward
// from both ends. The crossing rule (non-convex) is tested sample by sample.
template <class RunFn>
void covered_runs(const CoverageSetup& s, int j, int i0, int i1, RunFn&& run) {
  const double y = double(j);
  if (s.convex) {
    int lo = i0;
    while (lo <= i1 && !s.covers(double(lo), y)) ++lo;
    if (lo > i1) return;
    int hi = i1;
    while (hi > lo && !s.covers(double(hi), y)) --hi;
    run(lo, hi);
    return;
  }
  for (int i = i0; i <= i1;) {
    if (!s.covers(double(i), y)) {
      ++i;
      continue;
    }
    const int lo = i;
    while (i <= i1 && s.covers(double(i), y)) ++i;
    run(lo, i - 1);
  }
}

// Visits the rows row_lo..row_hi (inclusive) of an m x m lattice that have candidate samples:
// row(j, span, i0, i1) with the row's rounded boundary and its candidates i0..i1.
template <class RowFn>
void for_each_candidate_row(const CoverageSetup& s, int m, int row_lo, int row_hi, RowFn&& row) {
  if (s.empty) return;
  const int j0 = int(std::max(double(row_lo), std::ceil(s.ymin)));
  const int j1 = int(std::min(double(row_hi), std::floor(s.ymax)));
  for (int j = j0; j <= j1; ++j) {
    RowSpan span;
    int i0, i1;
    if (row_candidates(s, m, j, span, i0, i1)) row(j, span, i0, i1);
  }
}

// Visits the covered samples of an m x m lattice row by row, as runs: run(j, span, lo, hi) for
// each run of covered samples lo..hi of row j (span: the row's rounded boundary). Only rows
// row_lo..row_hi (inclusive) are visited, so a caller can work strip by strip.
template <class RunFn>
void for_each_covered_run(const CoverageSetup& s, int m, int row_lo, int row_hi, RunFn&& run) {
  for_each_candidate_row(s, m, row_lo, row_hi, [&](int j, const RowSpan& span, int i0, int i1) {
    covered_runs(s, j, i0, i1, [&](int lo, int hi) { run(j, span, lo, hi); });
  });
}

// Visits every covered sample of an m x m lattice row by row: row(j, span) once per row that has
// candidates, then sample(i, j) for each covered sample of that row.
// Only rows row_lo..row_hi (inclusive) are visited, so a caller can work strip by strip.
template <class RowFn, class SampleFn>
void for_each_covered_sample(const CoverageSetup& s, int m, int row_lo, int row_hi, RowFn&& row, SampleFn&& sample) {
  for_each_candidate_row(s, m, row_lo, row_hi, [&](int j, const RowSpan& span, int i0, int i1) {
    row(j, span);
    covered_runs(s, j, i0, i1, [&](int lo, int hi) {
      for (int i = lo; i <= hi; ++i) sample(i, j);
    });
  });
}

template <class SampleFn>
void for_each_covered_sample(const CoverageSetup& s, int m, SampleFn&& sample) {
  for_each_covered_sample(
      s, m, 0, m - 1, [](int, const RowSpan&) {}, sample);
}

// Coverage setup of a screen polygon on a lattice.
inline CoverageSetup setup_coverage(const ScreenPolygon& p, const SampleLattice& lattice) {
  double x[kMaxScreenVertices], y[kMaxScreenVertices];
  const int n = int(std::min<std::size_t>(p.vertices.size(), kMaxScreenVertices));
  for (int k = 0; k < n; ++k) {
    x[k] = lattice.from_screen(p.vertices[std::size_t(k)].xs);
    y[k] = lattice.from_screen(p.vertices[std::size_t(k)].ys);
  }
  return setup_coverage(x, y, n);
}

// Non-opaque polygons are screen-door transparent: they cover only the samples of a fixed
// checkerboard (half of each pixel's samples), so visibility stays order-independent.
inline bool screen_door_passes(bool opaque, int i, int j) { return opaque || ((i + j) & 1) == 0; }

}  // namespace cig
