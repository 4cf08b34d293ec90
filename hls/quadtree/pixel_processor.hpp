// Pixel processor of the recursive-subdivision raster processor (SPEC E; seed 004, Fig. 1:
// "final computations, filtering"): takes the pixel-level records the PEs emit, front to back,
// and keeps per pixel the samples already owned and the running sum of their colours.
//
// A record's samples that no earlier polygon owns become this polygon's: each gets I and W = 1/Z
// at its own position from the pixel's top-left value and the plane's gradients (S x S sample lanes,
// 16 for the seeds' 4 x 4:
// f + D di + E dj), colour x I, fog by 1/Z through the fog table, and is added to the pixel's sum
// (exact: up to 64 samples of 8 fractional bits fit BoxSum, UFixed<22, 14>), which is the box filter's sum. The
// pixel is full, and its bit in the level n-1 mask can be set, when all its samples are owned.
//
// Light points (SPEC B) are not polygons: the light point unit rasterises them before the frame's
// polygons into a per-pixel cover: for every sample, the light with the earliest priority
// position that covers it, and that light's colour (colour x I, fog by its Z; cmodel). A light
// with priority position p ranks just before polygon p (cmodel/frame/screen_frame.hpp), so when
// polygon q first owns a sample the light shows instead if p <= q; a sample no polygon owns shows
// its light, or the background. This is the same visibility as processing the lights in the
// priority stream (the segment processor's video channel), without their travelling through the
// PEs.
#pragma once

#include "hls/quadtree/quadtree_arith.hpp"
#include "hls/types/top_ports.hpp"

CIG_HLS_BEGIN_NAMESPACE

template <class P>
struct QuadPixelState {
  PixelSampleMask owned;     // samples some polygon owns (bit S dj + di)
  typename P::Accum sum[3];  // the owned samples' colours, summed
};

template <class P>
struct QuadLightCover {
  PixelSampleMask mask;                               // samples a light covers
  UInt<17> priority[kMaxSamplesPerPixel];             // that light's priority position
  typename P::Sample colour[kMaxSamplesPerPixel][3];  // its colour at the sample
};

template <class P>
struct QuadPixelTables {
  typename P::FogTable fog;  // indexed by the e8m7 code of 1/Z (fixed policy)
  SampleLevel fog_colour[3];
  SampleLevel background[3];
};

template <class P>
void quad_pixel_clear(QuadPixelState<P>& st) {
  st.owned = PixelSampleMask(0);
  for (int c = 0; c < 3; ++c) st.sum[c] = typename P::Accum();
}

// Whether the light cover shows at sample s instead of the polygon taking it: a light covers the
// sample from a priority position at or before the polygon's.
template <class P>
bool quad_light_shows(const QuadLightCover<P>& lights, int s, const QuadPolygon<P>& poly) {
  return lights.mask.bit(s) && lights.priority[s].value() <= poly.id.value();
}

// What a polygon's colour at sample s (bit S dj + di) of a pixel record depends on: I and the fog
// factor of W = 1/Z at the sample (exact plane values, f + D di + E dj, from the record's values f
// at its first sample and the polygon's constants).
template <class P>
void quad_sample_shading(const QuadPolygon<P>& poly, const typename P::Param (&f)[kQuadParams], int s,
                         const QuadPixelTables<P>& t, typename P::Intensity& in, typename P::FogFactorType& fog,
                         int side_log2 = kDefaultSideLog2) {
  const int di = s & ((1 << side_log2) - 1), dj = s >> side_log2;
  const typename P::Param vi =
      P::at_sample(f[kParamIntensity], poly.dp_di[kParamIntensity], poly.dp_dj[kParamIntensity], di, dj);
  const typename P::Param vw =
      P::at_sample(f[kParamInverseDepth], poly.dp_di[kParamInverseDepth], poly.dp_dj[kParamInverseDepth], di, dj);
  in = P::intensity(vi);
  fog = P::fog_factor(t.fog, vw, poly.w_exponent);
}

// The colour of sample s (bit S dj + di) of a pixel record (values f, polygon poly) when this
// polygon takes it: the light's, when it shows (quad_light_shows), else colour x I, fog by 1/Z at
// the sample.
template <class P>
void quad_sample_colour(const QuadPolygon<P>& poly, const typename P::Param (&f)[kQuadParams], int s,
                        const QuadPixelTables<P>& t, const QuadLightCover<P>& lights, typename P::Sample (&colour)[3],
                        int side_log2 = kDefaultSideLog2) {
  if (quad_light_shows(lights, s, poly)) {
    for (int c = 0; c < 3; ++c) colour[c] = lights.colour[s][c];
    return;
  }
  typename P::Intensity in;
  typename P::FogFactorType fog;
  quad_sample_shading(poly, f, s, t, in, fog, side_log2);
  for (int c = 0; c < 3; ++c) colour[c] = P::sample_colour(poly.colour[c], in, fog, t.fog_colour[c]);
}

// The samples of a record that no earlier polygon owns: they become this polygon's.
inline PixelSampleMask quad_pixel_fresh(const PixelSampleMask& samples, const PixelSampleMask& owned) {
  return PixelSampleMask(samples.value() & ~owned.value());
}

