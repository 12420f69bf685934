#include "app/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include <frictionid/io/input_error.hpp>
#include "app/model_setup.hpp"
#include "io/json_number.hpp"

namespace frictionid::app {

namespace {

constexpr double kStandardGravity = 9.81;  // g of the default N = M_b g [m/s^2]

void require_finite(double x, const char* name, bool positive) {
  if (!std::isfinite(x) || (positive && !(x > 0.0)))
    throw InputError(std::string(name) + " must be a finite number" + (positive ? " > 0" : ""));
}

void check(const SimulateRequest& r) {
  if (!r.inertia_ratio) throw InputError("simulate needs --inertia-ratio I/(M_b R^2)");
  require_finite(*r.inertia_ratio, "--inertia-ratio", true);
  require_finite(r.mass, "--mass", true);
  require_finite(r.R, "--R", true);
  if (r.N) require_finite(*r.N, "--N", true);
  require_finite(r.v0, "--v0", false);
  if (r.v0 < 0.0) throw InputError("--v0 is a speed and must be >= 0 (use --slip-angle 180)");
  require_finite(r.omega0, "--omega0", false);
  require_finite(r.slip_angle_deg, "--slip-angle", false);
  if (r.v0 == 0.0 && r.omega0 == 0.0)
    throw InputError("--v0 and --omega0 are both 0: the body is at rest");
  // The state's norm and the kinetic energy square the speeds: past 1e150 they overflow.
  constexpr double kMaxSpeed = 1e150;
  if (std::fabs(r.v0) > kMaxSpeed || std::fabs(r.omega0 * r.R) > kMaxSpeed)
    throw InputError(fmt::format(
        "--v0 and --omega0 R must be at most 1e150 (got v0 = {:g}, omega0 R = {:g}): the "
        "kinetic energy of a faster body overflows a double",
        r.v0, r.omega0 * r.R));
  if (!(r.tol >= 1e-14 && r.tol <= 1e-3)) throw InputError("--tol must be in [1e-14, 1e-3]");
  if (!(r.stop_fraction >= 1e-15 && r.stop_fraction <= 1e-3))
    throw InputError("--stop-fraction must be in [1e-15, 1e-3]");
  if (r.max_steps < 1) throw InputError("--max-steps must be >= 1");
}

// The terminal ratio as a root of d(eps)/dt = 0, where it is defined: without tilt the direction
// is kept by an isotropic law or slip along a principal axis (with both motions present; pure
// sliding or spinning keeps eps at inf or 0). The stable root nearest to eps_final; null when
// there is none (eps -> 0 or inf).
template <typename Friction>
nlohmann::ordered_json eps_fixed_point(const Friction& friction, const ModelSetup& s,
                                       const SimulateRequest& r, const model::BodyProperties& body,
                                       const model::BodySimulation& sim) {
  nlohmann::ordered_json fixed = nullptr;
  const double final_alpha = sim.slip_angle_final;
  const bool on_axis = std::fabs(std::sin(2.0 * final_alpha)) < 1e-6;
  // An ellipse or a rectangle keeps the direction only along its axes (a circle with an
  // isotropic law any direction); a pressure map need not be symmetric.
  const bool circle = s.contact.kind == model::SpotKind::Circle;
  if (s.params[kH] == 0.0 && s.params[kHy] == 0.0 && s.contact.kind != model::SpotKind::Map &&
      ((s.params[kKappa] == 1.0 && circle) || on_axis) && r.omega0 != 0.0 && r.v0 != 0.0) {
    double best = HUGE_VAL;
    for (const auto& root : model::eps_fixed_points(friction, body, final_alpha)) {
      if (!root.stable) continue;
      const double d =
          std::isfinite(sim.eps_final)
              ? std::fabs(std::log(root.eps) - std::log(std::max(sim.eps_final, 1e-300)))
              : -root.eps;
      if (d < best) {
        best = d;
        fixed = root.eps;
      }
    }
  }
  return fixed;
}

}  // namespace

SimulationOutcome simulate(const SimulateRequest& r) {
  const ModelSetup s = make_model_setup(r.model);
  check(r);
  model::BodyProperties body;
  body.mass = r.mass;
  body.inertia_ratio = *r.inertia_ratio;
  body.R = r.R;
  body.N = r.N.value_or(r.mass * kStandardGravity);
  const double alpha = r.slip_angle_deg * M_PI / 180.0;
  const model::BodyInitialState init{r.v0 * std::cos(alpha), r.v0 * std::sin(alpha), r.omega0};
  model::BodySimulationSettings settings;
  settings.tol = r.tol;
  settings.direction_tol = r.tol;
  settings.stop_fraction = r.stop_fraction;
  settings.max_steps = r.max_steps;
  settings.record = r.trajectory || !r.output.empty();

  // A tabulated law is integrated piece by piece between its samples, and an ellipse or a
  // rectangle ray by ray: the integrator's thousands of evaluations pay for a table at once.
  const ModelEvaluator<double> eval(
      s.kind, s.law, s.params.data(),
      s.law.kind == model::PressureKind::Table
          ? ring_table_for(s.kind, s.law, s.params[kN], false, {}, s.contact)
          : nullptr,
      nullptr,
      s.contact.kind == model::SpotKind::Map
          ? s.contact  // integrated cell by cell (35 us) rather than tabulated (3 s)
          : spot_with_table_if_bounded(s.kind, s.law, s.params[kQ], s.params[kN], s.contact));
  const auto friction = [&eval](const model::Kinematics& k) { return eval(k); };
  const auto start = std::chrono::steady_clock::now();
  SimulationOutcome out;
  model::BodySimulation& sim = out.sim;
  try {
    sim = model::simulate_sliding_spinning_body(friction, body, init, settings);
  } catch (const std::domain_error& e) {
    throw InputError(e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::ordered_json j = model_json(s);
  const double t_stop = std::max(sim.t_stop_slide, sim.t_stop_spin);
  j.update(nlohmann::ordered_json{
      {"inertia_ratio", body.inertia_ratio},
      {"mass", body.mass},
      {"R", body.R},
      {"N", body.N},
      {"v0", r.v0},
      {"omega0", r.omega0},
      {"slip_angle_deg", r.slip_angle_deg},
      {"eps0", json_number(r.omega0 != 0.0 ? r.v0 / (std::fabs(r.omega0) * r.R) : HUGE_VAL)},
      {"eps_final", json_number(sim.eps_final)},
      {"eps_fixed_point", eps_fixed_point(friction, s, r, body, sim)},
      {"t_stop_slide", sim.t_stop_slide},
      {"t_stop_spin", sim.t_stop_spin},
      {"t_stop_relative_difference",
       t_stop > 0.0 ? std::fabs(sim.t_stop_slide - sim.t_stop_spin) / t_stop : 0.0},
      {"slip_angle_final_deg", sim.slip_angle_final * 180.0 / M_PI},
      {"distance", sim.distance},
      {"rotation", sim.rotation},
      {"energy_initial", sim.energy_initial},
      {"stopped", sim.stopped},
      {"steps", sim.stats.accepted},
      {"rejected_steps", sim.stats.rejected},
      {"evaluations", sim.stats.evaluations},
      {"tol", r.tol},
      {"stop_fraction", r.stop_fraction},
      {"wall_time_s", wall}});
  out.summary = std::move(j);
  return out;
}

std::string trajectory_csv(const model::BodySimulation& sim) {
  std::string out = "t,v_x,v_y,omega,eps,T_x,T_y,M_z,energy\n";
  for (const auto& s : sim.trajectory)
    fmt::format_to(std::back_inserter(out),
                   "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", s.t,
                   s.v_x, s.v_y, s.omega, s.eps, s.T_x, s.T_y, s.M_z, s.energy);
  return out;
}

}  // namespace frictionid::app
