#include "image/ssim.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace cig {

namespace {

constexpr int kRadius = kSsimWindow / 2;
constexpr double kSigma = 1.5, kK1 = 0.01, kK2 = 0.03, kL = 255.0;
constexpr double kC1 = (kK1 * kL) * (kK1 * kL), kC2 = (kK2 * kL) * (kK2 * kL);  // eq. 7, 9

using Weights = std::array<double, kSsimWindow>;

// One dimension of the window: exp(-k^2 / (2 sigma^2)), k = -5..5, over its sum. The 11 x 11
// window of sec. III-B is the product of two, so it sums to 1 as eq. 14-16 need.
Weights gaussian_weights() {
  Weights w;
  double sum = 0;
  for (int k = -kRadius; k <= kRadius; ++k)
    sum += w[std::size_t(k + kRadius)] = std::exp(-0.5 * k * k / (kSigma * kSigma));
  for (double& v : w) v /= sum;
  return w;
}

// The weighted sums of x, y, x^2, y^2 and xy at each window position of a row (or their sums over
// a column of such rows): the moments eq. 14-16 are made of.
struct Moments {
  std::vector<double> x, y, xx, yy, xy;
  explicit Moments(std::size_t n) : x(n), y(n), xx(n), yy(n), xy(n) {}
  void clear() {
    for (std::vector<double>* v : {&x, &y, &xx, &yy, &xy}) std::fill(v->begin(), v->end(), 0.0);
  }
};

// Row `row` of colour channel `c` filtered along x, at the columns whose window lies inside, tap by
// tap (each sum in tap order). The row's x, y, x^2, y^2, xy go to the workspace `in` first (exact:
// integers up to 255^2).
void filter_row(const Image& a, const Image& b, int c, int row, const Weights& w, Moments& in, Moments& out) {
  const std::uint8_t* pa = a.at(0, row) + c;
  const std::uint8_t* pb = b.at(0, row) + c;
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    const double x = pa[3 * i], y = pb[3 * i];
    in.x[i] = x, in.y[i] = y, in.xx[i] = x * x, in.yy[i] = y * y, in.xy[i] = x * y;
  }
  const std::size_t n = out.x.size();
  out.clear();
  for (std::size_t k = 0; k < std::size_t(kSsimWindow); ++k)
    for (std::size_t i = 0; i < n; ++i) {
      out.x[i] += w[k] * in.x[i + k];
      out.y[i] += w[k] * in.y[i + k];
      out.xx[i] += w[k] * in.xx[i + k];
      out.yy[i] += w[k] * in.yy[i + k];
      out.xy[i] += w[k] * in.xy[i + k];
    }
}

// acc += wk * row, moment by moment (the filter along y).
void accumulate(Moments& acc, const Moments& row, double wk) {
  for (std::size_t i = 0; i < acc.x.size(); ++i) {
    acc.x[i] += wk * row.x[i];
    acc.y[i] += wk * row.y[i];
    acc.xx[i] += wk * row.xx[i];
    acc.yy[i] += wk * row.yy[i];
    acc.xy[i] += wk * row.xy[i];
  }
}

// Eq. 13 at every window position of one output row, summed. The variances and covariance are
// E[x^2] - E[x]^2 and E[xy] - E[x]E[y], equal to eq. 15-16 since the weights sum to 1.
double ssim_row_sum(const Moments& m) {
  double sum = 0;
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    const double ux = m.x[i], uy = m.y[i];
    const double vx = m.xx[i] - ux * ux, vy = m.yy[i] - uy * uy, vxy = m.xy[i] - ux * uy;
    const double a1 = 2 * ux * uy + kC1, a2 = 2 * vxy + kC2;
    const double b1 = ux * ux + uy * uy + kC1, b2 = vx + vy + kC2;
    sum += (a1 * a2) / (b1 * b2);
  }
  return sum;
}

// MSSIM of colour channel c (eq. 17). Rows filtered along x wait in a ring of kSsimWindow rows;
// each output row sums them along y. Memory is 11 rows, work 2 x 11 taps x 5 moments a pixel.
double channel_ssim(const Image& a, const Image& b, int c, const Weights& w) {
  const std::size_t cols = std::size_t(a.width - 2 * kRadius);
  const int rows = a.height - 2 * kRadius;
  std::vector<Moments> ring(kSsimWindow, Moments(cols));
  Moments pixels(std::size_t(a.width)), acc(cols);
  double total = 0;  // of per-row sums: the rounding error grows with rows + columns, not pixels
  for (int y = 0; y < a.height; ++y) {
    filter_row(a, b, c, y, w, pixels, ring[std::size_t(y % kSsimWindow)]);
    if (y < kSsimWindow - 1) continue;
    acc.clear();
    for (int k = 0; k < kSsimWindow; ++k)
      accumulate(acc, ring[std::size_t((y - kSsimWindow + 1 + k) % kSsimWindow)], w[std::size_t(k)]);
    total += ssim_row_sum(acc);
  }
  return total / (double(cols) * double(rows));
}

}  // namespace

std::array<double, 3> ssim_channels(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("ssim: images differ in size");
  if (!ssim_defined(a.width, a.height))
    throw std::invalid_argument("ssim: a " + std::to_string(a.width) + " x " + std::to_string(a.height) +
                                " image is smaller than the " + std::to_string(kSsimWindow) + " x " +
                                std::to_string(kSsimWindow) + " window");
  const Weights w = gaussian_weights();
  return {channel_ssim(a, b, 0, w), channel_ssim(a, b, 1, w), channel_ssim(a, b, 2, w)};
}

double ssim(const Image& a, const Image& b) {
  const std::array<double, 3> s = ssim_channels(a, b);
  return (s[0] + s[1] + s[2]) / 3.0;
}

}  // namespace cig
