// The seed's closed-form approximants (physics.md §3) and the "corrected" variant, extended to
// any slip direction by the structure of the exact general-alpha result (physics.md §2):
//
//   T_par  = F0 [d11 (t + s h sin(a) s_hat) + s d12 h cos(a) p_hat]
//   T_perp = F0 [d12 (t + s h sin(a) s_hat) + s d22 h cos(a) p_hat]
//   M_z    = s M0 g_hat + F0 R h rho_roll [cos(a) d12 (x_hat - u_hat) - sin(a) (d22 u_hat - d11
//   v_hat)]
//
// with eps = v/(|omega| R), F0 = f N, M0 = (1+kappa)/2 mu_M f N R, rho_roll = m3/(2 m1) and
// closed-form stand-ins for the normalised ring integrals:
//   t     = eps/sqrt(eps^2 + a)                        (I_P/(2 pi m1), the seed's T_par)
//   p_hat = eps/sqrt((1 + b eps^2)(eps^2 + a))         seed (I_Q/(2 pi m1); odd, 0 at v = 0)
//         = p0/sqrt(1 + b~ eps^2)                      corrected (finite pure-spin limit p0)
//   g_hat = 1/sqrt(1 + m(alpha) eps^2), m(alpha) = m kappa^2/d22^2   (the seed's M_v)
//   s_hat = p0/(1 + b_S eps^2)^(3/2)                   (I_S/(2 pi m1): p0 at 0, ~eps^-3 at inf)
//   x_hat = eps/sqrt(eps^2 + c_X), v_hat = eps/sqrt(eps^2 + c_V)   (I_X, I_V over pi m3)
//   u_hat = (m2/(4 m3)) eps/(1 + c_U eps^2)^(3/2)      (I_U/(pi m3): 0 at both ends)
// Each stand-in matches the exact integral's value and leading slope at eps -> 0 and its leading
// term at eps -> inf; b_S, c_X, c_V, c_U come from the pressure law's moments. At alpha = 0
// (slip along +x, the seed's domain) every tilt stand-in except p_hat drops out and the seed's
// three published formulas are reproduced exactly; for v_x < 0 the structure makes T_y even in
// v (the exact parity), where the published T_perp (defined for v_x >= 0 only) would be odd.
#pragma once

#include <cmath>

#include "model/coefficients.hpp"
#include "model/kinematics.hpp"
#include "model/pressure_law.hpp"
#include "model/scalar_ops.hpp"

