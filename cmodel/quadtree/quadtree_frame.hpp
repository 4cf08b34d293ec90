// The recursive-subdivision raster processor's frame around the PEs, shared by the engine
// (quadtree_engine.cpp) and the co-simulation harness (verif/cosim):
//   * the front end: formatter kernel -> setup kernel, polygon by polygon in priority order,
//     giving the pieces' level-0 windows (the polygon input port's stream);
//   * the pixel frame: the pixel processor kernel's per-pixel state, its tables (fog by the e8m7
//     code of 1/Z, fog colour, background), the light point unit's per-pixel covers, the
//     per-sample owners (for the id buffer) and the resolve. It is the PixelSink the architecture
//     model drives, and it provides the tables the RTL is loaded with.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <type_traits>
#include <vector>

#include "common/job_stream.hpp"
#include "common/parallel.hpp"
#include "formatter/fog_table.hpp"
#include "formatter/formatter_twin.hpp"
#include "frame/screen_frame.hpp"
#include "hls/formatter/formatter.hpp"
#include "hls/pixel/light_coding.hpp"
#include "hls/quadtree/pixel_processor.hpp"
#include "hls/quadtree/setup.hpp"
#include "hls/quadtree/span_setup.hpp"
#include "image/raster_image.hpp"
#include "quadtree/arch_model.hpp"
#include "quadtree/quadtree_double_arith.hpp"

