// A 16-point Gauss–Legendre rule on [0, 1], for radial pieces on which the integrand is smooth:
// pieces between a table's samples that keep a distance of at least half their length from the
// ring rho = eps. There the nearest singularity of the kernels lies outside the Bernstein
// ellipse of parameter 2 + sqrt(3), so the error is below 3.73^-32 ~ 5e-19 relative, and a
// table's cubic pieces times rho^k are integrated exactly (degree <= 31). One sixth of the
// fine tanh-sinh rule's nodes, which matters when a table has hundreds of samples.
#pragma once

#include <cmath>
#include <vector>

#include <frictionid/model/tanh_sinh_rule.hpp>

namespace frictionid::model {

inline std::vector<QuadratureNode> make_gauss_legendre_rule(int n) {
  std::vector<QuadratureNode> nodes;
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from Tricomi's initial guess; x in (-1, 1).
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int j = 2; j <= n; ++j) {
        const double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    // t = (1 + x)/2 and 1 - t = (1 - x)/2, each to full precision near its end.
    nodes.push_back({0.5 * (1.0 + x), 0.5 * (1.0 - x), 1.0 / ((1.0 - x * x) * dp * dp)});
  }
  return nodes;
}

// Gauss–Legendre in t with u = sin^2(pi t/2) on [0, 1]: sqrt(u) and sqrt(1 - u) become sin and
// cos, so integrands with square-root (or u^(k+1/2)) ends turn analytic.
inline std::vector<QuadratureNode> make_sine_squared_rule(int points) {
  std::vector<QuadratureNode> out;
  for (const QuadratureNode& g : make_gauss_legendre_rule(points)) {
    const double a = std::sin(0.5 * M_PI * g.from_left);
    const double b = std::sin(0.5 * M_PI * g.from_right);
    out.push_back({a * a, b * b, g.weight * M_PI * a * b});
  }
  return out;
}

// The n-point rule, 1 <= n <= kMaxGaussLegendrePoints, built once.
inline constexpr int kMaxGaussLegendrePoints = 64;
inline const std::vector<QuadratureNode>& gauss_legendre_rule(int n) {
  static const std::vector<std::vector<QuadratureNode>> rules = [] {
    std::vector<std::vector<QuadratureNode>> r(kMaxGaussLegendrePoints + 1);
    for (int k = 1; k <= kMaxGaussLegendrePoints; ++k)
      r[static_cast<std::size_t>(k)] = make_gauss_legendre_rule(k);
    return r;
  }();
  return rules[static_cast<std::size_t>(n)];
}

// The parameter rho = z + sqrt(z^2 - 1) of the Bernstein ellipse (foci at the ends of the
// interval, scaled to [-1, 1]) whose semi-major axis is z >= 1: the one through a point z
// half-lengths from the interval's middle along its line, or with z the half sum of the
// distances from a point to the two ends.
inline double bernstein_parameter(double z) {
  return z + std::sqrt((z - 1.0) * (z + 1.0));
}

// The same through the point (x, y), in half-lengths from the interval's middle: z is the half
// sum of its distances from the ends.
inline double bernstein_parameter_through(double x, double y) {
  return bernstein_parameter(0.5 * (std::hypot(x - 1.0, y) + std::hypot(x + 1.0, y)));
}

// The points n at which an integrand analytic inside the Bernstein ellipse of parameter rho,
// times a polynomial of `degrees`, errs by ~rho^-(2n - degrees) < exp(-log_tolerance) (not
// rounded to a whole number or clamped).
inline double gauss_legendre_points(double rho, double log_tolerance, int degrees) {
  return 0.5 * (log_tolerance / std::log(rho) + degrees);
}

inline const std::vector<QuadratureNode>& smooth_piece_rule() {
  static const std::vector<QuadratureNode> rule = make_gauss_legendre_rule(16);
  return rule;
}

// 8 points for a piece at least twice its length from the ring rho = eps: the Bernstein ellipse
// parameter is then 5 + sqrt(24) ~ 9.9 and the error below 9.9^-16 ~ 1e-16 relative; still
// exact for a cubic piece times rho^k (degree <= 15). Most samples of a fine table are that far.
inline const std::vector<QuadratureNode>& distant_piece_rule() {
  static const std::vector<QuadratureNode> rule = make_gauss_legendre_rule(8);
  return rule;
}

// 4 points for a piece at least 16 times its length away: parameter 33 + sqrt(1088) ~ 66, error
// below 66^-8 ~ 3e-15 relative, exact for a cubic times rho^3 (degree <= 7). Nearly every piece
// of a table with thousands of samples.
inline const std::vector<QuadratureNode>& remote_piece_rule() {
  static const std::vector<QuadratureNode> rule = make_gauss_legendre_rule(4);
  return rule;
}

}  // namespace frictionid::model
