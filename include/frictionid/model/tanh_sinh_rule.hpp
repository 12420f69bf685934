// Fixed tanh-sinh (double-exponential) rule on [0, 1]. It converges exponentially despite the
// endpoint behaviour of the radial integrands: (rho - eps) ln|rho - eps| at the ring k = 1 and
// (1 - rho^2)^n at the rim for fractional n (docs/physics.md §2 "Numerics"). Each node carries its
// distance to both ends so that callers can form 1 - k^2 and 1 - rho^2 without cancellation.
// Step 1/8 with weights kept down to 1e-15 (51 nodes) keeps every ring integral within ~1e-10
// relative: worst 6e-11 for n <= 1.7 and 1.1e-10 for power:8, both near eps = 2e-5, where the
// kernels' scale-eps structure sits next to the left end of [eps, 1]; measured against a
// geometrically split step-1/20 rule for eps in [1e-12, 0.5]. Step 1/6 (37 nodes) reaches only
// ~2e-9 there and ~1e-9 for steep laws (n >= 6).
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
  static const std::vector<QuadratureNode> rule = make_tanh_sinh_rule(1.0 / 8.0, 1e-15);
  return rule;
}

// A coarse rule for searches that only rank candidates (the global stage): step 1/4, 23 nodes,
// ~6e-5 relative, 2.2x cheaper than radial_rule().
inline const std::vector<QuadratureNode>& coarse_rule() {
  static const std::vector<QuadratureNode> rule = make_tanh_sinh_rule(1.0 / 4.0, 1e-12);
  return rule;
}

// A finer rule for one-off integrals (pressure-law moments, tables): ~1e-15.
inline const std::vector<QuadratureNode>& fine_rule() {
  static const std::vector<QuadratureNode> rule = make_tanh_sinh_rule(1.0 / 16.0, 1e-18);
  return rule;
}

}  // namespace frictionid::model
