// Brute-force maximum likelihood of a two-term noise model, to check noise_model.cpp against:
//
//   affine    sigma_i^2 = s_abs^2 + (s_rel y_i)^2
//   additive  sigma_i   = s_abs + s_rel |y_i|
//
// -2 ln L = sum ln sigma_i^2 + e_i^2/sigma_i^2 (docs/physics.md (8.10)) is minimised by a grid
// over (ln s_abs, ln s_rel) with nested golden-section searches in its best cells, and the two
// one-term bounds (s_rel = 0, s_abs = 0) in closed form. Thousands of passes over the rows:
// slow, simple, and independent of the estimator's method.
//
// The box: at any maximum, scaling both terms by the same factor gains nothing, so
// mean(e^2/sigma^2) = 1; as sigma_i >= s_abs and sigma_i >= s_rel |y_i|, s_abs <= RMS(e) and
// s_rel <= RMS(e/y). The grid spans 14 units of ln (a factor 1.2e6) below each; anything smaller
// is the bound within rounding.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace frictionid::test {

enum class TwoTerm { Affine, Additive };

struct BruteForceMaximum {
  double s_abs = 0.0, s_rel = 0.0;
  double neg2_loglik = std::numeric_limits<double>::infinity();
};

inline double two_term_neg2_loglik(TwoTerm form, double s_abs, double s_rel,
                                   const std::vector<double>& y, const std::vector<double>& e) {
  double sum = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double sd =
        form == TwoTerm::Affine ? std::hypot(s_abs, s_rel * y[i]) : s_abs + s_rel * std::fabs(y[i]);
    const double v = sd * sd;
    if (!(v > 0.0)) return std::numeric_limits<double>::infinity();
    sum += std::log(v) + e[i] * e[i] / v;
  }
  return sum;
}

// The minimum of f on [lo, hi] by golden section (f unimodal there); returns its argument.
template <class F>
double golden_section_minimum(F f, double lo, double hi, int iterations = 60) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < iterations; ++it) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = f(x2);
    }
  }
  return f1 <= f2 ? x1 : x2;
}

inline BruteForceMaximum brute_force_maximum(TwoTerm form, const std::vector<double>& y,
                                             const std::vector<double>& e) {
  const double n = static_cast<double>(y.size());
  double e2 = 0.0, r2 = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    e2 += e[i] * e[i];
    r2 += y[i] != 0.0 ? (e[i] / y[i]) * (e[i] / y[i]) : 0.0;
  }
  const auto nll = [&](double la, double lr) {
    return two_term_neg2_loglik(form, std::exp(la), std::exp(lr), y, e);
  };
  BruteForceMaximum best;
  const auto consider = [&](double s_abs, double s_rel, double value) {
    if (value < best.neg2_loglik) best = {s_abs, s_rel, value};
  };
  // The bounds: constant (s_rel = 0) and proportional (s_abs = 0) maximum likelihood.
  consider(std::sqrt(e2 / n), 0.0, two_term_neg2_loglik(form, std::sqrt(e2 / n), 0.0, y, e));
  consider(0.0, std::sqrt(r2 / n), two_term_neg2_loglik(form, 0.0, std::sqrt(r2 / n), y, e));
  if (!(e2 > 0.0 && r2 > 0.0)) return best;

  const double top_a = 0.5 * std::log(e2 / n) + 0.1, top_r = 0.5 * std::log(r2 / n) + 0.1;
  constexpr int kCells = 60;
  constexpr double kSpan = 14.0, kStep = kSpan / kCells;
  // For a given ln s_rel, the best ln s_abs: a scan of the whole range, then golden section
  // in the best cell and its neighbours.
  const auto inner = [&](double lr) {
    int best_k = 0;
    double b = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= kCells; ++k) {
      const double v = nll(top_a - k * kStep, lr);
      if (v < b) {
        b = v;
        best_k = k;
      }
    }
    const double c = top_a - best_k * kStep;
    return golden_section_minimum([&](double la) { return nll(la, lr); }, c - kStep, c + kStep);
  };
  // The profile over ln s_rel on the grid (a coarse joint grid misses the narrow valley of a
  // large sample), then golden section around its best point.
  int best_j = 0;
  double best_profile = std::numeric_limits<double>::infinity();
  for (int j = 0; j <= kCells; ++j) {
    const double l = top_r - j * kStep, v = nll(inner(l), l);
    if (v < best_profile) {
      best_profile = v;
      best_j = j;
    }
  }
  const double cr = top_r - best_j * kStep;
  const double lr = golden_section_minimum([&](double l) { return nll(inner(l), l); }, cr - kStep,
                                           cr + kStep, 40);
  const double la = inner(lr);
  consider(std::exp(la), std::exp(lr), nll(la, lr));
  return best;
}

}  // namespace frictionid::test
