// Image error of an engine against a reference: PSNR, SSIM (image/ssim.hpp), maximum absolute error
// per colour channel, pixels off by more than 2 LSB, and a difference image.
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
  // SSIM summed over the images that have one: those of at least the 11 x 11 window. A smaller
  // image has none (ssim_images 0), and its other figures stand.
  double ssim_sum = 0;
  long ssim_images = 0;
  double mse() const { return pixels ? sum_squared / (3.0 * double(pixels)) : 0; }
  double psnr() const;  // dB; 99 for identical images
  bool has_ssim() const { return ssim_images > 0; }
  double ssim() const;            // the mean over images; NaN when none has one
  void add(const ImageError& e);  // accumulate (for a PSNR over many images, a mean SSIM)
};

ImageError compare_images(const Image& got, const Image& reference);
ImageError compare_images(const Image& got, const Image& reference, const IdBuffer& got_ids,
                          const IdBuffer& reference_ids);
// |got - reference| per channel, times `gain`, saturated: errors made visible.
Image difference_image(const Image& got, const Image& reference, int gain);
// Pixels whose id differs.
long differing_ids(const IdBuffer& got, const IdBuffer& reference);
// Of those, the pixels at an edge in neither image (an edge pixel has a neighbour, of its 8,
// showing another id in the same image): where the engine shows another surface than the
// reference away from any boundary, which visibility by a wrong priority order does, and coverage
// of partly covered pixels or of a feature thinner than a pixel (an edge in one image) does not.
long differing_ids_off_edges(const IdBuffer& got, const IdBuffer& reference);

// What of an engine's error against a z-buffered reference comes from the engines' visibility by
// priority order, found with the same reference rendered with visibility by priority (`priority`):
//  * ids_priority_vs_depth: pixels whose id differs between engine and reference, and between
//    the priority reference and the reference (the engine followed the list where it disagrees
//    with depth);
//  * pixels_priority_colour, sum_squared_priority_colour: pixels where engine and reference show
//    the same polygon but the priority reference's colour differs from the reference's by more
//    than 2 LSB (a light point that list order shows and the z-buffer hides, or the reverse; a
//    polygon owning a minority of the pixel's samples), and the engine's squared error there.
struct PriorityAttribution {
  long ids_priority_vs_depth = 0;
  long pixels_priority_colour = 0;
  double sum_squared_priority_colour = 0;
  void add(const PriorityAttribution& a);
};
PriorityAttribution attribute_priority(const Image& got, const IdBuffer& got_ids, const Image& reference,
                                       const IdBuffer& reference_ids, const Image& priority,
                                       const IdBuffer& priority_ids);

}  // namespace cig