// The colour half of a record under a flat I plane (D = E = 0: every sample has the record's I):
// a sample's colour is then a function of its fog factor alone (quad_sample_colour), so a sample
// whose fog factor equals the previous shaded sample's takes that sample's colour; the same bits
// without the colour multipliers.
template <class P>
void quad_pixel_accumulate_flat(const QuadPolygon<P>& poly, const typename P::Param (&f)[kQuadParams],
                                const PixelSampleMask& fresh, const QuadPixelTables<P>& t,
                                const QuadLightCover<P>& lights, typename P::Accum (&sum)[3], int side_log2) {
  const int side = 1 << side_log2;
  const typename P::Intensity in =
      P::intensity(P::at_sample(f[kParamIntensity], poly.dp_di[kParamIntensity], poly.dp_dj[kParamIntensity], 0, 0));
  typename P::FogFactorType last_fog = typename P::FogFactorType();
  typename P::Sample colour[3] = {};
  bool shaded = false;  // colour is the colour at (in, last_fog)
  for (int s = 0; s < kMaxSamplesPerPixel; ++s) {
    if (s >= side * side) break;
    if (!fresh.bit(s)) continue;
    if (quad_light_shows(lights, s, poly)) {
      for (int c = 0; c < 3; ++c) sum[c] = P::accumulate(sum[c], lights.colour[s][c]);
      continue;
    }
    const typename P::Param vw = P::at_sample(f[kParamInverseDepth], poly.dp_di[kParamInverseDepth],
                                              poly.dp_dj[kParamInverseDepth], s & (side - 1), s >> side_log2);
    const typename P::FogFactorType fog = P::fog_factor(t.fog, vw, poly.w_exponent);
    if (!shaded || !(fog == last_fog)) {
      for (int c = 0; c < 3; ++c) colour[c] = P::sample_colour(poly.colour[c], in, fog, t.fog_colour[c]);
      last_fog = fog;
      shaded = true;
    }
    for (int c = 0; c < 3; ++c) sum[c] = P::accumulate(sum[c], colour[c]);
  }
}

// The colour half of a record (values f at its first sample; the polygon's constants poly, by
// reference: the same for every record of the piece): the fresh samples' colours added to the
// pixel's sums. Only the sums depend on it (the owned samples, and so the masks and the timing, do
// not).
template <class P>
void quad_pixel_accumulate(const QuadPolygon<P>& poly, const typename P::Param (&f)[kQuadParams],
                           const PixelSampleMask& fresh, const QuadPixelTables<P>& t, const QuadLightCover<P>& lights,
                           typename P::Accum (&sum)[3], int side_log2 = kDefaultSideLog2) {
  const typename P::Gradient zero = typename P::Gradient(0);
  if (poly.dp_di[kParamIntensity] == zero && poly.dp_dj[kParamIntensity] == zero) {
    quad_pixel_accumulate_flat(poly, f, fresh, t, lights, sum, side_log2);
    return;
  }
  const int side = 1 << side_log2;
  for (int s = 0; s < kMaxSamplesPerPixel; ++s) {
    if (s >= side * side) break;
    if (!fresh.bit(s)) continue;
    typename P::Sample colour[3];
    quad_sample_colour(poly, f, s, t, lights, colour, side_log2);
    for (int c = 0; c < 3; ++c) sum[c] = P::accumulate(sum[c], colour[c]);
  }
}

// One pixel record (a level-n window and its covered samples, S = 2^side_log2 a side); returns
// the samples it took.
template <class P>
PixelSampleMask quad_pixel_process(const QuadWindow<P>& px, const PixelSampleMask& samples, const QuadPixelTables<P>& t,
                                   const QuadLightCover<P>& lights, QuadPixelState<P>& st,
                                   int side_log2 = kDefaultSideLog2) {
  const PixelSampleMask fresh = quad_pixel_fresh(samples, st.owned);
  quad_pixel_accumulate(px.poly, px.f, fresh, t, lights, st.sum, side_log2);
  st.owned = PixelSampleMask(st.owned.value() | fresh.value());
  return fresh;
}

// The pixel's final colour: owned samples as summed, the others show their light or the
// background; the box filter's mean, rounded.
template <class P>
void quad_pixel_resolve(const QuadPixelState<P>& st, const QuadPixelTables<P>& t, const QuadLightCover<P>& lights,
                        UInt<8> (&rgb)[3], int side_log2 = kDefaultSideLog2) {
  typename P::Accum sum[3];
  for (int c = 0; c < 3; ++c) sum[c] = st.sum[c];
  for (int s = 0; s < kMaxSamplesPerPixel; ++s) {
    if (s >= (1 << (2 * side_log2))) break;
    if (st.owned.bit(s)) continue;
    for (int c = 0; c < 3; ++c)
      sum[c] = P::accumulate(sum[c], lights.mask.bit(s) ? lights.colour[s][c] : P::level_sample(t.background[c]));
  }
  for (int c = 0; c < 3; ++c) rgb[c] = P::resolve(sum[c], side_log2);
}

// Top function (HLS): one pixel record into the pixel's state, default format.
// Ports (hls/types/top_ports.hpp): name, direction, interface, C++ type.
#define CIG_HLS_PORTS_quadtree_pixel_top(PORT, ARRAY, RESULT)        \
  RESULT(PixelSampleMask)                                            \
  PORT(px, in, ap_none, const QuadWindow<DefaultQuadArith>&)         \
  PORT(samples, in, ap_none, PixelSampleMask)                        \
  PORT(t, in, ap_memory, const QuadPixelTables<DefaultQuadArith>&)   \
  PORT(lights, in, ap_none, const QuadLightCover<DefaultQuadArith>&) \
  PORT(st, inout, ap_ovld, QuadPixelState<DefaultQuadArith>&)
inline CIG_HLS_TOP(quadtree_pixel_top) { return quad_pixel_process(px, samples, t, lights, st); }

CIG_HLS_END_NAMESPACE