namespace cig::quad {

// ---- The fixed/double twin adaptation ---------------------------------------------------------
// QuadFront<P>: what differs between the bit-accurate kernels and their double twin around the PEs
// (the same pattern as the segment engine's Front<P>, segment_engine.cpp): the setup's input, the
// pixel processor's fog table, a light's colour.
template <class P>
struct QuadFront;

template <class Fmt>
struct QuadFront<hls::QuadFixedArith<Fmt>> {
  using P = hls::QuadFixedArith<Fmt>;
  // The setup's input: the formatter kernel's output.
  static void setup_input(const ScreenPolygon& p, std::uint16_t id, hls::QuadPrimitiveInput<P>& in) {
    hls::FormattedPrimitive f;
    hls::formatter_top(raw_from_polygon(p, id), f);
    hls::quad_input_from_formatted(f, in);
  }
  // The fixed pixel processor looks fog up by the e8m7 code of 1/Z (host fill, per frame).
  static void fill_fog(hls::QuadPixelTables<P>& t, const Fog& fog) { fill_fog_table(t.fog, fog, true); }
  // A light's colour at its samples: colour x I, fog by its Z (the pixel processor's arithmetic).
  static void light_colour(const ScreenLightPoint&, const hls::FormattedPrimitive& f, const hls::QuadPixelTables<P>& t,
                           typename P::Sample (&out)[3]) {
    const int e = P::depth_exponent(f.v[0].z);
    const typename P::Value w = P::inverse_depth_value(f.v[0].z, e);
    const typename P::Param v = typename P::Param(w) << P::G;
    const hls::FogFactor fog = P::fog_factor(t.fog, v, hls::Int<10>(P::w_exponent(e)));
    const typename P::Intensity in(hls::UFixed<9, 9>::from_raw(f.v[0].i));
    for (int c = 0; c < 3; ++c) out[c] = P::sample_colour(f.colour[c], in, fog, t.fog_colour[c]);
  }
};

template <>
struct QuadFront<QuadDoubleArith> {
  using P = QuadDoubleArith;
  // The twin keeps the formatter's positions (coverage is exact) and takes the unquantized I and Z
  // of the formatter twin.
  static void setup_input(const ScreenPolygon& p, std::uint16_t id, hls::QuadPrimitiveInput<P>& in) {
    hls::FormattedPrimitive f;
    hls::formatter_top(raw_from_polygon(p, id), f);
    const TwinPrimitive t = formatter_twin(p, id);
    in.n = f.n;
    for (int k = 0; k < hls::kMaxVertices; ++k) {
      in.v[k].x = f.v[k].x;
      in.v[k].y = f.v[k].y;
      in.v[k].i = k < t.n ? t.v[k].i : 0.0;
      in.v[k].z = k < t.n ? t.v[k].z : 1.0;
    }
    for (int c = 0; c < 3; ++c) in.colour[c] = f.colour[c];
    in.opaque = f.opaque;
    in.id = f.id;
  }
  static void fill_fog(hls::QuadPixelTables<P>& t, const Fog& fog) {
    t.fog.start = fog.start;
    t.fog.end = fog.end;
  }
  static void light_colour(const ScreenLightPoint& l, const hls::FormattedPrimitive& f,
                           const hls::QuadPixelTables<P>& t, typename P::Sample (&out)[3]) {
    const TwinPrimitive tw = formatter_twin(l, 0);
    const double fog = P::fog_factor(t.fog, 1.0 / tw.v[0].z, hls::Int<10>(0));
    for (int c = 0; c < 3; ++c) out[c] = P::sample_colour(f.colour[c], tw.v[0].i, fog, t.fog_colour[c]);
  }
};

struct FrontEndStats {
  long degenerate = 0, split = 0, bbox_edges = 0;
  long non_convex = 0, span_pieces = 0;  // polygons snapping made non-convex, and their pieces
};

// A polygon that snapping made non-convex: its span pieces' level-0 windows. False when the
// polygon is convex (the convex setup covers it).
template <class P>
bool span_piece_roots(const hls::QuadPrimitiveInput<P>& in, int raster_log2, int side_log2, hls::SpanPieces& pieces,
                      std::vector<hls::QuadWindow<P>>& roots, FrontEndStats& st) {
  hls::FormattedPrimitive positions;
  hls::span_input_from_setup(in, positions);
  hls::split_into_span_pieces(positions, raster_log2, pieces, side_log2);
  if (pieces.convex) return false;
  ++st.non_convex;
  hls::QuadWindow<P> root;
  for (int k = 0; k < int(pieces.count.value()); ++k) {
    bool ok = false;
    hls::quadtree_setup_span_piece(in, pieces.piece[k], raster_log2, root, ok, side_log2);
    if (!ok) break;  // all vertices on one line: covers nothing
    roots.push_back(root);
    ++st.span_pieces;
  }
  return true;
}

// The pieces' level-0 windows of a frame, in priority order (front to back), on the lattice of
// S = 2^side_log2 samples a side per pixel.
template <class P>
std::vector<hls::QuadWindow<P>> front_end(const ScreenFrame& frame, int raster_log2, FrontEndStats& st,
                                          int side_log2 = hls::kDefaultSideLog2) {
  std::vector<hls::QuadWindow<P>> roots;
  roots.reserve(frame.polygons.size());
  hls::QuadSetup<P> setup;
  hls::QuadPrimitiveInput<P> in;
  const auto pieces = std::make_unique<hls::SpanPieces>();
  for (std::size_t pi = 0; pi < frame.polygons.size(); ++pi) {
    QuadFront<P>::setup_input(frame.polygons[pi], std::uint16_t(pi), in);
    if (span_piece_roots(in, raster_log2, side_log2, *pieces, roots, st)) continue;
    hls::quadtree_setup(in, raster_log2, setup, side_log2);
    const int pieces = int(setup.pieces.value());
    if (pieces == 0) ++st.degenerate;
    if (pieces > 1) ++st.split;
    for (int k = 0; k < pieces; ++k) {
      roots.push_back(setup.root[k]);
      st.bbox_edges += long(setup.bbox_edges[k].value());
    }
  }
  return roots;
}

template <class P>
class PixelFrame final : public PixelSink<P> {
 public:
  PixelFrame() : tables_(std::make_unique<hls::QuadPixelTables<P>>()) {}

  // Keep every taken sample's colour and arrival rank (the merge of rendering pipelines reads them,
  // quadtree/pixel_merge.hpp); off by default: the pixel state's sums are all the resolve needs.
  void keep_samples(bool on) { keep_samples_ = on; }
  // Workers (EngineOptions::threads): with 2 or more, the pixel processor's colour half (sample
  // colours into the pixels' sums, hls quad_pixel_accumulate) and the resolve of the pixels that
  // become full run on a second thread, fed in record order, and the rest of the resolve is split
  // into strips. The owned samples, which feed back into the masks and so into the timing, stay on
  // the model's thread: same bits, same cycles.
  void set_threads(int threads) { threads_ = std::max(1, threads); }

