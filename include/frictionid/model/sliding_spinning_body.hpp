// Dynamics of a flat sliding–spinning body on a horizontal plane (docs/physics.md §4):
//   M_b dv/dt = -T(v, omega)   (vector, any slip direction),   I domega/dt = -M_z(v, omega),
// with the friction from any model (a callable Kinematics -> Resultants<double>). The principal
// axes x, y of the friction tensor (and the tilt h) are fixed in the plane; the body's own
// rotation angle does not enter the friction.
//
// Friction depends on (v, omega) only through the slip direction and eps = v/(|omega| R), so the
// right-hand side is homogeneous of degree 0 and both motions stop at a finite time, where an
// integrator in physical time would have to resolve the direction and eps on an ever shorter
// time scale. We therefore integrate in the rescaled time
//   d tau = a0 dt / |y|,   y = (v_x, v_y, u), u = omega R,
// (a0 = |dy/dt| at the start) in which the direction y/|y| and ln|y| obey an autonomous system
// with O(1) rates: the stop lies at tau = inf, ln|y| falls linearly there, and the direction
// (hence eps) converges exponentially to its terminal value. The integration ends when |y| has
// fallen to stop_fraction of its initial value and the direction has stopped changing (it may
// converge more slowly than |y| falls; in tau that costs a few steps, not a stall); the little
// time that remains is extrapolated from the last decelerations (t_stop = t + v/|dv/dt|),
// separately for sliding and spinning. Physical time, sliding path and turned angle are carried
// along as quadratures.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <frictionid/model/dormand_prince.hpp>
#include <frictionid/model/kinematics.hpp>

