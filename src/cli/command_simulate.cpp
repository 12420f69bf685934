// frictionid simulate: a flat body sliding and spinning to rest on a plane under the friction of
// any model variant (docs/physics.md §4); JSON summary on stdout, trajectory CSV on request.
#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>

#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include <frictionid/io/input_error.hpp>
#include <frictionid/model/sliding_spinning_body.hpp>
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/model_setup.hpp"
#include "io/atomic_file.hpp"
#include "io/json_number.hpp"

namespace frictionid::cli {

namespace {

constexpr double kStandardGravity = 9.81;  // g of the default N = M_b g [m/s^2]

void require_finite(double x, const char* name, bool positive) {
  if (!std::isfinite(x) || (positive && !(x > 0.0)))
    throw InputError(std::string(name) + " must be a finite number" + (positive ? " > 0" : ""));
}

std::string trajectory_csv(const model::BodySimulation& sim) {
  std::string out = "t,v_x,v_y,omega,eps,T_x,T_y,M_z,energy\n";
  for (const auto& s : sim.trajectory)
    fmt::format_to(std::back_inserter(out),
                   "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", s.t,
                   s.v_x, s.v_y, s.omega, s.eps, s.T_x, s.T_y, s.M_z, s.energy);
  return out;
}

}  // namespace

int run_simulate(const SimulateOptions& o) {
  const ModelSetup s = make_model_setup(o.model, o.pressure, o.params);
  if (!o.inertia_ratio) throw InputError("simulate needs --inertia-ratio I/(M_b R^2)");
  require_finite(*o.inertia_ratio, "--inertia-ratio", true);
  require_finite(o.mass, "--mass", true);
  require_finite(o.R, "--R", true);
  if (o.N) require_finite(*o.N, "--N", true);
  require_finite(o.v0, "--v0", false);
  if (o.v0 < 0.0) throw InputError("--v0 is a speed and must be >= 0 (use --slip-angle 180)");
  require_finite(o.omega0, "--omega0", false);
  require_finite(o.slip_angle_deg, "--slip-angle", false);
  if (o.v0 == 0.0 && o.omega0 == 0.0)
    throw InputError("--v0 and --omega0 are both 0: the body is at rest");
  if (!(o.tol >= 1e-14 && o.tol <= 1e-3)) throw InputError("--tol must be in [1e-14, 1e-3]");
  if (!(o.stop_fraction >= 1e-15 && o.stop_fraction <= 1e-3))
    throw InputError("--stop-fraction must be in [1e-15, 1e-3]");
  if (o.max_steps < 1) throw InputError("--max-steps must be >= 1");

  model::BodyProperties body;
  body.mass = o.mass;
  body.inertia_ratio = *o.inertia_ratio;
  body.R = o.R;
  body.N = o.N.value_or(o.mass * kStandardGravity);
  const double alpha = o.slip_angle_deg * M_PI / 180.0;
  const model::BodyInitialState init{o.v0 * std::cos(alpha), o.v0 * std::sin(alpha), o.omega0};
  model::BodySimulationSettings settings;
  settings.tol = o.tol;
  settings.direction_tol = o.tol;
  settings.stop_fraction = o.stop_fraction;
  settings.max_steps = o.max_steps;
  settings.record = !o.output.empty();

  // A tabulated law is integrated piece by piece between its samples: thousands of steps of the
  // integrator pay for its ring-integral table at once.
  const ModelEvaluator<double> eval(s.kind, s.law, s.params.data(),
                                    s.law.kind == model::PressureKind::Table
                                        ? ring_table_for(s.kind, s.law, s.params[kN], false)
                                        : nullptr);
  const auto friction = [&eval](const model::Kinematics& k) { return eval(k); };
  const auto start = std::chrono::steady_clock::now();
  model::BodySimulation sim;
  try {
    sim = model::simulate_sliding_spinning_body(friction, body, init, settings);
  } catch (const std::domain_error& e) {
    throw InputError(e.what());
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The terminal ratio as a root of d(eps)/dt = 0, where it is defined: without tilt the
  // direction is kept by an isotropic law or slip along a principal axis (with both motions
  // present; pure sliding or spinning keeps eps at inf or 0). The stable root nearest to
  // eps_final is reported; null when there is none (eps -> 0 or inf).
  nlohmann::ordered_json fixed = nullptr;
  const double final_alpha = sim.slip_angle_final;
  const bool on_axis = std::fabs(std::sin(2.0 * final_alpha)) < 1e-6;
  if (s.params[kH] == 0.0 && (s.params[kKappa] == 1.0 || on_axis) && o.omega0 != 0.0 &&
      o.v0 != 0.0) {
    double best = HUGE_VAL;
    for (const auto& r : model::eps_fixed_points(friction, body, final_alpha)) {
      if (!r.stable) continue;
      const double d = std::isfinite(sim.eps_final)
                           ? std::fabs(std::log(r.eps) - std::log(std::max(sim.eps_final, 1e-300)))
                           : -r.eps;
      if (d < best) {
        best = d;
        fixed = r.eps;
      }
    }
  }

  nlohmann::ordered_json j = model_json(s);
  const double t_stop = std::max(sim.t_stop_slide, sim.t_stop_spin);
  j.update(nlohmann::ordered_json{
      {"inertia_ratio", body.inertia_ratio},
      {"mass", body.mass},
      {"R", body.R},
      {"N", body.N},
      {"v0", o.v0},
      {"omega0", o.omega0},
      {"slip_angle_deg", o.slip_angle_deg},
      {"eps0", json_number(o.omega0 != 0.0 ? o.v0 / (std::fabs(o.omega0) * o.R) : HUGE_VAL)},
      {"eps_final", json_number(sim.eps_final)},
      {"eps_fixed_point", fixed},
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
      {"tol", o.tol},
      {"stop_fraction", o.stop_fraction},
      {"wall_time_s", wall}});
  if (!o.output.empty()) {
    write_file_atomically(o.output, trajectory_csv(sim));
    j["trajectory_rows"] = sim.trajectory.size();
  }
  std::cout << j.dump(2) << "\n";
  if (!sim.stopped) {
    std::cerr << "frictionid: error: the integration did not reach the stop within --max-steps "
              << o.max_steps << " steps (or the step size underflowed)\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace frictionid::cli
