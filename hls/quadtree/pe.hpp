// The quadtree processing element (SPEC E, seed 004): takes one window of level l - 1 and decides
// its four children (sub-windows of level l): the mask check, the coverage test through the
// recurrence d_i, the full-coverage test, the parameter recurrence f_i, and at the pixel level
// (l = n) the S x S-bit sub-pixel coverage mask (16 bits for the seeds' 4 x 4).
//
// Coverage recurrence (seed 004): for the child with address bits (x_b, y_b) and side 2^k samples
// (k = n - l + t, S = 2^t samples a side per pixel),
//   d_l = d_(l-1) - 2^k |A| e_A - 2^k |B| e_B,
// with e_A = 1 when the child does not contain the parent's maximising corner along x: e_A = !x_b
// for A >= 0 (the maximum lies at the right), x_b for A < 0; e_B likewise. d stays the maximum
// of the edge function over the child's samples, so the child may overlap the polygon only if
// d >= 0 for every edge. Adds and shifts only.
// Full coverage: the child's minimum of every edge function, d - (2^k - 1)(|A| + |B|), is >= 0.
// Parameter recurrence: f_l = f_(l-1) + 2^k D x_b + 2^k E y_b, f the value at the window's
// top-left sample (SPEC E: the scan's f_0 offset is an OCR doubt; this reference point makes f_n
// land on the pixel's first sample, and the tests prove the recurrence equals direct evaluation
// bit for bit).
// Pixel level: the value of each edge at the pixel's top-left sample is d - (S - 1) (max(A, 0) +
// max(B, 0)); sample (di, dj) is inside when E_tl + A di + B dj >= 0 for every edge (the same
// samples and tie rule as the float reference). A non-opaque polygon keeps only the samples of
// the screen-door checkerboard ((i + j) even on the lattice). The pixel is covered when its mask is not empty,
// full when every sample is covered (before the screen door).
//
// Widths: 2^k |A| <= 8190 * 2^(13 - n - t) * 2^(n + t - 1) < 2^25, so every d and minimum fits EdgeValue.
#pragma once

#include "hls/quadtree/quadtree_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

// The pixel-level mask of child window c: sample (di, dj) of the S x S pixel is inside when
// E_tl + A di + B dj >= 0 for every edge. full: every sample covered (before the screen door); a
// non-opaque polygon keeps the samples with (i + j) even on the whole lattice, as the reference.
template <class P>
std::uint64_t pixel_samples(const QuadWindow<P>& c, int side_log2, bool& full) {
  const int side = 1 << side_log2;
  const std::uint64_t all = side_log2 == 3 ? ~std::uint64_t{0} : (std::uint64_t{1} << (side * side)) - 1;
  std::uint64_t mask = all;
  for (int e = 0; e < kQuadMaxEdges; ++e) {
    const EdgeGradient& a = c.poly.a[e];
    const EdgeGradient& b = c.poly.b[e];
    const std::int64_t ap = a.value() > 0 ? a.value() : 0, bp = b.value() > 0 ? b.value() : 0;
    const Int<34> top_left = Int<34>(c.d[e].value() - (side - 1) * (ap + bp));
    // An edge whose minimum over the pixel's samples is >= 0 clears no bit: skip its lanes (the
    // same mask; unused edge slots, A = B = 0 and d = 0, always skip).
    const std::int64_t am = a.value() < 0 ? a.value() : 0, bm = b.value() < 0 ? b.value() : 0;
    const Int<34> minimum = Int<34>(top_left.value() + (side - 1) * (am + bm));
    if (minimum.value() >= 0) continue;
    for (int dj = 0; dj < kMaxSamplesPerSide; ++dj) {
      if (dj >= side) break;
      for (int di = 0; di < kMaxSamplesPerSide; ++di) {
        if (di >= side) break;
        const Int<34> v = Int<34>(top_left.value() + a.value() * di + b.value() * dj);
        if (v.value() < 0) mask &= ~(std::uint64_t{1} << (side * dj + di));
      }
    }
  }
  full = mask == all;
  if (!c.poly.opaque) {
    // Screen door: bit S dj + di kept where (S x + di) + (S y + dj) is even.
    const int parity = (side * int(c.x.value() + c.y.value())) & 1;
    for (int dj = 0; dj < kMaxSamplesPerSide; ++dj) {
      if (dj >= side) break;
      for (int di = 0; di < kMaxSamplesPerSide; ++di) {
        if (di >= side) break;
        if (((parity + di + dj) & 1) != 0) mask &= ~(std::uint64_t{1} << (side * dj + di));
      }
    }
  }
  return mask;
}