  // Loads the tables and the light covers of a frame and clears the pixel states.
  void begin(const ScreenFrame& frame, int raster_log2, int side_log2 = hls::kDefaultSideLog2) {
    n_ = 1 << raster_log2;
    log2_ = raster_log2;
    colour_jobs_.finish();  // a frame left unfinished
    side_log2_ = side_log2;
    spp_ = 1 << (2 * side_log2);
    // The fog table depends on the fog's range only: refilled when that changes.
    if (!fog_filled_ || frame.fog.start != fog_start_ || frame.fog.end != fog_end_) {
      QuadFront<P>::fill_fog(*tables_, frame.fog);
      fog_filled_ = true;
      fog_start_ = frame.fog.start;
      fog_end_ = frame.fog.end;
    }
    for (int c = 0; c < 3; ++c) {
      tables_->fog_colour[c] = hls::UInt<8>(unit_to_byte(frame.fog.colour[c]));
      tables_->background[c] = hls::UInt<8>(unit_to_byte(frame.background[c]));
    }
    const std::size_t pixels = std::size_t(n_) * std::size_t(n_);
    if (states_.size() != pixels || owners_.size() != pixels * std::size_t(spp_)) {
      states_.assign(pixels, hls::QuadPixelState<P>());
      owners_.assign(pixels * std::size_t(spp_), -1);
      stamp_.assign(pixels, 0);
      frame_stamp_ = 0;
      cover_index_.assign(pixels, -1);
      cover_pixels_.clear();
    }
    if (++frame_stamp_ == 0) {  // the stamps wrapped: every pixel cleared once
      std::fill(stamp_.begin(), stamp_.end(), 0u);
      frame_stamp_ = 1;
    }
    for (std::size_t pix : cover_pixels_) cover_index_[pix] = -1;
    cover_pixels_.clear();
    covers_.clear();
    sample_colour_.assign(keep_samples_ ? pixels * std::size_t(spp_) : 0, {});
    sample_rank_.assign(keep_samples_ ? pixels * std::size_t(spp_) : 0, 0);
    light_samples_ = rasterise_lights(frame);
    samples_written_ = 0;
    hls::quad_pixel_clear(empty_state_);
    // Without kept samples (a whole image, not a pipeline's part) a pixel is resolved as soon as
    // its samples are all owned: no later record changes its sums or owners.
    resolve_full_ = !keep_samples_;
    if (resolve_full_) {
      image_ = Image(n_, n_);
      ids_ = IdBuffer(n_, n_);
      resolved_.assign(pixels, 0);
      owners_scratch_.assign(std::size_t(spp_), 0);
    }
    pieces_ = nullptr;
    if (threads_ > 1) colour_jobs_.start([this](ColourJob& j) { colour(*j.poly, j.f, j.pix, j.fresh, j.full); });
  }

  // The end of the frame's records: waits for the colour worker (before any read of the sums).
  void finish() { colour_jobs_.finish(); }

  // The cycle model's pieces: the polygon constants the records' colour half reads by reference.
  void pieces(const std::vector<hls::QuadWindow<P>>& roots) override { pieces_ = &roots; }

