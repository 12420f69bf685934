// Synthetic datasets, as `frictionid generate` makes them (same design, noise and checks), handed
// to Python as columns instead of a file.
#include <cmath>

#include <pybind11/stl.h>

#include <frictionid/io/input_error.hpp>
#include <frictionid/synthetic_data.hpp>
#include "cli/model_setup.hpp"
#include "python/bindings.hpp"
#include "python/numpy_columns.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

py::dict generate(const std::string& model, const std::string& pressure,
                  const std::string& param_spec, std::size_t rows, double noise, double noise_abs,
                  bool sigma_columns, unsigned long long seed, double eps_min, double eps_max,
                  const std::vector<double>& loads, double R, double spin,
                  const std::vector<double>& slip_angles_deg, bool forward_only) {
  const cli::ModelSetup s = cli::make_model_setup(model, pressure, param_spec);
  if (rows == 0) throw InputError("--rows must be at least 1");
  if (!(noise >= 0.0) || !(noise_abs >= 0.0) || !std::isfinite(noise) || !std::isfinite(noise_abs))
    throw InputError("--noise and --noise-abs must be finite and >= 0");
  if (sigma_columns && noise == 0.0 && noise_abs == 0.0)
    throw InputError(
        "--sigma-columns needs --noise or --noise-abs > 0 (a sigma of 0 is not usable)");
  SyntheticDesign d;
  d.rows = rows;
  d.eps_min = eps_min;
  d.eps_max = eps_max;
  if (!(d.eps_min > 0.0) || !(d.eps_max >= d.eps_min) || !std::isfinite(d.eps_max))
    throw InputError("--eps-min/--eps-max: need 0 < eps-min <= eps-max, finite");
  if (loads.empty()) throw InputError("--loads: expected at least one load");
  for (double n : loads)
    if (!(n > 0.0) || !std::isfinite(n)) throw InputError("--loads: every load must be > 0");
  d.loads = loads;
  if (!(R > 0.0) || !std::isfinite(R)) throw InputError("--R must be a finite number > 0");
  if (!(spin > 0.0) || !std::isfinite(spin)) throw InputError("--spin must be a finite number > 0");
  d.contact_radius = R;
  d.spin = spin;
  if (slip_angles_deg.empty()) throw InputError("--slip-angles: expected at least one angle");
  d.slip_angles.clear();
  for (double deg : slip_angles_deg) {
    if (!std::isfinite(deg)) throw InputError("--slip-angles: every angle must be finite");
    d.slip_angles.push_back(deg * M_PI / 180.0);
  }
  d.negative_slip = !forward_only;

  Dataset data;
  {
    py::gil_scoped_release release;
    data = generate_dataset(s.kind, s.law, s.params, d, NoiseSpec{noise, noise_abs, sigma_columns},
                            seed);
  }
  const py::dict columns = dataset_columns(data);

  py::dict truth;
  for (int i : model_parameters(s.kind, s.law.kind)) truth[param_names()[i]] = s.params[i];
  py::dict out;
  out["columns"] = columns;
  out["parameters"] = truth;
  out["pressure"] = s.law_label;
  return out;
}

}  // namespace

void register_generate(py::module_& m) {
  m.def("generate", &generate, py::arg("model"), py::arg("pressure"), py::arg("params"),
        py::arg("rows"), py::arg("noise"), py::arg("noise_abs"), py::arg("sigma_columns"),
        py::arg("seed"), py::arg("eps_min"), py::arg("eps_max"), py::arg("loads"), py::arg("R"),
        py::arg("spin"), py::arg("slip_angles_deg"), py::arg("forward_only"));
}

}  // namespace frictionid::python
