// One operating point and the resultants the models predict for it (docs/physics.md §1).
#pragma once

#include <cmath>

#include <frictionid/model/scalar_ops.hpp>

namespace frictionid::model {

// Slip velocity of the spot's centre, spin about the normal, normal load, contact radius.
// Kinematics are data, never identified: a fit's rows are KinematicsT<double> for every scalar
// type of the parameters. The velocities may be dual numbers instead (K = the parameters' own
// autodiff type), for the derivatives of the resultants along the kinematics that the towed
// wheel's implicit steps need (docs/physics.md §10.8); N and R stay plain numbers.
template <typename K>
struct KinematicsT {
  K v_x = K(0), v_y = K(0), omega = K(0);
  double N = 1.0, R = 1.0;
  // The sign of the pressure tilt on this row: -1 turns sigma0 (1 + h x + h_y y) into
  // sigma0 (1 - h x - h_y y), as when the wheel rolls backwards (docs/physics.md §9.2).
  double tilt_sign = 1.0;
};
using Kinematics = KinematicsT<double>;

// k with velocities that are dual numbers (a Jet with one derivative part) seeded with the
// direction dk: a model evaluated at it gives its resultants and their derivatives along dk.
template <typename Dual>
KinematicsT<Dual> kinematics_along(const Kinematics& k, const Kinematics& dk) {
  const auto seeded = [](double x, double dx) {
    Dual d(x);
    d.v[0] = dx;
    return d;
  };
  return {seeded(k.v_x, dk.v_x),
          seeded(k.v_y, dk.v_y),
          seeded(k.omega, dk.omega),
          k.N,
          k.R,
          k.tilt_sign};
}

// Resistance convention (docs/physics.md §1): T = -∫tau dS, M_z = -∫(r x tau).e3 dS,
// M_roll = ∫ sigma x dS (about y), N = ∫ sigma dS, M_tilt = ∫ sigma y dS (about x; zero
// unless the pressure tilts across the rolling direction, docs/physics.md §9.2).
template <typename T>
struct Resultants {
  T T_x, T_y, M_z, M_roll, N;
  T M_tilt = T(0);
};

// The slip geometry shared by every model: speed, direction, spin sign and eps = v/(|omega| R).
template <typename K>
struct SlipGeometryT {
  K v, cos_alpha, sin_alpha;
  double spin_sign;
  K eps;         // v/(|omega| R); +inf for omega = 0
  K inv_eps;     // 1/eps = |omega| R/v; +inf for v = 0
  bool at_rest;  // v = omega = 0: friction is indeterminate
};
using SlipGeometry = SlipGeometryT<double>;

// The slip of a row with v_y = 0 (slip along x, or pure spin), where the direction is exact.
// D is a double for one row, or a vector of doubles for several rows at once, one per lane (the
// packet pass, src/identify/aligned_row_packets.hpp): the same expressions give each lane the
// bits of its row. Or a dual number, for derivatives along the kinematics.
template <typename D>
struct AxisSlip {
  D v, cos_alpha, spin_sign, eps, inv_eps;
};

template <typename D>
FRICTIONID_MODEL_INLINE AxisSlip<D> axis_slip(const D& v_x, const D& omega, const D& R) {
  AxisSlip<D> s;
  const D u = magnitude(omega) * R;
  s.v = magnitude(v_x);
  s.cos_alpha = select<D>(v_x < 0.0, -1.0, 1.0);  // pure spin: any alpha gives the same forces
  s.spin_sign = select<D>(omega > 0.0, 1.0, select<D>(omega < 0.0, -1.0, 0.0));
  s.eps = select<D>(u > 0.0, s.v / u, HUGE_VAL);
  s.inv_eps = select<D>(s.v > 0.0, u / s.v, HUGE_VAL);
  return s;
}

template <typename K>
SlipGeometryT<K> slip_geometry(const KinematicsT<K>& k) {
  using std::hypot;
  using std::sqrt;
  SlipGeometryT<K> g;
  g.at_rest = k.v_x == 0.0 && k.v_y == 0.0 && k.omega == 0.0;
  if (k.v_y == 0.0) {
    const AxisSlip<K> s = axis_slip(k.v_x, k.omega, K(k.R));
    g.v = s.v;
    g.cos_alpha = s.cos_alpha;
    g.sin_alpha = K(0.0);
    g.spin_sign = value_of(s.spin_sign);
    g.eps = s.eps;
    g.inv_eps = s.inv_eps;
    return g;
  }
  const K u = magnitude(k.omega) * k.R;
  g.spin_sign = k.omega > 0.0 ? 1.0 : (k.omega < 0.0 ? -1.0 : 0.0);
  // hypot guards against overflow at a cost; plain sqrt is exact enough for usual magnitudes.
  const double big = std::fmax(std::fabs(value_of(k.v_x)), std::fabs(value_of(k.v_y)));
  g.v =
      big < 1e150 && big > 1e-150 ? K(sqrt(k.v_x * k.v_x + k.v_y * k.v_y)) : K(hypot(k.v_x, k.v_y));
  const K inv_v = 1.0 / g.v;
  g.cos_alpha = k.v_x * inv_v;
  g.sin_alpha = k.v_y * inv_v;
  g.eps = select<K>(u > 0.0, g.v / u, HUGE_VAL);
  g.inv_eps = select<K>(g.v > 0.0, u / g.v, HUGE_VAL);
  return g;
}

}  // namespace frictionid::model