  std::uint64_t pixel(int, const QuadItem<P>& it, bool& became_full) override {
    const int x = int(it.w.x.value()), y = int(it.w.y.value());
    const std::size_t pix = std::size_t(y) * std::size_t(n_) + std::size_t(x);
    // The pixel processor (hls quad_pixel_process) in its two halves: the samples taken here, the
    // colours here or on the colour worker.
    hls::QuadPixelState<P>& state = touch(pix);
    const std::uint64_t f = hls::quad_pixel_fresh(it.samples, state.owned).value();
    became_full = false;
    if (f == 0) return f;  // (a full pixel's state is not written again: the worker may read it)
    state.owned = hls::PixelSampleMask(state.owned.value() | f);
    const std::uint64_t all = spp_ == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << spp_) - 1;
    became_full = state.owned.value() == all;
    samples_written_ += __builtin_popcountll(f);
    std::int32_t* owners = owners_.data() + pix * std::size_t(spp_);
    const std::int32_t id = std::int32_t(it.w.poly.id.value());
    if (f == all) std::fill(owners, owners + spp_, id);
    else
      for (std::uint64_t m = f; m != 0; m &= m - 1) owners[__builtin_ctzll(m)] = id;
    // The record's polygon constants are its piece's (a job points at them: the pieces outlive
    // the colour worker's frame); the cycle model always gives the pieces (PixelSink::pieces).
    const hls::QuadPolygon<P>& poly = pieces_ ? (*pieces_)[it.piece].poly : it.w.poly;
    if (colour_jobs_.running()) {
      ColourJob& job = colour_jobs_.push();
      job.poly = &poly;
      for (int p = 0; p < hls::kQuadParams; ++p) job.f[p] = it.w.f[p];
      job.pix = pix;
      job.fresh = f;
      job.full = became_full;
    } else {
      colour(poly, it.w.f, pix, f, became_full);
    }
    return f;
  }

  // What the merge of rendering pipelines reads (keep_samples on): per pixel the samples polygons
  // own and their light cover, per sample its owner, colour and arrival rank.
  std::uint64_t owned(std::size_t pix) const { return touched(pix) ? states_[pix].owned.value() : 0; }
  std::int32_t owner(std::size_t pix, int s) const {
    return touched(pix) ? owners_[pix * std::size_t(spp_) + std::size_t(s)] : -1;
  }
  const hls::QuadLightCover<P>& cover(std::size_t pix) const {
    const int ci = cover_index_[pix];
    return ci >= 0 ? covers_[std::size_t(ci)] : no_cover_;
  }
  struct TakenSample {
    typename P::Sample colour[3];
  };
  const TakenSample& taken(std::size_t pix, int s) const {
    return sample_colour_[pix * std::size_t(spp_) + std::size_t(s)];
  }
  std::uint64_t rank(std::size_t pix, int s) const { return sample_rank_[pix * std::size_t(spp_) + std::size_t(s)]; }
  int raster() const { return n_; }
  int side_log2() const { return side_log2_; }
  int samples_per_pixel() const { return spp_; }

  // The resolved image and the per-pixel ids (majority owner): the pixels resolved when they
  // became full, and the others now.
  void resolve(Image& image, IdBuffer& ids) {
    if (!resolve_full_) {
      image_ = Image(n_, n_);
      ids_ = IdBuffer(n_, n_);
      resolved_.assign(std::size_t(n_) * std::size_t(n_), 0);
    }
    const int strips = threads_ > 1 ? 4 * threads_ : 1;
    parallel_for(std::size_t(strips), threads_,
                 [&](std::size_t k, int) { resolve_rows(int(k) * n_ / strips, (int(k) + 1) * n_ / strips); });
    image = std::move(image_);
    ids = std::move(ids_);
    resolve_full_ = false;  // image_ and ids_ are handed over
  }

 private:
  // Rows [y0, y1) of the resolve, the pixels not resolved yet (rows are independent: strips may
  // run on several workers).
  void resolve_rows(int y0, int y1) {
    Image& image = image_;
    IdBuffer& ids = ids_;
    std::vector<std::int32_t> own(static_cast<std::size_t>(spp_));
    // A pixel no polygon and no light touched shows the background: resolved once.
    hls::UInt<8> empty_rgb[3];
    hls::quad_pixel_resolve(empty_state_, *tables_, no_cover_, empty_rgb, side_log2_);
    for (int py = y0; py < y1; ++py)
      for (int px = 0; px < n_; ++px) {
        const std::size_t pix = std::size_t(py) * std::size_t(n_) + std::size_t(px);
        if (resolved_[pix]) continue;
        std::uint8_t* dst = image.at(px, py);
        if (!touched(pix)) {
          hls::UInt<8> rgb[3];
          if (cover_index_[pix] >= 0) hls::quad_pixel_resolve(empty_state_, *tables_, cover(pix), rgb, side_log2_);
          for (int c = 0; c < 3; ++c) dst[c] = std::uint8_t((cover_index_[pix] >= 0 ? rgb : empty_rgb)[c].value());
          ids.id[pix] = -1;
          continue;
        }
        resolve_pixel(pix, dst, ids, own);
      }
  }

