// The towed wheel of docs/physics.md §10: a king pin moving forward at V and sideways by y (strut
// m_y, k_y, c_y), a fork yawing by psi about it (J, k_psi, c_psi), the contact centre trailing by
// the caster e, and a rigid wheel that rolls freely. Its kinematics (10.1), equations of motion
// (10.2) and energy (10.5) for given contact resultants; no integrator, no model, no I/O.
#pragma once

#include <array>
#include <cmath>

#include <frictionid/model/dormand_prince.hpp>
#include <frictionid/model/rosenbrock_rodas.hpp>

namespace frictionid::model {

struct ShimmyWheel {
  double V = 10.0;                           // forward speed of the king pin [m/s]
  double caster = 0.1;                       // e: the contact centre trails the king pin [m]
  double J = 1.0, k_psi = 1e4, c_psi = 0.0;  // yaw inertia, stiffness, damping of the fork
  double m_y = 10.0, k_y = 1e5, c_y = 0.0;   // lateral mass, stiffness, damping of the strut
  bool rigid_lateral = false;                // --lateral rigid: y = 0 throughout
  double N = 1000.0, R = 0.05;               // normal load [N], contact radius [m]
};

// The contact resultants in the wheel's frame (x_w heading, y_w to its left), resistance
// convention of docs/physics.md §1: the ground pushes the wheel with -T_x x_w - T_y y_w and the
// yaw moment -M_z.
struct ContactForces {
  double T_x = 0.0, T_y = 0.0, M_z = 0.0;
};

// w = (y, y', psi, psi', damping dissipated, contact work, friction dissipated): the motion and
// its energy account (10.6) integrated as extra states.
using ShimmyState = OdeVector<double, 7>;
enum ShimmyIndex { kSY = 0, kSYDot, kSPsi, kSPsiDot, kSDamping, kSContactWork, kSFriction };

// (10.1): lateral sliding velocity of the contact centre along y_w, u_y = -V sin psi +
// y' cos psi - e psi'. The spot spins with omega = psi'.
inline double lateral_slip(const ShimmyWheel& w, double y_dot, double psi, double psi_dot) {
  return -w.V * std::sin(psi) + y_dot * std::cos(psi) - w.caster * psi_dot;
}

// The slip of the spot as one vector s = (u_y, omega R): the friction depends on its direction
// only (docs/physics.md §1), and is undetermined at s = 0.
inline std::array<double, 2> spot_slip(const ShimmyWheel& w, const ShimmyState& x) {
  return {lateral_slip(w, x[kSYDot], x[kSPsi], x[kSPsiDot]), x[kSPsiDot] * w.R};
}

// (10.5): 1/2 m_y y'^2 + 1/2 k_y y^2 + 1/2 J psi'^2 + 1/2 k_psi psi^2.
inline double shimmy_energy(const ShimmyWheel& w, const ShimmyState& x) {
  return 0.5 * w.m_y * x[kSYDot] * x[kSYDot] + 0.5 * w.k_y * x[kSY] * x[kSY] +
         0.5 * w.J * x[kSPsiDot] * x[kSPsiDot] + 0.5 * w.k_psi * x[kSPsi] * x[kSPsi];
}

// The lateral force of the contact on the strut, F_Y = -T_x sin psi - T_y cos psi.
inline double lateral_contact_force(const ContactForces& f, double psi) {
  return -f.T_x * std::sin(psi) - f.T_y * std::cos(psi);
}

// dw/dt under given contact forces: the equations of motion (10.2) and the rates of the energy
// account (10.6). With a rigid strut y and y' stay 0.
inline ShimmyState shimmy_rate(const ShimmyWheel& w, const ShimmyState& x, const ContactForces& f) {
  const double y = x[kSY], yd = x[kSYDot], psi = x[kSPsi], pd = x[kSPsiDot];
  const double F_Y = lateral_contact_force(f, psi);
  const double yaw_moment = w.caster * f.T_y - f.M_z;  // about the king pin
  const double u_y = lateral_slip(w, yd, psi, pd);
  ShimmyState d{};
  if (!w.rigid_lateral) {
    d[kSY] = yd;
    d[kSYDot] = (-w.k_y * y - w.c_y * yd + F_Y) / w.m_y;
  }
  d[kSPsi] = pd;
  d[kSPsiDot] = (-w.k_psi * psi - w.c_psi * pd + yaw_moment) / w.J;
  d[kSDamping] = w.c_y * yd * yd + w.c_psi * pd * pd;
  d[kSContactWork] = yd * F_Y + pd * yaw_moment;
  d[kSFriction] = f.T_y * u_y + f.M_z * pd;
  return d;
}

// The slip direction theta of s = (u_y, omega R) = |s| (cos theta, sin theta) and its gradient
// with respect to (y, y', psi, psi'): d theta = (s1 d s2 - s2 d s1)/|s|^2 with (10.1). It grows
// like 1/|s| towards s = 0: the stiffness of the friction (docs/physics.md §10.8).
inline std::array<double, 4> slip_direction_gradient(const ShimmyWheel& w, const ShimmyState& x) {
  const auto s = spot_slip(w, x);
  const double n2 = s[0] * s[0] + s[1] * s[1];
  if (!(n2 > 0.0)) return {0.0, 0.0, 0.0, 0.0};
  const double psi = x[kSPsi], c = std::cos(psi), sn = std::sin(psi);
  // d s1 = cos psi dy' - (V cos psi + y' sin psi) dpsi - e dpsi';  d s2 = R dpsi'.
  return {0.0, -s[1] * c / n2, s[1] * (w.V * c + x[kSYDot] * sn) / n2,
          (s[0] * w.R + s[1] * w.caster) / n2};
}

// The Jacobian of shimmy_rate with respect to the state, for contact forces f that depend on
// the state through the slip direction only, with slope df = d(T_x, T_y, M_z)/d theta (zero
// when the forces are held fixed). The energy components (4..6) do not act back: their columns
// are zero.
inline OdeMatrix<7> shimmy_jacobian(const ShimmyWheel& w, const ShimmyState& x,
                                    const ContactForces& f, const ContactForces& df) {
  OdeMatrix<7> J{};
  const double yd = x[kSYDot], psi = x[kSPsi], pd = x[kSPsiDot];
  const double c = std::cos(psi), sn = std::sin(psi);
  const std::array<double, 4> dth = slip_direction_gradient(w, x);
  std::array<double, 4> dTx, dTy, dMz, dFY, dyaw, du;
  const double F_Y = lateral_contact_force(f, psi);
  const double yaw_moment = w.caster * f.T_y - f.M_z;
  const double u_y = lateral_slip(w, yd, psi, pd);
  du = {0.0, c, -w.V * c - yd * sn, -w.caster};
  for (std::size_t j = 0; j < 4; ++j) {
    dTx[j] = df.T_x * dth[j];
    dTy[j] = df.T_y * dth[j];
    dMz[j] = df.M_z * dth[j];
    dFY[j] = -sn * dTx[j] - c * dTy[j];
    dyaw[j] = w.caster * dTy[j] - dMz[j];
  }
  dFY[kSPsi] += -f.T_x * c + f.T_y * sn;
  for (std::size_t j = 0; j < 4; ++j) {
    if (!w.rigid_lateral) {
      J[kSY][j] = j == kSYDot ? 1.0 : 0.0;
      J[kSYDot][j] = dFY[j] / w.m_y;
    }
    J[kSPsi][j] = j == kSPsiDot ? 1.0 : 0.0;
    J[kSPsiDot][j] = dyaw[j] / w.J;
    J[kSContactWork][j] = yd * dFY[j] + pd * dyaw[j];
    J[kSFriction][j] = dTy[j] * u_y + f.T_y * du[j] + dMz[j] * pd;
  }
  if (!w.rigid_lateral) {
    J[kSYDot][kSY] -= w.k_y / w.m_y;
    J[kSYDot][kSYDot] -= w.c_y / w.m_y;
  }
  J[kSDamping][kSYDot] = 2.0 * w.c_y * yd;
  J[kSContactWork][kSYDot] += F_Y;
  J[kSPsiDot][kSPsi] -= w.k_psi / w.J;
  J[kSPsiDot][kSPsiDot] -= w.c_psi / w.J;
  J[kSDamping][kSPsiDot] = 2.0 * w.c_psi * pd;
  J[kSContactWork][kSPsiDot] += yaw_moment;
  J[kSFriction][kSPsiDot] += f.M_z;
  return J;
}

// d s/dt = (d u_y/dt, R psi'') under given contact forces.
inline std::array<double, 2> slip_rate(const ShimmyWheel& w, const ShimmyState& x,
                                       const ContactForces& f) {
  const ShimmyState d = shimmy_rate(w, x, f);
  const double psi = x[kSPsi], pd = x[kSPsiDot];
  const double du = -w.V * std::cos(psi) * pd + d[kSYDot] * std::cos(psi) -
                    x[kSYDot] * std::sin(psi) * pd - w.caster * d[kSPsiDot];
  return {du, w.R * d[kSPsiDot]};
}

// The stick phase (docs/physics.md §10.3): u_y = 0 and omega = psi' = 0, so psi stays, y' =
// V tan psi, y'' = psi'' = 0, and the contact carries the constraint forces T_x = 0 (free
// rolling), T_y = (-k_y y - c_y y')/cos psi, M_z = -k_psi psi + e T_y. A rigid strut sticks only
// at psi = 0, where the forces T_y = M_z = 0 hold it.
inline ContactForces stick_forces(const ShimmyWheel& w, const ShimmyState& x) {
  ContactForces f;
  if (w.rigid_lateral) return f;
  f.T_y = (-w.k_y * x[kSY] - w.c_y * x[kSYDot]) / std::cos(x[kSPsi]);
  f.M_z = -w.k_psi * x[kSPsi] + w.caster * f.T_y;
  return f;
}

// The Keldysh baseline (docs/physics.md §10.7): the no-slip constraint u_y = 0 with T_x = M_z = 0
// and the lateral force the constraint needs, from d u_y/dt = 0:
//   T_y (cos^2 psi/m_y + e^2/J) = cos psi Q_y/m_y - e Q_psi/J - psi' (V cos psi + y' sin psi),
// Q_y = -k_y y - c_y y', Q_psi = -k_psi psi - c_psi psi' (1/m_y = 0 with a rigid strut).
inline ContactForces nonholonomic_forces(const ShimmyWheel& w, const ShimmyState& x) {
  const double y = x[kSY], yd = x[kSYDot], psi = x[kSPsi], pd = x[kSPsiDot];
  const double c = std::cos(psi), s = std::sin(psi);
  const double inv_m = w.rigid_lateral ? 0.0 : 1.0 / w.m_y;
  const double Q_y = -w.k_y * y - w.c_y * yd, Q_psi = -w.k_psi * psi - w.c_psi * pd;
  ContactForces f;
  f.T_y = (c * Q_y * inv_m - w.caster * Q_psi / w.J - pd * (w.V * c + yd * s)) /
          (c * c * inv_m + w.caster * w.caster / w.J);
  return f;
}

}  // namespace frictionid::model
