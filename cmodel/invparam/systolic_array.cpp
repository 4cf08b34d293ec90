#include "invparam/systolic_array.hpp"

#include <algorithm>

namespace cig::invparam {

std::int64_t chain_codes(int m, std::int64_t n) { return 4 * ((std::int64_t(m) + 1) * n + 1); }

std::int64_t seed_frame_clocks(int m, std::int64_t n, int n_pp, int columns) {
  const std::int64_t nk = chain_codes(m, n);
  return padded_chain_codes(nk, n_pp) * (columns - 1) + nk + n_pp + 3;
}

std::int64_t covered_columns_clocks(const std::vector<std::int64_t>& nk, int n_pp) {
  std::int64_t t = 4 + nk.front() + n_pp - 1;
  for (std::size_t i = 1; i < nk.size(); ++i) t += padded_chain_codes(nk[i], n_pp);
  return t;
}

double covered_columns_clocks_mean(int m, double n, double width, int n_pp, int columns) {
  const double per_column = n * std::min(width, double(columns)) / columns;
  const double nk = 4 * ((m + 1) * per_column + 1);
  const double pad = 4.0 * ((n_pp + 3) / 4);
  return 4 + (columns - 1) * std::max(nk, pad) + nk + n_pp - 1;
}

Throughput invparam_throughput(int m, double n, double width, int n_pp, int columns, double t_t_seconds) {
  Throughput r;
  const double nk = 4 * ((m + 1) * n + 1);
  const double pad = 4.0 * ((n_pp + 3) / 4);
  r.full_clocks = std::max(nk, pad) * (columns - 1) + nk + n_pp + 3;  // the seed's formula, n real
  r.full_seconds = r.full_clocks * t_t_seconds;
  r.full_faces_per_s = m * n / r.full_seconds;
  r.covered_clocks = covered_columns_clocks_mean(m, n, width, n_pp, columns);
  r.covered_seconds = r.covered_clocks * t_t_seconds;
  r.covered_faces_per_s = m * n / r.covered_seconds;
  r.covered_limit_faces_per_s = m / (4.0 * (m + 1) * std::min(width, double(columns)) * t_t_seconds);
  return r;
}

}  // namespace cig::invparam
