// The approximants' coefficients a, b, m, p0 and b_tilde of any contact spot, by the same slope
// matching as the circle's (docs/physics.md §3, §9.6), with slip along x and omega > 0, so that
// the centre of rotation sits at c = (0, eps) (units of R):
//   a:  T_par ~ F0 eps/sqrt(a) as eps -> 0, with dT_x/d eps = f c ∫sigma0 x^2/|r|^3 dA;
//   b:  T_perp ~ h kappa F0/(sqrt(b) eps) as eps -> inf, with T_y ~ f kappa M_roll/(R eps);
//   m:  M ~ M0/(sqrt(m) eps) as eps -> inf, with M_z ~ f c kappa Axx R^3/eps;
//   p0: T_perp(v = 0) = h kappa F0 p0;   b_tilde = p0^2 b.
// For the circle these are (2 m1/m0)^2, (2 m1/m3)^2, ((1 + kappa) m2/(kappa m3))^2, m2/(2 m1)
// and (m2/m3)^2.
#pragma once

#include <optional>

#include <frictionid/model/coefficients.hpp>
#include <frictionid/model/contact_spot.hpp>
#include <frictionid/model/map_strip_integrator.hpp>
#include <frictionid/model/spot_integrals.hpp>

namespace frictionid::model {

inline Coefficients<double> spot_coefficients(const ContactSpot& spot,
                                              const PressureLaw<double>& law, double q,
                                              double kappa) {
  if (spot.kind == SpotKind::Circle) return coefficients(law_moments(law), kappa);
  // A map by its strips and corner sums (map_strip_integrator.hpp): its rays at the fine rules
  // took ~0.15 s a point on a 64 x 64 map, and every model set-up on it asks for three. Each
  // far cell by its own rule: three points do not repay the far cells' blocks (0.07 s there).
  const SpotIntegrator rays(spot, law, q, {&fine_rule(), &fine_rule()});
  std::optional<MapStripIntegrator> strips;
  if (spot.kind == SpotKind::Map && spot.map) strips.emplace(*spot.map);
  auto integrate = [&](double cx, double cy) {
    return strips ? strips->without_blocks(cx, cy) : rays(cx, cy);
  };
  const SpotMoments<double> A = spot_moments(spot, law_moments(law), spot.has_aspect() ? q : 1.0);
  const SpotIntegrals at_centre = integrate(0.0, 0.0);
  // The slope of ex[0] in c_y at 0 by a central difference: the odd part of the integral is
  // linear there up to O(delta^2 ln delta).
  const double delta = 1e-6;
  const double slope = (integrate(0.0, delta).ex[0] - integrate(0.0, -delta).ex[0]) / (2.0 * delta);
  const double spin_torque = kappa * at_centre.x_ey[0] - at_centre.y_ex[0];
  Coefficients<double> c;
  c.a = (A.A0 / slope) * (A.A0 / slope);
  c.b = (A.A0 / A.Axx) * (A.A0 / A.Axx);
  c.m = (spin_torque / (kappa * A.Axx)) * (spin_torque / (kappa * A.Axx));
  c.p0 = at_centre.ey[1] / A.A0;
  c.b_tilde = c.p0 * c.p0 * c.b;
  c.mu_M = (at_centre.x_ey[0] - at_centre.y_ex[0]) / A.A0;
  c.rho_roll = A.Axx / A.A0;
  return c;
}

}  // namespace frictionid::model
