// One operating point and the resultants the models predict for it (docs/physics.md §1).
#pragma once

#include <cmath>

#include <frictionid/model/scalar_ops.hpp>

namespace frictionid::model {

// Slip velocity of the spot's centre, spin about the normal, normal load, contact radius.
// Kinematics are data, never identified, so they stay double for every scalar type.
struct Kinematics {
  double v_x = 0.0, v_y = 0.0, omega = 0.0, N = 1.0, R = 1.0;
  // The sign of the pressure tilt on this row: -1 turns sigma0 (1 + h x + h_y y) into
  // sigma0 (1 - h x - h_y y), as when the wheel rolls backwards (docs/physics.md §9.2).
  double tilt_sign = 1.0;
};

// Resistance convention (docs/physics.md §1): T = -∫tau dS, M_z = -∫(r x tau).e3 dS,
// M_roll = ∫ sigma x dS (about y), N = ∫ sigma dS, M_tilt = ∫ sigma y dS (about x; zero
// unless the pressure tilts across the rolling direction, docs/physics.md §9.2).
template <typename T>
struct Resultants {
  T T_x, T_y, M_z, M_roll, N;
  T M_tilt = T(0);
};

// The slip geometry shared by every model: speed, direction, spin sign and eps = v/(|omega| R).
struct SlipGeometry {
  double v, cos_alpha, sin_alpha, spin_sign;
  double eps;      // v/(|omega| R); +inf for omega = 0
  double inv_eps;  // 1/eps = |omega| R/v; +inf for v = 0
  bool at_rest;    // v = omega = 0: friction is indeterminate
};

// The slip of a row with v_y = 0 (slip along x, or pure spin), where the direction is exact.
// D is a double for one row, or a vector of doubles for several rows at once, one per lane (the
// packet pass, src/identify/aligned_row_packets.hpp): the same expressions give each lane the
// bits of its row.
template <typename D>
struct AxisSlip {
  D v, cos_alpha, spin_sign, eps, inv_eps;
};

template <typename D>
FRICTIONID_MODEL_INLINE AxisSlip<D> axis_slip(const D& v_x, const D& omega, const D& R) {
  AxisSlip<D> s;
  const D u = magnitude(omega) * R;
  s.v = magnitude(v_x);
  s.cos_alpha = v_x < 0.0 ? -1.0 : 1.0;  // pure spin: any alpha gives the same forces
  s.spin_sign = omega > 0.0 ? 1.0 : (omega < 0.0 ? -1.0 : 0.0);
  s.eps = u > 0.0 ? s.v / u : HUGE_VAL;
  s.inv_eps = s.v > 0.0 ? u / s.v : HUGE_VAL;
  return s;
}

inline SlipGeometry slip_geometry(const Kinematics& k) {
  SlipGeometry g;
  g.at_rest = k.v_x == 0.0 && k.v_y == 0.0 && k.omega == 0.0;
  if (k.v_y == 0.0) {
    const AxisSlip<double> s = axis_slip(k.v_x, k.omega, k.R);
    g.v = s.v;
    g.cos_alpha = s.cos_alpha;
    g.sin_alpha = 0.0;
    g.spin_sign = s.spin_sign;
    g.eps = s.eps;
    g.inv_eps = s.inv_eps;
    return g;
  }
  const double u = std::fabs(k.omega) * k.R;
  g.spin_sign = k.omega > 0.0 ? 1.0 : (k.omega < 0.0 ? -1.0 : 0.0);
  // hypot guards against overflow at a cost; plain sqrt is exact enough for usual magnitudes.
  const double big = std::fmax(std::fabs(k.v_x), std::fabs(k.v_y));
  g.v = big < 1e150 && big > 1e-150 ? std::sqrt(k.v_x * k.v_x + k.v_y * k.v_y)
                                    : std::hypot(k.v_x, k.v_y);
  const double inv_v = 1.0 / g.v;
  g.cos_alpha = k.v_x * inv_v;
  g.sin_alpha = k.v_y * inv_v;
  g.eps = u > 0.0 ? g.v / u : HUGE_VAL;
  g.inv_eps = g.v > 0.0 ? u / g.v : HUGE_VAL;
  return g;
}

}  // namespace frictionid::model
