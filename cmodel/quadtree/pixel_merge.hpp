// The video stage of N quadtree rendering pipelines (seed 000's Nc; RasterEngine::render_parts):
// each part, a contiguous slice of one priority list, was rasterised into its own pixel frame
// (keep_samples on); the merge takes, sample by sample, what the whole list would have given.
//
// Why it is the same: the whole list's pixel processor gives sample s to the first polygon that
// covers it (part order = priority order, so that is the first part whose polygons own s), shows
// the light instead when a light ranks at or before that polygon (any light of an earlier part
// does; within the owning part the part's own processing decided), and shows the earliest light,
// else the background, where no polygon owns s. The box filter sums in the order the samples were
// taken, polygon by polygon in priority order, then the unowned samples by index: ordering the
// taken samples by (part, arrival within the part) gives the same order, so even the double
// twin's sums are bit for bit the same.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/parallel.hpp"
#include "image/raster_image.hpp"
#include "quadtree/quadtree_frame.hpp"

namespace cig::quad {

template <class P>
class PixelMerge {
 public:
  // offsets[k]: the polygons before part k in the whole list.
  PixelMerge(std::vector<const PixelFrame<P>*> parts, std::vector<std::int32_t> offsets)
      : parts_(std::move(parts)), offsets_(std::move(offsets)), spp_(parts_[0]->samples_per_pixel()) {}

  void run(int threads, RasterImage& out) const {
    const int n = parts_[0]->raster();
    out.image = Image(n, n);
    out.ids = IdBuffer(n, n);
    parallel_for(std::size_t(n), threads, [&](std::size_t py, int) {
      std::vector<Taken> taken;
      std::vector<std::int32_t> owners(std::size_t(spp_), -1);
      for (int px = 0; px < n; ++px) {
        const std::size_t pix = py * std::size_t(n) + std::size_t(px);
        std::uint8_t* dst = out.image.at(px, int(py));
        out.ids.id[pix] = pixel(pix, taken, owners, dst);
      }
    });
  }

 private:
  struct Taken {
    std::size_t part;
    std::uint64_t rank;
    int sample;
    const typename P::Sample* colour;
  };

  // One pixel: its colour into rgb, its id returned.
  std::int32_t pixel(std::size_t pix, std::vector<Taken>& taken, std::vector<std::int32_t>& owners,
                     std::uint8_t* rgb) const {
    taken.clear();
    std::uint64_t unowned = 0;
    for (int s = 0; s < spp_; ++s) {
      std::size_t first = parts_.size(), owner = parts_.size();  // first part covering s; first owning it
      for (std::size_t k = 0; k < parts_.size(); ++k) {
        const bool owns = (parts_[k]->owned(pix) >> s) & 1u;
        if (first == parts_.size() && (owns || parts_[k]->cover(pix).mask.bit(s))) first = k;
        if (owns) {
          owner = k;
          break;
        }
      }
      owners[std::size_t(s)] = owner < parts_.size() ? parts_[owner]->owner(pix, s) + offsets_[owner] : -1;
      if (owner == parts_.size()) {
        unowned |= std::uint64_t{1} << s;
        continue;
      }
      // An earlier part's light shows over the polygon that owns the sample.
      const typename P::Sample* colour =
          first == owner ? parts_[owner]->taken(pix, s).colour : parts_[first]->cover(pix).colour[s];
      taken.push_back({owner, parts_[owner]->rank(pix, s), s, colour});
    }
    std::sort(taken.begin(), taken.end(),
              [](const Taken& a, const Taken& b) { return a.part != b.part ? a.part < b.part : a.rank < b.rank; });
    typename P::Accum sum[3];
    for (int c = 0; c < 3; ++c) sum[c] = typename P::Accum();
    for (const Taken& t : taken)
      for (int c = 0; c < 3; ++c) sum[c] = P::accumulate(sum[c], t.colour[c]);
    for (int s = 0; s < spp_; ++s) {
      if (((unowned >> s) & 1u) == 0) continue;
      for (int c = 0; c < 3; ++c) sum[c] = P::accumulate(sum[c], unowned_colour(pix, s, c));
    }
    for (int c = 0; c < 3; ++c) rgb[c] = std::uint8_t(P::resolve(sum[c], parts_[0]->side_log2()).value());
    return majority_owner(owners.data(), spp_);
  }

  // A sample no part's polygons own: the earliest light that covers it, else the background.
  typename P::Sample unowned_colour(std::size_t pix, int s, int c) const {
    for (const PixelFrame<P>* part : parts_)
      if (part->cover(pix).mask.bit(s)) return part->cover(pix).colour[s][c];
    return P::level_sample(parts_[0]->tables().background[c]);
  }

  std::vector<const PixelFrame<P>*> parts_;
  std::vector<std::int32_t> offsets_;
  int spp_;
};

}  // namespace cig::quad
