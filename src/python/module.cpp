// frictionid._frictionid: the C++ library for the Python package (python/frictionid), which
// adds the typed, documented API on top. Errors keep the command line's messages: InputError
// becomes frictionid.InputError (a ValueError), FitError frictionid.FitError (a RuntimeError).
#include <pybind11/pybind11.h>

#include <frictionid/fit_error.hpp>
#include <frictionid/io/input_error.hpp>
#include "io/text.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_frictionid, m) {
  m.doc() = "frictionid's C++ core; use the frictionid package instead of this module.";
  static py::exception<frictionid::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<frictionid::FitError> fit_error(m, "FitError", PyExc_RuntimeError);
  static py::exception<frictionid::python::FitCancelled> fit_cancelled(m, "FitCancelled",
                                                                       fit_error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const frictionid::python::FitCancelled& e) {
      fit_cancelled(e.what());
    } catch (const frictionid::InputError& e) {
      input_error(e.what());
    } catch (const frictionid::FitError& e) {
      fit_error(frictionid::text::for_terminal(e.what()).c_str());
    }
  });
  frictionid::python::register_fit(m);
  frictionid::python::register_evaluate(m);
  frictionid::python::register_generate(m);
  frictionid::python::register_simulate(m);
  frictionid::python::register_shimmy(m);
  frictionid::python::register_batch(m);
}
