// Complete elliptic integrals for any scalar type (double or an autodiff Jet), by the
// arithmetic-geometric mean. Besides K and E it returns the associate integrals
//   B = (E - m1 K)/m,  D = (K - E)/m,  (B - D)/m,
// computed from the AGM's c_n sequence so that none of them cancels as m -> 0
// (docs/physics.md §2 "Numerics"). m1 = 1 - m is passed separately because callers know it
// to full relative precision near m = 1 (the ring where k = 1), where 1 - m would not.
#pragma once

#include <cmath>

namespace frictionid::model {

template <typename T>
struct EllipticParts {
  T K, E, B, D, b_minus_d_over_m;
};

// m in [0, 1], m1 = 1 - m >= 0 (floored at 1e-300; K diverges like ln(4/sqrt(m1))).
template <typename T>
EllipticParts<T> elliptic_parts(const T& m, const T& m1_in) {
  using std::sqrt;
  // On k = 1 itself K is infinite; a floor keeps every kernel finite (m1 K -> 0 there).
  const T m1 = m1_in < 1e-300 ? T(1e-300) : m1_in;
  const T kp = sqrt(m1);
  T a = T(1), b = kp;
  // c_n / m with c_1 = m / (2 (1 + k')) and c_{n+1} = c_n^2 / (4 a_{n+1}): no differences taken.
  T g = T(1) / (T(2) * (T(1) + kp));
  T a_next = (a + b) * 0.5;
  b = sqrt(a * b);
  a = a_next;
  T sum_g2 = T(2) * g * g;  // sum_{n>=1} 2^n (c_n/m)^2
  double pow2 = 2.0;
  for (int iter = 0; iter < 60; ++iter) {
    a_next = (a + b) * 0.5;
    g = m * g * g / (T(4) * a_next);  // c_{n+1}/m = m (c_n/m)^2 / (4 a_{n+1})
    b = sqrt(a * b);
    a = a_next;
    pow2 *= 2.0;
    const T term = pow2 * g * g;
    sum_g2 += term;
    // The Jet comparison uses the value part; one more pass settles the derivative part.
    if (!(m * term > 1e-17 * sum_g2) && !((a - b) > 1e-15 * a)) break;
  }
  const T K = T(M_PI) / (T(2) * a);
  const T s1_over_m = m * sum_g2;  // S1/m with S1 = sum_{n>=1} 2^n c_n^2
  EllipticParts<T> out;
  out.K = K;
  out.D = K * 0.5 * (T(1) + s1_over_m);
  out.B = K * 0.5 * (T(1) - s1_over_m);
  out.E = out.B + m1 * out.D;
  out.b_minus_d_over_m = -K * sum_g2;
  return out;
}

}  // namespace frictionid::model
