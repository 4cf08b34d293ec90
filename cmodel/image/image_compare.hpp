// Image error of an engine against a reference: PSNR, maximum absolute error per colour channel,
// pixels off by more than 2 LSB, and a difference image.
#pragma once

#include <cstdint>

#include "image/image.hpp"

namespace cig {

struct ImageError {
  long pixels = 0;
  double sum_squared = 0;  // over all pixels and colour channels
  int max_abs[3] = {0, 0, 0};
  long pixels_over_2lsb = 0;  // pixels with some channel off by more than 2
  // Attribution, when id buffers are given: the squared error of pixels whose visible polygon
  // differs (visibility, coverage) against the rest (shading, fog, quantization).
  double sum_squared_ids_differ = 0;
  long pixels_ids_differ = 0;
  double mse() const { return pixels ? sum_squared / (3.0 * double(pixels)) : 0; }
  double psnr() const;  // dB; 99 for identical images
  void add(const ImageError& e);  // accumulate (for a PSNR over many images)
};

ImageError compare_images(const Image& got, const Image& reference);
ImageError compare_images(const Image& got, const Image& reference, const IdBuffer& got_ids,
                          const IdBuffer& reference_ids);
// |got - reference| per channel, times `gain`, saturated: errors made visible.
Image difference_image(const Image& got, const Image& reference, int gain);
// Pixels whose id differs.
long differing_ids(const IdBuffer& got, const IdBuffer& reference);

}  // namespace cig
