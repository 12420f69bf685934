// The local (differential) anisotropic Coulomb law, docs/physics.md §1:
//   tau = -sigma f D v_Sigma/|v_Sigma|,  v_Sigma = v + omega e3 x r,  D = diag(1, kappa).
// Used by tests and tools that integrate the law directly; the models integrate it in closed form.
#pragma once

#include <cmath>

namespace frictionid::model {

template <typename T>
struct Vec2 {
  T x, y;
};

// Sliding velocity of the contact point r = (x, y) for centre velocity v and spin omega.
template <typename T>
Vec2<T> slip_velocity_at(const T& v_x, const T& v_y, const T& omega, const T& x, const T& y) {
  return {v_x - omega * y, v_y + omega * x};
}

// Friction stress at a point with pressure sigma. Zero where the point does not slip (the
// instantaneous centre): the law leaves tau undetermined there and it carries no area.
template <typename T>
Vec2<T> local_traction(const T& sigma, const T& f, const T& kappa, const Vec2<T>& v_sigma) {
  using std::sqrt;
  const T speed2 = v_sigma.x * v_sigma.x + v_sigma.y * v_sigma.y;
  if (!(speed2 > 0.0)) return {T(0), T(0)};
  const T inv = T(1) / sqrt(speed2);
  return {-sigma * f * v_sigma.x * inv, -sigma * f * kappa * v_sigma.y * inv};
}

// Tilted pressure sigma0(rho) (1 + h rho cos(theta)) (docs/physics.md §1).
template <typename T>
T tilted_pressure(const T& sigma0, const T& h, const T& rho, const T& cos_theta) {
  return sigma0 * (T(1) + h * rho * cos_theta);
}

}  // namespace frictionid::model
