// The closed-form approximants' coefficients implied by a pressure law (docs/physics.md §3):
// each matches a slope of the exact model at eps -> 0 or eps -> inf.
#pragma once

#include <cmath>

#include <frictionid/model/pressure_law.hpp>

namespace frictionid::model {

template <typename T>
struct Coefficients {
  T a;         // (2 m1/m0)^2: small-v slope of T_par, any kappa
  T b;         // (2 m1/m3)^2: small-u slope of the seed's T_perp
  T m;         // [(1+kappa) m2/(d22 m3)]^2: small-u slope of M_z; d22 = sin^2 a + kappa cos^2 a
  T b_tilde;   // (m2/m3)^2: the corrected T_perp's small-u slope
  T p0;        // m2/(2 m1): pure-spin lateral force T_perp(v=0) / (h kappa f N0)
  T mu_M;      // m2/m1 = M0/(f N0 R) at kappa = 1
  T rho_roll;  // m3/(2 m1) = M_roll/(h N0 R)
};

template <typename T>
T d22(const T& kappa, double alpha) {
  const double c = std::cos(alpha), s = std::sin(alpha);
  return T(s * s) + kappa * (c * c);
}

template <typename T>
Coefficients<T> coefficients(const LawMoments<T>& mo, const T& kappa, double alpha = 0.0) {
  Coefficients<T> c;
  const T r_a = T(2) * mo[1] / mo[0];
  const T r_b = T(2) * mo[1] / mo[3];
  const T r_m = (T(1) + kappa) * mo[2] / (d22(kappa, alpha) * mo[3]);
  const T r_bt = mo[2] / mo[3];
  c.a = r_a * r_a;
  c.b = r_b * r_b;
  c.m = r_m * r_m;
  c.b_tilde = r_bt * r_bt;
  c.p0 = mo[2] / (T(2) * mo[1]);
  c.mu_M = mo[2] / mo[1];
  c.rho_roll = mo[3] / (T(2) * mo[1]);
  return c;
}

// The consistency bounds of docs/physics.md §3 for sigma0 >= 0:
//   a <= 4, b >= 4, ((1+kappa)/d22)^2 <= m <= ((1+kappa)/d22)^2 sqrt(b)/2.
struct ConsistencyCheck {
  bool a_at_most_4, b_at_least_4, m_lower, m_upper;
  bool all() const { return a_at_most_4 && b_at_least_4 && m_lower && m_upper; }
};

inline ConsistencyCheck check_consistency(const Coefficients<double>& c, double kappa,
                                          double alpha = 0.0, double rel_slack = 1e-12) {
  const double r = (1.0 + kappa) / d22(kappa, alpha);
  const double lo = r * r, hi = r * r * std::sqrt(c.b) / 2.0;
  return {c.a <= 4.0 * (1 + rel_slack), c.b >= 4.0 * (1 - rel_slack), c.m >= lo * (1 - rel_slack),
          c.m <= hi * (1 + rel_slack)};
}

}  // namespace frictionid::model
