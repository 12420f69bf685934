// What a model predicts, vectorised over rows (as `frictionid eval --input`), and the
// coefficients a pressure law implies (as `frictionid coefficients`).
#include <cmath>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <frictionid/io/input_error.hpp>
#include <frictionid/io/pressure_law_reader.hpp>
#include <frictionid/model/coefficients.hpp>
#include <frictionid/model_variant.hpp>
#include "cli/model_setup.hpp"
#include "cli/option_parsers.hpp"
#include "python/bindings.hpp"
#include "python/numpy_columns.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

// Arrays of one length (the Python side broadcasts them); N and R > 0, all finite.
py::dict evaluate(const std::string& model, const std::string& pressure,
                  const std::string& param_spec, const DoubleArray& v_x, const DoubleArray& v_y,
                  const DoubleArray& omega, const DoubleArray& N, const DoubleArray& R) {
  const cli::ModelSetup s = cli::make_model_setup(model, pressure, param_spec);
  const std::size_t rows = static_cast<std::size_t>(v_x.size());
  const DoubleArray* inputs[] = {&v_x, &v_y, &omega, &N, &R};
  const char* names[] = {"v_x", "v_y", "omega", "N", "R"};
  for (int k = 0; k < 5; ++k) {
    if (inputs[k]->ndim() != 1 || static_cast<std::size_t>(inputs[k]->size()) != rows)
      throw InputError(
          fmt::format("{}: expected a one-dimensional array of {} values", names[k], rows));
    const double* x = inputs[k]->data();
    for (std::size_t i = 0; i < rows; ++i)
      if (!std::isfinite(x[i]) || (k >= 3 && !(x[i] > 0.0)))
        throw InputError(fmt::format("{} at index {} is {}; expected a finite number{}", names[k],
                                     i, x[i], k >= 3 ? " > 0" : ""));
  }
  std::vector<double> out[5];
  for (auto& o : out) o.resize(rows);
  {
    py::gil_scoped_release release;
    const ModelEvaluator<double> eval(
        s.kind, s.law, s.params.data(),
        ring_table_for_rows(s.kind, s.law, s.params[kN], false, rows));
    for (std::size_t i = 0; i < rows; ++i) {
      const auto r = eval(model::Kinematics{v_x.data()[i], v_y.data()[i], omega.data()[i],
                                            N.data()[i], R.data()[i]});
      out[0][i] = r.T_x;
      out[1][i] = r.T_y;
      out[2][i] = r.M_z;
      out[3][i] = r.M_roll;
      out[4][i] = r.N;
    }
  }
  py::dict d;
  const char* outputs[] = {"T_x", "T_y", "M_z", "M_roll", "N"};
  for (int k = 0; k < 5; ++k) d[outputs[k]] = to_numpy(out[k]);
  return d;
}

// The fields of `frictionid coefficients`' JSON, same names and checks.
py::dict coefficients(const std::string& pressure, double kappa, double alpha) {
  if (!(kappa > 0.0) || !std::isfinite(kappa))
    throw InputError("--kappa must be a finite number > 0");
  if (!std::isfinite(alpha)) throw InputError("--alpha must be a finite angle in radians");
  const auto law = parse_pressure_option(pressure);
  const auto mo = model::law_moments(law);
  const auto c = model::coefficients(mo, kappa, alpha);
  for (double v : {c.a, c.b, c.m, c.b_tilde, c.p0, c.mu_M, c.rho_roll})
    if (!std::isfinite(v))
      throw InputError("--kappa " + fmt::format("{:g}", kappa) +
                       " is too small: m = ((1+kappa) m2/(d22 m3))^2 overflows");
  const auto ok = model::check_consistency(c, kappa, alpha);
  py::dict j;
  j["pressure"] = pressure_law_label(law, pressure);
  j["kappa"] = kappa;
  j["alpha"] = alpha;
  for (int k = 0; k <= 3; ++k) j[py::str("m" + std::to_string(k))] = mo[k];
  j["a"] = c.a;
  j["b"] = c.b;
  j["m"] = c.m;
  j["b_tilde"] = c.b_tilde;
  j["p0"] = c.p0;
  j["mu_M"] = c.mu_M;
  j["M_roll_per_hNR"] = c.rho_roll;
  py::dict consistency;
  consistency["a_at_most_4"] = ok.a_at_most_4;
  consistency["b_at_least_4"] = ok.b_at_least_4;
  consistency["m_lower_bound"] = ok.m_lower;
  consistency["m_upper_bound"] = ok.m_upper;
  consistency["all"] = ok.all();
  j["consistency"] = consistency;
  return j;
}

}  // namespace

void register_evaluate(py::module_& m) {
  m.def("evaluate", &evaluate, py::arg("model"), py::arg("pressure"), py::arg("params"),
        py::arg("v_x"), py::arg("v_y"), py::arg("omega"), py::arg("N"), py::arg("R"));
  m.def("coefficients", &coefficients, py::arg("pressure"), py::arg("kappa"), py::arg("alpha"));
}

}  // namespace frictionid::python
