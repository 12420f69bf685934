// Synthetic datasets, as `frictionid generate` makes them (app::generate: same design, noise and
// checks), handed to Python as columns instead of a file.
#include <pybind11/stl.h>

#include "app/generation.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"
#include "python/numpy_columns.hpp"
#include "python/python_observer.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

py::dict generate(const std::string& model, const std::string& pressure,
                  const app::ParameterValues& params, std::size_t rows, double noise,
                  double noise_abs, bool sigma_columns, unsigned long long seed, double eps_min,
                  double eps_max, const std::vector<double>& loads, double R, double spin,
                  const std::vector<double>& slip_angles_deg, bool forward_only,
                  const std::string& contact, bool pressure_given, int threads,
                  const py::object& cancel, const py::object& progress) {
  app::GenerateRequest r;
  r.model = {model, pressure, params, contact, pressure_given};
  r.rows = rows;
  r.noise = noise;
  r.noise_abs = noise_abs;
  r.sigma_columns = sigma_columns;
  r.seed = seed;
  r.eps_min = eps_min;
  r.eps_max = eps_max;
  r.loads = loads;
  r.R = R;
  r.spin = spin;
  r.slip_angles_deg = slip_angles_deg;
  r.forward_only = forward_only;
  r.threads = threads;
  app::GeneratedData g;
  run_observed(cancel, progress, [&](FitObserver& observer) { g = app::generate(r, &observer); });
  py::dict out;
  out["columns"] = dataset_columns(g.data);
  out["truth"] = to_python(app::truth_json(r, g));
  return out;
}

}  // namespace

void register_generate(py::module_& m) {
  m.def("generate", &generate, py::arg("model"), py::arg("pressure"), py::arg("params"),
        py::arg("rows"), py::arg("noise"), py::arg("noise_abs"), py::arg("sigma_columns"),
        py::arg("seed"), py::arg("eps_min"), py::arg("eps_max"), py::arg("loads"), py::arg("R"),
        py::arg("spin"), py::arg("slip_angles_deg"), py::arg("forward_only"),
        py::arg("contact") = "circle", py::arg("pressure_given") = true, py::arg("threads") = 0,
        py::arg("cancel") = py::none(), py::arg("progress") = py::none());
}

}  // namespace frictionid::python
