#include "image/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "image/ssim.hpp"

namespace cig {

double ImageError::psnr() const {
  const double m = mse();
  return m == 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / m);
}

double ImageError::ssim() const {
  return has_ssim() ? ssim_sum / double(ssim_images) : std::numeric_limits<double>::quiet_NaN();
}

void ImageError::add(const ImageError& e) {
  pixels += e.pixels;
  ssim_sum += e.ssim_sum;
  ssim_images += e.ssim_images;
  sum_squared += e.sum_squared;
  for (int c = 0; c < 3; ++c) max_abs[c] = std::max(max_abs[c], e.max_abs[c]);
  pixels_over_2lsb += e.pixels_over_2lsb;
  sum_squared_ids_differ += e.sum_squared_ids_differ;
  pixels_ids_differ += e.pixels_ids_differ;
}

ImageError compare_images(const Image& got, const Image& reference, const IdBuffer& got_ids,
                          const IdBuffer& reference_ids) {
  if (got.width != reference.width || got.height != reference.height)
    throw std::runtime_error("compare: images differ in size");
  const bool with_ids = !got_ids.id.empty() && got_ids.id.size() == reference_ids.id.size();
  ImageError e;
  e.pixels = long(got.width) * long(got.height);
  for (std::size_t p = 0; p < std::size_t(e.pixels); ++p) {
    bool over = false;
    double sq = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(got.rgb[3 * p + std::size_t(c)]) - int(reference.rgb[3 * p + std::size_t(c)]));
      sq += double(d) * d;
      e.max_abs[c] = std::max(e.max_abs[c], d);
      over = over || d > 2;
    }
    e.sum_squared += sq;
    e.pixels_over_2lsb += over;
    if (with_ids && got_ids.id[p] != reference_ids.id[p]) {
      e.sum_squared_ids_differ += sq;
      ++e.pixels_ids_differ;
    }
  }
  if (ssim_defined(got.width, got.height)) {
    e.ssim_sum = ssim(got, reference);
    e.ssim_images = 1;
  }
  return e;
}

namespace {

bool at_edge(const IdBuffer& b, int x, int y) {
  const std::int32_t id = b.id[std::size_t(y) * std::size_t(b.width) + std::size_t(x)];
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u >= 0 && v >= 0 && u < b.width && v < b.height &&
          b.id[std::size_t(v) * std::size_t(b.width) + std::size_t(u)] != id)
        return true;
    }
  return false;
}

}  // namespace

long differing_ids_off_edges(const IdBuffer& got, const IdBuffer& reference) {
  if (got.id.size() != reference.id.size() || got.width != reference.width || got.id.empty()) return 0;
  long n = 0;
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(got.width) + std::size_t(x);
      if (got.id[p] != reference.id[p] && !at_edge(got, x, y) && !at_edge(reference, x, y)) ++n;
    }
  return n;
}

ImageError compare_images(const Image& got, const Image& reference) {
  return compare_images(got, reference, IdBuffer(), IdBuffer());
}

void PriorityAttribution::add(const PriorityAttribution& a) {
  ids_priority_vs_depth += a.ids_priority_vs_depth;
  pixels_priority_colour += a.pixels_priority_colour;
  sum_squared_priority_colour += a.sum_squared_priority_colour;
}

PriorityAttribution attribute_priority(const Image& got, const IdBuffer& got_ids, const Image& reference,
                                       const IdBuffer& reference_ids, const Image& priority,
                                       const IdBuffer& priority_ids) {
  const std::size_t n = reference_ids.id.size();
  if (got.rgb.size() != reference.rgb.size() || priority.rgb.size() != reference.rgb.size() || got_ids.id.size() != n ||
      priority_ids.id.size() != n || reference.rgb.size() != 3 * n)
    throw std::runtime_error("attribute_priority: images differ in size");
  PriorityAttribution a;
  for (std::size_t p = 0; p < n; ++p) {
    if (got_ids.id[p] != reference_ids.id[p]) {
      a.ids_priority_vs_depth += priority_ids.id[p] != reference_ids.id[p];
      continue;
    }
    bool priority_changes = false;
    double sq = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int r = reference.rgb[3 * p + c];
      priority_changes = priority_changes || std::abs(int(priority.rgb[3 * p + c]) - r) > 2;
      const int d = int(got.rgb[3 * p + c]) - r;
      sq += double(d) * d;
    }
    if (priority_changes) {
      ++a.pixels_priority_colour;
      a.sum_squared_priority_colour += sq;
    }
  }
  return a;
}

Image difference_image(const Image& got, const Image& reference, int gain) {
  Image d(got.width, got.height);
  for (std::size_t i = 0; i < d.rgb.size(); ++i)
    d.rgb[i] = std::uint8_t(std::min(255, gain * std::abs(int(got.rgb[i]) - int(reference.rgb[i]))));
  return d;
}

long differing_ids(const IdBuffer& got, const IdBuffer& reference) {
  long n = 0;
  for (std::size_t i = 0; i < got.id.size() && i < reference.id.size(); ++i) n += got.id[i] != reference.id[i];
  return n;
}

}  // namespace cig