 public:
  const hls::QuadPixelTables<P>& tables() const { return *tables_; }
  // Light covers: per pixel the index of its cover (-1: none).
  const std::vector<int>& cover_index() const { return cover_index_; }
  const std::vector<hls::QuadLightCover<P>>& covers() const { return covers_; }
  long light_samples() const { return light_samples_; }
  long long samples_written() const { return samples_written_; }

 private:
  // The colour half of a record: its fresh samples' colours into the pixel's sums; the pixel
  // resolved when the record made it full.
  void colour(const hls::QuadPolygon<P>& poly, const typename P::Param (&f)[hls::kQuadParams], std::size_t pix,
              std::uint64_t fresh, bool full) {
    hls::quad_pixel_accumulate(poly, f, hls::PixelSampleMask(fresh), *tables_, cover(pix), states_[pix].sum,
                               side_log2_);
    if (keep_samples_) keep_taken(poly, f, pix, fresh);
    if (full && resolve_full_) {
      const int n = n_;
      resolve_pixel(pix, image_.at(int(pix % std::size_t(n)), int(pix / std::size_t(n))), ids_, owners_scratch_);
      resolved_[pix] = 1;
    }
  }
  // A touched pixel's colour (hls quad_pixel_resolve) and id.
  void resolve_pixel(std::size_t pix, std::uint8_t* dst, IdBuffer& ids, std::vector<std::int32_t>& own) const {
    hls::UInt<8> rgb[3];
    hls::quad_pixel_resolve(states_[pix], *tables_, cover(pix), rgb, side_log2_);
    for (int c = 0; c < 3; ++c) dst[c] = std::uint8_t(rgb[c].value());
    ids.id[pix] = pixel_id(pix, own);
  }
  struct ColourJob {
    const hls::QuadPolygon<P>* poly = nullptr;  // the piece's (PixelSink::pieces)
    typename P::Param f[hls::kQuadParams];      // the record's values at its first sample
    std::size_t pix = 0;
    std::uint64_t fresh = 0;
    bool full = false;  // the record made the pixel full
  };

  bool touched(std::size_t pix) const { return stamp_[pix] == frame_stamp_; }
  // The pixel's state for this frame: cleared when the frame first reaches it.
  hls::QuadPixelState<P>& touch(std::size_t pix) {
    if (!touched(pix)) {
      stamp_[pix] = frame_stamp_;
      hls::quad_pixel_clear(states_[pix]);
      const auto first = owners_.begin() + std::ptrdiff_t(pix * std::size_t(spp_));
      std::fill(first, first + spp_, -1);
    }
    return states_[pix];
  }
  // The majority owner of a touched pixel's samples (one owner: no sort).
  std::int32_t pixel_id(std::size_t pix, std::vector<std::int32_t>& own) const {
    const std::int32_t* first = owners_.data() + pix * std::size_t(spp_);
    if (std::all_of(first + 1, first + spp_, [&](std::int32_t o) { return o == first[0]; })) return first[0];
    std::copy(first, first + spp_, own.begin());
    return majority_owner(own.data(), spp_);
  }

  // The colours of the samples a record took (the pixel processor's own per-sample function) and
  // their arrival order.
  void keep_taken(const hls::QuadPolygon<P>& poly, const typename P::Param (&f)[hls::kQuadParams], std::size_t pix,
                  std::uint64_t taken) {
    for (int s = 0; s < spp_; ++s) {
      if (((taken >> s) & 1u) == 0) continue;
      const std::size_t k = pix * std::size_t(spp_) + std::size_t(s);
      hls::quad_sample_colour(poly, f, s, *tables_, cover(pix), sample_colour_[k].colour, side_log2_);
      sample_rank_[k] = next_rank_++;
    }
  }

