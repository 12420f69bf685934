// One step of the linearly implicit Rosenbrock method RODAS (order 4, embedded order 3,
// L-stable and stiffly accurate; Hairer & Wanner, "Solving ODEs II", §IV.7, the coefficients of
// their code RODAS) for an autonomous system y' = f(y) of small fixed size, with its continuous
// extension of order 3. For the stiff phases of the towed wheel (docs/physics.md §10.8), where an
// explicit method's step is bounded by the friction's stiffness rather than by accuracy.
// The stages solve (I/(gamma h) - J) g_i = f(Y_i) + sum_j c_ij g_j / h with one LU of the matrix
// per step; J is the caller's Jacobian of f at y. Plain doubles; no I/O.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <frictionid/model/dormand_prince.hpp>

namespace frictionid::model {

template <std::size_t N>
using OdeMatrix = std::array<std::array<double, N>, N>;

namespace detail {

// The transformed coefficients of RODAS (gamma = 1/4; c2..c4 are the stage times, unused by an
// autonomous system). Stage i is evaluated at y + sum_j a_ij g_j; the 3rd-order solution is
// Y6 = Y5 + g5, the 4th-order one Y6 + g6, and g6 is the error estimate.
struct RodasTableau {
  static constexpr double gamma = 0.25;
  static constexpr double a21 = 1.544;
  static constexpr double a31 = 0.9466785280815826, a32 = 0.2557011698983284;
  static constexpr double a41 = 3.314825187068521, a42 = 2.896124015972201,
                          a43 = 0.9986419139977817;
  static constexpr double a51 = 1.221224509226641, a52 = 6.019134481288629, a53 = 12.53708332932087,
                          a54 = -0.687886036105895;
  static constexpr double c21 = -5.6688;
  static constexpr double c31 = -2.430093356833875, c32 = -0.2063599157091915;
  static constexpr double c41 = -0.1073529058151375, c42 = -9.594562251023355,
                          c43 = -20.47028614809616;
  static constexpr double c51 = 7.496443313967647, c52 = -10.24680431464352,
                          c53 = -33.99990352819905, c54 = 11.7089089320616;
  static constexpr double c61 = 8.083246795921522, c62 = -7.981132988064893,
                          c63 = -31.52159432874371, c64 = 16.31930543123136,
                          c65 = -6.058818238834054;
  // The continuous extension's two coefficient vectors from g1..g5.
  static constexpr double d21 = 10.12623508344586, d22 = -7.487995877610167,
                          d23 = -34.80091861555747, d24 = -7.992771707568823,
                          d25 = 1.025137723295662;
  static constexpr double d31 = -0.6762803392801253, d32 = 6.087714651680015,
                          d33 = 16.43084320892478, d34 = 24.76722511418386,
                          d35 = -6.594389125716872;
};

// LU factorisation with partial pivoting of a small dense matrix, in place; false if singular.
template <std::size_t N>
bool lu_factor(OdeMatrix<N>& a, std::array<std::size_t, N>& pivot) {
  for (std::size_t k = 0; k < N; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < N; ++i)
      if (std::fabs(a[i][k]) > std::fabs(a[p][k])) p = i;
    pivot[k] = p;
    if (!(std::fabs(a[p][k]) > 0.0)) return false;
    if (p != k) std::swap(a[p], a[k]);
    for (std::size_t i = k + 1; i < N; ++i) {
      const double m = a[i][k] / a[k][k];
      a[i][k] = m;
      for (std::size_t j = k + 1; j < N; ++j) a[i][j] -= m * a[k][j];
    }
  }
  return true;
}

template <std::size_t N>
void lu_solve(const OdeMatrix<N>& lu, const std::array<std::size_t, N>& pivot,
              OdeVector<double, N>& b) {
  // The rows were swapped whole (multipliers included): permute b first, then substitute.
  for (std::size_t k = 0; k < N; ++k) std::swap(b[k], b[pivot[k]]);
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t i = k + 1; i < N; ++i) b[i] -= lu[i][k] * b[k];
  for (std::size_t k = N; k-- > 0;) {
    for (std::size_t j = k + 1; j < N; ++j) b[k] -= lu[k][j] * b[j];
    b[k] /= lu[k][k];
  }
}

}  // namespace detail

