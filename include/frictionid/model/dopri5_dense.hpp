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

// A step of size h from (t, y) with f0 = f(t, y): dopri5_step's six new evaluations of f, and
// the continuous extension from its stages.
template <std::size_t N, typename Rhs>
Dopri5DenseStep<N> dopri5_dense_step(const Rhs& f, double t, const OdeVector<double, N>& y,
                                     const OdeVector<double, N>& f0, double h) {
  constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                   d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                   d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
  Dopri5Stages<double, N> k;
  const Dopri5Step<double, N> step = dopri5_step(f, t, y, f0, h, &k);
  Dopri5DenseStep<N> s;
  s.t0 = t;
  s.h = h;
  s.y0 = y;
  s.y1 = step.y;
  s.f1 = step.f_end;
  s.error = step.error;
  for (std::size_t i = 0; i < N; ++i) {
    const double dy = s.y1[i] - y[i];
    const double bspl = h * f0[i] - dy;
    s.r2[i] = dy;
    s.r3[i] = bspl;
    s.r4[i] = dy - h * s.f1[i] - bspl;
    s.r5[i] =
        h * (d1 * f0[i] + d3 * k.k3[i] + d4 * k.k4[i] + d5 * k.k5[i] + d6 * k.k6[i] + d7 * s.f1[i]);
  }
  return s;
}

}  // namespace frictionid::model
