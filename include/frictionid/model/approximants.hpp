// The seed's closed-form approximants (docs/physics.md §3) and the "corrected" variant, extended to
// any slip direction by the structure of the exact general-alpha result (docs/physics.md §2):
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

#include <array>
#include <cmath>
#include <type_traits>

#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/pressure_law.hpp>
#include <frictionid/model/scalar_ops.hpp>

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

// Products of parameters alone, the same for every row: formed once per parameter vector, since
// in autodiff each product of two Jets costs as much as the rest of a row's arithmetic.
template <typename T>
struct ApproximantProducts {
  T fkh;   // f kappa h: the lateral force factor at alpha = 0
  T spin;  // (1 + kappa) mu_M f / 2 = M0/(N R)
};

template <typename T>
ApproximantProducts<T> approximant_products(const ApproximantParams<T>& p,
                                            const ApproximantShape<double>& shape) {
  return {p.f * p.kappa * p.h, (T(1) + p.kappa) * (0.5 * shape.mu_M) * p.f};
}

// What the stand-ins t, p_hat and (slip along x) g_hat need of a row's eps, as factors:
//   t = f_t/sqrt(y_t0 + a y_t1), p_hat's y_p from y_p0 + b y_p1, g_hat = g_g/sqrt(g_e + m g_f).
// For large eps the forms are divided through by eps; q = 1/eps stays a plain number (0 for pure
// sliding), because sqrt of a constant-zero Jet has a NaN derivative. D is a double for one row
// or a vector of doubles for several (the packet pass of src/identify/aligned_row_packets.hpp):
// the same expressions give each lane the bits of its row.
template <typename D>
struct EpsFactors {
  D e2, q, inv2;          // eps^2; 1/eps and 1/eps^2 for eps > 1, else 0
  D y_t0, y_t1, f_t;      // t = eps/sqrt(eps^2 + a)
  D y_p0, y_p1;           // (1 + b eps^2) of p_hat
  D f_seed, f_corrected;  // p_hat's factor: seed eps, corrected 1 (each over eps for large)
  D g_e, g_f, g_g;        // g_hat at alpha = 0: 1/sqrt(1 + m eps^2)
};

template <typename D>
FRICTIONID_MODEL_INLINE EpsFactors<D> eps_factors(const D& eps, const D& inv_eps) {
  EpsFactors<D> f;
  const auto small = eps <= 1.0;
  f.e2 = eps * eps;
  f.q = select<D>(small, 0.0, inv_eps);
  f.inv2 = f.q * f.q;
  f.y_t0 = select<D>(small, f.e2, 1.0);
  f.y_t1 = select<D>(small, 1.0, f.inv2);
  f.f_t = select<D>(small, eps, 1.0);
  f.y_p0 = select<D>(small, 1.0, f.inv2);
  f.y_p1 = select<D>(small, f.e2, 1.0);
  f.f_seed = select<D>(small, eps, f.q);
  f.f_corrected = select<D>(small, 1.0, f.q);
  f.g_e = select<D>(small, 1.0, f.inv2);
  f.g_f = select<D>(small, f.e2, 1.0);
  f.g_g = select<D>(small, 1.0, f.q);
  return f;
}

// y_t of t = f_t/sqrt(y_t).
template <typename T, typename D>
FRICTIONID_MODEL_INLINE T stand_in_y_t(const ApproximantParams<T>& p, const EpsFactors<D>& f) {
  return affine(f.y_t0, p.a, f.y_t1);
}

// p_hat: seed eps/sqrt((1 + b eps^2)(eps^2 + a)); corrected p0/sqrt(1 + b~ eps^2).
template <typename T, typename D>
FRICTIONID_MODEL_INLINE T stand_in_p_hat(ApproximantForm form, const ApproximantParams<T>& p,
                                         const T& y_t, const EpsFactors<D>& f) {
  const T c_p = affine(f.y_p0, p.b, f.y_p1);
  // p_hat = f_p/sqrt(y_p); the seed's f_p is a plain number, the corrected form's p0 a parameter.
  if (form == ApproximantForm::Seed) return inv_sqrt(c_p * y_t) * f.f_seed;
  return p.p0 * (inv_sqrt(c_p) * f.f_corrected);
}

// A row of slip along x (or pure spin), apart from its eps: the sign factors times N and R.
template <typename D>
struct AxisRow {
  D ca_n;  // f_t cos(alpha) N
  D s_n;   // spin sign N
  D s_nr;  // spin sign N R
  D nr;    // N R
};

template <typename D>
FRICTIONID_MODEL_INLINE AxisRow<D> axis_row(const EpsFactors<D>& f, const D& cos_alpha,
                                            const D& spin_sign, const D& N, const D& R) {
  return {f.f_t * cos_alpha * N, spin_sign * N, spin_sign * N * R, N * R};
}

// The rolling-resistance moment M_roll = h N R rho_roll, every slip direction.
template <typename T, typename D>
FRICTIONID_MODEL_INLINE T rolling_moment(const T& h, const D& nr, double rho_roll) {
  return h * (nr * rho_roll);
}

template <typename T>
struct AxisResultants {
  T T_x, T_y, M_z;
};

