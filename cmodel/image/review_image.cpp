#include "image/review_image.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace cig {

namespace {

// Bin 0 a dark neutral grey (a correct image is uniform), then cold to hot, the largest white.
// Magenta is kept for the id mark, and no bin is the canvas colour.
constexpr Rgb8 kBinColours[kErrorBins] = {
    {64, 64, 64},     // 0
    {40, 60, 150},    // 1
    {30, 110, 230},   // 2-3
    {0, 190, 190},    // 4-7
    {60, 200, 60},    // 8-15
    {230, 230, 40},   // 16-31
    {255, 150, 0},    // 32-63
    {230, 30, 30},    // 64-127
    {255, 255, 255},  // 128-255
};

const char* const kIdLabel = "polygon id differs";

void blit(Image& dst, int x0, int y0, const Image& src) {
  for (int y = 0; y < src.height; ++y) std::memcpy(dst.at(x0, y0 + y), src.at(0, y), std::size_t(src.width) * 3);
}

}  // namespace

int error_bin(int error) {
  int bin = 0;
  for (int e = std::clamp(error, 0, 255); e > 0 && bin < kErrorBins - 1; e >>= 1) ++bin;
  return bin;
}

int error_bin_floor(int bin) { return bin <= 0 ? 0 : 1 << (bin - 1); }

std::string error_bin_label(int bin) {
  return std::to_string(error_bin_floor(bin)) + (bin == kErrorBins - 1 ? "+" : "");
}

Rgb8 error_bin_colour(int bin) { return kBinColours[std::clamp(bin, 0, kErrorBins - 1)]; }

Rgb8 error_colour(int error) { return error_bin_colour(error_bin(error)); }

int pixel_error(const Image& got, const Image& reference, int x, int y) {
  const std::uint8_t *a = got.at(x, y), *b = reference.at(x, y);
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

Image error_heat_map(const Image& got, const Image& reference, const IdBuffer* got_ids, const IdBuffer* reference_ids) {
  if (got.width != reference.width || got.height != reference.height)
    throw std::runtime_error("error map: the images differ in size");
  const bool ids = got_ids && reference_ids;
  if (ids && (got_ids->width != got.width || got_ids->height != got.height || reference_ids->width != got.width ||
              reference_ids->height != got.height))
    throw std::runtime_error("error map: the id buffers differ in size from the images");
  Image out(got.width, got.height);
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(got.width) + std::size_t(x);
      const Rgb8 c = ids && got_ids->id[i] != reference_ids->id[i] ? kIdDiffersColour
                                                                   : error_colour(pixel_error(got, reference, x, y));
      std::uint8_t* p = out.at(x, y);
      p[0] = c.r, p[1] = c.g, p[2] = c.b;
    }
  return out;
}

int ReviewLayout::box_x(int k) const {
  const int margin = 4 * text_scale;
  return margin + k * box_width + (k >= kErrorBins ? 8 * text_scale : 0);
}

ReviewLayout review_layout(int panel_width, int panel_height) {
  ReviewLayout l;
  const int s = l.text_scale = panel_width >= 256 ? 2 : 1;
  const int margin = 4 * s, gap = 4 * s, line = (kGlyphHeight + 2) * s;
  l.title_y = margin;
  l.names_y = margin + line;
  l.panel_y = margin + 2 * line;
  for (int i = 0; i < 3; ++i) l.panel_x[i] = margin + i * (panel_width + gap);
  l.scale_y = l.panel_y + panel_height + margin;
  l.box_width = 26 * s;  // "128+" (23 s) fits under a box
  l.box_height = 10 * s;
  l.labels_y = l.scale_y + l.box_height + 2 * s;
  l.height = l.labels_y + kGlyphHeight * s + margin;
  const int scale_right = l.box_x(kErrorBins) + std::max(l.box_width, text_width(kIdLabel, s));
  l.width = std::max(2 * margin + 3 * panel_width + 2 * gap, scale_right + margin);
  return l;
}

Image review_image(const RasterImage& got, const RasterImage& reference, const ReviewLabels& labels) {
  const int w = got.image.width, h = got.image.height;
  const Image errors = error_heat_map(got.image, reference.image, &got.ids, &reference.ids);
  const ReviewLayout l = review_layout(w, h);
  const int s = l.text_scale;
  Image out(l.width, l.height);
  fill_rect(out, 0, 0, l.width, l.height, kReviewBackground);
  draw_text(out, l.panel_x[0], l.title_y, labels.caption, s, kReviewText, l.width - l.panel_x[0]);
  std::string error_name = "|error| LSB (max of R, G, B)";  // shortened until it fits the panel
  for (const char* shorter : {"|error| LSB", "|error|"})
    if (text_width(error_name, s) > w) error_name = shorter;
  const std::string names[3] = {labels.engine, labels.reference, error_name};
  const Image* panels[3] = {&got.image, &reference.image, &errors};
  for (int i = 0; i < 3; ++i) {
    draw_text(out, l.panel_x[i], l.names_y, names[i], s, kReviewText, l.panel_x[i] + w);
    blit(out, l.panel_x[i], l.panel_y, *panels[i]);
  }
  for (int k = 0; k <= kErrorBins; ++k) {
    const Rgb8 c = k < kErrorBins ? error_bin_colour(k) : kIdDiffersColour;
    fill_rect(out, l.box_x(k), l.scale_y, l.box_width, l.box_height, c);
    const std::string label = k < kErrorBins ? error_bin_label(k) : kIdLabel;
    const int x = k < kErrorBins ? l.box_x(k) + (l.box_width - text_width(label, s)) / 2 : l.box_x(k);
    draw_text(out, x, l.labels_y, label, s, kReviewText, l.width);
  }
  return out;
}

}  // namespace cig
