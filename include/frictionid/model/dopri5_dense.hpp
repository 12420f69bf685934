// One Dormand–Prince 5(4) step that keeps its stages, and the step's 4th-order continuous
// extension (dense output; Hairer, Nørsett & Wanner, "Solving ODEs I", §II.6, the coefficients
// of their code DOPRI5). For drivers that stop at events or write rows at fixed times between
// steps; the tableau is the one of dormand_prince.hpp.
#pragma once

#include <cstddef>

#include <frictionid/model/dormand_prince.hpp>

namespace frictionid::model {

template <std::size_t N>
struct Dopri5DenseStep {
  double t0 = 0.0, h = 0.0;
  OdeVector<double, N> y0{}, y1{};              // the solution at t0 and t0 + h (5th order)
  OdeVector<double, N> error{};                 // y5 - y4
  OdeVector<double, N> f1{};                    // f(t0 + h, y1): the next step's first stage
  OdeVector<double, N> r2{}, r3{}, r4{}, r5{};  // the dense-output polynomial's coefficients

  // The continuous extension at t in [t0, t0 + h]: exact at both ends, 4th order between.
  OdeVector<double, N> at(double t) const {
    const double s = h != 0.0 ? (t - t0) / h : 0.0, s1 = 1.0 - s;
    OdeVector<double, N> y;
    for (std::size_t i = 0; i < N; ++i)
      y[i] = y0[i] + s * (r2[i] + s1 * (r3[i] + s * (r4[i] + s1 * r5[i])));
    return y;
  }
};

// A step of size h from (t, y) with f0 = f(t, y): six new evaluations of f.
template <std::size_t N, typename Rhs>
Dopri5DenseStep<N> dopri5_dense_step(const Rhs& f, double t, const OdeVector<double, N>& y,
                                     const OdeVector<double, N>& f0, double h) {
  using C = detail::Dopri5Tableau;
  constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                   d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                   d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
  OdeVector<double, N> tmp, k2, k3, k4, k5, k6;
  for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (C::a21 * f0[i]);
  k2 = f(t + C::c2 * h, tmp);
  for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (C::a31 * f0[i] + C::a32 * k2[i]);
  k3 = f(t + C::c3 * h, tmp);
  for (std::size_t i = 0; i < N; ++i)
    tmp[i] = y[i] + h * (C::a41 * f0[i] + C::a42 * k2[i] + C::a43 * k3[i]);
  k4 = f(t + C::c4 * h, tmp);
  for (std::size_t i = 0; i < N; ++i)
    tmp[i] = y[i] + h * (C::a51 * f0[i] + C::a52 * k2[i] + C::a53 * k3[i] + C::a54 * k4[i]);
  k5 = f(t + C::c5 * h, tmp);
  for (std::size_t i = 0; i < N; ++i)
    tmp[i] = y[i] + h * (C::a61 * f0[i] + C::a62 * k2[i] + C::a63 * k3[i] + C::a64 * k4[i] +
                         C::a65 * k5[i]);
  k6 = f(t + h, tmp);
  Dopri5DenseStep<N> s;
  s.t0 = t;
  s.h = h;
  s.y0 = y;
  for (std::size_t i = 0; i < N; ++i)
    s.y1[i] =
        y[i] + h * (C::b1 * f0[i] + C::b3 * k3[i] + C::b4 * k4[i] + C::b5 * k5[i] + C::b6 * k6[i]);
  s.f1 = f(t + h, s.y1);
  for (std::size_t i = 0; i < N; ++i) {
    s.error[i] = h * (C::e1 * f0[i] + C::e3 * k3[i] + C::e4 * k4[i] + C::e5 * k5[i] +
                      C::e6 * k6[i] + C::e7 * s.f1[i]);
    const double dy = s.y1[i] - y[i];
    const double bspl = h * f0[i] - dy;
    s.r2[i] = dy;
    s.r3[i] = bspl;
    s.r4[i] = dy - h * s.f1[i] - bspl;
    s.r5[i] = h * (d1 * f0[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * s.f1[i]);
  }
  return s;
}

}  // namespace frictionid::model
