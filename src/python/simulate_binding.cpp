// The sliding-spinning body of `frictionid simulate` (docs/physics.md §4): app::simulate's checks
// and integration, returned as the summary and the trajectory's columns.
#include <optional>

#include <pybind11/stl.h>

#include "app/simulation.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"
#include "python/numpy_columns.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

py::dict simulate(const std::string& model, const std::string& pressure,
                  const app::ParameterValues& params, double inertia_ratio, double v0,
                  double omega0, double slip_angle_deg, double mass, double R,
                  std::optional<double> N, double tol, double stop_fraction, long max_steps,
                  bool trajectory, const std::string& contact, bool pressure_given) {
  app::SimulateRequest r;
  r.model = {model, pressure, params, contact, pressure_given};
  r.inertia_ratio = inertia_ratio;
  r.v0 = v0;
  r.omega0 = omega0;
  r.slip_angle_deg = slip_angle_deg;
  r.mass = mass;
  r.R = R;
  r.N = N;
  r.tol = tol;
  r.stop_fraction = stop_fraction;
  r.max_steps = max_steps;
  r.trajectory = trajectory;
  app::SimulationOutcome outcome;
  {
    py::gil_scoped_release release;
    outcome = app::simulate(r);
  }
  py::dict out(to_python(outcome.summary));
  if (trajectory) {
    std::vector<double> cols[9];
    for (auto& c : cols) c.reserve(outcome.sim.trajectory.size());
    for (const auto& p : outcome.sim.trajectory) {
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
        py::arg("max_steps"), py::arg("trajectory"), py::arg("contact") = "circle",
        py::arg("pressure_given") = true);
}

}  // namespace frictionid::python
