// Dormand–Prince 5(4) explicit Runge–Kutta with FSAL and adaptive step control, for small
// fixed-size systems y' = f(t, y) (Hairer, Nørsett & Wanner, "Solving ODEs I", §II.4-5).
// The solution is propagated with the 5th-order formula (local extrapolation); the embedded
// 4th-order one only estimates the error. Templated on the scalar type like the rest of
// src/model; no I/O.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace frictionid::model {

template <typename T, std::size_t N>
using OdeVector = std::array<T, N>;

// Tolerances and limits of the adaptive driver. The error of a step is measured in the RMS norm
// of e_i / (atol + rtol max(|y_i|, |y_new_i|)) and accepted when <= 1.
struct OdeSettings {
  double rtol = 1e-10;
  double atol = 1e-12;
  double initial_step = 0.0;  // 0: Hairer's starting-step heuristic
  double max_step = std::numeric_limits<double>::infinity();
  long max_steps = 200000;  // accepted + rejected
};

struct OdeStats {
  long accepted = 0, rejected = 0, evaluations = 0;
  bool stopped_by_observer = false;  // false: max_steps reached or the step size underflowed
};

namespace detail {
// The Butcher tableau of DOPRI5 (c, a, b5) and the error weights e = b5 - b4.
struct Dopri5Tableau {
  static constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  static constexpr double a21 = 1.0 / 5;
  static constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  static constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  static constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                          a54 = -212.0 / 729;
  static constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                          a64 = 49.0 / 176, a65 = -5103.0 / 18656;
  static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                          b6 = 11.0 / 84;
  static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                          e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
};
}  // namespace detail

template <typename T, std::size_t N>
struct Dopri5Step {
  OdeVector<T, N> y;      // 5th-order solution at t + h
  OdeVector<T, N> error;  // y5 - y4, the local error estimate of the 4th-order solution
  OdeVector<T, N> f_end;  // f(t + h, y): the first stage of the next step (FSAL)
};

// The inner stages of a step, for its dense output (dopri5_dense.hpp).
template <typename T, std::size_t N>
struct Dopri5Stages {
  OdeVector<T, N> k3, k4, k5, k6;
};

// One step of size h from (t, y) with f0 = f(t, y). Six new evaluations of f. `stages`, when
// given, receives the stages the dense output needs.
template <typename T, std::size_t N, typename Rhs>
Dopri5Step<T, N> dopri5_step(const Rhs& f, const T& t, const OdeVector<T, N>& y,
                             const OdeVector<T, N>& f0, const T& h,
                             Dopri5Stages<T, N>* stages = nullptr) {
  using C = detail::Dopri5Tableau;
  OdeVector<T, N> tmp, k2, k3, k4, k5, k6;
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
  Dopri5Step<T, N> s;
  for (std::size_t i = 0; i < N; ++i)
    s.y[i] =
        y[i] + h * (C::b1 * f0[i] + C::b3 * k3[i] + C::b4 * k4[i] + C::b5 * k5[i] + C::b6 * k6[i]);
  s.f_end = f(t + h, s.y);
  for (std::size_t i = 0; i < N; ++i)
    s.error[i] = h * (C::e1 * f0[i] + C::e3 * k3[i] + C::e4 * k4[i] + C::e5 * k5[i] +
                      C::e6 * k6[i] + C::e7 * s.f_end[i]);
  if (stages) *stages = {k3, k4, k5, k6};
  return s;
}

// RMS of e_i / (atol + rtol max(|y_i|, |z_i|)).
template <typename T, std::size_t N>
T dopri5_error_norm(const OdeVector<T, N>& e, const OdeVector<T, N>& y, const OdeVector<T, N>& z,
                    const OdeSettings& s) {
  using std::abs;
  using std::max;
  using std::sqrt;
  T sum = T(0);
  for (std::size_t i = 0; i < N; ++i) {
    const T scale = T(s.atol) + T(s.rtol) * max(abs(y[i]), abs(z[i]));
    const T r = e[i] / scale;
    sum += r * r;
  }
  return sqrt(sum / T(N));
}

// Integrates from (t, y) with adaptive steps until observe(t, y, f(t, y)) returns false (it is
// called once at the start and after every accepted step), max_steps is reached or the step
// size underflows. There is no end time: the observer decides. Returns the counts.
template <typename T, std::size_t N, typename Rhs, typename Observer>
OdeStats dopri5_integrate(const Rhs& f, T t, OdeVector<T, N> y, const OdeSettings& s,
                          Observer&& observe) {
  using std::abs;
  using std::max;
  using std::min;
  using std::pow;
  using std::sqrt;
  OdeStats stats;
  OdeVector<T, N> fy = f(t, y);
  stats.evaluations = 1;
  if (!observe(t, y, fy)) {
    stats.stopped_by_observer = true;
    return stats;
  }
  T h = T(s.initial_step);
  if (!(h > T(0))) {
    // Hairer's heuristic: a step whose explicit Euler increment is 1 % of the scale, then
    // limited so that the second-derivative estimate's error is about the tolerance.
    const OdeVector<T, N> zero{};
    const T d0 = dopri5_error_norm(y, zero, y, s);
    const T d1 = dopri5_error_norm(fy, zero, y, s);
    T h0 = (d0 < T(1e-5) || d1 < T(1e-5)) ? T(1e-6) : T(0.01) * d0 / d1;
    OdeVector<T, N> y1;
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h0 * fy[i];
    const OdeVector<T, N> f1 = f(t + h0, y1);
    ++stats.evaluations;
    OdeVector<T, N> df;
    for (std::size_t i = 0; i < N; ++i) df[i] = f1[i] - fy[i];
    const T d2 = dopri5_error_norm(df, zero, y, s) / h0;
    const T dmax = max(d1, d2);
    const T h1 = dmax <= T(1e-15) ? max(T(1e-6), h0 * T(1e-3)) : pow(T(0.01) / dmax, T(0.2));
    h = min(T(100) * h0, h1);
  }
  h = min(h, T(s.max_step));

  // Standard controller: h_new = h * clamp(0.9 err^(-1/5), 0.2, 5) (no growth right after a
  // rejection).
  bool last_rejected = false;
  while (stats.accepted + stats.rejected < s.max_steps) {
    if (!(abs(h) > abs(t) * T(4 * std::numeric_limits<double>::epsilon())) || !(h > T(0)))
      return stats;  // the step size underflowed: the solution is not smooth here
    const Dopri5Step<T, N> step = dopri5_step(f, t, y, fy, h);
    stats.evaluations += 6;
    const T err = dopri5_error_norm(step.error, y, step.y, s);
    bool finite = err == err;  // NaN check that works for any ordered scalar
    for (std::size_t i = 0; i < N && finite; ++i) finite = step.y[i] == step.y[i];
    if (finite && err <= T(1)) {
      t += h;
      y = step.y;
      fy = step.f_end;
      ++stats.accepted;
      if (!observe(t, y, fy)) {
        stats.stopped_by_observer = true;
        return stats;
      }
      T factor = err > T(0) ? T(0.9) * pow(err, T(-0.2)) : T(5);
      factor = min(T(5), max(T(0.2), factor));
      if (last_rejected) factor = min(T(1), factor);
      h = min(h * factor, T(s.max_step));
      last_rejected = false;
    } else {
      ++stats.rejected;
      T factor = finite ? max(T(0.2), T(0.9) * pow(err, T(-0.2))) : T(0.25);
      h *= factor;
      last_rejected = true;
    }
  }
  return stats;
}

}  // namespace frictionid::model
