// Radial integrals of the ring kernels weighted by the static pressure (physics.md §2):
//   I_P = ∫ sigma0 rho P,  I_Q = ∫ sigma0 rho^2 Q,  I_S = ∫ sigma0 rho^2 S,
//   I_U = ∫ sigma0 rho^3 U, I_V = ∫ sigma0 rho^3 V, I_X = ∫ sigma0 rho^3 X,  argument eps/rho.
// The radial range is split at rho = eps (the ring through the instantaneous centre, where the
// kernels' derivatives carry (1-k^2) ln|1-k|) and each piece gets the tanh-sinh rule. Kernel
// values depend on eps only, so they are computed in double and weighted by sigma0 of type T.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/pressure_law.hpp"
#include "model/ring_kernels.hpp"
#include "model/tanh_sinh_rule.hpp"

namespace frictionid::model {

template <typename T>
struct RingIntegrals {
  T P, Q, S, U, V, X;
};

namespace detail {
template <typename T>
void accumulate(RingIntegrals<T>& acc, const RingKernels<double>& k, double w, double rho,
                const T& sigma) {
  const double r2 = rho * rho, r3 = r2 * rho;
  const T ws = sigma * w;
  acc.P += ws * (rho * k.P);
  acc.Q += ws * (r2 * k.Q);
  acc.S += ws * (r2 * k.S);
  acc.U += ws * (r3 * k.U);
  acc.V += ws * (r3 * k.V);
  acc.X += ws * (r3 * k.X);
}
constexpr double kMinM1 = 1e-300;  // keeps K finite on the ring k = 1 itself
}  // namespace detail

// The six integrals for any radial weight w(rho, 1 - rho) (the pressure law, or its derivative
// with respect to a shape parameter) on a given rule; eps in [0, inf). Kernels are evaluated
// once per node in double, only the weight carries the scalar type.
template <typename T, typename Weight>
RingIntegrals<T> weighted_ring_integrals(const Weight& weight, double eps,
                                         const std::vector<QuadratureNode>& rule) {
  RingIntegrals<T> acc{T(0), T(0), T(0), T(0), T(0), T(0)};
  // Inner piece rho in [0, L], L = min(eps, 1): k = eps/rho >= 1, kernels in q = rho/eps.
  if (eps > 0.0) {
    const double len = std::min(eps, 1.0);
    for (const auto& node : rule) {
      const double rho = len * node.from_left;
      const double q = rho / eps;
      const double one_minus_q = ((eps - len) + len * node.from_right) / eps;
      const double m1 = std::max(one_minus_q * (1.0 + q), detail::kMinM1);
      const RingKernels<double> k = ring_kernels_outside(q, q * q, m1);
      detail::accumulate(acc, k, node.weight * len, rho,
                         weight(rho, (1.0 - len) + len * node.from_right));
    }
  }
  // Outer piece rho in [eps, 1]: k = eps/rho <= 1.
  if (eps < 1.0) {
    const double len = 1.0 - eps;
    for (const auto& node : rule) {
      const double rho = eps + len * node.from_left;
      const double k = eps / rho;
      const double above = len * node.from_left;  // rho - eps
      const double m1 = std::max(above * (rho + eps) / (rho * rho), detail::kMinM1);
      const RingKernels<double> kern = ring_kernels_inside(k, k * k, m1);
      detail::accumulate(acc, kern, node.weight * len, rho, weight(rho, len * node.from_right));
    }
  }
  return acc;
}

// Pure sliding (eps = inf): every kernel tends to its limit and each integral is a moment.
template <typename T>
RingIntegrals<T> sliding_ring_integrals(const LawMoments<T>& moments) {
  RingIntegrals<T> acc{T(0), T(0), T(0), T(0), T(0), T(0)};
  acc.P = T(2 * M_PI) * moments[1];
  acc.V = T(M_PI) * moments[3];
  acc.X = acc.V;
  return acc;
}

// eps in [0, inf]. moments are needed only for eps = inf (pure sliding).
template <typename T>
RingIntegrals<T> ring_integrals(const PressureLaw<T>& law, const LawMoments<T>& moments, double eps,
                                const std::vector<QuadratureNode>& rule = radial_rule()) {
  if (!(eps < HUGE_VAL)) return sliding_ring_integrals(moments);
  return weighted_ring_integrals<T>(law, eps, rule);
}

}  // namespace frictionid::model
