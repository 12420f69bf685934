// Integration of the towed wheel (docs/physics.md §10) through its slip and stick phases.
//
// Slip: the contact slips with s = (u_y, omega R) != 0 and resists with the model's resultants at
// v_x = 0, v_y = u_y, omega = psi' (10.2); adaptive Dormand–Prince 5(4) with dense output, and
// the implicit Rosenbrock method RODAS where the friction makes the system stiff (§10.8: the
// explicit steps held at their stability limit), the energy account (10.6) integrated as extra
// states. The friction depends on the direction of s
// only, so the right-hand side is smooth while s != 0 and jumps where s passes through 0; a step
// over which s reverses (s0.s1 < 0) is rejected, so that the integrator closes in on the
// instant where |s| vanishes (reached in finite time, like the coasting disk of §4) with
// geometrically shrinking steps instead of grinding through the jump.
// The switch: when |s| <= stick_threshold s_ref the state is projected onto s = 0 (psi' = 0,
// y' = V tan psi; a rigid strut: psi = 0) and the cohesion test (10.3) decides: the constraint
// loads of the stick phase inside the friction limit -> stick; else slip starts again in the
// direction (10.4) in which the excess load drives it (the friction of that direction held until
// |s| has grown past the threshold).
// Stick: psi stays, y drifts at y' = V tan psi, the constraint loads are affine in y; the phase
// ends where the cohesion margin crosses zero (bisection in y), in closed form otherwise.
// The small velocity changes of the projections and seeds are charged to the contact work (they
// are the contact's impulses), so the energy balance (10.6) closes exactly in every phase.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <frictionid/model/dopri5_dense.hpp>
#include <frictionid/model/kinematics.hpp>
#include <frictionid/model/rosenbrock_rodas.hpp>
#include <frictionid/model/shimmy_limit_curve.hpp>
#include <frictionid/model/shimmy_outcome.hpp>
#include <frictionid/model/shimmy_wheel.hpp>

namespace frictionid::model {

enum class ShimmyContactLaw { Friction, Nonholonomic };

struct ShimmyStart {
  double y = 0.0, y_dot = 0.0, psi = 0.0, psi_dot = 0.0;
};

struct ShimmySettings {
  double duration = 2.0;
  double rtol = 1e-10, atol = 1e-10;  // atol relative to each state's scale (ShimmyScales)
  double output_step = 0.0;           // > 0: rows at k output_step; 0: every accepted step
  bool record = false;                // call the row sink at all
  double stick_threshold = 1e-5;      // |s| <= this s_ref ends a slip phase; the cohesion
                                      // test's tolerance, relative to the friction's scale
  double cycle_tol = 1e-3;            // relative amplitude change of a limit cycle per cycle
  bool stop_at_limit_cycle = false;   // end the run once the limit cycle is found (sweeps)
  double rest_angle = 1e-9;           // a stick phase with |psi| <= this is rest [rad]
  long max_steps = 20'000'000;        // accepted + rejected steps
  bool stiff_switching = true;        // implicit (RODAS) steps where the friction is stiff
  ShimmyContactLaw law = ShimmyContactLaw::Friction;
};

// The size of each state's motion, from the start and the wheel's own rates: the integrator's
// absolute tolerances, and the test's yardstick.
struct ShimmyScales {
  double psi, y, y_dot, psi_dot, energy, slip, rate;
  double of(int i) const {
    switch (i) {
      case kSY:
        return y;
      case kSYDot:
        return y_dot;
      case kSPsi:
        return psi;
      case kSPsiDot:
        return psi_dot;
      default:
        return energy;
    }
  }
};

inline ShimmyScales shimmy_scales(const ShimmyWheel& w, const ShimmyStart& s) {
  ShimmyScales c;
  const double L = std::max(std::fabs(w.caster), w.R);
  c.rate = std::max(
      {std::sqrt(w.k_psi / w.J), w.rigid_lateral ? 0.0 : std::sqrt(w.k_y / w.m_y), w.V / L});
  c.psi = std::max({std::fabs(s.psi), std::fabs(s.y) / L, std::fabs(s.psi_dot) / c.rate});
  if (!(c.psi > 0.0)) c.psi = 1e-3;
  c.y = std::max(std::fabs(s.y), c.psi * L);
  c.y_dot = std::max({c.y * c.rate, w.V * c.psi, std::fabs(s.y_dot)});
  c.psi_dot = std::max(c.psi * c.rate, std::fabs(s.psi_dot));
  c.energy = 0.5 * (w.k_psi * c.psi * c.psi + w.J * c.psi_dot * c.psi_dot);
  if (!w.rigid_lateral) c.energy += 0.5 * (w.k_y * c.y * c.y + w.m_y * c.y_dot * c.y_dot);
  c.slip = std::max({w.V * c.psi, w.R * c.psi_dot, c.y_dot});
  return c;
}

struct ShimmyRow {
  double t, y, y_dot, psi, psi_dot, u_y, T_x, T_y, M_z;
};

struct ShimmyRun {
  ShimmyState final{};  // the state and the energy account at t_end
  double t_end = 0.0;
  ShimmyOutcome outcome = ShimmyOutcome::Duration;
  CycleEstimate cycle;
  bool in_stick = false;  // the run ended in a stick phase
  double energy_initial = 0.0, energy_final = 0.0;
  double impulse_work = 0.0;            // the part of the contact work from projections and seeds
  double largest_projected_slip = 0.0;  // max |s|/s_ref where a slip phase was ended
  long forced_switches = 0;    // slip phases ended because the step could not shrink further
  double first_switch = -1.0;  // the end of the first slip phase (-1: none)
  long steps = 0, rejected = 0, evaluations = 0, stick_phases = 0, slip_starts = 0;
  long implicit_steps = 0;      // accepted RODAS steps (stiff phases, §10.8)
  long stiffness_switches = 0;  // changes between the explicit and the implicit method
  bool step_limit = false;      // max_steps reached
  std::vector<PsiExtreme> extremes;
  ShimmyScales scales{};
};

namespace detail {

// Follows the sign of psi' and pushes the extreme of psi between two sign changes.
struct ExtremeTracker {
  int sign = 0;
  PsiExtreme candidate{0.0, 0.0};
  std::vector<PsiExtreme>* out = nullptr;