// Slip along the x axis (cos(alpha) = +-1) or pure spin: d11 = 1, d12 = 0, d22 = kappa,
// m(alpha) = m and every tilt stand-in but p_hat drops out; the common case of test-rig data,
// and the seed's three published formulas. F0 = f N and M0 = spin N R.
template <typename T, typename D>
FRICTIONID_MODEL_INLINE AxisResultants<T> axis_resultants(ApproximantForm form,
                                                          const ApproximantParams<T>& p,
                                                          const ApproximantProducts<T>& pp,
                                                          const EpsFactors<D>& f,
                                                          const AxisRow<D>& row) {
  const T y_t = stand_in_y_t(p, f);
  const T p_hat = stand_in_p_hat(form, p, y_t, f);
  const T t = inv_sqrt(y_t) * row.ca_n;
  const T g_aligned = inv_sqrt(affine(f.g_e, p.m, f.g_f)) * f.g_g;
  return {p.f * t, pp.fkh * (p_hat * row.s_n), pp.spin * (g_aligned * row.s_nr)};
}

// The shape constants are plain doubles: the pressure law of a closed-form fit is fixed, so
// they never carry derivatives (and autodiff need not pay for them). The velocities of k are
// doubles, or dual numbers of T itself for derivatives along the kinematics.
template <typename T, typename K = double>
Resultants<T> approximant_resultants(ApproximantForm form, const ApproximantParams<T>& p,
                                     const ApproximantProducts<T>& pp,
                                     const ApproximantShape<double>& shape,
                                     const KinematicsT<K>& k) {
  static_assert(std::is_same_v<K, double> || std::is_same_v<K, T>,
                "kinematics are plain numbers or the parameters' own scalar type");
  const SlipGeometryT<K> g = slip_geometry(k);
  Resultants<T> r;
  r.M_roll = rolling_moment(p.h, k.N * k.R, shape.rho_roll);
  r.N = T(k.N);
  if (g.at_rest) {
    r.T_x = r.T_y = r.M_z = T(0);
    return r;
  }
  const K eps = g.eps, ca = g.cos_alpha, sa = g.sin_alpha;
  const double s = g.spin_sign;
  const EpsFactors<K> ef = eps_factors(eps, g.inv_eps);
  // Slip along x has its own shorter form; a dual-number row takes the general one, which
  // equals it at sin(alpha) = 0 and carries the derivative off the axis too.
  if constexpr (std::is_same_v<K, double>) {
    if (sa == 0.0) {
      const AxisResultants<T> a = axis_resultants(form, p, pp, ef, axis_row(ef, ca, s, k.N, k.R));
      r.T_x = a.T_x;
      r.T_y = a.T_y;
      r.M_z = a.M_z;
      return r;
    }
  }
  const bool small = eps <= 1.0;
  const K e2 = ef.e2, q = ef.q, inv2 = ef.inv2, f_t = ef.f_t;
  const T y_t = stand_in_y_t(p, ef);
  const T p_hat = stand_in_p_hat(form, p, y_t, ef);
  const T F0 = p.f * k.N;
  const T M0 = pp.spin * (k.N * k.R);
  const T d11 = T(ca * ca) + p.kappa * (sa * sa);
  const T d22 = T(sa * sa) + p.kappa * (ca * ca);
  const T d12 = (p.kappa - T(1)) * (sa * ca);
  // g_hat = 1/sqrt(1 + m(alpha) eps^2), m(alpha) = m kappa^2/d22^2, as d22/sqrt(d22^2 + ...).
  const T mk2 = p.m * (p.kappa * p.kappa);
  const T y_g = small ? d22 * d22 + mk2 * e2 : d22 * d22 * inv2 + mk2;
  const T f_g = small ? d22 : q * d22;
  // The tilt stand-ins act only off the principal axis (sin(a) != 0; d12 = 0 otherwise):
  // s_hat = p0 (1 + b_S eps^2)^(-3/2), u_hat = (m2/(4 m3)) eps (1 + c_U eps^2)^(-3/2),
  // x_hat = eps/sqrt(eps^2 + c_X), v_hat = eps/sqrt(eps^2 + c_V); for large eps in q.
  const std::array<K, 4> y_tilt =
      small ? std::array<K, 4>{1.0 + shape.b_S * e2, 1.0 + shape.c_U * e2, e2 + shape.c_X,
                               e2 + shape.c_V}
            : std::array<K, 4>{inv2 + shape.b_S, inv2 + shape.c_U, 1.0 + shape.c_X * inv2,
                               1.0 + shape.c_V * inv2};
  const T t = f_t * inv_sqrt(y_t);
  const T g_hat = f_g * inv_sqrt(y_g);
  const std::array<K, 4> r_tilt = inv_sqrt_each(y_tilt);
  const K qs = select<K>(small, 1.0, q * r_tilt[0]);
  const K s_hat = shape.p0_law * select<K>(small, r_tilt[0] * r_tilt[0] * r_tilt[0], qs * qs * qs);
  const K u_hat = shape.u_scale * select<K>(small, eps, inv2) * (r_tilt[1] * r_tilt[1] * r_tilt[1]);
  const K x_hat = select<K>(small, eps, 1.0) * r_tilt[2];
  const K v_hat = select<K>(small, eps, 1.0) * r_tilt[3];

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

// The same with the parameter products formed here (one row at a time: tests, references).
template <typename T, typename K = double>
Resultants<T> approximant_resultants(ApproximantForm form, const ApproximantParams<T>& p,
                                     const ApproximantShape<double>& shape,
                                     const KinematicsT<K>& k) {
  return approximant_resultants(form, p, approximant_products(p, shape), shape, k);
}

}  // namespace frictionid::model
