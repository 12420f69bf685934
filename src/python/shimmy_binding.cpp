// The towed wheel of `frictionid shimmy` (docs/physics.md §10): app::shimmy's checks and
// integration, returned as the summary and the trajectory's columns.
#include <pybind11/stl.h>

#include <cmath>

#include <frictionid/io/input_error.hpp>
#include "app/shimmy.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"
#include "python/numpy_columns.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

// options: the request's numbers by their command-line names without "--" and with "_" for "-"
// (speed, caster, yaw_inertia, ...); text: model, pressure, contact, lateral, contact_law,
// integrator, from_report.
py::dict shimmy(const app::ParameterValues& params, const std::map<std::string, double>& options,
                const std::map<std::string, std::string>& text, bool pressure_given) {
  app::ShimmyRequest r;
  const auto str = [&](const char* name, std::string& target) {
    const auto it = text.find(name);
    if (it != text.end()) target = it->second;
  };
  str("model", r.model.model);
  str("pressure", r.model.pressure);
  str("contact", r.model.contact);
  str("lateral", r.lateral);
  str("contact_law", r.contact_law);
  str("integrator", r.integrator);
  str("from_report", r.from_report);
  r.model.params = params;
  r.model.pressure_given = pressure_given;
  const std::map<std::string, double*> numbers{{"N", &r.N},
                                               {"R", &r.R},
                                               {"speed", &r.speed},
                                               {"caster", &r.caster},
                                               {"yaw_inertia", &r.yaw_inertia},
                                               {"yaw_stiffness", &r.yaw_stiffness},
                                               {"yaw_damping", &r.yaw_damping},
                                               {"lateral_mass", &r.lateral_mass},
                                               {"lateral_stiffness", &r.lateral_stiffness},
                                               {"lateral_damping", &r.lateral_damping},
                                               {"psi0", &r.psi0},
                                               {"y0", &r.y0},
                                               {"duration", &r.duration},
                                               {"output_step", &r.output_step},
                                               {"tol", &r.tol},
                                               {"stick_threshold", &r.stick_threshold},
                                               {"cycle_tol", &r.cycle_tol}};
  for (const auto& [name, value] : options) {
    if (name == "table_directions") {
      if (!(value >= 0.0 && value <= 1048576.0) || value != std::floor(value))
        throw InputError("table_directions must be a whole number from 0 to 1048576");
      r.table_directions = static_cast<int>(value);
      continue;
    }
    const auto it = numbers.find(name);
    if (it == numbers.end()) throw InputError("shimmy(): unknown option '" + name + "'");
    *it->second = value;
  }
  r.trajectory = true;
  app::ShimmyResult result;
  {
    py::gil_scoped_release release;
    result = app::shimmy(r);
  }
  py::dict out(to_python(result.summary));
  std::vector<double> cols[8];
  for (auto& c : cols) c.reserve(result.rows.size());
  for (const auto& p : result.rows) {
    const double row[8] = {p.t, p.y, p.y_dot, p.psi, p.psi_dot, p.u_y, p.T_y, p.M_z};
    for (int k = 0; k < 8; ++k) cols[k].push_back(row[k]);
  }
  const char* names[8] = {"t", "y", "y_dot", "psi", "psi_dot", "u_y", "T_y", "M_z"};
  py::dict t;
  for (int k = 0; k < 8; ++k) t[names[k]] = to_numpy(cols[k]);
  out["trajectory"] = t;
  return out;
}

}  // namespace

void register_shimmy(py::module_& m) {
  m.def("shimmy", &shimmy, py::arg("params"), py::arg("options"), py::arg("text"),
        py::arg("pressure_given"));
}

}  // namespace frictionid::python
