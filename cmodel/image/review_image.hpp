// The side-by-side review image of `cig compare --out` (docs/review_outputs.md): the engine's image,
// the reference's and a false-colour map of the error, with a title strip naming the panels and a
// colour scale under them.
//
// The error of a pixel is the largest absolute difference of its R, G and B in 8-bit LSB. The scale
// has kErrorBins bins, each from its lower bound up to the next one's: 0, 1, 2-3, 4-7, 8-15, 16-31,
// 32-63, 64-127, 128-255 (labelled 0 1 2 4 8 16 32 64 128+). Bin 0 is a dark neutral grey, so
// that a correct image is one uniform grey; the others run from dark blue through cyan, green,
// yellow, orange and red to white. A pixel whose polygon id differs from the reference's is drawn
// magenta (kIdDiffersColour) whatever its colour error: visibility and coverage differences stand
// apart from shading.
#pragma once

#include <string>

#include "image/bitmap_text.hpp"
#include "image/image.hpp"
#include "image/raster_image.hpp"

namespace cig {

constexpr int kErrorBins = 9;
constexpr Rgb8 kIdDiffersColour{255, 0, 255};
constexpr Rgb8 kReviewBackground{24, 24, 32};  // canvas around the panels (not a scale colour)
constexpr Rgb8 kReviewText{230, 230, 230};

int error_bin(int error);              // 0..kErrorBins-1 for an error 0..255 (clamped)
int error_bin_floor(int bin);          // the bin's lower bound: 0, 1, 2, 4, ..., 128
std::string error_bin_label(int bin);  // "0", "1", ..., "64", "128+"
Rgb8 error_bin_colour(int bin);        // the scale's colour of a bin
Rgb8 error_colour(int error);          // error_bin_colour(error_bin(error))
int pixel_error(const Image& got, const Image& reference, int x, int y);  // max over R, G, B

// The heat-map panel alone: every pixel the colour of its error, or magenta where the ids differ
// (ids may be null: no id mark). Images and id buffers of one size; std::runtime_error otherwise.
Image error_heat_map(const Image& got, const Image& reference, const IdBuffer* got_ids, const IdBuffer* reference_ids);

// Where everything lies in a review image of panels w x h. Text is drawn at `text_scale` pixels
// per glyph dot (2 from 256-pixel panels up, else 1); margins and gaps scale with it.
struct ReviewLayout {
  int text_scale = 1;
  int width = 0, height = 0;
  int title_y = 0;  // the caption line; the panel names one line below it
  int names_y = 0;
  int panel_y = 0;             // top row of the three panels
  int panel_x[3] = {0, 0, 0};  // engine, reference, error map
  int scale_y = 0;             // top of the scale's boxes
  int box_width = 0, box_height = 0;
  int labels_y = 0;        // top of the tick labels under the boxes
  int box_x(int k) const;  // bins 0..kErrorBins-1, then kErrorBins = the id-differs box
};
ReviewLayout review_layout(int panel_width, int panel_height);

struct ReviewLabels {
  std::string engine, reference;  // the first two panels' names
  std::string caption;            // one line above the names (the comparison's numbers)
};

// engine | reference | error map, the titles and the scale (docs/review_outputs.md).
Image review_image(const RasterImage& got, const RasterImage& reference, const ReviewLabels& labels);

}  // namespace cig