template <std::size_t N>
struct RodasStep {
  double t0 = 0.0, h = 0.0;
  bool ok = false;                  // false: the matrix I/(gamma h) - J was singular
  OdeVector<double, N> y0{}, y1{};  // the solution at t0 and t0 + h (4th order)
  OdeVector<double, N> error{};     // y1 minus the embedded 3rd-order solution
  OdeVector<double, N> c3{}, c4{};  // the continuous extension's coefficients

  // The continuous extension at t in [t0, t0 + h]: exact at both ends, 3rd order between.
  OdeVector<double, N> at(double t) const {
    const double s = h != 0.0 ? (t - t0) / h : 0.0, s1 = 1.0 - s;
    OdeVector<double, N> y;
    for (std::size_t i = 0; i < N; ++i) y[i] = y0[i] * s1 + s * (y1[i] + s1 * (c3[i] + s * c4[i]));
    return y;
  }
};

// A step of size h from y with f0 = f(y) and jac = df/dy at y: five new evaluations of f.
template <std::size_t N, typename Rhs>
RodasStep<N> rodas_step(const Rhs& f, double t, const OdeVector<double, N>& y,
                        const OdeVector<double, N>& f0, const OdeMatrix<N>& jac, double h) {
  using C = detail::RodasTableau;
  RodasStep<N> s;
  s.t0 = t;
  s.h = h;
  s.y0 = y;
  OdeMatrix<N> e;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) e[i][j] = (i == j ? 1.0 / (C::gamma * h) : 0.0) - jac[i][j];
  std::array<std::size_t, N> pivot{};
  if (!detail::lu_factor(e, pivot)) return s;
  const double inv_h = 1.0 / h;
  OdeVector<double, N> g1 = f0, g2, g3, g4, g5, g6, q;
  detail::lu_solve(e, pivot, g1);
  const auto stage = [&](const OdeVector<double, N>& at, auto&& correction,
                         OdeVector<double, N>& g) {
    const OdeVector<double, N> fy = f(t, at);
    for (std::size_t i = 0; i < N; ++i) g[i] = fy[i] + correction(i) * inv_h;
    detail::lu_solve(e, pivot, g);
  };
  for (std::size_t i = 0; i < N; ++i) q[i] = y[i] + C::a21 * g1[i];
  stage(
      q, [&](std::size_t i) { return C::c21 * g1[i]; }, g2);
  for (std::size_t i = 0; i < N; ++i) q[i] = y[i] + C::a31 * g1[i] + C::a32 * g2[i];
  stage(
      q, [&](std::size_t i) { return C::c31 * g1[i] + C::c32 * g2[i]; }, g3);
  for (std::size_t i = 0; i < N; ++i)
    q[i] = y[i] + C::a41 * g1[i] + C::a42 * g2[i] + C::a43 * g3[i];
  stage(
      q, [&](std::size_t i) { return C::c41 * g1[i] + C::c42 * g2[i] + C::c43 * g3[i]; }, g4);
  for (std::size_t i = 0; i < N; ++i)
    q[i] = y[i] + C::a51 * g1[i] + C::a52 * g2[i] + C::a53 * g3[i] + C::a54 * g4[i];
  stage(
      q,
      [&](std::size_t i) {
        return C::c51 * g1[i] + C::c52 * g2[i] + C::c53 * g3[i] + C::c54 * g4[i];
      },
      g5);
  for (std::size_t i = 0; i < N; ++i) q[i] += g5[i];
  stage(
      q,
      [&](std::size_t i) {
        return C::c61 * g1[i] + C::c62 * g2[i] + C::c63 * g3[i] + C::c64 * g4[i] + C::c65 * g5[i];
      },
      g6);
  for (std::size_t i = 0; i < N; ++i) {
    s.y1[i] = q[i] + g6[i];
    s.error[i] = g6[i];
    s.c3[i] = C::d21 * g1[i] + C::d22 * g2[i] + C::d23 * g3[i] + C::d24 * g4[i] + C::d25 * g5[i];
    s.c4[i] = C::d31 * g1[i] + C::d32 * g2[i] + C::d33 * g3[i] + C::d34 * g4[i] + C::d35 * g5[i];
  }
  s.ok = true;
  return s;
}

}  // namespace frictionid::model
