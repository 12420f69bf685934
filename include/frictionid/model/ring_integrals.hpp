// Radial integrals of the ring kernels weighted by the static pressure (docs/physics.md §2):
//   I_P = ∫ sigma0 rho P,  I_Q = ∫ sigma0 rho^2 Q,  I_S = ∫ sigma0 rho^2 S,
//   I_U = ∫ sigma0 rho^3 U, I_V = ∫ sigma0 rho^3 V, I_X = ∫ sigma0 rho^3 X,  argument eps/rho.
// The radial range is split at rho = eps (the ring through the instantaneous centre, where the
// kernels' derivatives carry (1-k^2) ln|1-k|) and at the law's breakpoints (steps and kinks of
// sigma0, the samples of a table); pieces next to eps or the rim get the tanh-sinh rule, the rest
// Gauss–Legendre. Kernels depend on eps only: computed in double, weighted by sigma0 of type T.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <frictionid/model/gauss_legendre_rule.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/ring_kernels.hpp>
#include <frictionid/model/tanh_sinh_rule.hpp>

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

// The radial pieces of [0, 1]: split at rho = eps and at every breakpoint of the law (where
// sigma0 or a derivative jumps; a rule running across one converges only algebraically).
inline std::vector<double> radial_edges(double eps, const std::vector<double>& breakpoints) {
  std::vector<double> edges = {0.0, 1.0};
  if (eps > 0.0 && eps < 1.0) edges.push_back(eps);
  for (double b : breakpoints)
    if (b > 0.0 && b < 1.0) edges.push_back(b);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// The six integrals for any radial weight w(rho, 1 - rho) (the pressure law, or its derivative
// with respect to a shape parameter) on a given rule; eps in [0, inf). Kernels are evaluated
// once per node in double, only the weight carries the scalar type. Every piece between
// radial_edges() gets the rule; distances to eps and to the rim are formed from the piece's
// ends, so 1 - k^2 and 1 - rho^2 keep full relative precision next to both.
template <typename T, typename Weight>
RingIntegrals<T> weighted_ring_integrals(const Weight& weight, double eps,
                                         const std::vector<QuadratureNode>& rule,
                                         const std::vector<double>& breakpoints = {}) {
  RingIntegrals<T> acc{T(0), T(0), T(0), T(0), T(0), T(0)};
  const std::vector<double> edges = radial_edges(eps, breakpoints);
  for (std::size_t s = 0; s + 1 < edges.size(); ++s) {
    const double a = edges[s], b = edges[s + 1], len = b - a;
    // A piece between breakpoints, away from rho = eps and from the rim (where sigma0 may go
    // like (1 - rho^2)^gamma), is smooth: Gauss–Legendre is exact enough and far cheaper.
    const double to_singular = std::min(b <= eps ? eps - b : a - eps, 1.0 - b);
    const std::vector<QuadratureNode>& piece_rule = to_singular >= 16.0 * len ? remote_piece_rule()
                                                    : to_singular >= 2.0 * len
                                                        ? distant_piece_rule()
                                                    : to_singular >= 0.5 * len ? smooth_piece_rule()
                                                                               : rule;
    if (b <= eps) {
      // Inside the instantaneous centre: k = eps/rho >= 1, kernels in q = rho/eps.
      for (const auto& node : piece_rule) {
        const double rho = a + len * node.from_left;
        const double q = rho / eps;
        const double one_minus_q = ((eps - b) + len * node.from_right) / eps;
        const double m1 = std::max(one_minus_q * (1.0 + q), detail::kMinM1);
        const RingKernels<double> k = ring_kernels_outside(q, q * q, m1);
        detail::accumulate(acc, k, node.weight * len, rho,
                           weight(rho, (1.0 - b) + len * node.from_right));
      }
    } else {
      // Outside: k = eps/rho <= 1.
      for (const auto& node : piece_rule) {
        const double rho = a + len * node.from_left;
        const double k = eps / rho;
        const double above = (a - eps) + len * node.from_left;  // rho - eps
        const double m1 = std::max(above * (rho + eps) / (rho * rho), detail::kMinM1);
        const RingKernels<double> kern = ring_kernels_inside(k, k * k, m1);
        detail::accumulate(acc, kern, node.weight * len, rho,
                           weight(rho, (1.0 - b) + len * node.from_right));
      }
    }
  }
  return acc;
}

// The ring law sigma0 = delta(rho - 1): each integral is its kernel at k = eps (rho = 1).
inline RingIntegrals<double> rim_ring_integrals(double eps) {
  RingKernels<double> k;
  if (eps <= 1.0) {
    k = ring_kernels_inside(eps, eps * eps, std::max((1.0 - eps) * (1.0 + eps), detail::kMinM1));
  } else {
    const double q = 1.0 / eps;
    k = ring_kernels_outside(q, q * q, std::max((1.0 - q) * (1.0 + q), detail::kMinM1));
  }
  return {k.P, k.Q, k.S, k.U, k.V, k.X};
}

// The six integrals of a law at finite eps: the ring law directly, any other law by the radial
// rule split at its breakpoints.
template <typename T>
RingIntegrals<T> law_ring_integrals(const PressureLaw<T>& law, double eps,
                                    const std::vector<QuadratureNode>& rule) {
  if (law.kind == PressureKind::Ring) {
    const RingIntegrals<double> r = rim_ring_integrals(eps);
    return {T(r.P), T(r.Q), T(r.S), T(r.U), T(r.V), T(r.X)};
  }
  return weighted_ring_integrals<T>(law, eps, rule, law.breakpoints());
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
  return law_ring_integrals(law, eps, rule);
}

}  // namespace frictionid::model