  void start(double t, double psi) { candidate = {t, psi}; }
  void see(double t, double psi) {
    if ((sign > 0 && psi > candidate.psi) || (sign < 0 && psi < candidate.psi))
      candidate = {t, psi};
  }
  // psi' at t has the sign s (0: ignored). Returns whether an extreme was pushed.
  bool turn(double t, double psi, int s) {
    if (s == 0 || s == sign) {
      see(t, psi);
      return false;
    }
    out->push_back(candidate);
    sign = s;
    candidate = {t, psi};
    return true;
  }
};

inline int sign_of(double x) {
  return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0);
}

}  // namespace detail

// friction: Kinematics -> Resultants<double>, any model, with
// slip_slope(k, dk) -> ContactForces, its derivative along dk (the model's automatic derivative,
// for the implicit steps' Jacobian, §10.8); row: called with each ShimmyRow when settings.record.
template <typename Friction, typename RowSink>
ShimmyRun simulate_shimmy(const Friction& friction, const ShimmyWheel& w, const ShimmyStart& start,
                          const ShimmySettings& set, RowSink&& row) {
  ShimmyRun run;
  const bool nonholonomic = set.law == ShimmyContactLaw::Nonholonomic;
  ShimmyState x{};
  x[kSY] = w.rigid_lateral ? 0.0 : start.y;
  x[kSYDot] = w.rigid_lateral ? 0.0 : start.y_dot;
  x[kSPsi] = start.psi;
  x[kSPsiDot] = start.psi_dot;
  if (nonholonomic) {
    // The constraint u_y = 0 fixes one velocity: psi' = 0 and y' = V tan psi, or with a rigid
    // strut psi' = -V sin psi / e.
    if (w.rigid_lateral)
      x[kSPsiDot] = -w.V * std::sin(x[kSPsi]) / w.caster;
    else
      x[kSYDot] = (w.V * std::sin(x[kSPsi]) + w.caster * x[kSPsiDot]) / std::cos(x[kSPsi]);
  }
  run.energy_initial = shimmy_energy(w, x);
  run.scales = shimmy_scales(w, {x[kSY], x[kSYDot], x[kSPsi], x[kSPsiDot]});
  const ShimmyScales& sc = run.scales;
  std::array<double, 7> abs_tol;
  for (int i = 0; i < 7; ++i) abs_tol[static_cast<std::size_t>(i)] = set.atol * sc.of(i);

  // The limit curve is needed only by the friction law.
  const ShimmyLimitCurve curve =
      nonholonomic
          ? ShimmyLimitCurve([](const Kinematics&) { return Resultants<double>{}; }, w.N, w.R, 4)
          : ShimmyLimitCurve(friction, w.N, w.R);
  const double force_scale = nonholonomic ? 1.0 : std::max(curve.scale(), 1e-300);

  // A slip that starts from s = 0 has the direction theta* of (10.4) until it has grown past the
  // threshold: the friction is taken there, not from the direction of a slip still at rounding
  // level (held < 0: none).
  double held = -1.0;
  double s_hold = 0.0;
  int collapses = 0;  // held slips that fell back to zero in a row
  const auto forces_of = [&](const ShimmyState& s) {
    ++run.evaluations;
    if (nonholonomic) return nonholonomic_forces(w, s);
    const auto sl = spot_slip(w, s);
    if (held >= 0.0 && std::hypot(sl[0], sl[1]) <= s_hold) return curve.at(friction, held);
    const Resultants<double> r = friction(Kinematics{0.0, sl[0], s[kSPsiDot], w.N, w.R});
    return ContactForces{r.T_x, r.T_y, r.M_z};
  };
  const auto rhs = [&](double, const ShimmyState& s) { return shimmy_rate(w, s, forces_of(s)); };
  const auto emit = [&](double t, const ShimmyState& s, const ContactForces& f) {
    row(ShimmyRow{t, s[kSY], s[kSYDot], s[kSPsi], s[kSPsiDot],
                  lateral_slip(w, s[kSYDot], s[kSPsi], s[kSPsiDot]), f.T_x, f.T_y, f.M_z});
  };
  const double T = set.duration;
  const double dt = set.output_step;
  long next_row = 0;  // the next row's index k (rows at k dt)
  const auto rows_until = [&](double t1, auto&& state_at, auto&& forces_at) {
    if (!set.record || !(dt > 0.0)) return;
    for (;; ++next_row) {
      const double tk = static_cast<double>(next_row) * dt;
      if (tk > t1 || tk > T * (1.0 + 1e-15)) break;
      const ShimmyState s = state_at(tk);
      emit(tk, s, forces_at(s));
    }
  };
  const auto row_now = [&](double t, const ShimmyState& s, const ContactForces& f) {
    if (set.record && !(dt > 0.0)) emit(t, s, f);
  };
  const auto s_norm = [&](const ShimmyState& s) {
    const auto sl = spot_slip(w, s);
    return std::hypot(sl[0], sl[1]);
  };
  const double s_stick = set.stick_threshold * sc.slip;

  detail::ExtremeTracker track;
  track.out = &run.extremes;
  track.start(0.0, x[kSPsi]);
  bool done = false;
  const auto after_extreme = [&] {
    if (!set.stop_at_limit_cycle) return;
    if (classify_cycles(run.extremes, set.cycle_tol).outcome == ShimmyOutcome::LimitCycle)
      done = true;
  };

  double t = 0.0;
  bool stick = false;
  // Changes the velocities (and with a rigid strut psi) to `to`, charging the energy change to
  // the contact work.
  const auto impulse = [&](const ShimmyState& to) {
    const double dE = shimmy_energy(w, to) - shimmy_energy(w, x);
    x = to;
    x[kSContactWork] += dE;
    run.impulse_work += dE;
  };
  // The cohesion test's tolerance: within stick_threshold of s = 0 the loads are known to about
  // that fraction of the friction; a stick phase ends at twice it outside (hysteresis).
  const double eta_enter = set.stick_threshold * force_scale;
  // Slip from s = 0 in direction th: the friction of th is held while |s| <= s_stick. Should the
  // slip fall back to zero, or a step from it not be taken (the direction of (10.4) not quite
  // found), the next start is seeded instead: s set to 4 s_stick 2^k along th (k: starts at this
  // instant), the velocity change an impulse.
  const auto start_slip = [&](double th, bool seed, int repeats) {
    ++run.slip_starts;
    if (!seed) {
      held = th;
      s_hold = s_stick;
      return;
    }
    held = -1.0;
    const double s_seed = 4.0 * s_stick * (1 << std::min(repeats, 10));
    ShimmyState q = x;
    q[kSPsiDot] = s_seed * std::sin(th) / w.R;
    q[kSYDot] = (s_seed * std::cos(th) + w.V * std::sin(q[kSPsi]) + w.caster * q[kSPsiDot]) /
                std::cos(q[kSPsi]);
    impulse(q);
  };
  // At |s| ~ 0: project, test cohesion, and either stick (return true) or start the slip.
  int seeds_here = 0;
  double last_seed_t = -1.0;
  const auto at_zero_slip = [&]() -> bool {
    if (run.first_switch < 0.0) run.first_switch = t;
    run.largest_projected_slip = std::max(run.largest_projected_slip, s_norm(x) / sc.slip);
    ShimmyState p = x;
    p[kSPsiDot] = 0.0;
    if (w.rigid_lateral)
      p[kSPsi] = 0.0;
    else
      p[kSYDot] = w.V * std::tan(p[kSPsi]);
    impulse(p);
    if (w.rigid_lateral) return true;  // psi = 0: the contact holds with T_y = M_z = 0
    const ContactForces W = stick_forces(w, x);
    const auto m = curve.margin(friction, W);
    if (m.value >= -eta_enter) return true;
    // Slip restarts in direction (10.4); a seed that keeps falling back is a stall.
    seeds_here = t - last_seed_t <= 1e-12 * std::max(T, 1.0) ? seeds_here + 1 : 0;
    last_seed_t = t;
    const double th = slip_start_direction(friction, curve, w, x, m.theta);
    start_slip(th, collapses > 0, seeds_here);
    return false;
  };

  // The stick phase from t: y drifts at V tan psi until the margin falls below -eta or the run
  // ends. Returns with t at its end (and the slip seeded) or done.
  const auto stick_phase = [&] {
    ++run.stick_phases;
    stick = true;
    const ShimmyState s0 = x;
    const double v = x[kSYDot];
    if (w.rigid_lateral || v == 0.0 || std::fabs(x[kSPsi]) <= set.rest_angle) {
      // Rest: nothing changes any more.
      rows_until(
          T, [&](double) { return s0; }, [&](const ShimmyState& s) { return stick_forces(w, s); });
      run.outcome = ShimmyOutcome::Rest;
      t = T;
      done = true;
      return;
    }
    const double eta = 2.0 * eta_enter;
    const auto margin_at = [&](double y) {
      ShimmyState s = s0;
      s[kSY] = y;
      return curve.margin(friction, stick_forces(w, s)).value + eta;
    };
    const double y0 = s0[kSY];
    double y1 = y0 + v * (T - t);
    double t1 = T;
    if (margin_at(y1) < 0.0) {
      double a = y0, b = y1;
      for (int it = 0; it < 200 && a != b; ++it) {
        const double mid = 0.5 * (a + b);
        if (mid == a || mid == b) break;
        (margin_at(mid) >= 0.0 ? a : b) = mid;
      }
      y1 = b;
      t1 = std::min(T, t + (y1 - y0) / v);
    }
    const auto state_at = [&](double tk) {
      ShimmyState s = s0;
      s[kSY] = y0 + v * (tk - t);
      return s;
    };
    rows_until(t1, state_at, [&](const ShimmyState& s) { return stick_forces(w, s); });
    const double dt_stick = t1 - t;
    x[kSY] = y1;
    x[kSDamping] += w.c_y * v * v * dt_stick;
    x[kSContactWork] += 0.5 * w.k_y * (y1 * y1 - y0 * y0) + w.c_y * v * v * dt_stick;
    t = t1;
    track.see(t, x[kSPsi]);
    row_now(t, x, stick_forces(w, x));
    if (t >= T) {
      done = true;
      return;
    }
    stick = false;
    const ContactForces W = stick_forces(w, x);
    const auto m = curve.margin(friction, W);
    start_slip(slip_start_direction(friction, curve, w, x, m.theta), false, 0);
  };

  // Slip is where the run starts unless s = 0 already.
  if (!nonholonomic && s_norm(x) <= s_stick) {
    if (at_zero_slip()) stick_phase();
  }
  ShimmyState f = rhs(t, x);
  if (!done) {
    if (set.record) {
      if (dt > 0.0)
        rows_until(
            0.0, [&](double) { return x; }, forces_of);
      else
        row_now(t, x, forces_of(x));
    }
  }
  const double h_max = 0.05 / sc.rate;
  double h = std::min(1e-3 / sc.rate, h_max);
  bool last_rejected = false;
  double held_start_slip = 0.0;  // |s| after the last step while the direction is held

  // Stiffness (§10.8): the friction's direction turns at a rate ~ 1/|s| near s = 0. Its size is
  // the largest row sum of the Jacobian of the motion (y, y', psi, psi'), each state in its own
  // scale; an explicit step h is stable only while stiffness * h stays below about 3. Where the
  // explicit steps are held there, the implicit RODAS steps take over, with the Jacobian of
  // (10.2) and the friction's slope in theta; they hand back once stiffness * h < 1/2.

  // The last Jacobian, reused while the state and the held direction are those it was made at.
  OdeMatrix<7> J_cached{};
  ShimmyState J_state{};
  double J_held = 0.0;
  bool J_valid = false;
  const auto jacobian_at = [&](const ShimmyState& s) {
    if (J_valid && s == J_state && held == J_held) return J_cached;
    const auto sl = spot_slip(w, s);
    const double sn = std::hypot(sl[0], sl[1]);
    const bool held_here = held >= 0.0 && sn <= s_hold;
    const ContactForces F = forces_of(s);
    ContactForces dF{};
    if (!held_here && sn > 0.0) {
      run.evaluations += 1;
      dF = curve.slope(friction, std::atan2(sl[1], sl[0]));
    }
    J_cached = shimmy_jacobian(w, s, F, dF);
    J_state = s;
    J_held = held;
    J_valid = true;
    return J_cached;
  };
  const auto stiffness_of = [&](const OdeMatrix<7>& J) {
    double worst = 0.0;
    for (std::size_t i = w.rigid_lateral ? 2 : 0; i < 4; ++i) {
      double row_sum = 0.0;
      for (std::size_t j = w.rigid_lateral ? 2 : 0; j < 4; ++j)
        row_sum += std::fabs(J[i][j]) * sc.of(static_cast<int>(j));
      worst = std::max(worst, row_sum / sc.of(static_cast<int>(i)));
    }
    return worst;
  };
  const bool may_switch = set.stiff_switching && !nonholonomic;
  bool implicit = false;
  int calm_steps = 0;  // implicit steps in a row that an explicit method could take
  Dopri5DenseStep<7> st_explicit;
  RodasStep<7> st_implicit;
  const auto dense_at = [&](double tk) {
    return implicit ? st_implicit.at(tk) : st_explicit.at(tk);
  };
  while (!done && t < T) {
    if (run.steps + run.rejected >= set.max_steps) {
      run.step_limit = true;
      break;
    }
    h = std::min({h, h_max, T - t});
    if (implicit) {
      st_implicit = rodas_step<7>(rhs, t, x, f, jacobian_at(x), h);
    } else {
      st_explicit = dopri5_dense_step<7>(rhs, t, x, f, h);
    }
    const ShimmyState& y1 = implicit ? st_implicit.y1 : st_explicit.y1;
    const ShimmyState& e1 = implicit ? st_implicit.error : st_explicit.error;
    double err = 0.0;
    bool finite = !implicit || st_implicit.ok;
    for (std::size_t i = 0; i < 7; ++i) {
      const double scale = abs_tol[i] + set.rtol * std::max(std::fabs(x[i]), std::fabs(y1[i]));
      const double r = e1[i] / scale;
      err += r * r;
      finite = finite && std::isfinite(y1[i]);
    }
    err = std::sqrt(err / 7.0);
    // The error exponent: 1/(order + 1) of the embedded solution (explicit 4, implicit 3).
    const double exponent = implicit ? -0.25 : -0.2;
    bool reversed = false;
    if (!nonholonomic) {
      const auto a = spot_slip(w, x), b = spot_slip(w, y1);
      reversed = a[0] * b[0] + a[1] * b[1] < 0.0;
    }
    if (!finite || !(err <= 1.0) || reversed) {
      ++run.rejected;
      h *= reversed || !finite ? 0.25 : std::max(0.2, 0.9 * std::pow(err, exponent));
      last_rejected = true;
      if (h <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(t, 1.0 / sc.rate)) {
        // The step cannot shrink further: s is at its zero however small it still is.
        if (!nonholonomic) {
          ++run.forced_switches;
          ++collapses;  // a held start that cannot be followed: seed the next one
          held = -1.0;
        }
        if (!nonholonomic && at_zero_slip()) {
          stick_phase();
        }
        held_start_slip = 0.0;
        f = rhs(t, x);
        h = 1e-6 / sc.rate;
      }
      continue;
    }
    ++run.steps;
    if (implicit) ++run.implicit_steps;
    const double t1 = t + h;
    rows_until(t1, dense_at, forces_of);
    // Extremes of psi: psi' changing sign within the step is located on the dense output.
    const int s1 = detail::sign_of(y1[kSPsiDot]);
    if (s1 != 0 && track.sign != 0 && s1 != track.sign &&
        detail::sign_of(x[kSPsiDot]) == track.sign) {
      double a = t, b = t1;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (a + b);
        (detail::sign_of(dense_at(mid)[kSPsiDot]) == track.sign ? a : b) = mid;
      }
      track.see(0.5 * (a + b), dense_at(0.5 * (a + b))[kSPsi]);
    }
    t = t1;
    x = y1;
    f = implicit ? rhs(t, x) : st_explicit.f1;
    if (track.turn(t, x[kSPsi], s1)) after_extreme();
    row_now(t, x, forces_of(x));
    if (std::fabs(x[kSPsi]) > 0.5 * M_PI) {
      run.outcome = ShimmyOutcome::Growing;
      done = true;
      break;
    }
    double factor = err > 0.0 ? 0.9 * std::pow(err, exponent) : 5.0;
    factor = std::min(5.0, std::max(0.2, factor));
    if (last_rejected) factor = std::min(1.0, factor);
    last_rejected = false;
    const double h_taken = h;
    h *= factor;
    // The switch between the methods, on the step just taken (its size is what the explicit
    // method could afford, or what the implicit one needed).
    if (may_switch) {
      const auto sl = spot_slip(w, x);
      const bool near_zero = std::hypot(sl[0], sl[1]) < 0.1 * sc.slip;
      if (!implicit && near_zero && stiffness_of(jacobian_at(x)) * h_taken > 2.5) {
        implicit = true;
        calm_steps = 0;
        ++run.stiffness_switches;
      } else if (implicit) {
        const bool calm = !near_zero || stiffness_of(jacobian_at(x)) * h_taken < 0.5;
        calm_steps = calm ? calm_steps + 1 : 0;
        if (calm_steps >= 4) {
          implicit = false;
          ++run.stiffness_switches;
        }
      }
    }
    const double sn = nonholonomic ? 0.0 : s_norm(x);
    const bool fell_back = held >= 0.0 && sn < held_start_slip;
    if (held >= 0.0 && sn > s_hold) {
      held = -1.0;  // the slip has its own direction now
      collapses = 0;
    }
    held_start_slip = sn;
    if (!nonholonomic && (fell_back || (held < 0.0 && sn <= s_stick))) {
      collapses = fell_back ? collapses + 1 : 0;
      held = -1.0;
      if (at_zero_slip()) stick_phase();
      held_start_slip = 0.0;
      if (!done) {
        f = rhs(t, x);
        h = std::min(h, 1e-6 / sc.rate);
      }
    }
  }
  run.t_end = t;
  run.final = x;
  run.in_stick = stick;
  run.energy_final = shimmy_energy(w, x);
  if (run.outcome != ShimmyOutcome::Rest) {
    const bool turned_over = run.outcome == ShimmyOutcome::Growing;
    // The candidate extreme still open at the end is not an extreme.
    run.cycle = classify_cycles(run.extremes, set.cycle_tol);
    run.outcome = turned_over ? ShimmyOutcome::Growing : run.cycle.outcome;
    // A run that ends with the contact holding the fork off centre is not oscillating any more,
    // whatever its last cycles did.
    if (run.outcome == ShimmyOutcome::Duration && stick) run.cycle.detail = DurationDetail::Holding;
  }
  return run;
}

}  // namespace frictionid::model
