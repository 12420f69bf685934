// Closed forms of the aligned-slip ring integrals (docs/physics.md §2 "Closed forms worth having"),
// used as fast paths by the exact model. All return the radial integrals I_P, I_Q + I_S
// (the isotropic spin torque) and, for Hertz, I_Q, in the units of ring_integrals.hpp.
#pragma once

#include <algorithm>
#include <cmath>

#include <frictionid/model/elliptic.hpp>

namespace frictionid::model {

struct AlignedIntegrals {
  double P, Q, J;  // I_P, I_Q, I_J = I_Q + I_S
};

// Largest eps for which the Hertz forms are used: past it the arcsin and sqrt terms cancel
// (the error grows like eps^4 * 1e-16) and the ring quadrature is more accurate.
inline constexpr double kHertzClosedFormMaxEps = 2.0;

// Hertz, sigma0 = sqrt(1 - rho^2): m1 = 1/3, m2 = pi/16. Polynomial in eps for eps <= 1.
inline AlignedIntegrals hertz_aligned_integrals(double eps) {
  const double e2 = eps * eps, e4 = e2 * e2;
  double t, mhat, p;
  if (eps <= 1.0) {
    t = (3.0 * M_PI / 32.0) * (4.0 * eps - e2 * eps);
    mhat = (8.0 - 8.0 * e2 + 3.0 * e4) / 8.0;
    p = (3.0 * M_PI / 256.0) * (8.0 - 4.0 * e2 + e4);
  } else {
    const double A = std::asin(1.0 / eps), W = std::sqrt((eps - 1.0) * (eps + 1.0));
    t = (3.0 / 16.0) * ((4.0 * eps - e2 * eps) * A + (e2 + 2.0) * W / eps);
    mhat = ((8.0 - 8.0 * e2 + 3.0 * e4) * A + 3.0 * (2.0 - e2) * W) / (4.0 * M_PI);
    p = (3.0 * (8.0 - 4.0 * e2 + e4) * A + (8.0 + 10.0 * e2 - 3.0 * e4) * W / e2) / 128.0;
  }
  const double two_pi_m1 = 2.0 * M_PI / 3.0, two_pi_m2 = M_PI * M_PI / 8.0;
  return {two_pi_m1 * t, two_pi_m1 * p, two_pi_m2 * mhat};
}

// Uniform, sigma0 = 1: m1 = 1/2, m2 = 1/3. t and the isotropic m-hat only (no closed form of
// p is known here), rewritten with B = (E - (1-m)K)/m etc. so nothing cancels at small or
// large eps. Q is not available: the returned Q is NaN by design and must not be used.
inline AlignedIntegrals uniform_aligned_integrals(double eps) {
  double t, mhat;
  if (eps <= 1.0) {
    const double m = eps * eps;
    const auto e = elliptic_parts(m, std::max((1.0 - eps) * (1.0 + eps), 1e-300));
    t = (4.0 / (3.0 * M_PI)) * eps * (e.B + e.E);
    mhat = (2.0 / (3.0 * M_PI)) * ((4.0 - 2.0 * m) * e.E - (1.0 - m) * e.K);
  } else {
    const double q = 1.0 / eps, m = q * q;
    const auto e = elliptic_parts(m, std::max((1.0 - q) * (1.0 + q), 1e-300));
    t = (4.0 / (3.0 * M_PI)) * (e.B + e.E);
    mhat = (2.0 * q / (3.0 * M_PI)) * (3.0 * e.B - e.D - e.b_minus_d_over_m);
  }
  return {M_PI * t, std::nan(""), (2.0 * M_PI / 3.0) * mhat};
}

}  // namespace frictionid::model
