// Fixed tanh-sinh (double-exponential) rule on [0, 1]. It converges exponentially despite the
// endpoint behaviour of the radial integrands: (rho - eps) ln|rho - eps| at the ring k = 1 and
// (1 - rho^2)^n at the rim for fractional n (physics.md §2 "Numerics"). Each node carries its
// distance to both ends so that callers can form 1 - k^2 and 1 - rho^2 without cancellation.
// Step 1/6 with weights kept down to 1e-15 gives ~1e-12 relative on the ring integrals
// (measured against 25-digit adaptive quadrature for eps in [1e-4, 1e2], n in {0, .1, .5, 1.7}).
#pragma once

#include <cmath>
#include <vector>

namespace frictionid::model {

struct QuadratureNode {
  double from_left;   // t
  double from_right;  // 1 - t, to full relative precision
  double weight;
};

inline std::vector<QuadratureNode> make_tanh_sinh_rule(double step, double min_weight) {
  std::vector<QuadratureNode> nodes;
  const double half_pi = 0.5 * M_PI;
  for (int i = -static_cast<int>(6.0 / step); i <= static_cast<int>(6.0 / step); ++i) {
    const double s = i * step;
    const double u = half_pi * std::sinh(s);
    const double w = 0.5 * step * half_pi * std::cosh(s) / (std::cosh(u) * std::cosh(u));
    const double left = 1.0 / (1.0 + std::exp(-2.0 * u));
    const double right = 1.0 / (1.0 + std::exp(2.0 * u));
    if (w < min_weight || left <= 0.0 || right <= 0.0) continue;
    nodes.push_back({left, right, w});
  }
  return nodes;
}

// The rule used by the exact model's radial integrals.
inline const std::vector<QuadratureNode>& radial_rule() {
  static const std::vector<QuadratureNode> rule = make_tanh_sinh_rule(1.0 / 6.0, 1e-15);
  return rule;
}

// A finer rule for one-off integrals (pressure-law moments, tables): ~1e-15.
inline const std::vector<QuadratureNode>& fine_rule() {
  static const std::vector<QuadratureNode> rule = make_tanh_sinh_rule(1.0 / 16.0, 1e-18);
  return rule;
}

}  // namespace frictionid::model