namespace frictionid::model {

struct BodyProperties {
  double mass = 1.0;           // M_b [kg]
  double inertia_ratio = 0.5;  // I/(M_b R^2): 1/2 uniform disk, 1 thin ring
  double R = 1.0;              // contact radius [m] (I is taken about the spot's centre)
  double N = 9.81;             // normal load [N]
};

struct BodyInitialState {
  double v_x = 0.0, v_y = 0.0, omega = 0.0;  // [m/s], [m/s], [rad/s]
};

struct BodySimulationSettings {
  double tol = 1e-10;            // rtol = atol of the rescaled system (all components O(1))
  double stop_fraction = 1e-12;  // end when |(v, omega R)| < stop_fraction |(v0, omega0 R)|
  double direction_tol = 1e-10;  // ... and |d(direction)/d tau| < direction_tol (eps settled)
  long max_steps = 200000;
  bool record = true;  // keep every accepted step in trajectory
};

struct BodySample {
  double t, v_x, v_y, omega, eps, T_x, T_y, M_z, energy;
};

struct BodySimulation {
  std::vector<BodySample> trajectory;  // initial state and every accepted step
  bool stopped = false;                // reached stop_fraction (else: step or size limits)
  double t_end = 0.0;                  // last integrated time
  double t_stop_slide = 0.0, t_stop_spin = 0.0;  // extrapolated stop times
  double eps_final = 0.0;                        // eps at the last step (inf: no spin left)
  double slip_angle_final = 0.0;                 // direction of v at the last step [rad]
  double energy_initial = 0.0;                   // (M_b v^2 + I omega^2)/2
  double distance = 0.0;                         // sliding path length [m]
  double rotation = 0.0;                         // angle turned [rad], signed
  OdeStats stats;
};

namespace detail {

constexpr double kMinLogSpeed = -600.0;  // ln(|y|/s0) below which the direction is not refined

// Decelerations A = dy/dt of y = (v_x, v_y, omega R) at a unit-speed point of direction z.
template <typename Friction>
std::array<double, 3> body_acceleration(const Friction& friction, const BodyProperties& b,
                                        const std::array<double, 3>& z) {
  const Kinematics k{z[0], z[1], z[2] / b.R, b.N, b.R};
  const Resultants<double> r = friction(k);
  return {-r.T_x / b.mass, -r.T_y / b.mass, -r.M_z / (b.inertia_ratio * b.mass * b.R)};
}

inline double eps_of(double v, double u) {
  return u != 0.0 ? v / std::fabs(u) : (v > 0.0 ? HUGE_VAL : 0.0);
}

}  // namespace detail

template <typename Friction>
BodySimulation simulate_sliding_spinning_body(const Friction& friction, const BodyProperties& b,
                                              const BodyInitialState& init,
                                              const BodySimulationSettings& settings) {
  if (!(b.mass > 0.0) || !(b.inertia_ratio > 0.0) || !(b.R > 0.0) || !(b.N > 0.0))
    throw std::invalid_argument("mass, inertia ratio, R and N must be > 0");
  const double u0 = init.omega * b.R;
  const double s0 = std::sqrt(init.v_x * init.v_x + init.v_y * init.v_y + u0 * u0);
  if (!(s0 > 0.0) || !std::isfinite(s0))
    throw std::invalid_argument("the body must be moving (v0 or omega0 != 0, finite)");
  const std::array<double, 3> z0{init.v_x / s0, init.v_y / s0, u0 / s0};
  const auto A0 = detail::body_acceleration(friction, b, z0);
  const double a0 = std::sqrt(A0[0] * A0[0] + A0[1] * A0[1] + A0[2] * A0[2]);
  if (!(a0 > 0.0) || !std::isfinite(a0))
    throw std::domain_error("no friction at the initial state: the body never stops");
  const double inertia = b.inertia_ratio * b.mass * b.R * b.R;

  // w = (z_x, z_y, z_u, L, t_hat, dist_hat, angle_hat): z the direction of y (|z| = 1 is a
  // first integral), L = ln(|y|/s0), and t = t_hat s0/a0, distance = dist_hat s0^2/a0,
  // rotation = angle_hat s0^2/(a0 R), all O(1).
  using W = OdeVector<double, 7>;
  const auto rhs = [&](double, const W& w) {
    const double zn2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    const double zn = std::sqrt(zn2);
    const std::array<double, 3> z{w[0] / zn, w[1] / zn, w[2] / zn};
    const auto A = detail::body_acceleration(friction, b, z);
    const std::array<double, 3> a{A[0] / a0, A[1] / a0, A[2] / a0};
    const double za = (w[0] * a[0] + w[1] * a[1] + w[2] * a[2]) / zn2;
    const double e = std::exp(w[3]);
    W d;
    for (int i = 0; i < 3; ++i) d[i] = a[i] - w[i] * za;
    d[3] = za * zn;
    d[4] = e;
    d[5] = e * e * std::hypot(z[0], z[1]);
    d[6] = e * e * z[2];
    return d;
  };

  BodySimulation out;
  out.energy_initial = 0.5 * b.mass * (init.v_x * init.v_x + init.v_y * init.v_y) +
                       0.5 * inertia * init.omega * init.omega;
  const double log_stop = std::log(settings.stop_fraction);
  const auto state_of = [&](const W& w) {
    const double zn = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double s = s0 * std::exp(w[3]) / zn;
    return std::array<double, 3>{s * w[0], s * w[1], s * w[2]};
  };
  const auto record = [&](const W& w) {
    const auto y = state_of(w);
    const double zn = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const Resultants<double> r =
        friction(Kinematics{w[0] / zn, w[1] / zn, w[2] / (zn * b.R), b.N, b.R});
    const double omega = y[2] / b.R;
    const double v2 = y[0] * y[0] + y[1] * y[1];
    out.trajectory.push_back({w[4] * s0 / a0, y[0], y[1], omega,
                              detail::eps_of(std::sqrt(v2), y[2]), r.T_x, r.T_y, r.M_z,
                              0.5 * b.mass * v2 + 0.5 * inertia * omega * omega});
  };
  W last{};
  bool below_stop = false;  // the trajectory keeps the steps down to stop_fraction, then the last
  const auto observe = [&](double, const W& w, const W& dw) {
    last = w;
    const bool recorded = settings.record && !below_stop;
    if (recorded) record(w);
    below_stop = below_stop || w[3] <= log_stop;
    // Done when the speed has fallen far enough and the direction (hence eps) has settled; in
    // tau the direction keeps converging at its own rate however small the speeds are, so the
    // second condition costs a few cheap steps (L is bounded only to keep exp(L) > 0).
    const double dz = std::sqrt(dw[0] * dw[0] + dw[1] * dw[1] + dw[2] * dw[2]);
    const bool settled = dz <= settings.direction_tol || w[3] < detail::kMinLogSpeed;
    const bool done = below_stop && settled;
    if (done && settings.record && !recorded) record(w);
    return !done;
  };
  OdeSettings ode;
  ode.rtol = ode.atol = settings.tol;
  ode.max_steps = settings.max_steps;
  const W w0{z0[0], z0[1], z0[2], 0.0, 0.0, 0.0, 0.0};
  out.stats = dopri5_integrate(rhs, 0.0, w0, ode, observe);
  out.stopped = out.stats.stopped_by_observer;

  // Final state and the extrapolated stops: each speed falls at its current deceleration.
  const auto y = state_of(last);
  const double zn = std::sqrt(last[0] * last[0] + last[1] * last[1] + last[2] * last[2]);
  const auto A = detail::body_acceleration(friction, b, {last[0] / zn, last[1] / zn, last[2] / zn});
  out.t_end = last[4] * s0 / a0;
  out.distance = last[5] * s0 * s0 / a0;
  out.rotation = last[6] * s0 * s0 / (a0 * b.R);
  const double v = std::hypot(y[0], y[1]), u = std::fabs(y[2]);
  out.eps_final = detail::eps_of(v, y[2]);
  out.slip_angle_final = v > 0.0 ? std::atan2(y[1], y[0]) : 0.0;
  const auto remaining = [&](double speed, double rate) {
    // rate = d(speed)/dt < 0 while it stops; a speed that is not falling stays as it is.
    if (speed == 0.0) return 0.0;
    return rate < 0.0 ? speed / -rate : 0.0;
  };
  const double dv = v > 0.0 ? (y[0] * A[0] + y[1] * A[1]) / v : 0.0;
  const double du = y[2] != 0.0 ? std::copysign(1.0, y[2]) * A[2] : 0.0;
  // Sliding or spinning that never started (zero initially and throughout) stops at t = 0.
  out.t_stop_slide = v > 0.0 ? out.t_end + remaining(v, dv)
                             : (init.v_x != 0.0 || init.v_y != 0.0 ? out.t_end : 0.0);
  out.t_stop_spin = u > 0.0 ? out.t_end + remaining(u, du) : (init.omega != 0.0 ? out.t_end : 0.0);
  return out;
}

// A fixed point of eps for slip along a direction the friction keeps (no tilt, and an isotropic
// law or slip along a principal axis): d ln(eps)/dt = (|omega|)^-1 G(eps) with
//   G(eps) = s M_z R/I - T_par/(M_b eps)   at v = eps along alpha, omega = 1/R,
// so the terminal ratio solves T_par/(M_b v) = M_z/(I omega). stable: G falls through zero.
struct EpsFixedPoint {
  double eps;
  bool stable;
};

// Roots of G over eps in [eps_lo, eps_hi]: a log-spaced scan for sign changes, then bisection
// in log(eps) to machine precision. G is the difference of two O(1) rates; where it is below
// noise_rel times their size its sign is taken as unknown, so that a marginal case (G -> 0 like
// eps^2 at small eps, e.g. Hertz pressure with I/(M_b R^2) = 1/2) reports no spurious root.
template <typename Friction>
std::vector<EpsFixedPoint> eps_fixed_points(const Friction& friction, const BodyProperties& b,
                                            double alpha, double eps_lo = 1e-8, double eps_hi = 1e8,
                                            int scan = 400, double noise_rel = 1e-8) {
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  const double inertia = b.inertia_ratio * b.mass * b.R * b.R;
  // G and the size of its two terms.
  const auto G = [&](double eps) {
    const Resultants<double> r = friction(Kinematics{eps * ca, eps * sa, 1.0 / b.R, b.N, b.R});
    const double spin = r.M_z * b.R / inertia;
    const double slide = (r.T_x * ca + r.T_y * sa) / (b.mass * eps);
    return std::array<double, 2>{spin - slide, std::fabs(spin) + std::fabs(slide)};
  };
  // Sign of G in the scan: +1, -1, or 0 where it is lost in the noise.
  const auto sign_of_G = [&](double eps) {
    const auto g = G(eps);
    if (!(std::fabs(g[0]) > noise_rel * g[1])) return 0;
    return g[0] > 0.0 ? 1 : -1;
  };
  std::vector<EpsFixedPoint> roots;
  const double l0 = std::log(eps_lo), l1 = std::log(eps_hi);
  double x_prev = l0;
  int s_prev = sign_of_G(eps_lo);
  for (int i = 1; i <= scan; ++i) {
    const double x = l0 + (l1 - l0) * i / scan;
    const int sg = sign_of_G(std::exp(x));
    if (sg == 0) continue;  // keep the last sample of known sign as the bracket's end
    if (s_prev != 0 && sg != s_prev) {
      double lo = x_prev, hi = x;
      for (int it = 0; it < 200 && hi - lo > 1e-16 * std::max(1.0, std::fabs(lo)); ++it) {
        const double mid = 0.5 * (lo + hi);
        const double gm = G(std::exp(mid))[0];
        if (gm == 0.0) {
          lo = hi = mid;
          break;
        }
        ((gm > 0.0) == (s_prev > 0) ? lo : hi) = mid;
      }
      roots.push_back({std::exp(0.5 * (lo + hi)), s_prev > 0});
    }
    x_prev = x;
    s_prev = sg;
  }
  return roots;
}

}  // namespace frictionid::model