namespace frictionid::model {

enum class ApproximantForm { Seed, Corrected };

template <typename T>
struct ApproximantParams {
  T f, kappa, h;
  T a;   // T_par slope coefficient
  T b;   // seed: b of T_perp; corrected: b_tilde
  T m;   // M_z coefficient at alpha = 0
  T p0;  // corrected only: pure-spin lateral force ratio
};

// Shape constants of the tilt stand-ins, fixed by the pressure law.
template <typename T>
struct ApproximantShape {
  T mu_M, rho_roll, p0_law, b_S, c_X, c_V, c_U, u_scale;
};

template <typename T>
ApproximantShape<T> approximant_shape(const LawMoments<T>& mo) {
  using std::cbrt;
  ApproximantShape<T> s;
  s.mu_M = mo[2] / mo[1];
  s.rho_roll = mo[3] / (T(2) * mo[1]);
  s.p0_law = mo[2] / (T(2) * mo[1]);
  const T rS = T(4) * mo[2] / mo[5];
  s.b_S = cbrt(rS * rS);
  const T rX = T(4) * mo[3] / (T(3) * mo[2]);
  s.c_X = rX * rX;
  const T rV = T(4) * mo[3] / mo[2];
  s.c_V = rV * rV;
  const T rU = mo[2] / mo[5];
  s.c_U = cbrt(rU * rU);
  s.u_scale = mo[2] / (T(4) * mo[3]);
  return s;
}

// eps/sqrt(eps^2 + c), written to stay finite for eps = 0 and eps = inf.
template <typename T>
T saturating(double eps, const T& c) {
  if (eps <= 1.0) return eps * inv_sqrt(T(eps * eps) + c);
  const double q = 1.0 / eps;
  return inv_sqrt(T(1) + c * (q * q));
}

// The shape constants are plain doubles: the pressure law of a closed-form fit is fixed, so
// they never carry derivatives (and autodiff need not pay for them).
template <typename T>
Resultants<T> approximant_resultants(ApproximantForm form, const ApproximantParams<T>& p,
                                     const ApproximantShape<double>& shape, const Kinematics& k) {
  const SlipGeometry g = slip_geometry(k);
  Resultants<T> r;
  r.M_roll = p.h * k.N * k.R * shape.rho_roll;
  r.N = T(k.N);
  if (g.at_rest) {
    r.T_x = r.T_y = r.M_z = T(0);
    return r;
  }
  const double eps = g.eps, ca = g.cos_alpha, sa = g.sin_alpha, s = g.spin_sign;
  const bool small = eps <= 1.0;
  // For large eps the forms are divided through by eps; q = 1/eps stays a plain double (0 for
  // pure sliding), because sqrt of a constant-zero Jet has a NaN derivative.
  const double e2 = eps * eps, q = small ? 0.0 : 1.0 / eps, inv2 = q * q;

  const T t = saturating(eps, p.a);
  T p_hat;
  if (form == ApproximantForm::Seed) {
    p_hat = small ? eps * inv_sqrt((T(1) + p.b * e2) * (T(e2) + p.a))
                  : q * inv_sqrt((T(inv2) + p.b) * (T(1) + p.a * inv2));
  } else {
    p_hat = small ? p.p0 * inv_sqrt(T(1) + p.b * e2) : (p.p0 * q) * inv_sqrt(T(inv2) + p.b);
  }
  const T F0 = p.f * k.N;
  const T M0 = (T(1) + p.kappa) * (0.5 * shape.mu_M * k.R) * F0;
  if (sa == 0.0) {
    // Slip along the x axis (ca = +-1) or pure spin: d11 = 1, d12 = 0, d22 = kappa, m(alpha) = m
    // and every tilt stand-in but p_hat drops out; the common case of test-rig data, and half
    // the arithmetic of the general case below.
    const T g_aligned = small ? inv_sqrt(T(1) + p.m * e2) : q * inv_sqrt(T(inv2) + p.m);
    r.T_x = F0 * (ca * t);
    r.T_y = F0 * p.kappa * p.h * (s * p_hat);
    r.M_z = M0 * s * g_aligned;
    return r;
  }
  const T d11 = T(ca * ca) + p.kappa * (sa * sa);
  const T d22 = T(sa * sa) + p.kappa * (ca * ca);
  const T d12 = (p.kappa - T(1)) * (sa * ca);
  const T m_alpha = p.m * (p.kappa * p.kappa) / (d22 * d22);
  const T g_hat = small ? inv_sqrt(T(1) + m_alpha * e2) : q * inv_sqrt(T(inv2) + m_alpha);
  // The tilt stand-ins act only off the principal axis (sin(a) != 0; d12 = 0 otherwise).
  // s_hat = p0/(1 + b_S eps^2)^(3/2); u_hat likewise: both decay, written for eps = inf too.
  const double sw = small ? 1.0 / (1.0 + shape.b_S * e2) : inv2 / (inv2 + shape.b_S);
  const double s_hat = shape.p0_law * sw * std::sqrt(sw);
  // eps (1 + c eps^2)^(-3/2) = eps^-2 (eps^-2 + c)^(-3/2) for large eps.
  const double uw = small ? 1.0 / (1.0 + shape.c_U * e2) : 1.0 / (inv2 + shape.c_U);
  const double u_hat = shape.u_scale * (small ? eps : inv2) * uw * std::sqrt(uw);
  const double x_hat = saturating(eps, shape.c_X);
  const double v_hat = saturating(eps, shape.c_V);

  const T base = t + p.h * (s * sa) * s_hat;
  const T tilt = p.h * (s * ca) * p_hat;
  const T t_par = F0 * (d11 * base + d12 * tilt);
  const T t_perp = F0 * (d12 * base + d22 * tilt);
  r.T_x = t_par * ca - t_perp * sa;
  r.T_y = t_par * sa + t_perp * ca;
  r.M_z = M0 * s * g_hat + F0 * k.R * p.h * shape.rho_roll *
                               (ca * d12 * (x_hat - u_hat) - sa * (d22 * u_hat - d11 * v_hat));
  return r;
}

}  // namespace frictionid::model
