// Small independent numerical helpers shared by the model tests. Nothing here uses src/model:
// Gauss–Legendre rules in long double (Newton on the three-term recurrence), the moments of the
// power laws from the Beta function, and central differences.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

namespace frictionid::testing {

constexpr double kPi = 3.14159265358979323846;
constexpr long double kPiL = 3.14159265358979323846264338327950288L;

struct GaussRule {
  std::vector<long double> x, w;  // nodes and weights on [-1, 1]
};

// n-point Gauss–Legendre rule on [-1, 1], nodes by Newton's method on P_n in long double.
inline const GaussRule& gauss_legendre(int n) {
  static std::map<int, GaussRule> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  GaussRule r;
  r.x.resize(n);
  r.w.resize(n);
  for (int i = 0; i < n; ++i) {
    long double x = std::cos(kPiL * (i + 0.75L) / (n + 0.5L));
    long double dp = 0;
    for (int it2 = 0; it2 < 100; ++it2) {
      long double p0 = 1, p1 = x;
      for (int j = 2; j <= n; ++j) {
        const long double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const long double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-19L) break;
    }
    // Recompute the derivative at the converged node for the weight.
    long double p0 = 1, p1 = x;
    for (int j = 2; j <= n; ++j) {
      const long double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - p0) / (x * x - 1);
    r.x[i] = x;
    r.w[i] = 2 / ((1 - x * x) * dp * dp);
  }
  return cache.emplace(n, std::move(r)).first->second;
}

// Moment m_k = ∫_0^1 (1 - rho^2)^n rho^k drho = B((k+1)/2, n+1)/2 (substitute s = rho^2).
inline double beta_moment(double n, int k) {
  const double a = 0.5 * (k + 1), b = n + 1.0;
  return 0.5 * std::exp(std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
}

// sigma0 = (1 - rho^2)^n for the reference integrator (n = 0 gives 1 everywhere).
inline std::function<double(double)> power_sigma0(double n) {
  if (n == 0.0) return [](double) { return 1.0; };
  return [n](double rho) { return std::pow(std::max(0.0, (1.0 - rho) * (1.0 + rho)), n); };
}

// Fourth-order central difference of g at x with step h.
inline double central_difference(const std::function<double(double)>& g, double x, double h) {
  return (8.0 * (g(x + h) - g(x - h)) - (g(x + 2 * h) - g(x - 2 * h))) / (12.0 * h);
}

}  // namespace frictionid::testing
