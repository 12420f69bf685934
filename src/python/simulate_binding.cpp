// The sliding-spinning body of `frictionid simulate` (docs/physics.md §4): the same checks and
// integration, returned as a summary and the trajectory's columns.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <pybind11/stl.h>

#include <frictionid/io/input_error.hpp>
#include <frictionid/model/sliding_spinning_body.hpp>
#include <frictionid/model_variant.hpp>
#include "cli/model_setup.hpp"
#include "python/bindings.hpp"
#include "python/numpy_columns.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

constexpr double kStandardGravity = 9.81;  // g of the default N = M_b g [m/s^2], as the CLI

void require_finite(double x, const char* name, bool positive) {
  if (!std::isfinite(x) || (positive && !(x > 0.0)))
    throw InputError(std::string(name) + " must be a finite number" + (positive ? " > 0" : ""));
}

py::dict simulate(const std::string& model, const std::string& pressure,
                  const std::string& param_spec, double inertia_ratio, double v0, double omega0,
                  double slip_angle_deg, double mass, double R, std::optional<double> N, double tol,
                  double stop_fraction, long max_steps, bool trajectory) {
  const cli::ModelSetup s = cli::make_model_setup(model, pressure, param_spec);
  require_finite(inertia_ratio, "--inertia-ratio", true);
  require_finite(mass, "--mass", true);
  require_finite(R, "--R", true);
  if (N) require_finite(*N, "--N", true);
  require_finite(v0, "--v0", false);
  if (v0 < 0.0) throw InputError("--v0 is a speed and must be >= 0 (use --slip-angle 180)");
  require_finite(omega0, "--omega0", false);
  require_finite(slip_angle_deg, "--slip-angle", false);
  if (v0 == 0.0 && omega0 == 0.0)
    throw InputError("--v0 and --omega0 are both 0: the body is at rest");
  if (!(tol >= 1e-14 && tol <= 1e-3)) throw InputError("--tol must be in [1e-14, 1e-3]");
  if (!(stop_fraction >= 1e-15 && stop_fraction <= 1e-3))
    throw InputError("--stop-fraction must be in [1e-15, 1e-3]");
  if (max_steps < 1) throw InputError("--max-steps must be >= 1");

  model::BodyProperties body;
  body.mass = mass;
  body.inertia_ratio = inertia_ratio;
  body.R = R;
  body.N = N.value_or(mass * kStandardGravity);
  const double alpha = slip_angle_deg * M_PI / 180.0;
  const model::BodyInitialState init{v0 * std::cos(alpha), v0 * std::sin(alpha), omega0};
  model::BodySimulationSettings settings;
  settings.tol = tol;
  settings.direction_tol = tol;
  settings.stop_fraction = stop_fraction;
  settings.max_steps = max_steps;
  settings.record = trajectory;

  model::BodySimulation sim;
  {
    py::gil_scoped_release release;
    const ModelEvaluator<double> eval(s.kind, s.law, s.params.data());
    const auto friction = [&eval](const model::Kinematics& k) { return eval(k); };
    try {
      sim = model::simulate_sliding_spinning_body(friction, body, init, settings);
    } catch (const std::domain_error& e) {
      throw InputError(e.what());
    }
  }

  py::dict out;
  out["eps_final"] = sim.eps_final;
  out["t_stop_slide"] = sim.t_stop_slide;
  out["t_stop_spin"] = sim.t_stop_spin;
  out["slip_angle_final_deg"] = sim.slip_angle_final * 180.0 / M_PI;
  out["distance"] = sim.distance;
  out["rotation"] = sim.rotation;
  out["energy_initial"] = sim.energy_initial;
  out["stopped"] = sim.stopped;
  out["steps"] = sim.stats.accepted;
  out["rejected_steps"] = sim.stats.rejected;
  out["evaluations"] = sim.stats.evaluations;
  out["N"] = body.N;
  if (trajectory) {
    std::vector<double> cols[9];
    for (const auto& p : sim.trajectory) {
      const double row[9] = {p.t, p.v_x, p.v_y, p.omega, p.eps, p.T_x, p.T_y, p.M_z, p.energy};
      for (int k = 0; k < 9; ++k) cols[k].push_back(row[k]);
    }
    const char* names[9] = {"t", "v_x", "v_y", "omega", "eps", "T_x", "T_y", "M_z", "energy"};
    py::dict t;
    for (int k = 0; k < 9; ++k) t[names[k]] = to_numpy(cols[k]);
    out["trajectory"] = t;
  }
  return out;
}

}  // namespace

void register_simulate(py::module_& m) {
  m.def("simulate", &simulate, py::arg("model"), py::arg("pressure"), py::arg("params"),
        py::arg("inertia_ratio"), py::arg("v0"), py::arg("omega0"), py::arg("slip_angle_deg"),
        py::arg("mass"), py::arg("R"), py::arg("N"), py::arg("tol"), py::arg("stop_fraction"),
        py::arg("max_steps"), py::arg("trajectory"));
}

}  // namespace frictionid::python
