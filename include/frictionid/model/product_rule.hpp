// Product integration (docs/physics.md §9.3): ∫ w(s) F(s) ds over a part [s0, s1], for a
// weight w that is a polynomial of low degree on each of many pieces (a table law, which kinks
// at every sample) and an F analytic across the pieces. F is taken at n Chebyshev points and its
// interpolant p = sum_{j<n} a_j T_j(x) (x the coordinate of s in [-1, 1]) integrated against w
// exactly: sum_j a_j mu_j with the moments mu_j = ∫ w T_j(x) ds. That is a weight per point,
//   W_i = (2/n) sum'_j mu_j T_j(x_i),   x_i = cos(pi (2i + 1)/(2n))   (sum': j = 0 halved),
// and the integral is sum_i W_i F(s_i). n readings of F a part, however many pieces the part
// holds, where Gauss–Legendre between the pieces' ends takes 4-7 a piece.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>

namespace frictionid::model {

// sum_k c_k (s - a)^k on [a, b).
struct PolynomialPiece {
  double a, b;
  std::array<double, 5> c;
  double operator()(double s) const {
    const double u = s - a;
    return c[0] + u * (c[1] + u * (c[2] + u * (c[3] + u * c[4])));
  }
};

inline constexpr int kMostProductPoints = 48;

// The Chebyshev points for an F analytic within the Bernstein ellipse of parameter rho: the
// interpolant errs by ~rho^-n, and a polynomial factor of `degrees` takes as many more.
inline int product_points(double rho, double log_tolerance, int degrees) {
  if (!(rho > 1.0)) return kMostProductPoints;
  const double n = std::ceil(log_tolerance / std::log(rho)) + degrees;
  return n < kMostProductPoints ? std::max(8, static_cast<int>(n)) : kMostProductPoints;
}

// The moments mu_j, j < n, over [s0, s1] of the weight the pieces (sorted, disjoint) make, each a
// polynomial of at most `degree`: Gauss–Legendre on each piece within, exact for w T_j.
inline void chebyshev_moments(const std::vector<PolynomialPiece>& pieces, double s0, double s1,
                              int n, int degree, double* mu) {
  std::fill(mu, mu + n, 0.0);
  const std::vector<QuadratureNode>& rule = gauss_legendre_rule((n + degree + 1) / 2);
  const double mid = 0.5 * (s0 + s1), inv_half = 2.0 / (s1 - s0);
  auto k = std::upper_bound(pieces.begin(), pieces.end(), s0,
                            [](double s, const PolynomialPiece& p) { return s < p.b; });
  for (; k != pieces.end() && k->a < s1; ++k) {
    const double lo = std::max(k->a, s0), hi = std::min(k->b, s1), len = hi - lo;
    if (!(len > 0.0)) continue;
    for (const QuadratureNode& g : rule) {
      const double s = lo + len * g.from_left, w = g.weight * len * (*k)(s);
      const double x = (s - mid) * inv_half;
      double t0 = 1.0, t1 = x;
      mu[0] += w;
      mu[1] += w * x;
      for (int j = 2; j < n; ++j) {
        const double t2 = 2.0 * x * t1 - t0;
        mu[j] += w * t2;
        t0 = t1;
        t1 = t2;
      }
    }
  }
}

// The points x_i in [-1, 1] and their weights W_i from the moments (above), i < n.
inline void product_weights(const double* mu, int n, double* x, double* W) {
  for (int i = 0; i < n; ++i) {
    x[i] = std::cos(M_PI * (2 * i + 1) / (2.0 * n));
    double t0 = 1.0, t1 = x[i], sum = 0.5 * mu[0] + mu[1] * x[i];
    for (int j = 2; j < n; ++j) {
      const double t2 = 2.0 * x[i] * t1 - t0;
      sum += mu[j] * t2;
      t0 = t1;
      t1 = t2;
    }
    W[i] = 2.0 / n * sum;
  }
}

}  // namespace frictionid::model
