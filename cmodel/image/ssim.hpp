// Structural similarity (SSIM) of two 8-bit RGB images: Wang, Bovik, Sheikh, Simoncelli 2004,
// "Image quality assessment: from error visibility to structural similarity" (IEEE TIP 13(4)).
// The paper's standard form: eq. 13 with C1 = (K1 L)^2, C2 = (K2 L)^2 (eq. 7, 9), K1 = 0.01,
// K2 = 0.03, L = 255; local statistics under an 11 x 11 Gaussian window of sigma 1.5 normalised to
// unit sum (eq. 14-16, sec. III-B); the mean over the window positions wholly inside the image
// (MSSIM, eq. 17), per colour channel, then the mean of R, G and B. The same definition as
// scikit-image's structural_similarity(gaussian_weights=True, sigma=1.5,
// use_sample_covariance=False, data_range=255, channel_axis=2) (verif/ssim/check_ssim.py).
// Cost linear in pixels: the window is separable, filtered by rows then by columns.
#pragma once

#include <array>

#include "image/image.hpp"

namespace cig {

constexpr int kSsimWindow = 11;  // pixels a side

// SSIM is defined for images of at least kSsimWindow x kSsimWindow (one window position).
inline bool ssim_defined(int width, int height) { return width >= kSsimWindow && height >= kSsimWindow; }

// MSSIM of R, G and B. Throws std::invalid_argument when the images differ in size or are smaller
// than the window (as scikit-image does): there is no window position to average over.
std::array<double, 3> ssim_channels(const Image& a, const Image& b);
// Their mean: 1 exactly for identical images, in [-1, 1] otherwise.
double ssim(const Image& a, const Image& b);

}  // namespace cig