  // The light point unit: every light's samples (the coding table's chords, hls/pixel/light_coding.hpp:
  // the float reference's disc, verif/kernels/test_segment_arith.cpp) into per-pixel covers; a
  // sample keeps the light with the earliest priority position (ties: the earlier light).
  long rasterise_lights(const ScreenFrame& frame) {
    const hls::LatticeGeometry g = hls::LatticeGeometry::for_raster(log2_, side_log2_);
    const int side = g.side();
    std::vector<std::size_t> order(frame.light_points.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return frame.light_points[a].priority < frame.light_points[b].priority;
    });
    long samples = 0;
    hls::LightChord chords[hls::kMaxLightRows];
    for (std::size_t li : order) {
      const ScreenLightPoint& l = frame.light_points[li];
      hls::FormattedPrimitive f;
      hls::formatter_top(raw_from_light(l, std::uint16_t(li)), f);
      typename P::Sample colour[3];
      QuadFront<P>::light_colour(l, f, *tables_, colour);
      const int k = hls::light_chords(f, log2_, chords, side_log2_);
      for (int s = 0; s < k; ++s) {
        const int row = chords[s].row;
        int i0 = 0, i1 = 0;
        hls::light_chord_columns(chords[s], g, i0, i1);
        i0 = std::max(0, i0);
        i1 = std::min(g.rows() - 1, i1);
        for (int i = i0; i <= i1; ++i) {
          const std::size_t pix = std::size_t(row / side) * std::size_t(n_) + std::size_t(i / side);
          if (cover_index_[pix] < 0) {
            cover_index_[pix] = int(covers_.size());
            cover_pixels_.push_back(pix);
            covers_.push_back(hls::QuadLightCover<P>{});
          }
          hls::QuadLightCover<P>& cv = covers_[std::size_t(cover_index_[pix])];
          const int bit = side * (row & (side - 1)) + (i & (side - 1));
          if (cv.mask.bit(bit)) continue;  // an earlier light holds the sample
          cv.mask = hls::PixelSampleMask(cv.mask.value() | (std::uint64_t{1} << bit));
          cv.priority[bit] = hls::UInt<17>(std::uint64_t(std::max(0, l.priority)));
          for (int c = 0; c < 3; ++c) cv.colour[bit][c] = colour[c];
          ++samples;
        }
      }
    }
    return samples;
  }

  int n_ = 0, log2_ = 0, side_log2_ = hls::kDefaultSideLog2, spp_ = hls::kSamplesPerPixel;
  std::unique_ptr<hls::QuadPixelTables<P>> tables_;
  // Model-speed device, not hardware: the pixel states and sample owners are cleared lazily. A
  // pixel whose stamp is not the frame's holds the cleared state (no sample owned, owners -1), so
  // a frame clears only the pixels its polygons reach instead of N^2 states and S^2 N^2 owners;
  // likewise only the light covers' pixels are reset.
  std::vector<hls::QuadPixelState<P>> states_;
  std::vector<std::int32_t> owners_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t frame_stamp_ = 0;
  std::vector<int> cover_index_;
  std::vector<std::size_t> cover_pixels_;  // the pixels with a light cover (their cover_index_ >= 0)
  hls::QuadPixelState<P> empty_state_{};
  std::vector<hls::QuadLightCover<P>> covers_;
  // A member rather than a function-local static: clang 14's ASan build once aborted (free():
  // invalid pointer) compiling the static's guarded initialisation of this large aggregate.
  hls::QuadLightCover<P> no_cover_{};
  bool keep_samples_ = false;
  std::vector<TakenSample> sample_colour_;
  std::vector<std::uint64_t> sample_rank_;
  std::uint64_t next_rank_ = 0;
  long light_samples_ = 0;
  long long samples_written_ = 0;  // samples polygons took (the pixel processor's work)
  int threads_ = 1;
  bool fog_filled_ = false;
  double fog_start_ = 0, fog_end_ = 0;
  // The image being resolved (resolve_full_: pixels resolved as they become full, marked in
  // resolved_); owners_scratch_: the colour worker's scratch for pixel_id.
  bool resolve_full_ = false;
  Image image_;
  IdBuffer ids_;
  std::vector<char> resolved_;
  std::vector<std::int32_t> owners_scratch_;
  const std::vector<hls::QuadWindow<P>>* pieces_ = nullptr;  // PixelSink::pieces (this frame's)
  JobStream<ColourJob> colour_jobs_;  // declared last: its worker stops before the members it uses go
};

}  // namespace cig::quad
