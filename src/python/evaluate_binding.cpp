// What a model predicts, vectorised over rows (as `frictionid eval --input`), and the
// coefficients a pressure law implies (as `frictionid coefficients`): the app layer's code.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <frictionid/io/input_error.hpp>
#include "app/evaluation.hpp"
#include "app/law_coefficients.hpp"
#include "app/model_setup.hpp"
#include "python/bindings.hpp"
#include "python/json_values.hpp"
#include "python/numpy_columns.hpp"
#include "python/python_observer.hpp"

namespace py = pybind11;

namespace frictionid::python {

namespace {

// Arrays of one length (the Python side broadcasts them).
py::dict evaluate(const std::string& model, const std::string& pressure,
                  const app::ParameterValues& params, const DoubleArray& v_x,
                  const DoubleArray& v_y, const DoubleArray& omega, const DoubleArray& N,
                  const DoubleArray& R, const std::string& contact, bool pressure_given,
                  int threads, const py::object& cancel, const py::object& progress) {
  const app::ModelSetup s =
      app::make_model_setup({model, pressure, params, contact, pressure_given});
  const std::size_t rows = static_cast<std::size_t>(v_x.size());
  const DoubleArray* inputs[] = {&v_x, &v_y, &omega, &N, &R};
  const char* names[] = {"v_x", "v_y", "omega", "N", "R"};
  for (int k = 0; k < 5; ++k)
    if (inputs[k]->ndim() != 1 || static_cast<std::size_t>(inputs[k]->size()) != rows)
      throw InputError(
          fmt::format("{}: expected a one-dimensional array of {} values", names[k], rows));
  app::ResultantColumns out;
  run_observed(cancel, progress, [&](FitObserver& observer) {
    out = app::evaluate_columns(s, {v_x.data(), v_y.data(), omega.data(), N.data(), R.data(), rows},
                                threads, &observer);
  });
  py::dict d;
  d["T_x"] = to_numpy(out.T_x);
  d["T_y"] = to_numpy(out.T_y);
  d["M_z"] = to_numpy(out.M_z);
  d["M_roll"] = to_numpy(out.M_roll);
  if (app::shows_tilt(s)) d["M_tilt"] = to_numpy(out.M_tilt);
  d["N"] = to_numpy(out.N);
  return d;
}

}  // namespace

void register_evaluate(py::module_& m) {
  m.def("evaluate", &evaluate, py::arg("model"), py::arg("pressure"), py::arg("params"),
        py::arg("v_x"), py::arg("v_y"), py::arg("omega"), py::arg("N"), py::arg("R"),
        py::arg("contact") = "circle", py::arg("pressure_given") = true, py::arg("threads") = 0,
        py::arg("cancel") = py::none(), py::arg("progress") = py::none());
  m.def(
      "coefficients",
      [](const std::string& pressure, double kappa, double alpha, const std::string& contact,
         bool pressure_given) {
        return to_python(app::law_coefficients({pressure, kappa, alpha, contact, pressure_given}));
      },
      py::arg("pressure"), py::arg("kappa"), py::arg("alpha"), py::arg("contact") = "circle",
      py::arg("pressure_given") = true);
}

}  // namespace frictionid::python