// One child of window w (q = 2 y_b + x_b). `masked`: its priority-mask bit is set, so the child is
// skipped without a test. side_log2 = t: S = 2^t samples a side per pixel.
template <class P>
void evaluate_child(const QuadWindow<P>& w, int q, int raster_log2, bool masked, QuadChild<P>& out,
                    int side_log2 = kDefaultSideLog2) {
  out.masked = masked;
  out.covered = false;
  out.full = false;
  out.samples = PixelSampleMask(0);
  if (masked) return;
  const int level = int(w.level.value()) + 1;
  const int k = raster_log2 - level + side_log2;  // the child's side: 2^k samples
  const bool xb = (q & 1) != 0, yb = (q & 2) != 0;
  bool covered = true, full = true;
  QuadWindow<P>& c = out.window;
  for (int e = 0; e < kQuadMaxEdges; ++e) {
    const EdgeGradient& a = w.poly.a[e];
    const EdgeGradient& b = w.poly.b[e];
    const EdgeValue abs_a = EdgeValue(abs_value(a)), abs_b = EdgeValue(abs_value(b));
    const bool ea = a.value() >= 0 ? !xb : xb;
    const bool eb = b.value() >= 0 ? !yb : yb;
    const EdgeValue step_a = ea ? (abs_a << k) : EdgeValue(0);
    const EdgeValue step_b = eb ? (abs_b << k) : EdgeValue(0);
    c.d[e] = wrap<32>(w.d[e] - step_a - step_b);  // exact (widths above)
    const EdgeValue sum_ab = wrap<32>(abs_a + abs_b);
    const Int<34> minimum = c.d[e] - (sum_ab << k) + sum_ab;
    covered = covered && c.d[e].value() >= 0;
    full = full && minimum.value() >= 0;
  }
  if (!covered) return;
  c.level = UInt<4>(level);
  c.x = UInt<10>(2 * int(w.x.value()) + (xb ? 1 : 0));
  c.y = UInt<10>(2 * int(w.y.value()) + (yb ? 1 : 0));
  for (int p = 0; p < kQuadParams; ++p) {
    typename P::Param f = w.f[p];
    if (xb) f = P::step(f, w.poly.dp_di[p], k);
    if (yb) f = P::step(f, w.poly.dp_dj[p], k);
    c.f[p] = f;
  }
  c.poly = w.poly;
  if (level == raster_log2) {
    const std::uint64_t mask = pixel_samples(c, side_log2, full);
    covered = mask != 0;
    out.samples = PixelSampleMask(mask);
  }
  out.covered = covered;
  out.full = full;
}

// Top function (HLS): one window and its mask word in, its four children out.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_quadtree_pe_top(PORT, ARRAY, RESULT)  \
  RESULT(void)                                              \
  PORT(w, in, ap_none, const QuadWindow<DefaultQuadArith>&) \
  PORT(mask_word, in, ap_none, UInt<4>)                     \
  PORT(raster_log2, in, ap_none, UInt<4>)                   \
  ARRAY(children, out, ap_vld, QuadChild<DefaultQuadArith>, kQuadChildren)
inline CIG_HLS_TOP(quadtree_pe_top) {
  for (int q = 0; q < kQuadChildren; ++q) evaluate_child(w, q, int(raster_log2.value()), mask_word.bit(q), children[q]);
}

CIG_HLS_END_NAMESPACE
