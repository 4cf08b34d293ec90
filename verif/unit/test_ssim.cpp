// SSIM (cmodel/image/ssim.hpp): exact cases, the formula at a single window position worked out
// directly from eq. 13-16, orderings, and images smaller than the window. Agreement with
// scikit-image on many pairs is verif/ssim/check_ssim.py's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/image_compare.hpp"
#include "image/ssim.hpp"

namespace cig {
namespace {

constexpr double kC1 = (0.01 * 255) * (0.01 * 255), kC2 = (0.03 * 255) * (0.03 * 255);

// A deterministic pseudo-random byte (a 32-bit LCG).
struct Bytes {
  std::uint32_t s = 12345;
  int next() { return int((s = s * 1664525u + 1013904223u) >> 24); }
};

Image random_image(int w, int h, Bytes& r) {
  Image im(w, h);
  for (auto& v : im.rgb) v = std::uint8_t(r.next());
  return im;
}

// Smooth gradients and a bright square: structure for noise to destroy.
Image pattern(int w, int h) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool square = x > w / 4 && x < 3 * w / 4 && y > h / 4 && y < 3 * h / 4;
      for (int c = 0; c < 3; ++c) im.at(x, y)[c] = std::uint8_t(square ? 230 : 20 + 3 * x + 2 * y + 40 * c);
    }
  return im;
}

// `im` plus noise uniform in [-amplitude, amplitude], clamped.
Image noisy(const Image& im, int amplitude, Bytes& r) {
  Image out = im;
  for (auto& v : out.rgb)
    v = std::uint8_t(std::clamp(int(v) + (r.next() * (2 * amplitude + 1)) / 256 - amplitude, 0, 255));
  return out;
}

TEST(Ssim, IdenticalImagesGiveExactlyOne) {
  Bytes r;
  const Image a = random_image(40, 30, r), b = a;
  EXPECT_EQ(ssim(a, b), 1.0);
  for (double s : ssim_channels(a, b)) EXPECT_EQ(s, 1.0);
  const ImageError e = compare_images(a, b);
  ASSERT_TRUE(e.has_ssim());
  EXPECT_EQ(e.ssim(), 1.0);
}

TEST(Ssim, ConstantImagesLeaveOnlyTheLuminanceTerm) {
  // No variance: eq. 13 reduces to (2 mu_x mu_y + C1) / (mu_x^2 + mu_y^2 + C1) times C2 / C2.
  Image a(24, 16), b(24, 16);
  const int va[3] = {100, 0, 255}, vb[3] = {150, 0, 128};
  for (int p = 0; p < 24 * 16; ++p)
    for (int c = 0; c < 3; ++c) {
      a.rgb[std::size_t(3 * p + c)] = std::uint8_t(va[c]);
      b.rgb[std::size_t(3 * p + c)] = std::uint8_t(vb[c]);
    }
  const std::array<double, 3> s = ssim_channels(a, b);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(s[std::size_t(c)], (2.0 * va[c] * vb[c] + kC1) / (double(va[c]) * va[c] + double(vb[c]) * vb[c] + kC1),
                1e-12);
  EXPECT_NEAR(s[1], 1.0, 1e-12);  // both black
  EXPECT_EQ(ssim(a, a), 1.0);
}

TEST(Ssim, OneWindowPositionIsEquation13WithTheGaussianWindow) {
  // 11 x 11: the only window position; mu, sigma^2 and sigma_xy by eq. 14-16 with the 2-D window
  // written out, the variances about the mean (not E[x^2] - mu^2 as the implementation has them).
  Bytes r;
  const Image a = random_image(11, 11, r), b = noisy(a, 60, r);
  double w[11][11], sum = 0;
  for (int i = 0; i < 11; ++i)
    for (int j = 0; j < 11; ++j) sum += w[i][j] = std::exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / (2 * 1.5 * 1.5));
  const std::array<double, 3> s = ssim_channels(a, b);
  for (int c = 0; c < 3; ++c) {
    double mx = 0, my = 0, vx = 0, vy = 0, cxy = 0;
    for (int y = 0; y < 11; ++y)
      for (int x = 0; x < 11; ++x) mx += w[y][x] / sum * a.at(x, y)[c], my += w[y][x] / sum * b.at(x, y)[c];
    for (int y = 0; y < 11; ++y)
      for (int x = 0; x < 11; ++x) {
        const double dx = a.at(x, y)[c] - mx, dy = b.at(x, y)[c] - my, wk = w[y][x] / sum;
        vx += wk * dx * dx, vy += wk * dy * dy, cxy += wk * dx * dy;
      }
    const double want = (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
    EXPECT_NEAR(s[std::size_t(c)], want, 1e-12) << "channel " << c;
  }
}

TEST(Ssim, MoreNoiseLowersItAndItIsSymmetric) {
  Bytes r;
  const Image a = pattern(64, 48);
  double last = 1.0;
  for (int amplitude : {2, 8, 32, 96}) {
    const Image b = noisy(a, amplitude, r);
    const double s = ssim(a, b);
    EXPECT_LT(s, last) << "amplitude " << amplitude;
    EXPECT_GT(s, -1.0);
    EXPECT_EQ(s, ssim(b, a));
    last = s;
  }
}

TEST(Ssim, AnImageAgainstItsNegativeIsBelowZero) {
  const Image a = pattern(32, 32);
  Image b = a;
  for (auto& v : b.rgb) v = std::uint8_t(255 - v);
  EXPECT_LT(ssim(a, b), 0.0);
}

TEST(Ssim, ImagesSmallerThanTheWindowHaveNone) {
  // ssim() refuses them (no window position to average over), as scikit-image does; compare_images
  // gives their other figures and no SSIM, and a total's mean leaves them out.
  Bytes r;
  EXPECT_FALSE(ssim_defined(10, 64));
  EXPECT_FALSE(ssim_defined(64, 10));
  EXPECT_TRUE(ssim_defined(11, 11));
  EXPECT_THROW(ssim(random_image(10, 64, r), random_image(10, 64, r)), std::invalid_argument);
  EXPECT_THROW(ssim(random_image(16, 16, r), random_image(16, 17, r)), std::invalid_argument);

  const Image small_a = random_image(6, 1, r), small_b = random_image(6, 1, r);
  ImageError total = compare_images(small_a, small_b);
  EXPECT_FALSE(total.has_ssim());
  EXPECT_TRUE(std::isnan(total.ssim()));
  EXPECT_GT(total.sum_squared, 0);
  const Image a = pattern(16, 16), b = noisy(a, 20, r);
  total.add(compare_images(a, b));
  EXPECT_EQ(total.ssim_images, 1);
  EXPECT_EQ(total.ssim(), ssim(a, b));
  total.add(compare_images(a, a));
  EXPECT_DOUBLE_EQ(total.ssim(), (ssim(a, b) + 1.0) / 2);
}

}  // namespace
}  // namespace cig
