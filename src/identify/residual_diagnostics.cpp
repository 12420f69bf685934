#include "identify/residual_diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace frictionid {
namespace {

std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
  std::vector<double> r(x.size());
  for (std::size_t k = 0; k < order.size(); ++k) r[order[k]] = static_cast<double>(k);
  return r;
}

}  // namespace

double rank_correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n < 3) return 0.0;
  const std::vector<double> ra = ranks({a.begin(), a.begin() + static_cast<long>(n)});
  const std::vector<double> rb = ranks({b.begin(), b.begin() + static_cast<long>(n)});
  const double mean = 0.5 * static_cast<double>(n - 1);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (ra[i] - mean) * (rb[i] - mean);
    saa += (ra[i] - mean) * (ra[i] - mean);
    sbb += (rb[i] - mean) * (rb[i] - mean);
  }
  return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

double residual_growth(const std::vector<double>& fitted, const std::vector<double>& measured) {
  const std::size_t n = std::min(fitted.size(), measured.size());
  std::vector<double> size(n), miss(n);
  for (std::size_t i = 0; i < n; ++i) {
    size[i] = std::fabs(fitted[i]);
    miss[i] = std::fabs(fitted[i] - measured[i]);
  }
  return rank_correlation(size, miss);
}

}  // namespace frictionid
